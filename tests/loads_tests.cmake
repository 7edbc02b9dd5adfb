# Loads a real geometry needs (issue 24 item 9): the normal pressure -bc_<b>_pressure and
# supports on physical points (docs/scenes.md "Normal pressure", "Physical points: supports"),
# label `loads`. tests/loads/loads.py: one ctest per case against closed forms and run-vs-run;
# tests/loads/loads_input.py: the refusals, one ctest per case.
foreach(case cylinder sphere slope axisymmetric table floating)
  poroseam_scene_test(loads.${case} "loads;verification" loads/loads.py --case ${case})
endforeach()
execute_process(COMMAND ${PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/loads/loads_input.py --list
                OUTPUT_VARIABLE POROSEAM_LOADS_INPUT_CASES OUTPUT_STRIP_TRAILING_WHITESPACE)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_SOURCE_DIR}/loads/loads_input.py)
string(REPLACE "\n" ";" POROSEAM_LOADS_INPUT_CASES "${POROSEAM_LOADS_INPUT_CASES}")
foreach(case ${POROSEAM_LOADS_INPUT_CASES})
  poroseam_scene_test(input.loads_${case} "input;loads" loads/loads_input.py --case ${case})
endforeach()
