# Interface hydraulics (three-node scheme, DESIGN.md sections 3.2, 3.3 and 5): closed forms and
# water balances. Drivers and scenes in tests/hydraulics/ (see each driver's docstring for the
# closed form and why the tolerance is what it is). Included by tests/CMakeLists.txt.

# Poiseuille flow along a gap of fixed opening: Q = h^3/(12 mu_w) dp/L, exact on any mesh.
foreach(mesh quad tri hex tet)
  poroseam_scene_test(hydraulics.poiseuille_${mesh} "hydraulics;interface"
                      hydraulics/poiseuille.py --mesh ${mesh})
endforeach()
poroseam_scene_test(hydraulics.poiseuille_quad_mpi "hydraulics;interface;mpi"
                    hydraulics/poiseuille.py --mesh quad --ranks 2)

# Transversal resistances in series through a joint between two soil layers (steady flux,
# pressures on both sides and in the joint).
poroseam_scene_test(hydraulics.series_resistances "hydraulics;interface"
                    hydraulics/joint_column.py --case series)
# Storage of a gap opened at a known rate, fed from the porous side only (T2 = 0).
poroseam_scene_test(hydraulics.gap_storage "hydraulics;interface"
                    hydraulics/gap_storage.py)
poroseam_scene_test(hydraulics.gap_storage_mpi "hydraulics;interface;mpi"
                    hydraulics/gap_storage.py --ranks 2)
# Terzaghi through a very permeable joint = Terzaghi without it.
poroseam_scene_test(hydraulics.terzaghi_joint "hydraulics;interface;terzaghi"
                    hydraulics/joint_column.py --case terzaghi)
# Impervious sides and closed gaps (DESIGN.md section 6): T2 = 0; T1 = T2 = 0 (sealed).
poroseam_scene_test(hydraulics.one_sided_closed_gap "hydraulics;interface;stability"
                    hydraulics/joint_column.py --case one_sided)
poroseam_scene_test(hydraulics.sealed_gap_refused "hydraulics;interface;input"
                    hydraulics/joint_column.py --case sealed)
# Water balance over whole runs with flow across and along a joint, and an opening joint.
poroseam_scene_test(hydraulics.mass_balance_consolidation "hydraulics;interface;conservation"
                    hydraulics/mass_balance.py --case consolidation)
poroseam_scene_test(hydraulics.mass_balance_opening "hydraulics;interface;conservation"
                    hydraulics/mass_balance.py --case opening)
poroseam_scene_test(hydraulics.mass_balance_consolidation_mpi "hydraulics;interface;conservation;mpi"
                    hydraulics/mass_balance.py --case consolidation --ranks 2)
# 1 rank against 2 ranks (partition cut on the joint).
poroseam_scene_test(hydraulics.mpi_series "hydraulics;interface;mpi"
                    hydraulics/joint_column.py --case series --mpi-match --ranks 2)
poroseam_scene_test(hydraulics.mpi_terzaghi_joint "hydraulics;interface;mpi"
                    hydraulics/joint_column.py --case terzaghi --mpi-match --ranks 2)

set_tests_properties(hydraulics.poiseuille_quad_mpi hydraulics.gap_storage_mpi
                     hydraulics.mass_balance_consolidation_mpi hydraulics.mpi_series
                     hydraulics.mpi_terzaghi_joint PROPERTIES PROCESSORS 2)

# The same checks with the iterative preset options/solvers/fieldsplit.opts (named splits
# displacement, pressures = {pressure, interface_pressure}) in place of the scenes' MUMPS LU:
# the preset must converge on every hydraulics test, and give the same closed-form errors.
# (The 1-vs-2-rank comparisons stay with LU: they check the partition, not the solver; the
# preset itself is compared with LU on 1 and 2 ranks by solvers.presets_*.)
function(hydraulics_fieldsplit_test name)
  poroseam_scene_test(hydraulics.fieldsplit.${name} "hydraulics;interface;solvers" ${ARGN})
  set_property(TEST hydraulics.fieldsplit.${name} APPEND PROPERTY ENVIRONMENT
               "POROSEAM_SOLVER=fieldsplit")
endfunction()
foreach(mesh quad tri hex tet)
  hydraulics_fieldsplit_test(poiseuille_${mesh} hydraulics/poiseuille.py --mesh ${mesh})
endforeach()
hydraulics_fieldsplit_test(poiseuille_quad_mpi hydraulics/poiseuille.py --mesh quad --ranks 2)
hydraulics_fieldsplit_test(series_resistances hydraulics/joint_column.py --case series)
hydraulics_fieldsplit_test(gap_storage hydraulics/gap_storage.py)
hydraulics_fieldsplit_test(gap_storage_mpi hydraulics/gap_storage.py --ranks 2)
hydraulics_fieldsplit_test(terzaghi_joint hydraulics/joint_column.py --case terzaghi)
hydraulics_fieldsplit_test(one_sided_closed_gap hydraulics/joint_column.py --case one_sided)
hydraulics_fieldsplit_test(mass_balance_consolidation hydraulics/mass_balance.py --case consolidation)
hydraulics_fieldsplit_test(mass_balance_opening hydraulics/mass_balance.py --case opening)
hydraulics_fieldsplit_test(mass_balance_consolidation_mpi hydraulics/mass_balance.py --case consolidation --ranks 2)
set_tests_properties(hydraulics.fieldsplit.poiseuille_quad_mpi hydraulics.fieldsplit.gap_storage_mpi
                     hydraulics.fieldsplit.mass_balance_consolidation_mpi PROPERTIES PROCESSORS 2)
