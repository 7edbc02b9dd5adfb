# The linear solver keeps its factorisation or preconditioner while the Jacobian is unchanged
# (-snes_keep_preconditioner, docs/performance.md "Keeping the factorisation"): counted from
# PETSc's -log_view, results against the run that rebuilds it (tests/solve/keep_factor.py).
foreach(case linear linear_order2 linear_np2 dt_change bdf2 iterative interface)
  poroseam_scene_test(solve.keep_factor_${case} "solve;keep_factor" solve/keep_factor.py
                      --case ${case})
endforeach()
set_tests_properties(solve.keep_factor_linear_np2 PROPERTIES LABELS "solve;keep_factor;mpi")
# The fieldsplit preset at -displacement_order 2 (node blocks and rigid-body modes on edge, face
# and cell nodes) agrees with MUMPS LU to 1e-6 on 1 and 2 ranks (tests/mpi/solver_presets.py).
foreach(case terzaghi_3d_order2 elastic_3d_order2 block_shear_3d_order2 caisson_3d_order2)
  poroseam_scene_test(solvers.presets_${case} "solvers;order" mpi/solver_presets.py --case ${case})
  poroseam_scene_test(solvers.presets_${case}_np2 "solvers;order;mpi" mpi/solver_presets.py
                      --case ${case} --ranks 2)
endforeach()
# The rigid-body near-null space is exact at both orders (K r = 0 without supports).
set_tests_properties(unit.test_rigid_modes PROPERTIES LABELS "unit;order;solvers")
