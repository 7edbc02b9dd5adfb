# scripts/study (issue 10, docs/studies.md): work-precision studies. Included by
# tests/CMakeLists.txt. Driver tests/study/check_study.py; about a minute in all on 2 cores.
#   study.orders        Terzaghi's spatial order (2) and backward Euler's time order (1), within
#                       0.15, computed by the study driver on tests/study/terzaghi_orders.toml
#   study.perturbation  the error columns against the closed form on runs that are the closed
#                       form with known perturbations; Richardson; a bad study file's message
#   study.cache         a study run twice runs nothing the second time
#   study.analytic      the self-checks of the closed forms (study/analytic.py)
poroseam_scene_test(study.orders "study;verification;convergence" study/check_study.py --orders)
poroseam_scene_test(study.perturbation "study" study/check_study.py --perturbation)
poroseam_scene_test(study.cache "study" study/check_study.py --cache)
add_test(NAME study.analytic COMMAND ${PYTHON3} ${CMAKE_SOURCE_DIR}/study/analytic.py)
set_tests_properties(study.analytic PROPERTIES LABELS "study;verification")
set_tests_properties(study.orders study.perturbation study.cache PROPERTIES TIMEOUT 300)
