# Displacement order 2 with axisymmetry, Mohr-Coulomb plasticity and probes (issue 25; label
# `order`, docs/elements.md "Order 2 with axisymmetry, plasticity and probes"). The C++ parts are
# cases of unit.test_order_mms (axisymmetric manufactured solutions) and
# unit.test_plastic_jacobian (order-2 regimes); these are the scene tests. Times on one core of
# an idle 2-core machine.
# Lame's thick cylinder, axisymmetric, Lagrange Q2, drained and undrained, probes between the
# nodes: rate 3 of u_r, the ring force on r = a exact (about 10 s).
poroseam_scene_test(verification.order_thick_cylinder "order;verification;axisymmetric"
                    verification/axisymmetric.py --order 2)
