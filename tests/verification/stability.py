"""Hard cases for the bulk (docs/verification.md, "Undrained limit and first steps"): no pressure oscillation in the first steps
of consolidation, and the nearly undrained limit.

    stability.py --case first_step [--mesh meshes/terzaghi_column_2d_tri.geo] [--ranks N]
    stability.py --case tiny_k     [--mesh ...]
    stability.py --case mandel_undrained
    stability.py --case mandel_drained_edge
    ... [--ts bdf2]   the same checks with -ts_type bdf -ts_bdf_order 2 (its one step is PETSc's
                      start-up: a backward-Euler half step, then BDF2 through 0, dt/2, dt)

The pressure and displacement are read at every vertex of the mesh from the field output
(fields.xmf + fields.h5, through tests/support/fields_reader.py).

first_step  Terzaghi column (terzaghi_2d.opts, or _3d with --dim 3), one step with
            dt = 1e-5 s = 4.8e-5 h^2/c_v (h = H/20).  Exact solution: p = q except in a layer
            2 sqrt(c_v dt) = 7e-4 m = 0.014 h under the drained top.  Equal-order elements
            without stabilisation give p ~ 2q at the vertices next to the top (checkerboard).
            Checks: every vertex pressure in [-0.01 q, 1.01 q] (1 % of q for the solver
            tolerance and round-off; the exact solution lies in [0, q]); vertices deeper than
            2h within 1 % of q (the stabilisation confines the transition to the top element
            in the 1D analysis of Aguilar et al.); the settlement, 0 for the exact undrained
            1D response, at most q h / M_c (a fully drained top element; the stabilised 1D
            scheme gives q h / (2 M_c)).
tiny_k      The same with k = 1e-20 m2 and the scene's dt = 0.2 s (c_v dt/h^2 = 4e-8): the
            nearly undrained limit. Same checks.
mandel_undrained
            mandel_undrained.opts: quarter of Mandel's specimen, k = 1e-20, every side
            impervious, uniform compression q on top, one step.  The undrained elastic
            solution (p = q/2, u_y(b) = -q b (1-nu_u)/(2G), u_x(a) = q a nu_u/(2G), nu_u = 1/2)
            is uniform, hence in the finite-element space: relative errors <= 1e-4 (solver
            tolerance).
mandel_drained_edge
            The same with the right side drained (p = 0): Mandel's specimen at t = 0+ under a
            flexible (traction) load, with a boundary layer 2 sqrt(c dt) = 2e-5 a, far below
            h = a/20.  Checks:
            - no undershoot: vertex pressures >= -0.01 p0;
            - the peak next to the drained corner is reported, not checked.  Under a
              flexible load the drained (softer) edge layer sheds load to the undrained
              material next to it, so the exact solution has a local peak just inside the
              layer, but no closed form bounds what an element 2500 times thicker than the
              layer should show there (poroseam: 1.17 p0 with the default stabilisation,
              1.07 p0 with the layer resolved, 2.09 p0 unstabilised).
            - centre pressure: the discrete drained layer (at most one element wide) acts like
              a drained strip of width w <= h, whose Mandel-Cryer rise in the closed form is
              about 0.3 w / a (0.018 at c t/a^2 = 0.001, where 2 sqrt(c t/a^2) = 0.063), so
              |p_centre - p0| / p0 <= 0.3 h / a = 0.015.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
from common import analytic as A  # noqa: E402
from terzaghi import H, terzaghi_parameters  # noqa: E402

TS_OPTIONS = {"beuler": [], "bdf2": ["-ts_type", "bdf", "-ts_bdf_order", 2]}


def terzaghi_case(case, args):
    scene = common.scene_path(f"terzaghi_{args.dim}d.opts")
    opts = common.read_scene(scene)
    mesh = args.mesh or opts["-mesh"]
    extra = ["-mesh", mesh, "-ts_max_steps", 1, "-output_fields_every", 1] + TS_OPTIONS[args.ts]
    if case == "first_step":
        dt = 1e-5
        extra += ["-ts_dt", dt, "-ts_max_time", dt]
    else:  # tiny_k
        dt = float(opts["-ts_dt"])
        extra += ["-region_soil_permeability", 1e-20, "-ts_max_time", dt]
        opts["-region_soil_permeability"] = "1e-20"
    q, Mc, kappa = terzaghi_parameters(opts)
    h = H / 20.0
    tag = f"stability_{case}_{os.path.splitext(os.path.basename(mesh))[0]}_np{args.ranks}_{args.ts}"
    out = common.output_dir(tag)
    common.run(scene, out, extra, ranks=args.ranks)
    ts = common.read_timeseries(out)
    if len(ts["time"]) != 1:
        common.fail(f"expected one step, got {len(ts['time'])}")
    t, X, fields = common.vertex_fields(out)
    if abs(t - dt) > 1e-9 * dt:
        common.fail(f"last field output at t = {t}, expected {dt}")
    cv = A.terzaghi_cv(kappa, Mc)
    print(f"  dt = {dt:g} s = {dt * cv / h**2:.2e} h^2/c_v, {len(X)} vertices")
    p = fields["pressure"]
    s = np.mean(fields["displacement"][np.abs(X[:, args.dim - 1] - H) < 1e-9, args.dim - 1])
    depth = H - X[:, args.dim - 1]
    print("  depth    min p/q   max p/q   (vertices at the 6 shallowest depths)")
    for d in np.unique(np.round(depth, 9))[:6]:
        sel = np.abs(depth - d) < 1e-8
        print(f"  {d:6.3f} {p[sel].min() / q:9.5f} {p[sel].max() / q:9.5f}")
    chk = common.Checks(f"stability {case}, mesh {mesh}, {args.ranks} rank(s), {args.ts}")
    chk.check("max p / q (<= 1.01)", p.max() / q, 1.01)
    chk.check("-min p / q (>= -0.01)", -p.min() / q, 0.01)
    deep = depth > 2 * h + 1e-9
    chk.check("max |p - q| / q below depth 2h", np.max(np.abs(p[deep] - q)) / q, 0.01)
    chk.check("|settlement| / (q h / M_c)", abs(s) / (q * h / Mc), 1.0)
    chk.finish()


def mandel_case(case, args):
    scene = common.scene_path("mandel_undrained.opts")
    opts = common.read_scene(scene)
    E, nu = float(opts["-region_soil_E"]), float(opts["-region_soil_nu"])
    q = -float(opts["-bc_top_traction"].split(",")[-1])
    a = b = 1.0
    m = A.Mandel(E, nu, 1e-20 / 1e-3, a, b, q * a)
    und = m.undrained()
    p0 = und["p0"]
    out = common.output_dir(f"stability_{case}_np{args.ranks}_{args.ts}")
    extra = ["-output_fields_every", 1] + TS_OPTIONS[args.ts]
    if case == "mandel_drained_edge":
        extra += ["-bc_right_p", 0]
    common.run(scene, out, extra, ranks=args.ranks)
    ts = common.read_timeseries(out)
    t, X, fields = common.vertex_fields(out)
    p = fields["pressure"]
    ux, uy = fields["displacement"][:, 0], fields["displacement"][:, 1]
    print(f"  p0 = q/2 = {p0:g} Pa; u_y(b) undrained {und['uy_top']:.6e}, u_x(a) {und['ux_side']:.6e}")
    print(f"  vertex p/p0 in [{p.min() / p0:.5f}, {p.max() / p0:.5f}], centre {common.column(ts, 'centre.p')[-1] / p0:.5f}")
    chk = common.Checks(f"stability {case}, {args.ranks} rank(s), {args.ts}")
    if case == "mandel_undrained":
        top = np.abs(X[:, 1] - b) < 1e-9
        right = np.abs(X[:, 0] - a) < 1e-9
        chk.check("max |p - p0| / p0", np.max(np.abs(p - p0)) / p0, 1e-4)
        chk.check("max |u_y(top) - u_y,undrained| / |u_y,undrained|",
                  np.max(np.abs(uy[top] - und["uy_top"])) / abs(und["uy_top"]), 1e-4)
        chk.check("max |u_x(right) - u_x,undrained| / u_x,undrained",
                  np.max(np.abs(ux[right] - und["ux_side"])) / abs(und["ux_side"]), 1e-4)
    else:
        h = a / 20.0
        i = int(np.argmax(p))
        print(f"  max p at ({X[i, 0]:.3f}, {X[i, 1]:.3f})")
        # The peak next to the drained corner is printed above, not checked: no closed form
        # bounds it when the layer is far thinner than an element (see the docstring).
        chk.check("-min p / p0 (>= -0.01)", -p.min() / p0, 0.01)
        pc = common.column(ts, "centre.p")[-1]
        chk.check("|p_centre - p0| / p0 (<= 0.3 h/a)", abs(pc - p0) / p0, 0.3 * h / a)
    chk.finish()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True,
                    choices=("first_step", "tiny_k", "mandel_undrained", "mandel_drained_edge"))
    ap.add_argument("--dim", type=int, choices=(2, 3), default=2)
    ap.add_argument("--mesh", default=None)
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--ts", choices=tuple(TS_OPTIONS), default="beuler")
    args = ap.parse_args()
    if args.case.startswith("mandel"):
        mandel_case(args.case, args)
    else:
        terzaghi_case(args.case, args)


if __name__ == "__main__":
    main()
