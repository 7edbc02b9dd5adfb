# Curved cells (-mesh_geometry_order 2; docs/elements.md "Curved geometry"). The FD Jacobian of
# curved interfaces and cells is in unit.test_quad_interface (cases *_curved).
# Weight of a quarter annulus, Lame's thick cylinder straight against curved, a curved
# interface through the wall on 1 and 2 ranks.
poroseam_scene_test(verification.curved_geometry "order;verification;curved;mpi"
                    verification/curved_geometry.py)
