"""A soil column crossed by a horizontal permeable joint (docs/physics.md section 5, docs/verification.md).

    joint_column.py --case series|terzaghi|one_sided|sealed|sealed_petsc_lu [--ranks N]
    joint_column.py --case series|terzaghi --mpi-match [--ranks 2]

Scene options/joint_column_2d.opts: column W = 0.1 m x 1 m, layers lower [0, 0.5]
and upper [0.5, 1] (Terzaghi material: M_c = 1.2e7 Pa, k/mu_w = 1e-9 m2/(Pa s)), joint at
y = 0.5 with side 1 = lower (e1 points up), D0 = 1e-5 m. Per unit area, with k' = k/mu_w:

series  Transversal resistances in series. Upper k = 2e-12 m2, T1 = 4e-9, T2 = 2e-9 m/(Pa s),
        p = P = 1e4 Pa at the bottom, 0 at the top, a top load of 1e5 Pa keeps the joint closed
        (p'_N = 1e5 - p3 > 0). Steady state (8 backward-Euler steps of 1e4 s: every transient
        mode is damped by at least 1/(1 + 0.03 dt) per step): Darcy in each layer, f1 = f2 in
        the joint, so the flux q per unit area is
            q = P / (H1/k1' + 1/T1 + 1/T2 + H2/k2') = 1e4 / (5e8 + 2.5e8 + 5e8 + 2.5e8)
        and p1 = P - q H1/k1' (below the joint), p3 = p1 - q/T1, p2 = p3 - q/T2 = q H2/k2'
        (above); jump p1 - p2 = q (1/T1 + 1/T2). The pressure is linear in each layer, which
        Q1 represents exactly, so the checks are to 1e-8 (relative to Q = q W, and to P):
        top.flux = -bottom.flux = joint.flux1 = joint.flux2 = Q; p1, p2 (probes 1e-10 m from
        the joint: their offset costs < 1e-9 of P), the jump, p3 (interface output).
terzaghi Consolidation through the joint, T1 = T2 = 1e-3 m/(Pa s) (resistance 2/T = 2e3 against
        H/k' = 1e9 for the soil), K_N = 1e12 Pa/m (closure q/K_N = 1e-8 m against a settlement
        q H/M_c = 8.3e-4 m): the Terzaghi checks and tolerances of tests/verification/terzaghi.py
        (same probes, times, 2 % / 0.5 % of q for p, 1 % / 0.5 % of q H/M_c for the settlement),
        and the difference from the same run without the joint (terzaghi_2d.opts, same vertices)
        within 1e-4 of q and of q H/M_c (expected ~1e-5: the two effects above).
one_sided T2 = 0 (upper side impervious to the joint), T1 = 1e-9, P = 1e4 at the bottom, 0 at the
        top, load 1e5 Pa: the closed gap (h = D0) is still well posed, every step converges
        without cut-back; no water crosses: p3 = p1 at every step (dh/dt = 0, no flow along the
        joint, f2 = 0, so f1 = 0), and at steady state p3 = p1 = P in the joint and the lower
        layer, p2 = 0 above; fluxes zero. Checks 1e-8 (of P, of W P k'/H).
sealed  T1 = T2 = 0 and no prescribed p3: no water can enter or leave the joint, so its pressure
        level is undetermined (the p3 equation is a pure-Neumann Laplacian, its Jacobian block
        singular). The scene is refused with an error naming the interface.
--mpi-match  series as above; terzaghi with T1 = T2 = 1e-9 and K_N = 1e10 (water really crosses
        the joint and it closes by 1e-6 m). 1 rank against --ranks ranks with -partitioner simple (cells numbered bottom up:
        the cut falls on the joint), every time-series column to 1e-8 relative to its largest
        magnitude (floored at 1e-6 of its quantity's scale, as tests/mpi/mpi_match.py does, with
        water flows m3/s as one quantity). A column below 1e-9 of its quantity's scale (e.g.
        the storage rate of a closed joint, the vertical force on rollers) is physically zero,
        round-off at the Newton tolerance: there the difference must stay below 1e-9 of the
        scale. Also the interface pressure, f1 and gap at the integration points (1e-8).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hydraulics_common import common, analytic as A, scene, interface_points, point_field  # noqa: E402

SCENE = os.path.join(common.SOURCE, "options", "joint_column_2d.opts")
W, H1, H2 = 0.1, 0.5, 0.5
MU_W = 1e-3
E, NU, K = 1e7, 0.25, 1e-12
D0 = 1e-5
EPS = 1e-9   # probe offset from the joint (probes accept points 1e-8 of a cell outside it: 2.5e-10 m here)

SERIES = dict(k2=2e-12, T1=4e-9, T2=2e-9, P=1e4, load=1e5)


def series_args(T1, T2, k2=K, P=1e4, load=1e5, steps=8, dt=1e4):
    return ["-region_upper_permeability", k2, "-interface_joint_T1", T1, "-interface_joint_T2", T2,
            "-bc_bottom_p", P, "-bc_top_traction", f"0,{-load}", "-ts_dt", dt,
            "-ts_max_steps", steps, "-ts_max_time", steps * dt, "-output_fields_every", 1,
            "-probe_below", f"{W / 2},{H1 - EPS}", "-probe_above", f"{W / 2},{H1 + EPS}"]


DEPTHS = [0.1, 0.25, 0.5, 1.0]
P_TIMES = [2.0, 6.0, 25.0]
S_TIMES = [1.0, 2.0, 6.0, 12.0, 25.0]
TERZAGHI_Q = 1e4


def terzaghi_args():
    extra = ["-probe_top", f"{W / 2},1"]
    for i, z in enumerate(DEPTHS):
        extra += [f"-probe_z{i}", f"{W / 2},{1.0 - z}"]
    return extra


def converged_every_step(chk, ts):
    chk.check("cut-backs (every step converges at once)", ts["rejected"].sum(), 0)


def series(args, chk):
    s = SERIES
    out = common.output_dir(f"hydraulics_series_np{args.ranks}")
    common.run(SCENE, out, series_args(s["T1"], s["T2"], s["k2"], s["P"], s["load"]), ranks=args.ranks)
    ts = common.read_timeseries(out)
    k1p, k2p = K / MU_W, s["k2"] / MU_W
    R = H1 / k1p + 1 / s["T1"] + 1 / s["T2"] + H2 / k2p
    q = s["P"] / R
    Q = q * W
    p1, p2 = s["P"] - q * H1 / k1p, q * H2 / k2p
    p3 = p1 - q / s["T1"]
    print(f"  R = {R:.4e} (Pa s)/m, q = {q:.6e} m/s, Q = {Q:.6e} m3/s per m; p1 = {p1:.4f}, "
          f"p3 = {p3:.4f}, p2 = {p2:.4f} Pa")
    last = -1
    print(f"  last step: top.flux {ts['top.flux'][last]:.10e}, bottom.flux {ts['bottom.flux'][last]:.10e}, "
          f"flux1 {ts['joint.flux1'][last]:.10e}, flux2 {ts['joint.flux2'][last]:.10e}")
    converged_every_step(chk, ts)
    chk.check("steady: |top.flux(last) - top.flux(last-1)| / Q",
              abs(ts["top.flux"][-1] - ts["top.flux"][-2]) / Q, 1e-10)
    chk.check("|top.flux - Q| / Q", abs(ts["top.flux"][last] - Q) / Q, 1e-8)
    chk.check("|-bottom.flux - Q| / Q", abs(-ts["bottom.flux"][last] - Q) / Q, 1e-8)
    chk.check("|joint.flux1 - Q| / Q", abs(ts["joint.flux1"][last] - Q) / Q, 1e-8)
    chk.check("|joint.flux2 - Q| / Q", abs(ts["joint.flux2"][last] - Q) / Q, 1e-8)
    pb, pa = ts["below.p"][last], ts["above.p"][last]
    print(f"  probes: p below {pb:.6f}, above {pa:.6f}; jump {pb - pa:.6f} (exact {q * (1 / s['T1'] + 1 / s['T2']):.6f})")
    chk.check("|p1 - (P - q H1/k1')| / P", abs(pb - p1) / s["P"], 1e-8)
    chk.check("|p2 - q H2/k2'| / P", abs(pa - p2) / s["P"], 1e-8)
    jump = q * (1 / s["T1"] + 1 / s["T2"])
    chk.check("|(p1 - p2) - q (1/T1 + 1/T2)| / jump", abs(pb - pa - jump) / jump, 1e-8)
    ifc = interface_points(out)
    p3_out = point_field(ifc, "interface_pressure")
    chk.check("max |p3 - (p1 - q/T1)| / P (interface output)", np.max(np.abs(p3_out - p3)) / s["P"], 1e-8)
    f1 = point_field(ifc, "transversal_flux1")
    chk.check("max |f1 - q| / q (interface output, per unit area)", np.max(np.abs(f1 - q)) / q, 1e-8)
    return out


def terzaghi(args, chk):
    out = common.output_dir(f"hydraulics_terzaghi_joint_np{args.ranks}")
    common.run(SCENE, out, terzaghi_args(), ranks=args.ranks)
    ref = common.output_dir("hydraulics_terzaghi_nojoint")
    common.run(common.scene_path("terzaghi_2d.opts"), ref, terzaghi_args())
    ts, tr = common.read_timeseries(out), common.read_timeseries(ref)
    converged_every_step(chk, ts)
    q, H = TERZAGHI_Q, H1 + H2
    Mc, kappa = A.constrained_modulus(E, NU), K / MU_W
    times = ts["time"]
    n_last = common.step_index(ts, max(S_TIMES + P_TIMES)) + 1
    p_be = A.terzaghi_pressure_be(DEPTHS, times[:n_last], q, H, Mc, kappa)
    s_be = A.terzaghi_settlement_be(times[:n_last], q, H, Mc, kappa)
    e_pe = e_pb = e_se = e_sb = 0.0
    for t in P_TIMES:
        i = common.step_index(ts, t)
        pe = A.terzaghi_pressure(np.array(DEPTHS), times[i], q, H, Mc, kappa)
        for j in range(len(DEPTHS)):
            p = ts[f"z{j}.p"][i]
            e_pe = max(e_pe, abs(p - pe[j]) / q)
            e_pb = max(e_pb, abs(p - p_be[i, j]) / q)
    s_ref = q * H / Mc
    for t in S_TIMES:
        i = common.step_index(ts, t)
        s = ts["top.uy"][i]
        e_se = max(e_se, abs(s - A.terzaghi_settlement(times[i], q, H, Mc, kappa)) / s_ref)
        e_sb = max(e_sb, abs(s - s_be[i]) / s_ref)
    chk.check("max |p - p_exact| / q", e_pe, 0.02)
    chk.check("max |p - p_BE| / q (spatial error)", e_pb, 0.005)
    chk.check("max |s - s_exact| / (qH/M_c)", e_se, 0.01)
    chk.check("max |s - s_BE| / (qH/M_c) (spatial error)", e_sb, 0.005)
    if len(tr["time"]) != len(ts["time"]):
        common.fail("the runs with and without the joint have different steps")
    dp = max(np.max(np.abs(ts[f"z{j}.p"] - tr[f"z{j}.p"])) for j in range(len(DEPTHS))) / q
    ds = np.max(np.abs(ts["top.uy"] - tr["top.uy"])) / s_ref
    chk.check("same run without the joint: max |p - p_nojoint| / q (all steps, 4 probes)", dp, 1e-4)
    chk.check("same run without the joint: max |s - s_nojoint| / (qH/M_c)", ds, 1e-4)
    flux_max = np.max(np.abs(ts["joint.flux1"]))
    tol = 1e-8  # a direct solve: round-off
    if common.SOLVER:
        # An iterative linear solver leaves the mass rows exact only to the Newton test:
        # |F| <= 1e-9 x force level (the sum of the boundary and joint force magnitudes), and a
        # mass row is a water rate times dt S, S = M_c / h (problem.cpp), h = 0.05 m (the
        # scene's mesh); the joint's imbalance sums its 3 interface-pressure rows (sqrt 3).
        level = sum(np.abs(ts[f"{b}.F{c}"]) for b in ("top", "bottom", "left", "right", "joint")
                    for c in "xy")
        bound = np.max(np.sqrt(3) * 1e-9 * level / (ts["dt"] * Mc / 0.05)) / flux_max
        print(f"  iterative solver ({common.SOLVER}): bound from the Newton test {bound:.2e}")
        tol = max(tol, bound)
    chk.check("water through the joint: |flux1 - flux2| / max|flux1| (closed gap, no storage)",
              np.max(np.abs(ts["joint.flux1"] - ts["joint.flux2"])) / flux_max, tol)
    return out


def one_sided(args, chk):
    P = 1e4
    out = common.output_dir(f"hydraulics_one_sided_np{args.ranks}")
    common.run(SCENE, out, series_args(1e-9, 0.0, P=P), ranks=args.ranks)
    ts = common.read_timeseries(out)
    converged_every_step(chk, ts)
    qref = W * P * (K / MU_W) / (H1 + H2)
    print(f"  Newton iterations per step: {ts['newton_its'].astype(int).tolist()}")
    ifc = interface_points(out)
    p3 = point_field(ifc, "interface_pressure")
    print(f"  last step: p3 in [{p3.min():.6f}, {p3.max():.6f}], p below {ts['below.p'][-1]:.6f}, "
          f"above {ts['above.p'][-1]:.3e}; top.flux {ts['top.flux'][-1]:.3e}, flux1 {ts['joint.flux1'][-1]:.3e}")
    chk.check("max |p3 - P| / P (p3 follows side 1)", np.max(np.abs(p3 - P)) / P, 1e-8)
    # Closed gap (dh/dt = 0), no flow along a horizontal joint in 1D, f2 = 0: f1 = 0 at every
    # step, so p3 equals p1 at the joint all along the transient, not only at steady state.
    if len(ifc.times) != len(ts["time"]) + 1:
        common.fail(f"{len(ifc.times)} interface outputs for {len(ts['time'])} steps")
    lag = max(np.max(np.abs(f["interface_pressure"] - ts["below.p"][k]))
              for k, f in enumerate(ifc.point_fields[1:]))
    chk.check("every step: max |p3 - p1(probe below)| / P", lag / P, 1e-8)
    chk.check("|p1 - P| / P", abs(ts["below.p"][-1] - P) / P, 1e-8)
    chk.check("|p2| / P", abs(ts["above.p"][-1]) / P, 1e-8)
    for col in ("top.flux", "bottom.flux", "joint.flux1", "joint.flux2"):
        chk.check(f"|{col}| / (W P k'/H)", abs(ts[col][-1]) / qref, 1e-8)
    return out


def sealed(args, chk, petsc_lu=False):
    """A sealed joint (T1 = T2 = 0, no prescribed p3) has an undetermined pressure level: the
    scene must be refused with a clear message, not run into a singular matrix."""
    import subprocess
    out = common.output_dir(f"hydraulics_sealed_np{args.ranks}")
    cmd = [common.EXE, "-options_file", SCENE, "-output_dir", out] + [str(a) for a in terzaghi_args()] + \
        ["-interface_joint_T1", "0", "-interface_joint_T2", "0"]
    res = subprocess.run(cmd, cwd=common.SOURCE, capture_output=True, text=True, timeout=120)
    text = res.stdout + res.stderr
    print("  " + (text.strip().splitlines()[-1] if text.strip() else "(no output)"))
    chk.check("exit status is non-zero", 0.0, 0.0, ok=res.returncode != 0)
    chk.check("the error names the sealed interface", 0.0, 0.0, ok="interface 'joint' is sealed" in text)
    chk.check("no crash", 0.0, 0.0, ok="Segmentation" not in text and "signal" not in text)


# ------------------------------------------------------------------------------------------
# 1 rank against N ranks

ZERO = 1e-9  # Newton stops at 1e-9 of the force scale: below this a column is physically zero


def kind(name):
    """Physical quantity of a time-series column (the scale for its noise floor)."""
    suffix = name.rsplit(".", 1)[-1]
    if suffix in ("Fx", "Fy", "Fz"):
        return "force"
    if suffix in ("ux", "uy", "uz"):
        return "displacement"
    if suffix in ("flux", "flux1", "flux2", "storage_rate", "outflow", "interface_outflow"):
        return "flow"
    return suffix


def mpi_match(args, chk):
    sys.path.insert(0, os.path.join(common.SOURCE, "tests", "mpi"))
    from mpi_match import read_csv, INTEGER_COLUMNS, SKIP_COLUMNS
    if args.case == "series":
        s = SERIES
        extra = series_args(s["T1"], s["T2"], s["k2"], s["P"], s["load"])
    else:
        extra = terzaghi_args() + ["-interface_joint_T1", 1e-9, "-interface_joint_T2", 1e-9,
                                   "-interface_joint_KN", 1e10, "-output_fields_every", 25]
    extra += ["-partitioner", "simple", "-partitioner_report"]
    dirs = {}
    for n in (1, args.ranks):
        dirs[n] = common.output_dir(f"hydraulics_mpi_{args.case}_np{n}")
        common.run(SCENE, dirs[n], extra, ranks=n)
    with open(os.path.join(dirs[args.ranks], "log.txt")) as f:
        for line in f:
            if "cohesive" in line or "rank" in line.lower():
                print("  " + line.rstrip())
    h1, d1 = read_csv(dirs[1])
    h2, d2 = read_csv(dirs[args.ranks])
    chk.check("timeseries headers equal", 0 if h1 == h2 else 1, 0)
    chk.check("timeseries row counts equal", abs(len(d1) - len(d2)), 0)
    if h1 != h2 or len(d1) != len(d2):
        return
    for name in INTEGER_COLUMNS:
        if name in h1:
            i = h1.index(name)
            chk.check(f"{name}: rows that differ", int(np.sum(d1[:, i] != d2[:, i])), 0)
    group = {}
    cols = [(i, n) for i, n in enumerate(h1) if n not in INTEGER_COLUMNS + SKIP_COLUMNS]
    for i, n in cols:
        m = np.nanmax(np.abs(np.r_[d1[:, i], d2[:, i]])) if np.any(np.isfinite(d1[:, i])) else 0.0
        group[kind(n)] = max(group.get(kind(n), 0.0), m)
    worst = (0.0, "")
    for i, n in cols:
        x, y = d1[:, i], d2[:, i]
        if np.any(np.isnan(x) != np.isnan(y)):
            chk.check(f"{n}: NaN on one run only", 1, 0)
            continue
        ok = np.isfinite(x)
        if not np.any(ok):
            continue
        big = np.max(np.abs(np.r_[x[ok], y[ok]]))
        diff = np.max(np.abs(x[ok] - y[ok]))
        if big < ZERO * group[kind(n)]:
            # physically zero (round-off of a quantity whose scale is the group's)
            if diff > ZERO * group[kind(n)]:
                chk.check(f"timeseries column {n} (zero): max |difference| / group scale",
                          diff / group[kind(n)], ZERO)
            continue
        r = diff / max(big, 1e-6 * group[kind(n)])
        if r > worst[0] or not worst[1]:
            worst = (r, n)
        if r > 1e-8:
            chk.check(f"timeseries column {n}: max relative difference", r, 1e-8)
    chk.check(f"timeseries: largest relative difference of all columns ({worst[1]})", worst[0], 1e-8)
    i1, i2 = interface_points(dirs[1]), interface_points(dirs[args.ranks])
    if len(i1.times) != len(i2.times) or i1.num_points != i2.num_points:
        chk.check("interface output: same times and number of points", 1, 0)
        return
    o1 = np.lexsort(np.round(i1.point_coordinates, 12).T[::-1])
    o2 = np.lexsort(np.round(i2.point_coordinates, 12).T[::-1])
    chk.check("interface points match after sorting (m)",
              np.max(np.abs(i1.point_coordinates[o1] - i2.point_coordinates[o2])), 1e-12)
    for name in ("interface_pressure", "transversal_flux1", "gap_normal"):
        ref = max(np.max(np.abs(f[name])) for f in i1.point_fields) or 1.0
        r = max(np.max(np.abs(a[name][o1] - b[name][o2])) for a, b in zip(i1.point_fields, i2.point_fields)) / ref
        chk.check(f"interface {name}: max relative difference", r, 1e-8)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True,
                    choices=("series", "terzaghi", "one_sided", "sealed", "sealed_petsc_lu"))
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--mpi-match", action="store_true")
    args = ap.parse_args()
    if args.mpi_match:
        if args.ranks < 2:
            args.ranks = 2
        chk = common.Checks(f"joint column {args.case}: 1 vs {args.ranks} ranks")
        mpi_match(args, chk)
        chk.finish()
    chk = common.Checks(f"joint column {args.case}, {args.ranks} rank(s)")
    if args.case == "series":
        series(args, chk)
    elif args.case == "terzaghi":
        terzaghi(args, chk)
    elif args.case == "one_sided":
        one_sided(args, chk)
    else:
        sealed(args, chk, petsc_lu=args.case == "sealed_petsc_lu")
    chk.finish()


if __name__ == "__main__":
    main()
