# Quadratic interfaces (-displacement_order 2 with -interfaces; docs/elements.md, "Quadratic
# interfaces"): labels `order` and `interface`. The C++ test (tests/unit/test_quad_interface.cpp,
# globbed by tests/CMakeLists.txt) checks every Jacobian block against finite differences and
# that quadratic jumps are reproduced at the integration points.
set_tests_properties(unit.test_quad_interface PROPERTIES LABELS "unit;order;interface")
