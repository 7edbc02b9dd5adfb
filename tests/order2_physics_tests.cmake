# Displacement order 2 with axisymmetry, Mohr-Coulomb plasticity and probes (issue 25; label
# `order`, docs/elements.md "Order 2 with axisymmetry, plasticity and probes"). The C++ parts are
# cases of unit.test_order_mms (axisymmetric manufactured solutions) and
# unit.test_plastic_jacobian (order-2 regimes); these are the scene tests. Times: CPU seconds of the
# whole test, measured on the shared machine at load ~20 (the wall time of an idle core is
# about that or less).
# Lame's thick cylinder, axisymmetric, Lagrange Q2, drained and undrained, probes between the
# nodes: rate 3 of u_r, the ring force on r = a exact (1.4 s).
poroseam_scene_test(verification.order_thick_cylinder "order;verification;axisymmetric"
                    verification/axisymmetric.py --order 2)
# The plastic scene (tests/plasticity/footing_block.opts: a block on a porous Mohr-Coulomb layer,
# geostatic state, probes) at order 2: a run stopped at step 12 and restarted from its checkpoint
# (the history of 6 points per triangle) equals the uninterrupted run (4.3 s).
poroseam_scene_test(plasticity.restart_order2 "plasticity;restart;order"
                    plasticity/scene.py --case restart --order 2)
# Strip footing on weightless soil with P2 triangles on an ordinary mesh (one diagonal per grid
# cell, where P1 triangles lock: +21 % Tresca), 40 cells under the half footing growing by 1.25
# away from it: the plateau within 1 % of Prandtl's (pi + 2) c and N_c c (phi = psi = 20 deg);
# measured +0.73 % and +0.86 % (docs/verification.md, "Order 2: collapse loads"). 14.8 s and
# 12.1 s.
poroseam_scene_test(plasticity.strip_footing_tresca_order2 "plasticity;verification;order"
                    plasticity/footing.py --case tresca --triangles --order 2 --cells 40
                    --growth 1.25 --tolerance 0.01)
poroseam_scene_test(plasticity.strip_footing_frictional_order2 "plasticity;verification;order"
                    plasticity/footing.py --case frictional --triangles --order 2 --cells 40
                    --growth 1.25 --tolerance 0.01)
# Rigid circular footing on a weightless Tresca soil (axisymmetric, the same mesh as above, the
# footing a disc of radius b): P2 triangles against Shield's N_c = 5.69 (smooth) and Eason and
# Shield's 6.05 (rough), within 3 %; measured +1.8 % and +2.8 %. P1 triangles lock here on every
# mesh (+36 % on this one; docs/verification.md has both orders side by side). 9.3 s each.
poroseam_scene_test(plasticity.circular_footing_smooth_order2
                    "plasticity;verification;order;axisymmetric"
                    plasticity/footing.py --case circular_smooth --triangles --order 2 --cells 40
                    --growth 1.25 --tolerance 0.03)
poroseam_scene_test(plasticity.circular_footing_rough_order2
                    "plasticity;verification;order;axisymmetric"
                    plasticity/footing.py --case circular_rough --triangles --order 2 --cells 40
                    --growth 1.25 --tolerance 0.03)
