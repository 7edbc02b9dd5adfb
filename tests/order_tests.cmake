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
