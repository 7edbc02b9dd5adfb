# Bad-input, MPI-consistency and solver-preset tests; included by tests/CMakeLists.txt.
# Drivers: tests/input/bad_input.py (one ctest per case), tests/input/user_scenes.py,
# tests/mpi/mpi_match.py (1 vs 2 ranks), tests/mpi/solver_presets.py (presets vs MUMPS LU).

# Broken scenes: non-zero exit, one error line that names the offending item, no crash, no
# hang; and the good runs next to them (valid meshes in every format, shell characters in
# paths, gmsh dying with a killed run, -malloc_dump clean). One ctest per case of the driver
# (its --list); cases ending in _np2 run on 2 ranks (label mpi too).
execute_process(COMMAND ${PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/input/bad_input.py --list
                OUTPUT_VARIABLE POROSEAM_INPUT_CASES OUTPUT_STRIP_TRAILING_WHITESPACE)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_SOURCE_DIR}/input/bad_input.py)
string(REPLACE "\n" ";" POROSEAM_INPUT_CASES "${POROSEAM_INPUT_CASES}")
foreach(case ${POROSEAM_INPUT_CASES})
  if(case MATCHES "_np2$")
    poroseam_scene_test(input.${case} "input;mpi" input/bad_input.py --case ${case})
  else()
    poroseam_scene_test(input.${case} "input" input/bad_input.py --case ${case})
  endif()
endforeach()
set_property(TEST input.malloc_dump_clean input.malloc_dump_clean_interface_np2 APPEND PROPERTY
             LABELS memory)
# The example scenes of options/ run from the source tree as their headers say, one ctest per
# scene (input.user_scenes.<scene>) so that ctest packs them beside the other tests: the two
# 3D caissons on their default mesh take 25-35 s each, the others 1-3 s. The glob is checked
# at every build, so a new options/*.opts gets its ctest without a manual re-configure.
file(GLOB POROSEAM_USER_SCENES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/options/*.opts)
if(NOT POROSEAM_USER_SCENES)
  poroseam_scene_test(input.user_scenes "input" input/user_scenes.py)  # fails: no scenes
endif()
foreach(path ${POROSEAM_USER_SCENES})
  get_filename_component(scene ${path} NAME_WE)
  poroseam_scene_test(input.user_scenes.${scene} "input" input/user_scenes.py --scene ${scene})
endforeach()
# -help with a scene: every option listed once with its value and description, no step taken,
# nothing written (tests/input/scene_help.py). A few seconds each.
foreach(case terzaghi joint_np2 bad_value)
  poroseam_scene_test(input.scene_help_${case} "input" input/scene_help.py --case ${case})
endforeach()
set_tests_properties(input.scene_help_joint_np2 PROPERTIES LABELS "input;mpi")

# 1 rank vs 2 ranks (MUMPS LU): time series to 1e-8, fields matched by vertex coordinates.
foreach(case terzaghi_2d terzaghi_3d two_regions_2d)
  poroseam_scene_test(mpi.match_${case} "mpi" mpi/mpi_match.py --case ${case})
endforeach()

# Solver presets (options/solvers/direct.opts, fieldsplit.opts) agree with MUMPS LU to 1e-6.
foreach(case terzaghi_2d two_regions_2d elastic_2d block_shear_2d joint_column_2d joint_realistic_2d)
  poroseam_scene_test(solvers.presets_${case} "solvers" mpi/solver_presets.py --case ${case})
  poroseam_scene_test(solvers.presets_${case}_np2 "solvers;mpi" mpi/solver_presets.py --case ${case} --ranks 2)
endforeach()
