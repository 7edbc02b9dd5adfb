# The gallery of example scenes (docs/gallery.md) and interfaces in layered ground (issue 24,
# items 3 and 10). Drivers in tests/gallery/. Included by tests/CMakeLists.txt.

# Every scene of options/ and examples/ has its entry, picture and command in docs/gallery.md,
# and every picture shown exists (no run; well under a second).
poroseam_scene_test(gallery.listed "gallery;docs" gallery/gallery_listed.py)

# The scenes promoted from tests/ to options/ run as given (a few steps each, a few seconds):
# run from the build folder, so that the mesh is found relative to the scene file.
foreach(spec "crack_jacking_2d|0.05" "strip_footing_2d|0.0625" "joint_column_2d|1")
  string(REPLACE "|" ";" parts "${spec}")
  list(GET parts 0 scene)
  list(GET parts 1 until)
  add_test(NAME gallery.runs.${scene}
           COMMAND $<TARGET_FILE:poroseam> -options_file ${CMAKE_SOURCE_DIR}/options/${scene}.opts
                   -ts_max_time ${until} -output_dir ${CMAKE_BINARY_DIR}/test-output/gallery/${scene}
           WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  set_tests_properties(gallery.runs.${scene} PROPERTIES LABELS "gallery;scene")
endforeach()

# Interfaces in layered ground: the recipe (one interface per layer) against the closed form
# of uniaxial strain, and water passing their junction (Poiseuille along the whole fault); one
# interface whose side 1 does not border all of it is refused with the regions named; a sealed interface's advice names the perfect barrier, which then holds.
foreach(case recipe refused_split refused_layers junction_flow sealed barrier)
  poroseam_scene_test(gallery.layered_interfaces.${case} "gallery;interface;input"
                      gallery/layered_interfaces.py --case ${case})
endforeach()
