# Dilatant joints (docs/physics.md section 4, shear dilation): closed forms of a joint sheared at
# constant normal stiffness (with and without the dilation limit, 1 and 2 ranks), a sheared
# joint carrying flow (transmissivity growing as (D0 + tan(psi) s_p)^3, with LU and with the
# fieldsplit preset) and a restart in the middle of the dilation. Driver
# tests/interface/dilatancy.py (its docstring gives the closed forms and tolerances). Each runs
# in about 2 s. Included by tests/CMakeLists.txt after hydraulics_tests.cmake (hydraulics_test).
poroseam_scene_test(interface.dilatancy_cns "interface;dilatancy" interface/dilatancy.py --case cns)
poroseam_scene_test(interface.dilatancy_cns_limit "interface;dilatancy" interface/dilatancy.py --case cns_limit)
poroseam_scene_test(interface.dilatancy_cns_np2 "interface;dilatancy;mpi" interface/dilatancy.py --case cns_limit --ranks 2)
hydraulics_test(dilatancy_flow "hydraulics;interface;dilatancy" 1 interface/dilatancy.py --case flow)
poroseam_scene_test(restart.dilatancy_np2 "restart;interface;dilatancy;mpi" interface/dilatancy.py --case restart --ranks 2)
