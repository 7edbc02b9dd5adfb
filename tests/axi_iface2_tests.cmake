# Axisymmetric quadratic interfaces (-axisymmetric -displacement_order 2 with -interfaces;
# docs/elements.md, "Quadratic interfaces"). The Jacobian blocks against finite differences are
# cases axi_* of tests/unit/test_quad_interface.cpp. Scenes with closed forms, full circle:
# the uniform-compression patch test (p'_N = q at every point, interface force q pi R^2) at the
# stiffest penalty, K_N h / E = 1e4 (all four pass by hand), Gauss and nodal rules (with the
# ring radius taken at the cell's centre instead of the point, Gauss fails it: p'_N off by up
# to 86 %, though the total force stays q pi R^2); the storage of a gap opened at a known
# rate (storage, exchange with the bulk pressure, p3 and its force on the faces, area pi).
poroseam_scene_test(interface.order2_patch_axisymmetric "interface;order;axisymmetric"
                    interface/patch.py --axisymmetric --order 2 --ratios 1e4)
poroseam_scene_test(hydraulics.order2_gap_storage_axisymmetric
                    "hydraulics;interface;order;axisymmetric" hydraulics/gap_storage.py --order 2
                    --axisymmetric)
# The coarse axisymmetric caissons at order 2 (tests/caisson/caisson.py --order 2, 1 rank): the
# caisson's vertical equilibrium every step (interface forces with p3, ring weights), the
# drained plateau F_ext = mu int p'_N and the outer skirt's weights adding up to 2 pi R_o L, the
# lid gap's storage rate against rho_w v_up pi R_i^2 (partially drained).
poroseam_scene_test(caisson.axisym_drained_order2 "caisson;order;axisymmetric"
                    caisson/caisson.py --case axisym_drained --ranks 1 --order 2)
poroseam_scene_test(caisson.axisym_partially_drained_order2 "caisson;order;axisymmetric"
                    caisson/caisson.py --case axisym_partially_drained --ranks 1 --order 2)
