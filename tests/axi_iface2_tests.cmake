# Axisymmetric quadratic interfaces (-axisymmetric -displacement_order 2 with -interfaces;
# docs/elements.md, "Quadratic interfaces"). The Jacobian blocks against finite differences are
# cases axi_* of tests/unit/test_quad_interface.cpp. Scenes with closed forms, full circle:
# the uniform-compression patch test (p'_N = q at every point, interface force q pi R^2) at the
# softest and stiffest penalty, Gauss and nodal rules; the storage of a gap opened at a known
# rate (storage, exchange with the bulk pressure, p3 and its force on the faces, area pi).
poroseam_scene_test(interface.order2_patch_axisymmetric "interface;order;axisymmetric"
                    interface/patch.py --axisymmetric --order 2 --ratios 1e-2,1e4)
poroseam_scene_test(hydraulics.order2_gap_storage_axisymmetric
                    "hydraulics;interface;order;axisymmetric" hydraulics/gap_storage.py --order 2
                    --axisymmetric)
