#!/usr/bin/python3
"""Bad input of the element order (-displacement_order), with the checks of bad_input.py
(one clear 'poroseam: error:' line naming the option and value, non-zero exit, no crash, no
hang), and one good order-2 run.

    order_input.py --case NAME      one case (one ctest each, labels input and order)
    order_input.py --list           the case names
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bad_input  # noqa: E402  (its runner, checks and scenes)

ORDER = ["-displacement_order", "2"]
# a block pressed on a base through an interface, 3D (tetrahedra with -mesh ..._tet.geo)
PATCH_3D = os.path.join(bad_input.SOURCE, "tests", "interface", "patch_3d.opts")
PATCH_2D = os.path.join(bad_input.SOURCE, "tests", "interface", "patch_2d.opts")
CASES = {
    "order_three": dict(args=["-displacement_order", "3"],
                        expect=["-displacement_order 3", "expected 1 (linear) or 2"]),
    "order_half": dict(args=["-displacement_order", "1.5"],
                       expect=["-displacement_order 1.5", "expected 1 (linear) or 2"]),
    "order_word": dict(args=["-displacement_order", "quadratic"],
                       expect=["-displacement_order quadratic", "expected a number"]),
    "order_misspelt": dict(args=["-displacement_ordr", "2"],
                           expect=["-displacement_ordr", "did you mean -displacement_order?"]),
    # order 2 with what it no longer refuses (tests/order2_physics_tests.cmake verifies them)
    "order2_plastic_runs": dict(args=ORDER + bad_input.MOHR_COULOMB + ["-ts_max_time", "0.4"],
                                ok=True, expect=["results in"]),
    "order2_axisymmetric_runs": dict(args=ORDER + ["-axisymmetric", "-ts_max_time", "0.4"],
                                     ok=True, expect=["results in"]),
    "order2_probes_runs_np2": dict(args=ORDER + ["-probe_top", "0.05,1", "-ts_max_time", "0.4"],
                                   ok=True, expect=["results in"], ranks=2),
    "order2_interfaces_run": dict(scene=bad_input.JOINT_SCENE, args=ORDER + ["-ts_max_time", "0.4"],
                                  ok=True, expect=["results in"]),
    # axisymmetric interfaces at order 2 (refused until 2026-11-27; tests/axi_iface2_tests.cmake
    # verifies them): a run on 2 ranks, not an error
    "order2_axisymmetric_interfaces_np2": dict(scene=PATCH_2D, args=ORDER + ["-axisymmetric"],
                                               ok=True, expect=["results in"], ranks=2),
    "order2_nodal_triangles": dict(scene=PATCH_3D,
                                   args=ORDER + ["-interface_contact_integration", "nodal",
                                                 "-mesh", "meshes/block_on_base_3d_tet.geo"],
                                   expect=["-interface_contact_integration nodal",
                                           "triangular face", "use gauss"]),
    "order2_nodal_triangles_np2": dict(scene=PATCH_3D,
                                       args=ORDER + ["-interface_contact_integration", "nodal",
                                                     "-mesh", "meshes/block_on_base_3d_tet.geo"],
                                       expect=["-interface_contact_integration nodal",
                                               "triangular face", "use gauss"], ranks=2),
    # The fieldsplit preset at order 2 (refused until 2026-11-27): a run, not an error.
    "order2_fieldsplit": dict(args=ORDER + ["-ts_max_time", "0.4", "-solver_preset", "fieldsplit"],
                              ok=True, expect=["solver preset fieldsplit", "results in"]),
    "order2_runs": dict(args=ORDER + ["-ts_max_time", "0.4"], ok=True, expect=["results in"]),
    "order2_runs_np2": dict(args=ORDER + ["-ts_max_time", "0.4"], ok=True, expect=["results in"],
                            ranks=2),
}


def main():
    if "--list" in sys.argv:
        print("\n".join(CASES))
        return 0
    bad_input.CASES.clear()
    bad_input.CASES.update(CASES)
    return bad_input.main()


if __name__ == "__main__":
    sys.exit(main())
