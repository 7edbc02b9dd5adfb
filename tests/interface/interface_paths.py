"""Interface mechanics along load paths, against the exact Coulomb return mapping.

A near-rigid block on a near-rigid base (tests/interface/shear_2d.opts): the block top is
pushed down by 1e-5 m (p'_N = K_N 1e-5 = 1e5 Pa over A = 1 m, F_N = 1e5 N/m) and moved
horizontally along a table. The interface state is uniform, so the interface force on the
base must be exactly A tau with tau from the 1D return mapping of the slip path:
    tau_trial = tau_n + K_T (g_T - g_T,n),  tau = clamp(tau_trial, -mu p'_N, mu p'_N).
Cases (--case):
  ramp      ramp to 4x the slip onset then back by 0.6x: tau = K_T g_T, then flat at
            mu p'_N, then elastic unloading at K_T (stick again).
  reversals 50 stick/slip reversals of amplitude 2x the slip onset: every step converges
            without cut-back; prints the largest Newton count, which must stay <= 4.
  --cutback forces every step to fail once and be cut: the history of the failed attempts must
            be discarded, so the forces still follow the return mapping of the accepted steps.
  opening   the block is lifted by 2e-5 m instead: zero traction, and the gap measured by
            probes on both faces equals the applied separation.
  soft      50 reversals with soft bodies (E = 1e8 Pa, nu = 0.3) of amplitude 1e-3 m at the
            block top: slip spreads from the edges, the interface state is not uniform and
            Newton must follow stick/slip changes. Every step converges without cut-back,
            Newton stays <= 8 per step, the block is in equilibrium (interface force = top
            reaction, 1e-8) and |F_x| <= mu |F_y| (Coulomb, 1e-9).
  oblique   3D (shear_3d.opts): slide along 30 degrees to 4x the onset, then turn to 120
            degrees: the force vector follows the vector return mapping
            tau_trial = tau_n + K_T (g_T - g_T,n), tau = mu p'_N tau_trial / |tau_trial| when
            |tau_trial| > mu p'_N; on the first leg |F_T| = mu F_N and F_T is parallel to the
            slip increment.
The expectation uses the gaps measured by probes on both faces (the bodies take K_N H / E =
1e-4 of the imposed closure). Tolerance: 1e-8 relative to mu F_N.
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402

KN = KT = 1e10
MU = 0.5
CLOSURE = 1e-5
PN = KN * CLOSURE
ONSET = MU * PN / KT  # slip onset g_T = 5e-6 m


def return_mapping(gt, pn):
    """tau after each step for slip path gt and contact pressure pn (arrays per step)."""
    tau, g_prev, out = 0.0, 0.0, []
    for g, p in zip(gt, pn):
        trial = tau + KT * (g - g_prev)
        tau = float(np.clip(trial, -MU * p, MU * p))
        g_prev = g
        out.append(tau)
    return np.array(out)


def return_mapping_2(gt, pn):
    """Vector version of return_mapping: gt is (steps, 2)."""
    tau, g_prev, out = np.zeros(2), np.zeros(2), []
    for g, p in zip(gt, pn):
        trial = tau + KT * (g - g_prev)
        norm = np.linalg.norm(trial)
        tau = trial if norm <= MU * p else MU * p * trial / norm
        g_prev = g
        out.append(tau.copy())
    return np.array(out)


def oblique(args):
    scene = os.path.join(HERE, "shear_3d.opts")
    out = common.output_dir(f"interface_oblique_{args.integration}_np{args.ranks}")
    a1, a2 = np.radians(30.0), np.radians(120.0)
    times = [0, 8, 12]
    corner = 4 * ONSET * np.array([np.cos(a1), np.sin(a1)])
    end = corner + 2 * ONSET * np.array([np.cos(a2), np.sin(a2)])
    extra = ["-ts_max_time", times[-1], "-interface_contact_integration", args.integration,
             "-probe_below", "0.5,0.5,0.4999999", "-probe_above", "0.5,0.5,0.5000001"]
    for k, comp in enumerate("xy"):
        table = os.path.join(out, f"u{comp}.csv")
        with open(table, "w") as f:
            f.write("time,factor\n")
            for t, v in zip(times, [0.0, corner[k], end[k]]):
                f.write(f"{t},{v!r}\n")
        extra += [f"-bc_top_u{comp}_table", table]
    common.run(scene, out, extra, ranks=args.ranks)
    ts = common.read_timeseries(out)
    chk = common.Checks(f"interface oblique sliding 3D ({args.integration}, {args.ranks} rank(s))")
    gt = np.stack([ts["above.ux"] - ts["below.ux"], ts["above.uy"] - ts["below.uy"]], axis=1)
    pn = -KN * (ts["above.uz"] - ts["below.uz"])
    expected = return_mapping_2(gt, pn)
    force = np.stack([ts["contact.Fx"], ts["contact.Fy"]], axis=1)  # area 1 m2
    chk.check("max |F_T - A tau_exact| / (mu F_N)", np.max(np.linalg.norm(force - expected, axis=1)) / (MU * PN), 1e-8)
    chk.check("max |F_z + F_N| / F_N", np.max(np.abs(ts["contact.Fz"] + pn)) / PN, 1e-8)
    first = (ts["time"] > 3) & (ts["time"] <= 8)  # slipping along the first leg
    ft = force[first]
    chk.check("first leg: max | |F_T| - mu F_N | / (mu F_N)", np.max(np.abs(np.linalg.norm(ft, axis=1) - MU * pn[first])) / (MU * PN), 1e-8)
    direction = np.array([np.cos(a1), np.sin(a1)])
    cross = np.abs(ft[:, 0] * direction[1] - ft[:, 1] * direction[0]) / np.linalg.norm(ft, axis=1)
    chk.check("first leg: sin(angle between F_T and the slip increment)", np.max(cross), 1e-8)
    turned = force[-1] / np.linalg.norm(force[-1])
    print(f"  force direction at the end {np.degrees(np.arctan2(turned[1], turned[0])):.2f} deg "
          f"(slip turned to 120 deg); Newton max {int(ts['newton_its'].max())}")
    chk.finish()


def soft(args):
    scene = os.path.join(HERE, "shear_2d.opts")
    out = common.output_dir(f"interface_soft_{args.integration}_np{args.ranks}")
    table = os.path.join(out, "ux.csv")
    with open(table, "w") as f:
        f.write("time,factor\n0,0\n")
        for k in range(1, 51):
            f.write(f"{4 * k},{1e-3 * (1 if k % 2 else -1)!r}\n")
    extra = ["-bc_top_ux_table", table, "-ts_max_time", 200, "-interface_contact_integration",
             args.integration, "-region_base_E", 1e8, "-region_block_E", 1e8,
             "-region_base_nu", 0.3, "-region_block_nu", 0.3, "-bc_top_uy", -2e-4]
    common.run(scene, out, extra, ranks=args.ranks)
    ts = common.read_timeseries(out)
    chk = common.Checks(f"interface 50 reversals, soft bodies ({args.integration}, {args.ranks} rank(s))")
    newton = ts["newton_its"]
    fx, fy = ts["contact.Fx"], ts["contact.Fy"]
    print(f"  {len(newton)} steps; Newton iterations per step: max {int(newton.max())}, "
          f"mean {newton.mean():.2f}; interface force Fx in [{fx.min():.4e}, {fx.max():.4e}], "
          f"mu |Fy| = {MU * np.abs(fy).max():.4e} N/m")
    chk.check("max Newton iterations per step (<= 8)", newton.max(), 8)
    chk.check("cut-backs", ts["rejected"].sum(), 0)
    chk.check("block equilibrium: max |contact.Fx - top.Fx| / max |Fx|",
              np.max(np.abs(fx - ts["top.Fx"])) / np.max(np.abs(fx)), 1e-8)
    chk.check("Coulomb: max (|Fx| - mu |Fy|) / (mu |Fy|)", np.max((np.abs(fx) - MU * np.abs(fy)) / (MU * np.abs(fy))), 1e-9)
    chk.check("full slip reached: min over reversals of |Fx| / (mu |Fy|) at the peaks (>= 0.999)",
              -np.min((np.abs(fx) / (MU * np.abs(fy)))[ts["time"] % 4 == 0]), -0.999)
    chk.finish()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", choices=("ramp", "reversals", "opening", "oblique", "soft"), required=True)
    ap.add_argument("--integration", choices=("gauss", "nodal"), default="gauss")
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--cutback", action="store_true",
                    help="force every step to be cut back once (history committed only on accepted steps)")
    args = ap.parse_args()
    if args.case == "oblique":
        return oblique(args)
    if args.case == "soft":
        return soft(args)
    scene = os.path.join(HERE, "shear_2d.opts")
    out = common.output_dir(f"interface_{args.case}_{args.integration}_np{args.ranks}{'_cut' if args.cutback else ''}")
    table = os.path.join(out, "ux.csv")
    if args.case == "ramp":
        times = [0, 20, 26]
        values = [0, 4 * ONSET, 3.4 * ONSET]
    elif args.case == "reversals":
        times = list(range(0, 101, 2))
        values = [0] + [2 * ONSET * (1 if k % 2 else -1) for k in range(1, 51)]
    else:
        times, values = [0, 1], [0, 0]
    with open(table, "w") as f:
        f.write("time,factor\n")
        for t, v in zip(times, values):
            f.write(f"{t},{v!r}\n")
    extra = ["-bc_top_ux_table", table, "-ts_max_time", times[-1],
             "-interface_contact_integration", args.integration,
             "-probe_below", "0.5,0.4999999", "-probe_above", "0.5,0.5000001"]
    if args.case == "opening":
        extra += ["-bc_top_uy", 2e-5, "-ts_max_time", 2]
    if args.cutback:
        extra += ["-test_fail_dt_above", 0.6]
    common.run(scene, out, extra, ranks=args.ranks)
    ts = common.read_timeseries(out)
    chk = common.Checks(f"interface {args.case} ({args.integration}, {args.ranks} rank(s))")
    if args.case == "opening":
        chk.check("|F| / (mu K_N 1e-5 A)", np.max(np.hypot(ts["contact.Fx"], ts["contact.Fy"])) / (MU * PN), 1e-8)
        gap = ts["above.uy"] - ts["below.uy"]
        chk.check("|gap - 2e-5| / 2e-5", np.max(np.abs(gap - 2e-5)) / 2e-5, 1e-6)
        chk.finish()
        return
    # Gap of the block relative to the base, measured at the interface: the bodies take
    # K_N H / E = 1e-10 of the imposed closure; the expectation uses the measured gaps all the same.
    gt = ts["above.ux"] - ts["below.ux"]
    pn = -KN * (ts["above.uy"] - ts["below.uy"])
    expected = return_mapping(gt, pn)
    # Force on the base (side 1) from the block: + tau in x, -p'_N in y (A = 1 m).
    err_t = np.max(np.abs(ts["contact.Fx"] - expected)) / (MU * PN)
    err_n = np.max(np.abs(ts["contact.Fy"] + pn)) / PN
    print(f"  slip from {gt.min():.3e} to {gt.max():.3e} m (onset {ONSET:.1e}); "
          f"force from {ts['contact.Fx'].min():.6e} to {ts['contact.Fx'].max():.6e} N/m")
    chk.check("max |F_x - A tau_exact| / (mu F_N)", err_t, 1e-8)
    chk.check("max |F_y + F_N| / F_N", err_n, 1e-8)
    if args.case == "ramp":
        slipping = np.abs(np.abs(expected) - MU * pn) < 1e-12 * PN
        chk.check("steps slipping at the plateau (>= 5)", -np.sum(slipping), -5)
        unloading = ts["time"] > 20
        chk.check("unloading is elastic: steps after reversal below the limit",
                  -np.sum(np.abs(expected[unloading]) < MU * pn[unloading]), -np.sum(unloading))
    newton = ts["newton_its"]
    print(f"  Newton iterations per step: max {int(newton.max())}, mean {newton.mean():.2f}; "
          f"cut-backs {int(ts['rejected'].sum())}")
    if args.case == "reversals":
        chk.check("max Newton iterations per step (<= 4)", newton.max(), 4)
        chk.check("cut-backs", ts["rejected"].sum(), 0)
    if args.cutback:
        # The last step is the exception: the time left (0.5 s) is below the failing size, so
        # the step that lands on -ts_max_time is not cut; it must land there exactly.
        chk.check("every step but the last was cut back (failed attempts discarded)",
                  -ts["rejected"][:-1].min(), -1)
        chk.check("the last step ends at -ts_max_time", abs(ts["time"][-1] - times[-1]), 1e-12)
    chk.finish()


if __name__ == "__main__":
    main()
