"""Spatial convergence of the pressure for Terzaghi 2D (time error removed).

    convergence.py [--mesh meshes/terzaghi_column_2d.geo] [--ranks N]

The scene terzaghi_2d.opts is run on 4 meshes, h = H/10, H/20, H/40, H/80
(-mesh_size_factor 2, 1, 0.5, 0.25), all with the same dt = 1 s (c_v dt / H^2 = 0.012) for
10 steps.  The reference is the backward-Euler series (analytic.terzaghi_pressure_be): the
exact solution of the time-discrete, space-continuous problem, so the difference is the
spatial error alone.  Error norm: root mean square of (p - p_BE)/q over 10 probes at depths
0.1, 0.2, ..., 1.0 m (vertices of every mesh) and all 10 steps.

Theory: linear (P1/Q1) pressure converges at second order in h; the Aguilar et al.
stabilisation term is O(h^2) as well, so the rate stays 2.  An independent 1D model of the
same stabilised scheme gives rates 1.96, 1.99, 2.00 on these meshes.  Checks: the
least-squares rate over the 4 meshes and the rate of the finest pair are both > 1.7.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
from common import analytic as A  # noqa: E402
from terzaghi import H, W, terzaghi_parameters  # noqa: E402

FACTORS = [2.0, 1.0, 0.5, 0.25]
BASE_NY = 20                       # elements along H at factor 1 (terzaghi_column_2d.geo)
DT, STEPS = 1.0, 10
DEPTHS = np.arange(1, 11) / 10.0
MIN_RATE = 1.7


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--mesh", default=None)
    ap.add_argument("--ranks", type=int, default=1)
    args = ap.parse_args()

    scene = common.scene_path("terzaghi_2d.opts")
    opts = common.read_scene(scene)
    q, Mc, kappa = terzaghi_parameters(opts)
    mesh = args.mesh or opts["-mesh"]
    step_times = DT * np.arange(1, STEPS + 1)
    p_be = A.terzaghi_pressure_be(DEPTHS, step_times, q, H, Mc, kappa)  # (steps, depths)

    chk = common.Checks(f"Terzaghi 2D spatial convergence, mesh {mesh}, {args.ranks} rank(s)")
    hs, errs = [], []
    for f in FACTORS:
        out = common.output_dir(f"convergence_{os.path.splitext(os.path.basename(mesh))[0]}_f{f:g}")
        extra = ["-mesh", mesh, "-mesh_size_factor", f, "-ts_dt", DT, "-ts_max_steps", STEPS,
                 "-ts_max_time", DT * STEPS]
        for j, z in enumerate(DEPTHS):
            extra += [f"-probe_z{j}", f"{W / 2},{H - z}"]
        common.run(scene, out, extra, ranks=args.ranks)
        ts = common.read_timeseries(out)
        if len(ts["time"]) != STEPS or np.max(np.abs(ts["time"] - step_times)) > 1e-9 * DT * STEPS:
            common.fail(f"expected {STEPS} steps of {DT} s, got times {ts['time']}")
        P = np.column_stack([common.column(ts, f"z{j}.p") for j in range(len(DEPTHS))])
        hs.append(H / int(np.ceil(BASE_NY / f - 1e-9)))
        errs.append(np.sqrt(np.mean((P - p_be) ** 2)) / q)
    hs, errs = np.array(hs), np.array(errs)
    rates = np.log(errs[:-1] / errs[1:]) / np.log(hs[:-1] / hs[1:])
    fit = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    print("       h        RMS |p - p_BE|/q    rate")
    for i, (h, e) in enumerate(zip(hs, errs)):
        print(f"  {h:9.5f}   {e:12.4e}      " + (f"{rates[i - 1]:.3f}" if i else ""))
    print(f"  least-squares rate {fit:.3f} (theory 2)")
    chk.check("least-squares rate (> 1.7)", fit, MIN_RATE, ok=fit > MIN_RATE)
    chk.check("finest-pair rate (> 1.7)", rates[-1], MIN_RATE, ok=rates[-1] > MIN_RATE)
    chk.finish()


if __name__ == "__main__":
    main()
