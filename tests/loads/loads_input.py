#!/usr/bin/python3
"""Bad input of the normal pressure (-bc_<b>_pressure) and of supports on physical points,
with the checks of tests/input/bad_input.py (one clear 'poroseam: error:' line naming the
option and value, non-zero exit, no crash, no hang).

    loads_input.py --case NAME      one case (one ctest each, labels input and loads)
    loads_input.py --list           the case names
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "input"))
import bad_input  # noqa: E402  (its runner, checks and scenes)

SLOPE = os.path.join(HERE, "slope.opts")        # bottom fixed in x and y, 2D
FLOATING = os.path.join(HERE, "floating.opts")  # held by physical points centre and east
SPHERE = os.path.join(HERE, "sphere.opts")      # 3D, with a physical curve 'rim'
ONE_POINT = os.path.join(HERE, "floating_one_point.opts")  # the rotation left free
CASES = {
    "pressure_normal_displacement": dict(
        scene=SLOPE, args=["-bc_bottom_pressure", "1e4"],
        expect=["-bc_bottom_uy and -bc_bottom_pressure", "'bottom'", "normal", "(0, -1)"]),
    "pressure_and_traction": dict(
        scene=SLOPE, args=["-bc_slope_pressure", "1e5", "-bc_slope_traction", "0,-1e5"],
        expect=["-bc_slope_pressure and -bc_slope_traction", "'slope'"]),
    "pressure_unknown_boundary": dict(
        scene=SLOPE, args=["-bc_roof_pressure", "1e5"],
        expect=["-bc_roof_pressure", "not in -boundaries"]),
    "pressure_not_a_number": dict(
        scene=SLOPE, args=["-bc_slope_pressure", "high"],
        expect=["-bc_slope_pressure high", "expected a number"]),
    "pressure_inside_mesh": dict(
        scene=SLOPE, args=["-boundaries", "bottom,slope,top,left,cut", "-bc_cut_pressure", "1e5"],
        expect=["-bc_cut_pressure", "'cut'", "inside the mesh"]),
    "pressure_inside_mesh_np2": dict(
        scene=SLOPE, args=["-boundaries", "bottom,slope,top,left,cut", "-bc_cut_pressure", "1e5"],
        expect=["-bc_cut_pressure", "'cut'", "inside the mesh"], ranks=2),
    "point_traction": dict(
        scene=FLOATING, args=["-bc_east_traction", "1e3,0"],
        expect=["-bc_east_traction", "'east' is a physical point", "displacements only"]),
    "point_pressure": dict(
        scene=FLOATING, args=["-bc_centre_pressure", "1e5"],
        expect=["-bc_centre_pressure", "'centre' is a physical point"]),
    "rotation_free": dict(
        scene=ONE_POINT, args=[],
        expect=["region 'square'", "rotation about z free", "second point"]),
    "curve_traction": dict(
        scene=SPHERE, args=["-boundaries", "inner,outer,xsym,ysym,zsym,rim",
                            "-bc_rim_traction", "1e3,0,0"],
        expect=["-bc_rim_traction", "'rim' is a physical curve", "displacements only"]),
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
