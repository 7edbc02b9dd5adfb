# The linear solver keeps its factorisation or preconditioner while the Jacobian is unchanged
# (-snes_keep_preconditioner, docs/performance.md "Keeping the factorisation"): counted from
# PETSc's -log_view, results against the run that rebuilds it (tests/solve/keep_factor.py).
foreach(case linear linear_order2 linear_np2 dt_change bdf2 iterative interface)
  poroseam_scene_test(solve.keep_factor_${case} "solve;keep_factor" solve/keep_factor.py
                      --case ${case})
endforeach()
set_tests_properties(solve.keep_factor_linear_np2 PROPERTIES PROCESSORS 2 LABELS "solve;keep_factor;mpi")
