"""Terzaghi 1D consolidation (2D column or 3D column) against the closed form.

    terzaghi.py --dim 2|3 [--mesh meshes/x.geo] [--ranks N]

Checks, with the scene terzaghi_<dim>d.opts (h = H/20, dt = 0.2 s = 0.0024 H^2/c_v):
  * pore pressure at depths 0.1, 0.25, 0.5 and 1.0 m (the impervious base) at
    T_v = 0.024, 0.072, 0.3, against
      - the exact series: |p - p_exact| <= 2 % of q.  Backward Euler with T_v = 0.0024 per step
        is first-order accurate in time; at these probes its error alone is 1.2 % of q at
        T_v = 0.024 (analytic.terzaghi_pressure_be vs terzaghi_pressure), and the spatial
        error adds ~0.1 %.
      - the backward-Euler series (time error removed, spatial error only):
        |p - p_BE| <= 0.5 % of q.  An independent 1D P1/P1 model of the same stabilised
        scheme gives 0.11 % of q at h = H/20 at the earliest of these times; 0.5 % leaves
        room for the 2D/3D cell-size measure in the stabilisation and simplices.
  * settlement (top vertical displacement) at T_v = 0.012, 0.024, 0.072, 0.144, 0.3, relative to
    the final settlement q H / M_c: exact series <= 1 %, backward-Euler series <= 0.5 %
    (1D model: 0.13 % and 0.18 %; the stabilisation drains a layer ~h/2 early on).
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
from common import analytic as A  # noqa: E402

H = 1.0   # column height (meshes/terzaghi_column_*.geo)
W = 0.1   # column width
DEPTHS = [0.1, 0.25, 0.5, 1.0]
P_TIMES = [2.0, 6.0, 25.0]                    # T_v = 0.024, 0.072, 0.3
S_TIMES = [1.0, 2.0, 6.0, 12.0, 25.0]
TOL_P_EXACT, TOL_P_BE = 0.02, 0.005           # fractions of q
TOL_S_EXACT, TOL_S_BE = 0.01, 0.005           # fractions of q H / M_c


def terzaghi_parameters(opts):
    """(q, M_c, mobility) from the scene options."""
    E = float(opts["-region_soil_E"])
    nu = float(opts["-region_soil_nu"])
    k = float(opts["-region_soil_permeability"])
    mu = float(opts.get("-fluid_viscosity", 1e-3))
    q = -float(opts["-bc_top_traction"].split(",")[-1])
    return q, A.constrained_modulus(E, nu), k / mu


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dim", type=int, choices=(2, 3), default=2)
    ap.add_argument("--mesh", help="mesh file (default: the scene's)")
    ap.add_argument("--ranks", type=int, default=1)
    args = ap.parse_args()

    scene = common.scene_path(f"terzaghi_{args.dim}d.opts")
    opts = common.read_scene(scene)
    q, Mc, kappa = terzaghi_parameters(opts)
    mesh = args.mesh or opts["-mesh"]
    tag = f"terzaghi_{args.dim}d_{os.path.splitext(os.path.basename(mesh))[0]}_np{args.ranks}"
    out = common.output_dir(tag)

    extra = ["-mesh", mesh]
    def point(height):  # on the column axis
        return f"{W / 2},{height}" if args.dim == 2 else f"{W / 2},{W / 2},{height}"
    for i, z in enumerate(DEPTHS):
        extra += [f"-probe_z{i}", point(H - z)]
    extra += ["-probe_top", point(H)]
    common.run(scene, out, extra, ranks=args.ranks)
    ts = common.read_timeseries(out)
    vert = "uz" if args.dim == 3 else "uy"

    times = common.column(ts, "time")
    # the semi-discrete (backward Euler) series needs every step time up to the last checked
    n_last = common.step_index(ts, max(S_TIMES + P_TIMES)) + 1
    step_times = times[:n_last]
    p_be_all = A.terzaghi_pressure_be(DEPTHS, step_times, q, H, Mc, kappa)
    s_be_all = A.terzaghi_settlement_be(step_times, q, H, Mc, kappa)

    chk = common.Checks(f"Terzaghi {args.dim}D, mesh {mesh}, {args.ranks} rank(s)")
    cv = A.terzaghi_cv(kappa, Mc)
    print(f"  q = {q:g} Pa, M_c = {Mc:g} Pa, c_v = {cv:g} m2/s, {len(times)} steps, dt = {times[0]:g} s")
    print("     t [s]    T_v   depth    p/q      exact     BE-series")
    err_p_exact = err_p_be = 0.0
    for t in P_TIMES:
        i = common.step_index(ts, t)
        p_exact = A.terzaghi_pressure(np.array(DEPTHS), times[i], q, H, Mc, kappa)
        for j, z in enumerate(DEPTHS):
            p = common.column(ts, f"z{j}.p")[i]
            print(f"  {times[i]:8.3f} {cv * times[i] / H**2:6.3f} {z:6.2f} {p / q:9.5f} {p_exact[j] / q:9.5f}"
                  f" {p_be_all[i, j] / q:9.5f}")
            err_p_exact = max(err_p_exact, abs(p - p_exact[j]) / q)
            err_p_be = max(err_p_be, abs(p - p_be_all[i, j]) / q)
    s_ref = q * H / Mc
    print("     t [s]    T_v   s/(qH/M_c)  exact     BE-series")
    err_s_exact = err_s_be = 0.0
    for t in S_TIMES:
        i = common.step_index(ts, t)
        s = common.column(ts, f"top.{vert}")[i]
        s_exact = A.terzaghi_settlement(times[i], q, H, Mc, kappa)
        print(f"  {times[i]:8.3f} {cv * times[i] / H**2:6.3f} {s / s_ref:10.5f} {s_exact / s_ref:9.5f}"
              f" {s_be_all[i] / s_ref:9.5f}")
        err_s_exact = max(err_s_exact, abs(s - s_exact) / s_ref)
        err_s_be = max(err_s_be, abs(s - s_be_all[i]) / s_ref)

    chk.check("max |p - p_exact| / q", err_p_exact, TOL_P_EXACT)
    chk.check("max |p - p_BE| / q (spatial error)", err_p_be, TOL_P_BE)
    chk.check("max |s - s_exact| / (qH/M_c)", err_s_exact, TOL_S_EXACT)
    chk.check("max |s - s_BE| / (qH/M_c) (spatial error)", err_s_be, TOL_S_BE)
    chk.finish()


if __name__ == "__main__":
    main()
