# Manufactured solutions with a cohesive interface (tests/unit/test_order_mms_interface.cpp,
# globbed by tests/CMakeLists.txt; the framework is tests/unit/order_mms.hpp): labels `order`
# and `interface`. Observed rates in docs/verification.md, "Manufactured solutions with an
# interface".
set_tests_properties(unit.test_order_mms_interface PROPERTIES LABELS "unit;order;interface")
