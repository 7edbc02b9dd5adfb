# Verification scenes (closed forms in study/analytic.py; drivers and scenes in
# tests/verification/; see the docstring of each driver for what it checks and why the
# tolerances are what they are).  Included by tests/CMakeLists.txt.


# Terzaghi 1D consolidation: pressure at 4 depths and settlement at 5 times vs the series.
poroseam_scene_test(verification.terzaghi_2d "verification;terzaghi"
                    verification/terzaghi.py --dim 2)
poroseam_scene_test(verification.terzaghi_2d_tri_np2 "verification;terzaghi;mpi"
                    verification/terzaghi.py --dim 2 --mesh meshes/terzaghi_column_2d_tri.geo --ranks 2)
poroseam_scene_test(verification.terzaghi_3d "verification;terzaghi"
                    verification/terzaghi.py --dim 3)
poroseam_scene_test(verification.terzaghi_3d_tet_np2 "verification;terzaghi;mpi"
                    verification/terzaghi.py --dim 3 --mesh meshes/terzaghi_column_3d_tet.geo --ranks 2)

# Mandel: centre pressure (Mandel-Cryer overshoot) and plate reaction, quarter model.
poroseam_scene_test(verification.mandel "verification;mandel"
                    verification/mandel.py --ranks 1)
poroseam_scene_test(verification.mandel_np2 "verification;mandel;mpi"
                    verification/mandel.py --ranks 2)

# Spatial convergence rate of the pressure (Terzaghi 2D, 4 meshes, time error removed).
poroseam_scene_test(verification.convergence_terzaghi_2d "verification;terzaghi;convergence"
                    verification/convergence.py --ranks 1)

# Hard cases (docs/verification.md): first steps with dt << h^2/c_v, nearly undrained loading.
poroseam_scene_test(verification.stability_first_step_quad "verification;stability;terzaghi"
                    verification/stability.py --case first_step)
poroseam_scene_test(verification.stability_first_step_tri "verification;stability;terzaghi"
                    verification/stability.py --case first_step --mesh meshes/terzaghi_column_2d_tri.geo)
poroseam_scene_test(verification.stability_first_step_tet_np2 "verification;stability;terzaghi;mpi"
                    verification/stability.py --case first_step --dim 3 --mesh meshes/terzaghi_column_3d_tet.geo --ranks 2)
poroseam_scene_test(verification.stability_tiny_k "verification;stability;terzaghi"
                    verification/stability.py --case tiny_k)
poroseam_scene_test(verification.stability_mandel_undrained "verification;stability;mandel"
                    verification/stability.py --case mandel_undrained)
poroseam_scene_test(verification.stability_mandel_drained_edge "verification;stability;mandel"
                    verification/stability.py --case mandel_drained_edge)
