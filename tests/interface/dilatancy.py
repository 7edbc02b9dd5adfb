"""Dilatant joints (docs/physics.md section 4, shear dilation) against closed forms.

    dilatancy.py --case cns|cns_limit|flow|restart [--ranks N]

cns        A joint sheared under constant normal stiffness (tests/interface/shear_cns_2d.opts,
           meshes/joint_cns_2d.geo): near-rigid base, block and cap (E = 1e17 Pa, nu = 0, each
           H = 0.5 m high); the joint (K_N = K_T = 1e10 Pa/m, mu = 0.5, psi = 10 deg) between
           base and block, a frictionless spring interface (K_CNS = 1e9 Pa/m) between block and
           cap, the cap pushed down by c = 1e-4 m and held, the block moved sideways through its
           sides by U(t). Normal equilibrium of the springs in series (the joint dilated by d,
           the cap fixed; the three bodies under uniform uniaxial stress add their compliance
           3 H / E, 1.4e-8 of the rest):
               sigma_n = K_s (c + d),   1 / K_s = 1 / K_N + 1 / K_CNS + 3 H / E,
           i.e. sigma_n = sigma_n0 + K_s tan(psi) s_p with sigma_n0 = K_s c: the normal stress
           grows by K_s tan(psi) per unit plastic slip. In stick tau = K_T U; sliding,
           tau = mu sigma_n and s_p = U - tau / K_T (monotonic: the accumulated plastic slip is
           the plastic displacement), so
               sigma_n = K_s (c + tan(psi) U) / (1 + mu K_s tan(psi) / K_T),
           exact for any step size (each step's return closes the yield condition exactly).
           Checked against the joint force per metre (A = 1 m) at every step, with U the imposed
           displacement (the block's shear deformation takes 2.5e-9 of it): tolerance 1e-8 of
           the largest normal force. (Stiffer bodies, E = 1e20 as in shear_2d.opts, leave a
           round-off floor of ~1 N in the residual, which the block's free normal position
           turns into a 5e-6 error.) Also the slope d sigma_n / d s_p = K_s tan(psi) between
           the first and last sliding steps below the limit, and the joint's normal gap
           measured by probes on its faces: g_N = d - sigma_n / K_N (the faces lifted apart by
           the dilation, pressed together by the penalty).
cns_limit  The same with -interface_joint_dilation_limit 1e-3 m: beyond s_p = 1e-3 m the normal
           stress stays at K_s (c + tan(psi) 1e-3) and tau = mu times it.
flow       A sheared joint carrying flow: tests/interface/poiseuille_2d.opts (near-rigid
           impervious bodies, p3 = 2e4 Pa at x = 0 and 1e4 Pa at x = L = 1 m) closed by
           c = 1e-5 m (top held: K_CNS infinite, sigma_n = K_N (c + d)) and sheared with
           psi = 10 deg to U = 5e-4 m in 20 steps of 1000 s. The hydraulic aperture is D0 + d
           with d = tan(psi) s_p, s_p = U - mu sigma_n / K_T, sigma_n = K_N (c + tan(psi) U) /
           (1 + mu K_N tan(psi) / K_T), so the flow rate is (D0 + tan(psi) s_p)^3 / (12 mu_w)
           dp / L at every step (the gap's storage rate only bends p3; (right - left) / 2 of the
           end outflows is the mean flux, exactly the cubic law's). Checks (relative 1e-8): the
           flow rate, the aperture (storage / A), the gap's water balance right + left +
           storage rate = 0, and storage rate = (h_k - h_(k-1)) / dt (the dilation's storage
           telescopes).
restart    The cns_limit scene stopped at t = 15 s (before the limit) with a checkpoint and
           continued with -restart: every column of the time series equals the uninterrupted
           run's to 1e-12 of its kind's scale (the accumulated plastic slip is in the checkpoint;
           without it the normal stress after the restart would drop back by K_s tan(psi) s_p).
"""
import argparse
import os
import re
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402

KN = KT = 1e10
K_CNS = 1e9
MU = 0.5
TAN_PSI = np.tan(np.radians(10.0))
E_BODY, H_BODY = 1e17, 0.5
K_S = 1.0 / (1.0 / KN + 1.0 / K_CNS + 3.0 * H_BODY / E_BODY)
CLOSURE = 1e-4                  # cns: the cap's push
U_END, T_END = 2e-3, 41         # cns: U from 0 at t = 1 s to 2 mm at t = 41 s
SLIP_LIMIT = 1e-3
MU_W = 1e-3
D0, C_FLOW, U_FLOW = 1e-5, 1e-5, 5e-4
P_LEFT, P_RIGHT, L = 2e4, 1e4, 1.0


def cns_options(out, limit):
    ux = common.time_table(out, "ux.csv", [0, 1, T_END], [0.0, 0.0, U_END])
    extra = ["-bc_block_left_ux_table", ux, "-bc_block_right_ux_table", ux, "-ts_max_time", T_END]
    if limit:
        extra += ["-interface_joint_dilation_limit", SLIP_LIMIT]
    return extra


