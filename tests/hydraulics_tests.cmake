# Interface hydraulics (three-node scheme, docs/physics.md section 5, docs/verification.md): closed forms and
# water balances. Drivers and scenes in tests/hydraulics/ (see each driver's docstring for the
# closed form and why the tolerance is what it is). Included by tests/CMakeLists.txt.
#
# Every check that solves runs twice: hydraulics.<name> with the scenes' MUMPS LU, and
# hydraulics.fieldsplit.<name> with the iterative preset options/solvers/fieldsplit.opts (named
# splits displacement, pressures = {pressure, interface_pressure}): the preset must converge on
# every hydraulics test and give the same closed-form errors. The 1-vs-2-rank comparisons stay
# with LU (they check the partition; solvers.presets_* compare the preset with LU on 1 and 2
# ranks).
# ranks: the number of ranks the driver's arguments ask for (a record; every test takes one ctest
# slot, tests/CMakeLists.txt says why).
function(hydraulics_test name labels ranks script)
  poroseam_scene_test(hydraulics.${name} "${labels}" ${script} ${ARGN})
  poroseam_preset_test(fieldsplit hydraulics.fieldsplit.${name} "${labels};solvers" ${script} ${ARGN})
endfunction()

# Poiseuille flow along a gap of fixed opening: Q = h^3/(12 mu_w) dp/L, exact on any mesh.
foreach(mesh quad tri hex tet)
  hydraulics_test(poiseuille_${mesh} "hydraulics;interface" 1
                  hydraulics/poiseuille.py --mesh ${mesh})
endforeach()
hydraulics_test(poiseuille_quad_mpi "hydraulics;interface;mpi" 2
                hydraulics/poiseuille.py --mesh quad --ranks 2)

# Transversal resistances in series through a joint between two soil layers (steady flux,
# pressures on both sides and in the joint).
hydraulics_test(series_resistances "hydraulics;interface" 1
                hydraulics/joint_column.py --case series)
# Storage of a gap opened at a known rate, fed from the porous side only (T2 = 0).
hydraulics_test(gap_storage "hydraulics;interface" 1 hydraulics/gap_storage.py)
hydraulics_test(gap_storage_mpi "hydraulics;interface;mpi" 2 hydraulics/gap_storage.py --ranks 2)
# Terzaghi through a very permeable joint = Terzaghi without it.
hydraulics_test(terzaghi_joint "hydraulics;interface;terzaghi" 1
                hydraulics/joint_column.py --case terzaghi)
# Impervious sides and closed gaps (docs/physics.md section 5): T2 = 0; T1 = T2 = 0 (sealed).
hydraulics_test(one_sided_closed_gap "hydraulics;interface;stability" 1
                hydraulics/joint_column.py --case one_sided)
poroseam_scene_test(hydraulics.sealed_gap_refused "hydraulics;interface;input"
                    hydraulics/joint_column.py --case sealed)
# Water balance over whole runs with flow across and along a joint, and an opening joint.
hydraulics_test(mass_balance_consolidation "hydraulics;interface;conservation" 1
                hydraulics/mass_balance.py --case consolidation)
hydraulics_test(mass_balance_opening "hydraulics;interface;conservation" 1
                hydraulics/mass_balance.py --case opening)
hydraulics_test(mass_balance_consolidation_mpi "hydraulics;interface;conservation;mpi" 2
                hydraulics/mass_balance.py --case consolidation --ranks 2)
# 1 rank against 2 ranks (partition cut on the joint).
poroseam_scene_test(hydraulics.mpi_series "hydraulics;interface;mpi"
                    hydraulics/joint_column.py --case series --mpi-match --ranks 2)
poroseam_scene_test(hydraulics.mpi_terzaghi_joint "hydraulics;interface;mpi"
                    hydraulics/joint_column.py --case terzaghi --mpi-match --ranks 2)
