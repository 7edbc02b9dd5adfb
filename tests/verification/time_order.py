"""Order of the time integration, the time error isolated; and why Crank-Nicolson is refused.

    time_order.py --case terzaghi | mandel | oscillation

terzaghi, mandel
    The scene (terzaghi_2d.opts: 2 x 20 quads; mandel.opts) on one mesh held fixed, run with
    backward Euler (-ts_type beuler) and BDF2 (-ts_type bdf -ts_bdf_order 2) at three steps
    dt, dt/2, dt/4. The reference is the same mesh with BDF2 at dt/32 (its own time error is
    1/64 of the finest BDF2 run's, 1/256 of the coarsest), so the differences are time errors
    alone (the spatial error is the same in every run and cancels). Error: the largest
    |q - q_ref| over the quantities below and the times of the second half of the run (all
    multiples of dt, so every run has a step there), relative to a scale of the quantity.
    The first half is left out: right after the sudden load the fast pressure modes near the
    drained boundary are not in the asymptotic range of the coarsest step (c_v dt / h^2 = 2.4
    at dt = 0.5 s on Terzaghi); they have decayed by the second half.
      Terzaghi: pressure at depths 0.1 ... 1.0 m (scale q), dt = 0.5, 0.25, 0.125 s to 8 s.
      Mandel: centre and corner pressure (scale p0) and the plate reaction top.Fy (scale F),
      dt = 2, 1, 0.5 s to 20 s (c t/a^2 = 0.2). The plate displacement is the closed form
      tabulated every dt/32 (the reference step), starting with the undrained value at t = 0
      so that the plate moves by a jump at 0+ in every run (the same table, hence the same
      problem, for every run; the rates of prescribed values use the integrator's own formula, so BDF2 keeps its
      order through them).
    Checks: observed order of each successive pair and the least-squares order within 0.15 of
    1 for backward Euler and within 0.2 of 2 for BDF2.

oscillation (why -ts_type cn is refused)
    Terzaghi after the sudden load with dt = 1 s (c_v dt / h^2 = 4.8: the stiff pressure modes
    near the drained top) for 10 steps. The exact pressure decreases in time at every depth
    and lies in [0, q]. Measured at the vertices 1 to 4 elements below the top: the largest
    rise of p from one step to the next and the extremes of p/q. Backward Euler and BDF2 must
    not rise by more than 0.5 % of q and stay within [-0.01 q, 1.01 q]; Crank-Nicolson (run
    through the test hook -test_allow_crank_nicolson, endpoint and midpoint variants) is
    reported, and checked to fail that monotonicity check (a rise above 0.5 % of q): if it
    ever stopped oscillating, its refusal (time_integration.cpp) would have to be revisited.
    Measured: endpoint (cn) rises 0.047 q, midpoint 2.04 q (p/q from -0.91 to 1.84); backward
    Euler and BDF2 decrease at every step (largest change -0.005 q and -0.004 q).
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
from common import analytic as A  # noqa: E402
from terzaghi import H, W, terzaghi_parameters  # noqa: E402

BE = ["-ts_type", "beuler"]
BDF2 = ["-ts_type", "bdf", "-ts_bdf_order", 2]
INTEGRATORS = {"backward Euler": (BE, 1.0, 0.15), "BDF2": (BDF2, 2.0, 0.2)}


def run(scene, tag, dt, t_end, extra):
    out = common.output_dir(tag)
    n = int(round(t_end / dt))
    common.run(scene, out, extra + ["-ts_dt", dt, "-ts_max_time", t_end, "-ts_max_steps", n])
    ts = common.read_timeseries(out)
    if len(ts["time"]) != n or abs(ts["time"][-1] - t_end) > 1e-9 * t_end:
        common.fail(f"{tag}: expected {n} steps to {t_end} s, got {len(ts['time'])} ending at {ts['time'][-1]}")
    return ts


def at_times(ts, names, times):
    """(len(times), len(names)) values of the columns at the given step times."""
    rows = [common.step_index(ts, t, rtol=1e-9) for t in times]
    return np.column_stack([common.column(ts, n)[rows] for n in names])


def order_study(case):
    if case == "terzaghi":
        scene = common.scene_path("terzaghi_2d.opts")
        opts = common.read_scene(scene)
        q, _, _ = terzaghi_parameters(opts)
        dts, t_end = [0.5, 0.25, 0.125], 8.0
        depths = np.arange(1, 11) / 10.0
        extra = []
        for j, z in enumerate(depths):
            extra += [f"-probe_z{j}", f"{W / 2},{H - z}"]
        names = [f"z{j}.p" for j in range(len(depths))]
        scales = np.full(len(names), q)
    else:
        import mandel  # tests/verification/mandel.py
        scene = common.scene_path("mandel.opts")
        opts = common.read_scene(scene)
        m = mandel.mandel_from_scene(opts)
        dts, t_end = [2.0, 1.0, 0.5], 20.0
        table_dir = common.output_dir("time_order_mandel_table")
        table = os.path.join(table_dir, "plate_uy.csv")
        dt_table = dts[-1] / 8  # the reference step
        times = dt_table * np.arange(1, int(round((t_end + dts[0]) / dt_table)) + 1)
        with open(table, "w") as f:
            # The undrained jump at t = 0+ (a table starting at 0 would ramp the load over the
            # first interval, a feature only the reference resolves): every run takes the jump
            # in its first step, from the initial state's zero displacement.
            f.write(f"time,factor\n0,{m.undrained()['uy_top']:.17g}\n")
            for t, u in zip(times, m.plate_displacement(times)):
                f.write(f"{t:.17g},{u:.17g}\n")
        extra = ["-bc_top_uy_table", table]
        names = ["centre.p", "corner.p", "top.Fy"]
        scales = np.array([m.p0, m.p0, mandel.F])
    dt_ref = dts[-1] / 8
    check_times = dts[0] * np.arange(1, int(round(t_end / dts[0])) + 1)
    check_times = check_times[check_times >= t_end / 2 - 1e-9]
    ref = at_times(run(scene, f"time_order_{case}_ref", dt_ref, t_end, extra + BDF2), names, check_times)
    chk = common.Checks(f"time order, {case}: reference BDF2 dt = {dt_ref:g} s")
    for label, (ts_opts, expected, tol) in INTEGRATORS.items():
        errs = []
        for dt in dts:
            tag = f"time_order_{case}_{'bdf2' if expected == 2 else 'be'}_dt{dt:g}"
            v = at_times(run(scene, tag, dt, t_end, extra + ts_opts), names, check_times)
            errs.append(float(np.max(np.abs(v - ref) / scales)))
        errs = np.array(errs)
        rates = np.log(errs[:-1] / errs[1:]) / np.log(2.0)
        fit = float(np.polyfit(np.log(dts), np.log(errs), 1)[0])
        print(f"  {label}:       dt     max error     order")
        for i, (dt, e) in enumerate(zip(dts, errs)):
            print(f"  {'':14s}{dt:7.4g}   {e:11.4e}   " + (f"{rates[i - 1]:.3f}" if i else ""))
        print(f"  {label}: least-squares order {fit:.3f} (theory {expected:g})")
        chk.check(f"{label}: |least-squares order - {expected:g}|", abs(fit - expected), tol)
        for i, r in enumerate(rates):
            chk.check(f"{label}: |order dt {dts[i]:g} -> {dts[i + 1]:g} - {expected:g}|", abs(r - expected), tol)
    chk.finish()


def oscillation():
    scene = common.scene_path("terzaghi_2d.opts")
    opts = common.read_scene(scene)
    q, _, _ = terzaghi_parameters(opts)
    h = H / 20
    dt, steps = 1.0, 10
    extra = []
    for j in range(1, 5):
        extra += [f"-probe_d{j}", f"{W / 2},{H - j * h}"]
    names = [f"d{j}.p" for j in range(1, 5)]
    variants = {
        "backward Euler": (BE, False),
        "BDF2": (BDF2, False),
        "Crank-Nicolson (cn, endpoint)": (["-ts_type", "cn", "-test_allow_crank_nicolson"], True),
        "theta 0.5 (midpoint)": (["-ts_type", "theta", "-ts_theta_theta", 0.5, "-test_allow_crank_nicolson"], True),
    }
    chk = common.Checks(f"pressure oscillation after a sudden load, Terzaghi, dt = {dt:g} s "
                        f"(c_v dt/h^2 = {dt * A.terzaghi_cv(terzaghi_parameters(opts)[2], terzaghi_parameters(opts)[1]) / h**2:.2g})")
    print("  integrator                        max rise/q   min p/q    max p/q   (vertices 1-4 h below the top)")
    for label, (ts_opts, oscillates) in variants.items():
        tag = "time_oscillation_" + "".join(c if c.isalnum() else "_" for c in label)
        ts = run(scene, tag, dt, dt * steps, extra + ts_opts)
        P = np.column_stack([common.column(ts, n) for n in names]) / q
        rise = float(np.max(np.diff(P, axis=0)))
        print(f"  {label:32s} {rise:10.4f} {P.min():10.4f} {P.max():10.4f}")
        if oscillates:
            chk.check(f"{label}: oscillates (fails the monotonicity check: rise > 0.005 q)", rise, 0.005,
                      ok=rise > 0.005)
        else:
            chk.check(f"{label}: largest rise of p between steps / q", rise, 0.005)
            chk.check(f"{label}: max p / q - 1", P.max() - 1.0, 0.01)
            chk.check(f"{label}: -min p / q", -P.min(), 0.01)
    chk.finish()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True, choices=("terzaghi", "mandel", "oscillation"))
    args = ap.parse_args()
    if args.case == "oscillation":
        oscillation()
    else:
        order_study(args.case)


if __name__ == "__main__":
    main()
