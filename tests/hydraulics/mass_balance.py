"""Water balance over a whole run with water crossing (and running along) an interface.

    mass_balance.py --case consolidation|opening [--ranks N]

Scene options/joint_column_2d.opts (column W = 0.1 m x 1 m, joint at mid height,
T1 = T2 = 1e-9 m/(Pa s), comparable to the soil's H/k' = 5e8 per layer, so the joint matters).
Incompressible constituents (alpha = 1, 1/M = 0): the water gained by the bulk is its volume
change, which the divergence theorem gives from boundary displacements only:

    dV_bulk = int_top u_y dx - int_joint g_N ds

(bottom fixed, sides on rollers: u.n = 0; the two faces of the joint give -(u_upper - u_lower).e_y
= -g_N). The discrete balance is exact: the pressure test functions sum to one over the bulk
and the joint (the stabilisation and the longitudinal flux cancel), so

    sum_n dt_n (top.flux + bottom.flux + joint.outflow) = -(dV_bulk + dS_joint)

to round-off and Newton tolerance: checked to 1e-8 relative to the water that moved.
int_top u_y is the trapezoid rule on the top vertices of the field output (exact: u is linear
along the edges), int g_N the integration-point sum of the interface output (exact for the
linear gap). NB: left.flux/right.flux are not added: they repeat the drained top's corner
vertices (a boundary's flux is reported through all its vertices, like its force).

consolidation  load q = 1e4 Pa on the drained top, bottom impervious, p3 = 0 at both ends of the
               joint (-bc_left_p3 0 -bc_right_p3 0, D0 = 5e-5 m: the joint drains sideways as
               much as upwards), K_N = 1e10 Pa/m (closure q/K_N = 1e-6 m, 1e-3 of the
               settlement, so leaving the joint term out would fail by 1e-3). 40 steps.
opening        the top (drained) is pulled up by 1e-5 m over 4 s, bottom impervious, closed joint
               ends: the joint opens (no initial stress) and draws water through the upper
               layer (flux2 < 0); dS_joint = int o ds != 0. The lower layer, sealed below and
               1D, cannot drain: p1 = -sigma_yy = p3 and flux1 = 0 exactly. 40 steps.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hydraulics_common import common, scene, interface_points, point_field  # noqa: E402

W = 0.1
CASES = {
    "consolidation": ["-interface_joint_T1", 1e-9, "-interface_joint_T2", 1e-9, "-interface_joint_KN", 1e10,
                      "-interface_joint_D0", 5e-5, "-bc_left_p3", 0, "-bc_right_p3", 0,
                      "-ts_max_steps", 40, "-ts_max_time", 8],
    "opening": ["-interface_joint_T1", 1e-9, "-interface_joint_T2", 1e-9, "-bc_top_traction", "0,0",
                "-bc_top_uy", 1e-5, "-bc_top_uy_ramp", 4, "-ts_max_steps", 40, "-ts_max_time", 8],
}


def initial_row(out_dir, names):
    """The step-0 row (initial state) of timeseries.csv, which common.read_timeseries drops."""
    path = os.path.join(out_dir, "timeseries.csv")
    with open(path) as f:
        header = f.readline().strip().split(",")
        first = [float(x) for x in f.readline().strip().split(",")]
    row = dict(zip(header, first))
    if row.get("step", 1) != 0:
        common.fail(f"{path}: the first row is not step 0")
    return [row[n] for n in names]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", choices=sorted(CASES), required=True)
    ap.add_argument("--ranks", type=int, default=1)
    args = ap.parse_args()
    out = common.output_dir(f"hydraulics_mass_balance_{args.case}_np{args.ranks}")
    common.run(os.path.join(common.SOURCE, "options", "joint_column_2d.opts"), out, CASES[args.case] + ["-output_fields_every", 1],
               ranks=args.ranks)
    ts = common.read_timeseries(out)
    chk = common.Checks(f"water balance with a joint, {args.case}, {args.ranks} rank(s)")
    dt = ts["dt"]
    out_top = np.sum(dt * ts["top.flux"])
    out_bottom = np.sum(dt * ts["bottom.flux"])
    out_joint = np.sum(dt * ts["joint.outflow"])
    ends = ts["left.interface_outflow"] + ts["right.interface_outflow"]
    crossed = np.sum(dt * ts["joint.flux1"]), np.sum(dt * ts["joint.flux2"])
    (s0,) = initial_row(out, ["joint.storage"])
    dS = ts["joint.storage"][-1] - s0

    t, xyz, fields = common.vertex_fields(out)
    if abs(t - ts["time"][-1]) > 1e-9 * ts["time"][-1]:
        common.fail(f"last field output at t = {t}, last step at {ts['time'][-1]}")
    top = np.abs(xyz[:, 1] - 1.0) < 1e-12
    order = np.argsort(xyz[top, 0])
    x, uy = xyz[top, 0][order], fields["displacement"][top, 1][order]
    if abs(x[0]) > 1e-12 or abs(x[-1] - W) > 1e-12 or np.any(np.diff(x) <= 0):
        common.fail(f"top vertices do not span [0, W] once: {x}")
    top_volume = float(np.sum(0.5 * (uy[1:] + uy[:-1]) * np.diff(x)))
    ifc = interface_points(out)
    w, gn = point_field(ifc, "weight"), point_field(ifc, "gap_normal")
    joint_volume = float(np.sum(w * gn))
    dV = top_volume - joint_volume
    total_out = out_top + out_bottom + out_joint
    print(f"  {len(dt)} steps to t = {ts['time'][-1]:g} s; water out: top {out_top:.10e}, bottom {out_bottom:.3e}, "
          f"along the joint {out_joint:.10e} m3 per m;\n  across the joint: sum dt flux1 {crossed[0]:.6e}, "
          f"sum dt flux2 {crossed[1]:.6e}")
    print(f"  bulk volume change {dV:.10e} = top {top_volume:.10e} - joint gap {joint_volume:.6e}; "
          f"joint storage change {dS:.10e}")
    scale = max(abs(out_top), abs(out_joint), abs(dV), abs(dS))
    chk.check("cut-backs", ts["rejected"].sum(), 0)
    chk.check("|sum dt outflows + dV_bulk + dS_joint| / (water moved)", abs(total_out + dV + dS) / scale, 1e-8)
    chk.check("joint.outflow = left + right interface_outflow (every step, relative)",
              np.max(np.abs(ts["joint.outflow"] - ends)) / max(np.max(np.abs(ends)), 1e-300)
              if np.any(ends) else 0.0, 1e-8)
    chk.check("joint balance: |sum dt (flux1 - flux2 - outflow) - dS| / (water moved)",
              abs(np.sum(dt * (ts["joint.flux1"] - ts["joint.flux2"] - ts["joint.outflow"])) - dS) / scale, 1e-8)
    if args.case == "consolidation":
        chk.check("water left along the joint (-fraction of the total, must be < -0.1)",
                  -out_joint / total_out, -0.1)
        chk.check("joint closure in the balance (-|int g_N| / |dV|, must be < -1e-4)",
                  -abs(joint_volume) / abs(dV), -1e-4)
    else:
        chk.check("the joint opened (-dS / |dV_bulk + dS|, must be < -0.01)", -dS / abs(dV + dS), -0.01)
    chk.finish()


if __name__ == "__main__":
    main()
