# Time integration (docs/time_stepping.md): orders of backward Euler and BDF2 with the time error
# isolated, why Crank-Nicolson is refused, the first-step stability cases with BDF2, and the
# adaptive step control on the coarse partially drained caisson. Included by
# tests/CMakeLists.txt; drivers tests/verification/time_order.py, stability.py and
# tests/caisson/adaptive.py (their docstrings say what is checked and why).

poroseam_scene_test(verification.time_order_terzaghi "verification;study;terzaghi;time"
                    verification/time_order.py --case terzaghi)
poroseam_scene_test(verification.time_order_mandel "verification;study;mandel;time"
                    verification/time_order.py --case mandel)
poroseam_scene_test(verification.time_oscillation "verification;study;stability;time"
                    verification/time_order.py --case oscillation)

# The first-step stability cases of scene_tests.cmake again with BDF2.
poroseam_scene_test(verification.stability_first_step_quad_bdf2 "verification;stability;terzaghi;time"
                    verification/stability.py --case first_step --ts bdf2)
poroseam_scene_test(verification.stability_first_step_tri_bdf2 "verification;stability;terzaghi;time"
                    verification/stability.py --case first_step --mesh meshes/terzaghi_column_2d_tri.geo --ts bdf2)
poroseam_scene_test(verification.stability_first_step_tet_np2_bdf2 "verification;stability;terzaghi;mpi;time"
                    verification/stability.py --case first_step --dim 3 --mesh meshes/terzaghi_column_3d_tet.geo --ranks 2 --ts bdf2)
poroseam_scene_test(verification.stability_tiny_k_bdf2 "verification;stability;terzaghi;time"
                    verification/stability.py --case tiny_k --ts bdf2)
poroseam_scene_test(verification.stability_mandel_undrained_bdf2 "verification;stability;mandel;time"
                    verification/stability.py --case mandel_undrained --ts bdf2)
poroseam_scene_test(verification.stability_mandel_drained_edge_bdf2 "verification;stability;mandel;time"
                    verification/stability.py --case mandel_drained_edge --ts bdf2)

# Adaptive steps (BDF2, error control) against fixed steps on the coarse partially drained
# caisson: the same error within a factor 1.5 with at most half the steps.
poroseam_scene_test(caisson.adaptive_steps "study;caisson;time" caisson/adaptive.py --ranks 2)
set_tests_properties(caisson.adaptive_steps PROPERTIES PROCESSORS 2 TIMEOUT 600)
