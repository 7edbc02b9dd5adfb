"""Strip footing on a weightless Mohr-Coulomb soil against Prandtl's collapse pressure.

A rigid smooth footing of half-width b on a stress-free weightless soil (half model, plane
strain) is pushed down by a prescribed settlement; the mean footing pressure q = -footing.Fy /
b must level off at the closed-form collapse pressure N_c c (tests/plasticity/closed_forms.py):
    --case tresca      phi = psi = 0:           N_c = pi + 2 = 5.14  (settlement 8 % of b, 32 steps)
    --case frictional  phi = psi = 20 deg:      N_c = 14.83          (settlement 12 % of b, 40 steps)
(associated flow: the limit theorems that give N_c assume it).
Circular footing (axisymmetric, x = r, the axis at x = 0; the same mesh, the footing a disc of
radius b; q = -footing.Fy / (pi b^2), footing.Fy being the whole ring's force) on a Tresca soil:
    --case circular_smooth   N_c = 5.69  (Shield 1955, smooth rigid punch)
    --case circular_rough    N_c = 6.05  (Eason and Shield 1960, rough: -bc_footing_ux 0)
Linear triangles lock here (the hoop strain adds incompressibility constraints; Sloan and
Randolph 1982): measured +23 % with 56 cells under the footing and still rising, where P2
triangles are at +1.2 % (docs/verification.md).
Mesh: meshes/strip_footing_2d.geo, crossed triangles (42 x 24 cells, 4032 triangles at factor 1, 14 cells under the footing); --quads meshes the same grid
with bilinear quadrilaterals instead (they lock: see the .geo), for comparison only; --triangles
meshes it with one diagonal per grid cell (an ordinary triangle mesh, 2016 triangles at factor 1:
linear triangles lock on it, quadratic ones do not). --order 2: -displacement_order 2 (P2
triangles, 6 integration points each), checked within --tolerance (1 % for the order-2 tests).
Checks: |q_end / (N_c c) - 1| <= 5 % (the issue's tolerance on a moderate mesh); the curve has
levelled off (q grows by less than 0.5 % over the last quarter of the settlement), so q_end is a
collapse pressure and not a point on a still rising curve. Prints the Newton residual history
(-snes_monitor) of the last step and of the step with the most iterations. Newton with the
consistent tangent ends each step quadratically (the digits double); checked as: in every step
the last iteration reduces the residual at least 100-fold (measured: median 4e-6, largest
9e-4 (Tresca) and 2e-3 (phi = 20 deg); a wrong tangent converges by a roughly constant factor).
The active set of the piecewise-linear return changes in the first iterations, which are
slower.
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, HERE)
import closed_forms  # noqa: E402
import common  # noqa: E402
import newton_history  # noqa: E402

B, C = 1.0, 1e4
CASES = {"tresca": dict(phi=0.0, settlement=0.08, steps=32),
         "frictional": dict(phi=20.0, settlement=0.12, steps=40),
         "circular_smooth": dict(phi=0.0, settlement=0.08, steps=32, circular=True, nc=5.69),
         "circular_rough": dict(phi=0.0, settlement=0.08, steps=32, circular=True, nc=6.05,
                                rough=True)}

parser = argparse.ArgumentParser()
parser.add_argument("--case", choices=sorted(CASES), default="tresca")
parser.add_argument("--quads", action="store_true", help="bilinear quadrilaterals (lock)")
parser.add_argument("--triangles", action="store_true", help="ordinary triangles, not crossed")
parser.add_argument("--order", type=int, default=1, choices=(1, 2), help="-displacement_order")
parser.add_argument("--tolerance", type=float, default=0.05, help="on |q_end / (N_c c) - 1|")
parser.add_argument("--steps", type=int, default=0, help="load steps (0: the case's)")
parser.add_argument("--cells", type=int, default=0,
                    help="cells under the footing at factor 1 (the .geo's n; 0: its 14)")
parser.add_argument("--growth", type=float, default=0.0,
                    help="growth ratio of the cells away from the footing (the .geo's g; 0: 1.1)")
parser.add_argument("--factor", type=float, default=1.0, help="-mesh_size_factor")
parser.add_argument("--ranks", type=int, default=1)
args = parser.parse_args()
case = CASES[args.case]

if args.steps:
    case["steps"] = args.steps
mesh_kind = "_quads" if args.quads else "_triangles" if args.triangles else ""
grid = (f"_n{args.cells}" if args.cells else "") + (f"_g{args.growth:g}" if args.growth else "")
name = f"footing_{args.case}{mesh_kind}{grid}_order{args.order}_{args.factor:g}_np{args.ranks}"
out = common.output_dir(name)
extra = ["-mesh_size_factor", args.factor, "-displacement_order", args.order,
         "-region_soil_friction_angle", case["phi"], "-region_soil_dilation_angle", case["phi"],
         "-bc_footing_uy", -case["settlement"], "-ts_dt", 1.0 / case["steps"], "-snes_monitor"]
if case.get("circular"):
    extra += ["-axisymmetric"]
if case.get("rough"):
    extra += ["-bc_footing_ux", 0]
if args.quads or args.triangles or grid:
    # The same .geo with crossed = 0 (and triangles = 1), n, g, through a wrapper that sets
    # them before including it.
    wrapper = os.path.join(out, f"strip_footing_2d{mesh_kind}{grid}.geo")
    with open(wrapper, "w") as f:
        if args.quads or args.triangles:
            f.write("crossed = 0;\ntriangles = %d;\n" % int(args.triangles))
        if args.cells:
            f.write("n = %d;\n" % args.cells)
        if args.growth:
            f.write("g = %r;\n" % args.growth)
        f.write("Include \"%s\";\n" % os.path.join(common.SOURCE, "meshes", "strip_footing_2d.geo"))
    extra += ["-mesh", wrapper]
common.run(os.path.join(common.SOURCE, "options", "strip_footing_2d.opts"), out, extra, ranks=args.ranks, timeout=600)

ts = common.read_timeseries(out)
time = common.column(ts, "time")
area = np.pi * B**2 if case.get("circular") else B  # per metre of the half strip
q = -common.column(ts, "footing.Fy") / area
settlement = case["settlement"] * np.minimum(time, 1.0)  # the ramp holds after t = 1
nc = case["nc"] if case.get("circular") else closed_forms.prandtl_bearing_factor(case["phi"])
q_u = nc * C
print(f"  closed form: N_c = {nc:.4f}, q_u = {q_u:.1f} Pa")
print("  settlement [mm] / q [kPa] / q / q_u:")
for i in range(0, len(q), max(1, len(q) // 10)):
    print(f"    {1e3 * settlement[i]:7.2f}  {q[i] / 1e3:8.3f}  {q[i] / q_u:.4f}")
print(f"    {1e3 * settlement[-1]:7.2f}  {q[-1] / 1e3:8.3f}  {q[-1] / q_u:.4f}  (end)")

chk = common.Checks(f"{'circular' if case.get('circular') else 'strip'} footing, {args.case} "
                    f"(phi = {case['phi']:g} deg)"
                    f"{', quadrilaterals' if args.quads else ''}"
                    f"{', ordinary triangles' if args.triangles else ''}"
                    f"{', displacement order 2' if args.order == 2 else ''}")
chk.check("|q_end / (N_c c) - 1|", abs(q[-1] / q_u - 1.0), args.tolerance)
i75 = int(np.argmin(np.abs(settlement - 0.75 * settlement[-1])))
chk.check("levelled off: (q_end - q(0.75 settlement)) / q_end", (q[-1] - q[i75]) / q[-1], 0.005)

its = common.column(ts, "newton_its")
last = newton_history.report(os.path.join(out, "log.txt"), its)
chk.check("every step's last Newton iteration reduces the residual >= 100 x (quadratic end)",
          max(last), 1e-2)
chk.finish()
