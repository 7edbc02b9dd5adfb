# A scene that names no solver gets -solver_preset auto, and a failed linear solve is reported
# as one (issue 24, item 1; docs/scenes.md "Time stepping and solvers"). Driver
# tests/solver_default/solver_default.py (its docstring says what each case checks). Included
# by tests/CMakeLists.txt. A few seconds each.
poroseam_scene_test(solvers.default_interfaces_2d "solvers;interface;hydraulics" solver_default/solver_default.py --case interfaces_2d)
poroseam_scene_test(solvers.default_3d "solvers" solver_default/solver_default.py --case scene_3d)
poroseam_scene_test(solvers.linear_failure "solvers;cutback" solver_default/solver_default.py --case linear_failure)
