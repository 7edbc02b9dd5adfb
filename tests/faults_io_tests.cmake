# I/O faults of the output directory (tests/input/io_faults.py, one ctest per case, 2 ranks):
# a directory where a file should be, a read-only directory, two runs in one directory, a
# killed run's lock, symbolic links, a full disk. Each must end in one line, never hang: the
# driver kills a run after 120 s and ctest's TIMEOUT backs it up. Cases that need mount(8)
# (read-only bind mount, tmpfs) are skipped (exit 77) where mounting is not allowed.
execute_process(COMMAND ${PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/input/io_faults.py --list
                OUTPUT_VARIABLE POROSEAM_IO_FAULT_CASES OUTPUT_STRIP_TRAILING_WHITESPACE)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_SOURCE_DIR}/input/io_faults.py)
string(REPLACE "\n" ";" POROSEAM_IO_FAULT_CASES "${POROSEAM_IO_FAULT_CASES}")
foreach(case ${POROSEAM_IO_FAULT_CASES})
  poroseam_scene_test(faults.io_${case} "faults;mpi" input/io_faults.py --case ${case})
  set_tests_properties(faults.io_${case} PROPERTIES TIMEOUT 300 SKIP_RETURN_CODE 77)
endforeach()
