# Element order (-displacement_order, docs/elements.md): label `order`. The C++ tests are
# unit tests (tests/unit/test_order_*.cpp, globbed by tests/CMakeLists.txt); they get the
# label here too.
set_tests_properties(unit.test_order_mms PROPERTIES LABELS "unit;order")
set_tests_properties(unit.test_element_order PROPERTIES LABELS "unit;order")
set_tests_properties(unit.test_biot_jacobian PROPERTIES LABELS "unit;order")
# Terzaghi's column at orders 1 and 2 against the closed form (consolidation, first undrained
# step).
poroseam_scene_test(verification.order_terzaghi_2d "order;verification;terzaghi"
                    verification/order_terzaghi.py)
# Bad input of -displacement_order and the scenes order 2 refuses (tests/input/order_input.py,
# one ctest per case; _np2 on 2 ranks).
execute_process(COMMAND ${PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/input/order_input.py --list
                OUTPUT_VARIABLE POROSEAM_ORDER_INPUT_CASES OUTPUT_STRIP_TRAILING_WHITESPACE)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_SOURCE_DIR}/input/order_input.py)
string(REPLACE "\n" ";" POROSEAM_ORDER_INPUT_CASES "${POROSEAM_ORDER_INPUT_CASES}")
foreach(case ${POROSEAM_ORDER_INPUT_CASES})
  poroseam_scene_test(input.${case} "input;order" input/order_input.py --case ${case})
endforeach()
# The geostatic initial state at order 2, 2D and 3D layered columns.
poroseam_scene_test(verification.order_geostatic "order;verification;geostatic"
                    verification/order_geostatic.py)
# fields.h5 at order 2: quadratic XDMF cells, nodes where VTK puts them, values at every node.
set_tests_properties(unit.test_output_quadratic PROPERTIES LABELS "unit;order;outputs")
# Mandel's problem at order 2 (Taylor-Hood, no stabilisation): the same closed-form checks as
# order 1 (tests/verification/mandel.py --order 2). Measured: centre pressure 0.38 % of p0
# (order 1: 0.51 %; both dominated by backward Euler's time error), top force 0.36 % of F.
poroseam_scene_test(verification.mandel_order2 "order;verification;mandel"
                    verification/mandel.py --ranks 1 --order 2)
