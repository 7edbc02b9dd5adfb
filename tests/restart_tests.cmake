# Checkpoints and restarts (docs/checkpoints.md) on the coarse partially drained axisymmetric
# caisson, 2 ranks: a run killed with SIGKILL at a random step and restarted from its last
# checkpoint, a run stopped by SIGTERM and restarted, both equal to the uninterrupted run to
# 1e-12; a 2-rank checkpoint refused on 1 rank; a new run clears an earlier run's files. Driver tests/restart/restart.py (its docstring
# says what is checked and why). Included by tests/CMakeLists.txt.

poroseam_scene_test(restart.kill_np2 "restart;mpi;caisson" restart/restart.py --case kill --ranks 2)
poroseam_scene_test(restart.sigterm_np2 "restart;mpi;caisson" restart/restart.py --case signal --ranks 2)
poroseam_scene_test(restart.other_ranks "restart;mpi;input" restart/restart.py --case ranks)
poroseam_scene_test(restart.stale_files_np2 "restart;mpi;input" restart/restart.py --case stale --ranks 2)
set_tests_properties(restart.kill_np2 restart.sigterm_np2 restart.other_ranks restart.stale_files_np2
                     PROPERTIES TIMEOUT 600)
