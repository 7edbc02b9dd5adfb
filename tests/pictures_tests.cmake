# Pictures drawn with ParaView (docs/viewing.md): scripts/render_fields and figure 9a of
# scripts/plot_caisson on a small axisymmetric caisson run; without ParaView, the one-line
# messages of both scripts. Driver tests/pictures/pictures.py (its docstring lists the checks).
# SKIPPED (exit 77) after the checks without ParaView when pvpython is not installed: ParaView
# is not a dependency of poroseam. About 10 s on a quiet machine (pvpython starts twice).
# Included by tests/CMakeLists.txt.
poroseam_scene_test(pictures.caisson_fig9a "pictures" pictures/pictures.py)
set_tests_properties(pictures.caisson_fig9a PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
# The plastic zone (render_fields --field equivalent_plastic_strain / yield_state) against
# fields.h5 (tests/pictures/plastic_zone.py); SKIPPED without pvpython.
poroseam_scene_test(pictures.plastic_zone "pictures" pictures/plastic_zone.py)
set_tests_properties(pictures.plastic_zone PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
# ParaView draws the order-2 displacement as the quadratic field it is (quadratic XDMF cells of
# fields.xmf against the Lagrange interpolation of fields.h5; tests/pictures/quadratic_fields.py).
poroseam_scene_test(pictures.quadratic_fields "pictures;order;outputs" pictures/quadratic_fields.py)
set_tests_properties(pictures.quadratic_fields PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
