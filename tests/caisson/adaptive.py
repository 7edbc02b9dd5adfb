"""Adaptive time steps against fixed steps on the coarse partially drained caisson
(options/caisson_axisym_partially_drained.opts, -mesh_size_factor 2, 2 ranks): a fast
transient while the lid gap opens, then a stationary phase after about 2 mm of uplift.

    adaptive.py [--ranks 2] [--rtol R]

Runs (all to the scene's 288 s = 4.8 mm):
  fixed      the scene as it is: backward Euler, dt = 6 s (48 steps), the default a user gets;
  adaptive   BDF2 with error control: -ts_type bdf -ts_adapt_type basic -ts_rtol R, first
             step 6 s, at most 48 s (-ts_adapt_dt_max);
  reference  BDF2 with fixed dt = 1.5 s (dt/4, 192 steps); its own error is estimated by
             Richardson from a BDF2 run at dt = 3 s: |q(3) - q(1.5)| / 3.
Quantities (those tests/caisson/caisson.py uses; full circle): the vertical forces on the outer
and inner skirt (caisson.outer_skirt.Fy, caisson.inner_skirt.Fy), the water force in the lid
gap (caisson.lid.p3_force) and the lid storage rate (caisson.lid.storage_rate). Error of a run:
the largest |q(t) - q_ref(t)| over its own step times, q_ref interpolated linearly between the
reference's steps, relative to the largest |q_ref - q_ref(0)|.
Checks: per quantity, the adaptive error at most 1.5 times the fixed-step error; the adaptive
run takes at most half the fixed run's steps, without cut-backs beyond the error control's
own rejections; and the reference's estimated error below a third of every error it judges
(else the comparison would measure the reference). The step ratio and the error ratios are
printed.
Measured (rtol 1e-2): 20 adaptive steps against 48 (ratio 0.417; dt 1.4 to 48 s, 2 rejected
attempts); error ratios adaptive/fixed 0.36 (outer skirt), 0.82 (inner skirt), 0.57 (lid p3
force), 0.03 (lid storage rate). Both runs' largest errors sit in the first steps (the weight
and the start of the uplift at 0+; the first step is 6 s in both); rtol 1e-3 gives 48 steps
and rtol 3e-3 30 steps with the same largest errors.
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402

SCENE = os.path.join(common.SOURCE, "options", "caisson_axisym_partially_drained.opts")
QUANTITIES = ["caisson.outer_skirt.Fy", "caisson.inner_skirt.Fy", "caisson.lid.p3_force",
              "caisson.lid.storage_rate"]
T_END, DT = 288.0, 6.0
BDF2 = ["-ts_type", "bdf", "-ts_bdf_order", 2]


def run(tag, extra, ranks):
    out = common.output_dir(f"caisson_adaptive_{tag}")
    wall = common.run(SCENE, out, ["-mesh_size_factor", 2, "-output_fields_every", 0, "-ts_max_time", T_END]
                      + extra, ranks=ranks, timeout=600)
    path = os.path.join(out, "timeseries.csv")
    with open(path) as f:
        header = [h.strip() for h in f.readline().split(",")]
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    ts = {h: data[:, i] for i, h in enumerate(header)}  # row 0 (initial state) kept
    if abs(ts["time"][-1] - T_END) > 1e-6:
        common.fail(f"{tag}: run ended at {ts['time'][-1]} s, not {T_END} s")
    return ts, wall


def errors(ts, ref, scales):
    t = ts["time"][1:]
    return np.array([np.max(np.abs(ts[q][1:] - np.interp(t, ref["time"], ref[q]))) / s
                     for q, s in zip(QUANTITIES, scales)])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--rtol", type=float, default=1e-2)
    args = ap.parse_args()
    n_fixed = int(round(T_END / DT))
    ref, w_ref = run("reference", BDF2 + ["-ts_dt", DT / 4, "-ts_max_steps", 4 * n_fixed], args.ranks)
    half, _ = run("reference_half", BDF2 + ["-ts_dt", DT / 2, "-ts_max_steps", 2 * n_fixed], args.ranks)
    fixed, w_fixed = run("fixed", ["-ts_dt", DT, "-ts_max_steps", n_fixed], args.ranks)
    adaptive, w_adaptive = run("adaptive", BDF2 + ["-ts_adapt_type", "basic", "-ts_rtol", args.rtol,
                                                   "-ts_dt", DT, "-ts_adapt_dt_max", 8 * DT,
                                                   "-ts_max_steps", 10 * n_fixed], args.ranks)
    scales = [float(np.max(np.abs(ref[q] - ref[q][0]))) for q in QUANTITIES]
    # Richardson estimate of the reference's own error at the dt/2 run's step times (every
    # other reference step): second order, so |q(dt/2) - q(dt/4)| / 3.
    e_ref = np.array([np.max(np.abs(half[q] - np.interp(half["time"], ref["time"], ref[q]))) / 3.0 / s
                      for q, s in zip(QUANTITIES, scales)])
    e_fixed = errors(fixed, ref, scales)
    e_adapt = errors(adaptive, ref, scales)
    steps_fixed, steps_adapt = len(fixed["time"]) - 1, len(adaptive["time"]) - 1
    dts = np.diff(adaptive["time"])
    print(f"  steps: fixed {steps_fixed} (backward Euler, dt {DT:g} s), adaptive {steps_adapt} (BDF2, rtol {args.rtol:g}; "
          f"dt from {dts.min():.3g} to {dts.max():.3g} s, {int(adaptive['rejected'].sum())} rejected attempts); "
          f"ratio adaptive/fixed {steps_adapt / steps_fixed:.3f}")
    print(f"  wall: fixed {w_fixed:.1f} s, adaptive {w_adaptive:.1f} s, reference {w_ref:.1f} s")
    print("  quantity                      scale         fixed err    adaptive err  ratio   reference err (Richardson)")
    for q, s, ef, ea, er in zip(QUANTITIES, scales, e_fixed, e_adapt, e_ref):
        print(f"  {q:28s} {s:12.5g}   {ef:11.3e}   {ea:11.3e}  {ea / ef:6.3f}   {er:.2e}")
    chk = common.Checks(f"adaptive vs fixed steps, coarse axisymmetric partially drained caisson, {args.ranks} ranks")
    chk.check("adaptive steps / fixed steps (<= 0.5)", steps_adapt / steps_fixed, 0.5)
    for q, ef, ea, er in zip(QUANTITIES, e_fixed, e_adapt, e_ref):
        chk.check(f"{q}: adaptive error / fixed error (<= 1.5)", ea / ef, 1.5)
        chk.check(f"{q}: reference error / smaller of the two errors (<= 1/3)", er / min(ef, ea), 1.0 / 3.0)
    chk.finish()


if __name__ == "__main__":
    main()
