# Interface patch test with quadratic jumps at the solver level (tests/unit/test_quad_patch_jump.cpp,
# globbed by tests/CMakeLists.txt; docs/verification.md, "Order 2: quadratic jumps across an
# interface"): an exact solution of degree 2 in both bodies; quadratic slip (slip), quadratic
# opening and tangential jump (open), quadratic bodies with a linear jump (stick), and a
# quadratic opening and slip in stick held by a manufactured interface load; 2D quadrilaterals
# and triangles, 3D hexahedra and tetrahedra. Order 2 reproduces it to round-off; the same
# scenes at order 1 must miss it. About 10 s of wall time on a loaded machine, 2.6 s of CPU.
set_tests_properties(unit.test_quad_patch_jump PROPERTIES LABELS "unit;order;interface")
