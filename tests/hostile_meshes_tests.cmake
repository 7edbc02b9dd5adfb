# Hostile meshes and .geo files (issue 23; tests/input/hostile_meshes.py, one ctest per case):
# a .geo that runs a program or writes a file, an endless loop (gmsh's time limit), gmsh dying
# out of memory, a mesh too large for the machine's memory, absurd node tags, coincident
# nodes, degenerate and folded cells, a 2D mesh off z = 0, empty physical groups, interface
# T-junctions and non-edges, a body that floats free. Each ends in one line in seconds.
execute_process(COMMAND ${PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/input/hostile_meshes.py --list
                OUTPUT_VARIABLE POROSEAM_HOSTILE_MESH_CASES OUTPUT_STRIP_TRAILING_WHITESPACE)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_SOURCE_DIR}/input/hostile_meshes.py)
string(REPLACE "\n" ";" POROSEAM_HOSTILE_MESH_CASES "${POROSEAM_HOSTILE_MESH_CASES}")
foreach(case ${POROSEAM_HOSTILE_MESH_CASES})
  poroseam_scene_test(input.hostile_mesh.${case} "input" input/hostile_meshes.py --case ${case})
  set_tests_properties(input.hostile_mesh.${case} PROPERTIES TIMEOUT 90)
  if(case MATCHES "_np2$")
    set_tests_properties(input.hostile_mesh.${case} PROPERTIES LABELS "input;mpi")
  endif()
endforeach()
