"""The geostatic initial state at displacement order 2 is in equilibrium: one step of the
layered ground columns (tests/physics/geostatic_layers_{2d,3d}.opts: three Biot layers with
their own K0, densities and alpha, gravity, K0 stresses and hydrostatic pressure) moves
nothing. The body load and the initial stresses are integrated with the quadratic basis: a
missing edge share, or a basis out of closure order, would leave forces that move the column.

    order_geostatic.py

Measured: |u| <= 4.3e-20 m and |excess p| <= 4e-11 Pa (order 1: 1.0e-20 m, 9e-12 Pa).
"""

import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402


def main():
    chk = common.Checks("Geostatic layered columns at displacement order 2")
    for dim in ("2d", "3d"):
        scene = os.path.join(common.SOURCE, "tests", "physics", f"geostatic_layers_{dim}.opts")
        out = common.output_dir(f"order_geostatic_{dim}")
        common.run(scene, out, ["-displacement_order", 2, "-ts_max_time", 1, "-ts_max_steps", 1,
                                "-output_fields_every", 1])
        _, _, f = common.vertex_fields(out)
        chk.check(f"{dim}: max |u| [m]", float(np.max(np.abs(f["displacement"]))), 1e-12)
        chk.check(f"{dim}: max |p - p_hydrostatic| [Pa]", float(np.max(np.abs(f["excess_pressure"]))), 1e-6)
    chk.finish()


if __name__ == "__main__":
    main()
