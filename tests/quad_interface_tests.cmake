# Quadratic interfaces (-displacement_order 2 with -interfaces; docs/elements.md, "Quadratic
# interfaces"): labels `order` and `interface`. The C++ test (tests/unit/test_quad_interface.cpp,
# globbed by tests/CMakeLists.txt) checks every Jacobian block against finite differences and
# that quadratic jumps are reproduced at the integration points.
set_tests_properties(unit.test_quad_interface PROPERTIES LABELS "unit;order;interface")
# Runs at order 2 (each a few seconds): the integration rule of stiff interfaces chosen by a
# patch test (tests/interface/quad_rule.py: uniform pressure, and no zig-zag of p'_N under a
# non-uniform state at K_N h / E = 1e3); stick and slip of near-rigid bodies, every point
# (quad_slide.py, 2D, 3D hexahedra and tetrahedra); the uniform-compression patch test for
# K_N h / E from 1e-2 to 1e4 (patch.py --order 2, 2D quadrilaterals and 3D tetrahedra);
# Poiseuille flow and gap storage against their closed forms (the hydraulic couplings).
poroseam_scene_test(interface.order2_rule "interface;order" interface/quad_rule.py)
poroseam_scene_test(interface.order2_slide_2d "interface;order" interface/quad_slide.py --dim 2)
poroseam_scene_test(interface.order2_slide_3d "interface;order" interface/quad_slide.py --dim 3)
poroseam_scene_test(interface.order2_slide_3d_tet "interface;order" interface/quad_slide.py
                    --dim 3 --mesh meshes/block_on_base_3d_tet.geo)
poroseam_scene_test(interface.order2_patch_2d "interface;order" interface/patch.py --dim 2
                    --order 2)
poroseam_scene_test(interface.order2_patch_3d_tet "interface;order" interface/patch.py --dim 3
                    --order 2 --mesh meshes/block_on_base_3d_tet.geo)
poroseam_scene_test(hydraulics.order2_poiseuille_quad "hydraulics;interface;order"
                    hydraulics/poiseuille.py --mesh quad --order 2)
poroseam_scene_test(hydraulics.order2_poiseuille_tet "hydraulics;interface;order"
                    hydraulics/poiseuille.py --mesh tet --order 2)
poroseam_scene_test(hydraulics.order2_gap_storage "hydraulics;interface;order"
                    hydraulics/gap_storage.py --order 2)
# A run stopped between slip and unloading and continued from its checkpoint equals the
# uninterrupted run (the integration-point history of the quadratic cells), 2 ranks.
poroseam_scene_test(restart.order2_interface_np2 "restart;interface;order;mpi"
                    interface/quad_slide.py --restart --ranks 2)
