# Suction caisson uplift (docs/caisson.md, paper section 3): the checks any correct model
# must pass, on options/caisson_*.opts as they are, coarsened on the command line
# (-mesh_size_factor 2, fewer and larger steps). Driver: tests/caisson/caisson.py (its docstring
# says what is checked and why). Included by tests/CMakeLists.txt. About 20 s in all on 2 cores.

# Axisymmetric, drained: vertical equilibrium every step, drained plateau F_ext = mu int p'_N,
# uplift at full mobilisation of the outer skirt (reported beside the paper's 0.63 mm);
# scripts/plot_caisson on the output.
poroseam_scene_test(caisson.axisym_drained "caisson"
                    caisson/caisson.py --case axisym_drained --ranks 2 --plot)
# Axisymmetric, partially drained: vertical equilibrium (p3 included) every step, storage rate of
# the lid gap in the stationary phase = rho_w v_up pi R_int^2; scripts/plot_caisson.
poroseam_scene_test(caisson.axisym_partially_drained "caisson"
                    caisson/caisson.py --case axisym_partially_drained --ranks 2 --plot)
# 3D quarter model, partially drained: the same with the quarter's storage rate 0.189 kg/s;
# scripts/plot_caisson on a 3D run.
poroseam_scene_test(caisson.quarter_partially_drained "caisson"
                    caisson/caisson.py --case quarter_partially_drained --ranks 2 --plot)
# 3D quarter model (coarse) against the axisymmetric model (default mesh), drained: plateau
# forces x 4 within 5 %, equilibrium of the quarter.
poroseam_scene_test(caisson.quarter_vs_axisym "caisson"
                    caisson/caisson.py --case quarter_vs_axisym --ranks 2)

# Axisymmetric, drained, Mohr-Coulomb soil (issue 13): equilibrium and the drained plateau as
# above, the plastic zone around the skirt, Newton iterations within the recorded counts, the
# run ending at -ts_max_time after the cut-back of its first step. 4 s on 2 idle cores (52-122 s
# measured while 4 other agents loaded them).
poroseam_scene_test(caisson.axisym_drained_mohr_coulomb "caisson;plasticity"
                    caisson/caisson.py --case axisym_drained_mohr_coulomb --ranks 2)

set_tests_properties(caisson.axisym_drained caisson.axisym_partially_drained
                     caisson.axisym_drained_mohr_coulomb
                     caisson.quarter_partially_drained caisson.quarter_vs_axisym PROPERTIES PROCESSORS 2 TIMEOUT 600)

# The partially drained caissons again with the iterative preset options/solvers/fieldsplit.opts
# (named splits; sliding skirts make the displacement block unsymmetric): the same checks
# must pass, without cut-backs.
foreach(case axisym_partially_drained quarter_partially_drained)
  poroseam_preset_test(fieldsplit caisson.fieldsplit.${case} "caisson;solvers"
                       caisson/caisson.py --case ${case} --ranks 2)
  set_tests_properties(caisson.fieldsplit.${case} PROPERTIES PROCESSORS 2 TIMEOUT 600)
endforeach()
# The quarter with the preset takes about a minute: start it first, not last, on a fresh build.
set_tests_properties(caisson.fieldsplit.quarter_partially_drained PROPERTIES COST 1000)