def cns_closed_form(u, limit):
    """(sigma_n, tau, s_p) for the imposed displacements u (monotonic from 0)."""
    sigma0 = K_S * CLOSURE
    sigma = K_S * (CLOSURE + TAN_PSI * u) / (1.0 + MU * K_S * TAN_PSI / KT)
    slip = u - MU * sigma / KT
    if limit:
        past = slip > SLIP_LIMIT
        sigma = np.where(past, K_S * (CLOSURE + TAN_PSI * SLIP_LIMIT), sigma)
        slip = np.where(past, u - MU * sigma / KT, slip)
    stick = KT * u <= MU * sigma0
    sigma = np.where(stick, sigma0, sigma)
    tau = np.where(stick, KT * u, MU * sigma)
    slip = np.where(stick, 0.0, slip)
    return sigma, tau, slip


def cns(args, limit):
    scene = os.path.join(HERE, "shear_cns_2d.opts")
    out = common.output_dir(f"dilatancy_cns{'_limit' if limit else ''}_np{args.ranks}")
    common.run(scene, out, cns_options(out, limit), ranks=args.ranks)
    ts = common.read_timeseries(out)
    chk = common.Checks(f"joint sheared at constant normal stiffness{', dilation limit' if limit else ''} "
                        f"({args.ranks} rank(s))")
    t = common.column(ts, "time")
    u = np.interp(t, [0.0, 1.0, T_END], [0.0, 0.0, U_END])
    sigma, tau, slip = cns_closed_form(u, limit)
    # The force of the block on the base (side 1): +tau in x, -sigma_n in y, A = 1 m.
    fn, ft = -common.column(ts, "joint.Fy"), common.column(ts, "joint.Fx")
    scale = np.max(sigma)
    print(f"  sigma_n from {fn[0]:.6e} to {fn[-1]:.6e} Pa (closed form {sigma[-1]:.6e}); "
          f"tau at the end {ft[-1]:.6e} Pa; plastic slip {slip[-1]:.4e} m; "
          f"Newton max {int(ts['newton_its'].max())}, cut-backs {int(ts['rejected'].sum())}")
    chk.check("max |sigma_n - closed form| / max sigma_n", np.max(np.abs(fn - sigma)) / scale, 1e-8)
    chk.check("max |tau - closed form| / max sigma_n", np.max(np.abs(ft - tau)) / scale, 1e-8)
    chk.check("sliding steps (>= 30)", -np.sum(slip > 0), -30)
    gain = (fn[-1] - fn[0]) / (K_S * CLOSURE)
    chk.check("normal stress gained by dilation, (sigma_end - sigma_0) / sigma_0 (>= 1)", -gain, -1.0)
    # Slope of the normal stress path against the plastic slip (= U - tau / K_T, measured).
    s_meas = u - ft / KT
    dilating = (slip > 0) & (slip < (SLIP_LIMIT if limit else np.inf))
    i, j = np.flatnonzero(dilating)[[0, -1]]
    slope = (fn[j] - fn[i]) / (s_meas[j] - s_meas[i])
    chk.check("|d sigma_n / d s_p - K_s tan(psi)| / (K_s tan(psi))",
              abs(slope - K_S * TAN_PSI) / (K_S * TAN_PSI), 1e-8)
    # The joint's normal gap, probes on both faces: lifted by d, pressed by sigma_n / K_N.
    gap = common.column(ts, "above.uy") - common.column(ts, "below.uy")
    expected_gap = TAN_PSI * np.minimum(slip, SLIP_LIMIT if limit else np.inf) - sigma / KN
    chk.check("max |joint normal gap - (d - sigma_n / K_N)| / (tan(psi) max s_p)",
              np.max(np.abs(gap - expected_gap)) / (TAN_PSI * slip.max()), 1e-8)
    if limit:
        past = slip > SLIP_LIMIT
        chk.check("steps past the dilation limit (>= 10)", -np.sum(past), -10)
        flat = K_S * (CLOSURE + TAN_PSI * SLIP_LIMIT)
        chk.check("past the limit: max |sigma_n - K_s (c + tan(psi) s_lim)| / that",
                  np.max(np.abs(fn[past] - flat)) / flat, 1e-8)
    chk.finish()


