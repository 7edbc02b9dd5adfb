# Bad-input, MPI-consistency and solver-preset tests; included by tests/CMakeLists.txt.
# Drivers: tests/input/bad_input.py (one ctest per case), tests/input/user_scenes.py,
# tests/mpi/mpi_match.py (1 vs 2 ranks), tests/mpi/solver_presets.py (presets vs MUMPS LU).

# Broken scenes: non-zero exit, the error names the offending item, no crash, no hang.
foreach(case
    missing_mesh mesh_extension unknown_region unknown_boundary bc_unlisted_boundary
    missing_E E_zero E_negative nu_half nu_below_minus_one negative_permeability
    missing_material unknown_material non_numeric probe_wrong_coords probe_outside
    inverted_element unused_option shell_characters_in_paths help)
  poroseam_scene_test(input.${case} "input" input/bad_input.py --case ${case})
endforeach()
# The same failures on 2 ranks: every rank must exit.
foreach(case probe_outside_np2 inverted_element_np2 missing_E_np2)
  poroseam_scene_test(input.${case} "input;mpi" input/bad_input.py --case ${case})
  set_tests_properties(input.${case} PROPERTIES PROCESSORS 2)
endforeach()
# The example scenes of options/ run from the source tree as their headers say.
poroseam_scene_test(input.user_scenes "input" input/user_scenes.py)

# 1 rank vs 2 ranks (MUMPS LU): time series to 1e-8, fields matched by vertex coordinates.
foreach(case terzaghi_2d terzaghi_3d two_regions_2d)
  poroseam_scene_test(mpi.match_${case} "mpi" mpi/mpi_match.py --case ${case})
  set_tests_properties(mpi.match_${case} PROPERTIES PROCESSORS 2)
endforeach()

# Solver presets (options/solvers/direct.opts, fieldsplit.opts) agree with MUMPS LU to 1e-6.
foreach(case terzaghi_2d two_regions_2d elastic_2d block_shear_2d joint_column_2d joint_realistic_2d)
  poroseam_scene_test(solvers.presets_${case} "solvers" mpi/solver_presets.py --case ${case})
  poroseam_scene_test(solvers.presets_${case}_np2 "solvers;mpi" mpi/solver_presets.py --case ${case} --ranks 2)
  set_tests_properties(solvers.presets_${case}_np2 PROPERTIES PROCESSORS 2)
endforeach()
