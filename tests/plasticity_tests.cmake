# Elastoplastic (Mohr-Coulomb) soil in the assembly (issue 13): one element loaded like a
# laboratory sample against the closed forms of perfect plasticity (tests/plasticity/element.py
# says what each case checks). Included by tests/CMakeLists.txt.
poroseam_scene_test(plasticity.triaxial_compression "plasticity" plasticity/element.py --case compression)
poroseam_scene_test(plasticity.triaxial_extension "plasticity" plasticity/element.py --case extension)
poroseam_scene_test(plasticity.triaxial_axisymmetric "plasticity;axisymmetric" plasticity/element.py --case axisymmetric)
poroseam_scene_test(plasticity.undrained "plasticity" plasticity/element.py --case undrained)
poroseam_scene_test(plasticity.undrained_dilatant "plasticity" plasticity/element.py --case undrained_dilatant)