def flow(args):
    scene = os.path.join(HERE, "poiseuille_2d.opts")
    out = common.output_dir(f"dilatancy_flow_np{args.ranks}")
    # Slow shear (dt = 1000 s): the dilation's storage rate stays below the flow rate, so the
    # end outflows (10 significant digits in timeseries.csv) resolve the flow rate to 1e-10.
    steps, dt = 20, 1000.0
    t_end = (steps + 1) * dt
    ux = common.time_table(out, "ux.csv", [0, dt, t_end], [0.0, 0.0, U_FLOW])
    extra = ["-bc_top_uy", -C_FLOW, "-bc_top_ux", 1, "-bc_top_ux_table", ux,
             "-interface_contact_dilation_angle", 10, "-ts_dt", dt, "-ts_max_time", t_end,
             "-ts_max_steps", 4 * (steps + 1), "-output_fields_every", 0]
    common.run(scene, out, extra, ranks=args.ranks)
    ts = common.read_timeseries(out)
    chk = common.Checks(f"sheared joint carrying flow, psi = 10 deg ({args.ranks} rank(s))")
    t = common.column(ts, "time")
    u = np.interp(t, [0.0, dt, t_end], [0.0, 0.0, U_FLOW])
    sigma0 = KN * C_FLOW
    sigma = KN * (C_FLOW + TAN_PSI * u) / (1.0 + MU * KN * TAN_PSI / KT)
    slip = np.where(KT * u <= MU * sigma0, 0.0, u - MU * sigma / KT)
    h = D0 + TAN_PSI * slip
    q_exact = h**3 / (12.0 * MU_W) * (P_LEFT - P_RIGHT) / L
    left = common.column(ts, "base_left.interface_outflow")
    right = common.column(ts, "base_right.interface_outflow")
    rate = common.column(ts, "contact.storage_rate")
    storage = common.column(ts, "contact.storage")
    q = 0.5 * (right - left)
    print(f"  aperture from {storage[0]:.4e} to {storage[-1]:.4e} m (D0 {D0:.1e}); flow rate grew "
          f"x{q[-1] / q[0]:.1f} (closed form x{q_exact[-1] / q_exact[0]:.1f}); "
          f"Newton max {int(ts['newton_its'].max())}")
    chk.check("max |Q - (D0 + tan(psi) s_p)^3 / (12 mu_w) dp / L| / Q", np.max(np.abs(q - q_exact) / q_exact), 1e-8)
    chk.check("max |h - (D0 + tan(psi) s_p)| / h (h = storage / A)", np.max(np.abs(storage - h) / h), 1e-8)
    chk.check("transmissivity growth (D0 + tan(psi) s_p)^3 / D0^3 at the end (>= 100)", -q[-1] / q[0], -100)
    chk.check("max |right + left + storage_rate| / Q", np.max(np.abs(right + left + rate) / q_exact), 1e-8)
    step = np.diff(np.concatenate([[0.0], t]))
    before = np.concatenate([[D0], storage[:-1]])
    chk.check("max |storage_rate dt - (h_k - h_(k-1))| / h", np.max(np.abs(rate * step - (storage - before)) / storage), 1e-8)
    chk.check("the gap stores water as it dilates: max storage rate > 0", -np.max(rate), 0.0)
    chk.finish()


def restart(args):
    scene = os.path.join(HERE, "shear_cns_2d.opts")
    ref = common.output_dir(f"dilatancy_restart_reference_np{args.ranks}")
    common.run(scene, ref, cns_options(ref, True), ranks=args.ranks)
    out = common.output_dir(f"dilatancy_restart_np{args.ranks}")
    extra = cns_options(out, True)
    common.run(scene, out, extra + ["-ts_max_time", 15, "-checkpoint_every", 5], ranks=args.ranks)
    # The continuation, in the same directory (its log names the checkpoint it starts from).
    common.run(scene, out, extra + ["-restart", out], ranks=args.ranks)
    with open(os.path.join(out, "log.txt")) as f:
        log = f.read()
    chk = common.Checks(f"dilatant joint restarted from a checkpoint ({args.ranks} rank(s))")
    m = re.search(r"restart from \S+step-(\d+)\.h5: step (\d+)", log)
    chk.check("continued from the checkpoint of step 15", 0.0 if m and int(m.group(2)) == 15 else 1.0,
              0.0)
    a, b = common.read_timeseries(ref), common.read_timeseries(out)
    same_rows = len(a["step"]) == len(b["step"]) and np.array_equal(a["step"], b["step"])
    chk.check(f"time series rows: {len(b['step'])} (uninterrupted {len(a['step'])})", 0.0 if same_rows else 1.0, 0.0)
    if same_rows:
        worst, where = common.largest_series_difference(a, b)
        chk.check(f"largest difference relative to its kind's scale ({where})", worst, 1e-12)
        later = a["time"] > 15
        chk.check("the normal stress still grows after the restart (slip past t = 15 s dilates)",
                  -(-b["joint.Fy"][later][-1] + b["joint.Fy"][later][0]), 0.0)
    chk.finish()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", choices=("cns", "cns_limit", "flow", "restart"), required=True)
    ap.add_argument("--ranks", type=int, default=1)
    args = ap.parse_args()
    if args.case == "flow":
        return flow(args)
    if args.case == "restart":
        return restart(args)
    return cns(args, args.case == "cns_limit")


if __name__ == "__main__":
    main()
