# Issue 24 items 7 and 11 (polish): interface output interval, cut-back lines, -help listing,
# steady and excess pore pressures. Included by tests/CMakeLists.txt.
poroseam_scene_test(polish.interface_output_interval "polish;outputs;interface;restart"
                    polish/interface_interval.py)
poroseam_scene_test(polish.cut_back_lines "polish;cutback;mpi" polish/cut_back_lines.py)
poroseam_scene_test(polish.help_listing "polish;input" polish/help_listing.py)
poroseam_scene_test(polish.steady_pressure "polish;outputs;physics" polish/steady_pressure.py)
