# PETSc options typed wrong (issue 24 item 5): misspelt names stop the run before its first
# step or at its first linear solve with "did you mean"; bad values of PETSc's choice options
# are one line (tests/input/petsc_options.py; each case a few seconds).
foreach(case ts_dtt snes_montor ksp_typ two_typos fieldsplit_pc_typ mumps_icntl_144 unused_ok
             unused_ok_misspelt
             preset_unused_not_typed hypre_type ksp_type linesearch_type ts_type split_pc_type
             schur_fact_type order_coarsening_value stiff_ratio_value)
  poroseam_scene_test(input.petsc_options.${case} "input;options" input/petsc_options.py --case ${case})
endforeach()
foreach(case ksp_typ_np2 fieldsplit_pc_typ_np2 hypre_type_np2 ksp_type_np2 linesearch_type_np2
             ts_type_np2 split_pc_type_np2 schur_fact_type_np2 order_coarsening_value_np2
             stiff_ratio_value_np2)
  poroseam_scene_test(input.petsc_options.${case} "input;options;mpi" input/petsc_options.py --case ${case})
endforeach()
