# A stop from outside keeps the work (issue 23, item 1; docs/checkpoints.md, "A stop from
# outside"): SIGTERM, SIGINT, SIGHUP sent to mpiexec after step 20 of a 2-rank run, a step that
# outlasts mpiexec's grace, and a stdout nobody reads; then -restart equals the uninterrupted
# run. Driver tests/input/stop_signals.py (its docstring says what is checked); the many-trial
# measurement is scripts/stop_trials. Included by tests/CMakeLists.txt.
execute_process(COMMAND ${PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/input/stop_signals.py --list
                OUTPUT_VARIABLE POROSEAM_STOP_CASES OUTPUT_STRIP_TRAILING_WHITESPACE)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_SOURCE_DIR}/input/stop_signals.py)
string(REPLACE "\n" ";" POROSEAM_STOP_CASES "${POROSEAM_STOP_CASES}")
foreach(case ${POROSEAM_STOP_CASES})
  poroseam_scene_test(faults.stop_${case} "faults;mpi" input/stop_signals.py --case ${case})
  set_tests_properties(faults.stop_${case} PROPERTIES TIMEOUT 600)
endforeach()
