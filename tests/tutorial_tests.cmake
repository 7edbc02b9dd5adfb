# docs/tutorial.md run exactly as written (tests/tutorial/tutorial.py): its files, its commands,
# its own check of equilibrium and water balance; examples/sheet_pile/ equal to the page.
poroseam_scene_test(tutorial.sheet_pile "tutorial" tutorial/tutorial.py)
set_tests_properties(tutorial.sheet_pile PROPERTIES PROCESSORS 2 TIMEOUT 600)
