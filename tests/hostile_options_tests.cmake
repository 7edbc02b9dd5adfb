# Hostile options files and option values (tests/input/hostile_options.py, one ctest per case,
# label input; cases ending in _np2 run on 2 ranks, label mpi too): self-including and cyclic
# options files, binary files, /dev/zero, FIFOs (a hang fails), 600 probes (PETSc's 512-option
# table), control characters in a path, values longer than PETSc reads, integers that overflow,
# a file where the checkpoints folder belongs; and the good runs: a scene copied elsewhere finds
# its mesh, nested options and time table next to the files that name them. Included by
# tests/CMakeLists.txt.
execute_process(COMMAND ${PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/input/hostile_options.py --list
                OUTPUT_VARIABLE POROSEAM_HOSTILE_CASES OUTPUT_STRIP_TRAILING_WHITESPACE)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_SOURCE_DIR}/input/hostile_options.py)
string(REPLACE "\n" ";" POROSEAM_HOSTILE_CASES "${POROSEAM_HOSTILE_CASES}")
foreach(case ${POROSEAM_HOSTILE_CASES})
  if(case MATCHES "_np2$")
    poroseam_scene_test(input.hostile.${case} "input;mpi" input/hostile_options.py --case ${case})
  else()
    poroseam_scene_test(input.hostile.${case} "input" input/hostile_options.py --case ${case})
  endif()
endforeach()
