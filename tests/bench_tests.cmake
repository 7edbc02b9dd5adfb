# scripts/bench (issue 9): that the benchmark runs end to end in its --smoke mode and writes its
# CSV files and plots with finite numbers (tests/bench/smoke.py); not a timing test. Included by
# tests/CMakeLists.txt. About 20 s on 2 cores.
poroseam_scene_test(bench.smoke "bench" bench/smoke.py)
set_tests_properties(bench.smoke PROPERTIES TIMEOUT 300)
