# Curved cells (-mesh_geometry_order 2) outside the computation (tests/verification/
# curved_output.py, its docstring gives the closed forms): fields.h5's nodes on the circles the
# meshes are built on (quadrilaterals with an interface, triangles, hexahedra; the straight-sided
# run's chords beside them), about 6 s; the interface penalty warning's cell height from the
# curved cell and face (two rings of quadrilaterals, of triangles, and their slab of hexahedra,
# meshes/two_rings_plane_tri.geo, two_rings_slab_3d.geo), about 6 s. Included by tests/CMakeLists.txt.
poroseam_scene_test(outputs.fields_curved "outputs;order;curved"
                    verification/curved_output.py --case fields)
poroseam_scene_test(interface.penalty_height_curved "interface;curved"
                    verification/curved_output.py --case penalty)
