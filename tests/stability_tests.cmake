# Hard cases of Newton's method with zero-thickness interfaces (issue 11, part 5): each must reach
# its final time without cut-backs and within a bound on Newton iterations per step, measured
# and recorded in tests/solve/hard_cases.py (its docstring has the counts before the kink line
# search and the honest stopping test of src/solve/newton_control.cpp). Included by
# tests/CMakeLists.txt.
poroseam_scene_test(stability.shear_stiff_ramp "stability;interface" solve/hard_cases.py --case shear_stiff_ramp)
poroseam_scene_test(stability.shear_stiff_reversals "stability;interface" solve/hard_cases.py --case shear_stiff_reversals)
poroseam_scene_test(stability.caisson_mu10_drained "stability;caisson;interface" solve/hard_cases.py --case caisson_mu10_drained)
poroseam_scene_test(stability.caisson_mu10_partially_drained "stability;caisson;interface;hydraulics" solve/hard_cases.py --case caisson_mu10_partially_drained)
poroseam_scene_test(stability.crack_jacking "stability;hydraulics;interface" solve/hard_cases.py --case crack_jacking)
poroseam_scene_test(stability.joint_stall "stability;hydraulics;interface" solve/hard_cases.py --case joint_stall)
