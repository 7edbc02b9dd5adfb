# Sneddon's pressurised crack (tests/verification/sneddon.py, scene
# tests/verification/sneddon.opts on meshes/sneddon_half_2d.geo): the opening of a crack
# modelled as a zero-thickness interface loaded by its own water pressure, at displacement
# orders 1 and 2 on one mesh, against the closed form (profile in L2, centre opening, volume).
# About 8 s.
poroseam_scene_test(verification.sneddon "order;verification;interface"
                    verification/sneddon.py)
