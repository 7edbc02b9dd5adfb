"""Poiseuille flow along a gap held at a fixed opening (docs/verification.md, interface flow).

    poiseuille.py --mesh quad|tri|hex|tet [--ranks N] [--order 2]

Two near-rigid impervious bodies (E = 1e20 Pa, T1 = T2 = 0); the block is pulled up by 1e-5 m
at the first step so that h = D0 + 1e-5 = 2e-5 m, and p3 is prescribed at the two ends of the
interface, x = 0 (2e4 Pa) and x = L = 1 m (1e4 Pa); other ends closed. At the second step
(steady: the opening no longer changes) the cubic law with a uniform aperture gives a linear
p3, which the P1/Q1 interface pressure represents exactly on any mesh, so the flow rate is

    Q = h^3 / (12 mu_w) (p_left - p_right) / L * B      (B = 1 m width in 3D, per metre in 2D)

Checks (step 2):
  * (right - left) / 2 of <b>.interface_outflow equals Q             (relative 1e-8)
  * right + left = -contact.storage_rate (interface water balance)   (relative to Q, 1e-8)
  * the aperture storage / A equals D0 + 1e-5                        (relative 1e-8)
  * p3_force, the integral of p3, equals (p_left + p_right)/2 A corrected for the measured
    storage rate (p3 linear plus the parabola it causes)                 (relative 1e-8)
The tolerance 1e-8 is the brief's; the bodies take p3 H / E ~ 1e-16 m of the opening and
Newton stops at 1e-9 of the force scale, both far below it.
--order 2: quadratic bodies and interfaces (-displacement_order 2); p3 stays linear, so the same
closed forms hold to the same tolerance.
Scenes: tests/interface/poiseuille_2d.opts (2D; triangles: meshes/block_on_base_2d_tri.geo),
tests/hydraulics/poiseuille_3d.opts (3D; tetrahedra: meshes/block_on_base_3d_tet.geo).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hydraulics_common import common, scene, MU_W  # noqa: E402

H = 2e-5          # D0 + opening
P_LEFT, P_RIGHT, L = 2e4, 1e4, 1.0
AREA = 1.0        # interface area (2D: length x 1 m; 3D: 1 m x 1 m)
TOL = 1e-8

MESHES = {
    "quad": (os.path.join(common.SOURCE, "tests", "interface", "poiseuille_2d.opts"), None),
    "tri": (os.path.join(common.SOURCE, "tests", "interface", "poiseuille_2d.opts"),
            "meshes/block_on_base_2d_tri.geo"),
    "hex": (scene("poiseuille_3d.opts"), None),
    "tet": (scene("poiseuille_3d.opts"), "meshes/block_on_base_3d_tet.geo"),
}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--mesh", choices=sorted(MESHES), default="quad")
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--order", type=int, choices=(1, 2), default=1)
    args = ap.parse_args()
    opts, mesh = MESHES[args.mesh]
    order = f"_order{args.order}" if args.order > 1 else ""
    out = common.output_dir(f"hydraulics_poiseuille_{args.mesh}{order}_np{args.ranks}")
    extra = ["-output_fields_every", 0] + (["-mesh", mesh] if mesh else [])
    extra += ["-displacement_order", args.order] if args.order > 1 else []
    common.run(opts, out, extra, ranks=args.ranks)
    ts = common.read_timeseries(out)
    chk = common.Checks(f"Poiseuille along a gap, {args.mesh} mesh{order}, {args.ranks} rank(s)")
    i = common.step_index(ts, 3.0)  # step 1 opens the gap, step 2 settles p3 on the bodies
    q_exact = H**3 / (12.0 * MU_W) * (P_LEFT - P_RIGHT) / L
    left = common.column(ts, "base_left.interface_outflow")[i]
    right = common.column(ts, "base_right.interface_outflow")[i]
    rate = common.column(ts, "contact.storage_rate")[i]
    h = common.column(ts, "contact.storage")[i] / AREA
    q = 0.5 * (right - left)
    print(f"  Q exact {q_exact:.10e} m3/s, computed (right - left)/2 {q:.10e}; "
          f"left {left:.6e}, right {right:.6e}, storage rate {rate:.3e}; newton {int(ts['newton_its'][i])}")
    chk.check("|Q - h^3/(12 mu_w) dp/L| / Q", abs(q - q_exact) / q_exact, TOL)
    chk.check("|right + left + storage_rate| / Q", abs(right + left + rate) / q_exact, TOL)
    chk.check("|contact.outflow - (right + left)| / Q",
              abs(common.column(ts, "contact.outflow")[i] - (right + left)) / q_exact, TOL)
    chk.check("|h - (D0 + 1e-5)| / h", abs(h - H) / H, TOL)
    # p3 along the gap: dh/dt - k p3'' = 0 with k = h^3/(12 mu_w) gives p3 = linear +
    # (dh/dt)/(2k) x (x - L), so its integral is the mean end pressure times the area minus
    # (dh/dt) L^3/(12 k) per unit width (dh/dt: the measured storage rate per area, round-off
    # of the closing gap; it bends p3 by ~1e-7 relative).
    p3_force = common.column(ts, "contact.p3_force")[i]
    k = H**3 / (12.0 * MU_W)
    expected = 0.5 * (P_LEFT + P_RIGHT) * AREA - (rate / AREA) * L**3 / (12.0 * k) * (AREA / L)
    chk.check("|p3_force - (p_left + p_right)/2 A| / that", abs(p3_force - expected) / expected, TOL)
    chk.finish()


if __name__ == "__main__":
    main()
