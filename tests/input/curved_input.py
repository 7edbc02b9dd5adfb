#!/usr/bin/python3
"""Bad input of the mesh geometry order (-mesh_geometry_order), with the checks of
bad_input.py (one clear 'poroseam: error:' line naming the option, file and value, non-zero
exit, no crash, no hang), and good curved runs (1 and 2 ranks).

    curved_input.py --case NAME      one case (one ctest each, labels input and curved)
    curved_input.py --list           the case names

tests/input/meshes/terzaghi_column_2d_order{1,2}.msh: meshes/terzaghi_column_2d.geo meshed by
gmsh 4.8 with -order 1 and -order 2 at -clscale 4; ..._order2_folded.msh: the order-2 mesh with
the node of the first quadrangle's first edge moved 2.5 times across the cell's centre.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bad_input  # noqa: E402  (its runner, checks and scenes)

CURVED = ["-mesh_geometry_order", "2", "-displacement_order", "2"]
ORDER2_MSH = "tests/input/meshes/terzaghi_column_2d_order2.msh"
ORDER1_MSH = "tests/input/meshes/terzaghi_column_2d_order1.msh"
CASES = {
    "geometry_order_three": dict(args=["-mesh_geometry_order", "3"],
                                 expect=["-mesh_geometry_order 3", "expected 1"]),
    "geometry_order_word": dict(args=["-mesh_geometry_order", "curved"],
                                expect=["-mesh_geometry_order curved", "expected a number"]),
    "geometry_order2_linear_elements": dict(
        args=["-mesh_geometry_order", "2"],
        expect=["-mesh_geometry_order 2", "-displacement_order 2"]),
    "second_order_msh_straight": dict(
        args=["-mesh", ORDER2_MSH, "-displacement_order", "2"],
        expect=["terzaghi_column_2d_order2.msh", "second-order elements", "-mesh_geometry_order 2"]),
    "first_order_msh_curved": dict(
        args=["-mesh", ORDER1_MSH] + CURVED,
        expect=["-mesh_geometry_order 2", "terzaghi_column_2d_order1.msh", "first-order"]),
    # the same mesh with one edge node moved across its cell: the curved cell folds
    "curved_cell_folds": dict(
        args=["-mesh", ORDER2_MSH.replace(".msh", "_folded.msh")] + CURVED,
        expect=["-mesh_geometry_order 2", "quadrilateral cell", "folds", "misplaced"]),
    # curved interface faces in axisymmetry: refused (the ring weight's radius is the straight
    # face's), on 2 ranks so that a refusal on one rank only would hang and fail the test
    "curved_axisymmetric_interfaces_np2": dict(
        scene=os.path.join(bad_input.SOURCE, "tests", "interface", "patch_2d.opts"),
        args=["-axisymmetric"] + CURVED, ranks=2,
        expect=["-mesh_geometry_order 2", "-axisymmetric", "-interfaces", "not available"]),
    "curved_msh_runs": dict(args=["-mesh", ORDER2_MSH, "-ts_max_time", "0.4"] + CURVED,
                            ok=True, expect=["results in"]),
    "curved_msh_runs_np2": dict(args=["-mesh", ORDER2_MSH, "-ts_max_time", "0.4"] + CURVED, ok=True,
                                expect=["results in"], ranks=2),
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
