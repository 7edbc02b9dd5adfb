# Curved cells (-mesh_geometry_order 2; docs/elements.md "Curved geometry"). The FD Jacobian of
# curved interfaces is in unit.test_quad_interface (cases *_curved), of curved bulk cells in
# unit.test_curved_jacobian (tests/curvedfd_tests.cmake).
# Weight of a quarter annulus, Lame's thick cylinder straight against curved (quadrilaterals
# and triangles), a curved interface through the wall on 1 and 2 ranks.
poroseam_scene_test(verification.curved_geometry "order;verification;curved;mpi"
                    verification/curved_geometry.py)
# Bad input of -mesh_geometry_order and second-order meshes (tests/input/curved_input.py, one
# ctest per case; _np2 on 2 ranks).
execute_process(COMMAND ${PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/input/curved_input.py --list
                OUTPUT_VARIABLE POROSEAM_CURVED_INPUT_CASES OUTPUT_STRIP_TRAILING_WHITESPACE)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_SOURCE_DIR}/input/curved_input.py)
string(REPLACE "\n" ";" POROSEAM_CURVED_INPUT_CASES "${POROSEAM_CURVED_INPUT_CASES}")
foreach(case ${POROSEAM_CURVED_INPUT_CASES})
  poroseam_scene_test(input.${case} "input;curved" input/curved_input.py --case ${case})
endforeach()
