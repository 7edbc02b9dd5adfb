# Mohr-Coulomb soil against closed forms (tests/plasticity/; issue 13 item 2). Included by
# tests/CMakeLists.txt. Run times on one core: footings about 10 s each, cavity about 2 s.
# Strip footing on weightless soil: the plateau of the footing pressure within 5 % of
# Prandtl's (pi + 2) c (Tresca) and N_c c (phi = psi = 20 deg), crossed-triangle mesh.
poroseam_scene_test(plasticity.strip_footing_tresca "plasticity;verification"
                    plasticity/footing.py --case tresca)
poroseam_scene_test(plasticity.strip_footing_frictional "plasticity;verification"
                    plasticity/footing.py --case frictional)
# Cylindrical cavity expansion (phi = 30, psi = 5 deg): pressure-expansion within 2 % of the
# small-strain closed form, on 1 and 2 ranks.
poroseam_scene_test(plasticity.cavity_expansion "plasticity;verification;axisymmetric"
                    plasticity/cavity.py)
poroseam_scene_test(plasticity.cavity_expansion_np2 "plasticity;verification;axisymmetric;mpi"
                    plasticity/cavity.py --ranks 2)
# The closed forms themselves against independent results (Prandtl's numbers, first yield,
# the incompressible Tresca cavity c (1 + ln(2 G u / (c a))), the phi -> 0 limit).
poroseam_scene_test(plasticity.closed_forms "plasticity;verification" plasticity/closed_forms.py)
# The assembly (issue 13 items 1-2): one element loaded like a laboratory sample against the
# closed forms of perfect plasticity (tests/plasticity/element.py says what each case checks).
poroseam_scene_test(plasticity.triaxial_compression "plasticity" plasticity/element.py --case compression)
poroseam_scene_test(plasticity.triaxial_extension "plasticity" plasticity/element.py --case extension)
poroseam_scene_test(plasticity.triaxial_axisymmetric "plasticity;axisymmetric" plasticity/element.py --case axisymmetric)
poroseam_scene_test(plasticity.undrained "plasticity" plasticity/element.py --case undrained)
poroseam_scene_test(plasticity.undrained_dilatant "plasticity" plasticity/element.py --case undrained_dilatant)
# A small plastic scene (tests/plasticity/footing_block.opts, tests/plasticity/scene.py): Newton
# quadratic near convergence, 2 ranks = 1 rank, a plastic restart equals the uninterrupted run.
poroseam_scene_test(plasticity.newton "plasticity" plasticity/scene.py --case newton)
poroseam_scene_test(plasticity.ranks "plasticity;mpi" plasticity/scene.py --case ranks)
poroseam_scene_test(plasticity.restart "plasticity;restart" plasticity/scene.py --case restart)
