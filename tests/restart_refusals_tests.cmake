# Restarts refuse what they cannot honour (issue 23, item 5; docs/checkpoints.md): a changed
# physics or discretisation option, a changed mesh file, a final time at or before the
# checkpoint, damaged checkpoints (fallback to the previous whole one, or one error), a missing
# output file; and a later final time continues the run, equal to the uninterrupted one. Driver
# tests/restart/restart_refusals.py (one ctest per case and number of ranks; its docstring says
# what is checked). Included by tests/CMakeLists.txt.
execute_process(COMMAND ${PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_refusals.py --list
                OUTPUT_VARIABLE POROSEAM_RESTART_REFUSALS OUTPUT_STRIP_TRAILING_WHITESPACE)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_refusals.py)
string(REPLACE "\n" ";" POROSEAM_RESTART_REFUSALS "${POROSEAM_RESTART_REFUSALS}")
foreach(case ${POROSEAM_RESTART_REFUSALS})
  poroseam_scene_test(restart.refusals_${case} "faults;restart" restart/restart_refusals.py
                      --case ${case} --ranks 1)
  poroseam_scene_test(restart.refusals_${case}_np2 "faults;restart;mpi" restart/restart_refusals.py
                      --case ${case} --ranks 2)
endforeach()
