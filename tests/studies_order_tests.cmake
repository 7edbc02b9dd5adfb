# The element-order axis of scripts/study (issue 25, docs/studies.md "Element orders").
# Included by tests/CMakeLists.txt. No poroseam run, about 3 s.
#   study.element_orders  displacement_orders in a study file: the runs per order, their
#                         -displacement_order and cache keys, the file checks; the cheapest
#                         run per order and target, the wall-time ratio, study.md's per-order
#                         table and the plot's line styles on fabricated runs
add_test(NAME study.element_orders
         COMMAND ${PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/study/check_study_orders.py)
set_tests_properties(study.element_orders PROPERTIES LABELS "study" TIMEOUT 120
  ENVIRONMENT "POROSEAM_SOURCE=${CMAKE_SOURCE_DIR};POROSEAM_TEST_OUTPUT=${CMAKE_BINARY_DIR}/test-output")
