# Sneddon's pressurised crack (tests/verification/sneddon.py, scene
# tests/verification/sneddon.opts on meshes/sneddon_half_2d.geo): the opening of a crack
# modelled as a zero-thickness interface loaded by its own water pressure, at displacement
# orders 1 and 2 on one mesh, against the closed form (profile in L2, centre opening, volume).
# About 8 s.
poroseam_scene_test(verification.sneddon "order;verification;interface"
                    verification/sneddon.py)
# One step of 1e6 s (the scene's is 0.01 s) must reach the same opening: the water rows of the
# residual, scaled by dt, start 1e15 times above the forces, and PETSc's relative test alone
# accepted the first Newton iterate with the crack still shut (src/solve/newton_control.cpp
# now measures that test against the first residual's force rows when the water rows dwarf
# them). About 6 s.
poroseam_scene_test(verification.sneddon_long_step "verification;interface;stability"
                    verification/sneddon.py --long-step)
