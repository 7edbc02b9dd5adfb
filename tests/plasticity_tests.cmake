# Elastoplastic (Mohr-Coulomb) soil in the assembly (issue 13): one element loaded like a
# laboratory sample against the closed forms of perfect plasticity (tests/plasticity/element.py
# says what each case checks). Included by tests/CMakeLists.txt.
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
set_tests_properties(plasticity.ranks PROPERTIES PROCESSORS 2)
