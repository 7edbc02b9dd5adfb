# Bulk Jacobian on curved cells (-mesh_geometry_order 2) against finite differences
# (tests/unit/test_curved_jacobian.cpp, globbed by tests/CMakeLists.txt): Biot in plane strain
# (quadrilaterals, triangles), axisymmetric and 3D (hexahedra, tetrahedra), Mohr-Coulomb on a
# face and the triaxial edge; meshes/thick_cylinder_plane*.geo, thick_cylinder_slab_3d*.geo.
set_tests_properties(unit.test_curved_jacobian PROPERTIES LABELS "unit;order;curved")
