# Inputs that passed silently with a wrong meaning (issue 23, item 4): two conditions on one
# unknown, corners shared by two boundaries, time tables, -stabilization_factor out of range,
# derived defaults (K0). Driver: tests/input/silent_cases.py (one ctest per case of its
# --list, through bad_input.py's checks); cases ending in _np2 run on 2 ranks (label mpi too).
execute_process(COMMAND ${PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/input/silent_cases.py --list
                OUTPUT_VARIABLE POROSEAM_SILENT_CASES OUTPUT_STRIP_TRAILING_WHITESPACE)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_SOURCE_DIR}/input/silent_cases.py)
string(REPLACE "\n" ";" POROSEAM_SILENT_CASES "${POROSEAM_SILENT_CASES}")
foreach(case ${POROSEAM_SILENT_CASES})
  if(case MATCHES "_np2$")
    poroseam_scene_test(input.silent.${case} "input;mpi" input/silent_cases.py --case ${case})
  else()
    poroseam_scene_test(input.silent.${case} "input" input/silent_cases.py --case ${case})
  endif()
endforeach()
