"""Strip footing on a weightless Mohr-Coulomb soil against Prandtl's collapse pressure.

A rigid smooth footing of half-width b on a stress-free weightless soil (half model, plane
strain) is pushed down by a prescribed settlement; the mean footing pressure q = -footing.Fy /
b must level off at the closed-form collapse pressure N_c c (tests/plasticity/closed_forms.py):
    --case tresca      phi = psi = 0:           N_c = pi + 2 = 5.14  (settlement 8 % of b, 32 steps)
    --case frictional  phi = psi = 20 deg:      N_c = 14.83          (settlement 12 % of b, 40 steps)
(associated flow: the limit theorems that give N_c assume it). Mesh: meshes/strip_footing_2d.geo,
crossed triangles (42 x 24 cells, 4032 triangles at factor 1, 14 cells under the footing); --quads meshes the same grid
with bilinear quadrilaterals instead (they lock: see the .geo), for comparison only.
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
         "frictional": dict(phi=20.0, settlement=0.12, steps=40)}

parser = argparse.ArgumentParser()
parser.add_argument("--case", choices=sorted(CASES), default="tresca")
parser.add_argument("--quads", action="store_true", help="bilinear quadrilaterals (lock)")
parser.add_argument("--factor", type=float, default=1.0, help="-mesh_size_factor")
parser.add_argument("--ranks", type=int, default=1)
args = parser.parse_args()
case = CASES[args.case]

name = f"footing_{args.case}{'_quads' if args.quads else ''}_{args.factor:g}_np{args.ranks}"
out = common.output_dir(name)
extra = ["-mesh_size_factor", args.factor,
         "-region_soil_friction_angle", case["phi"], "-region_soil_dilation_angle", case["phi"],
         "-bc_footing_uy", -case["settlement"], "-ts_dt", 1.0 / case["steps"], "-snes_monitor"]
if args.quads:
    # The same .geo with crossed = 0, through a wrapper that sets it before including it.
    wrapper = os.path.join(out, "strip_footing_2d_quads.geo")
    with open(wrapper, "w") as f:
        f.write("crossed = 0;\nInclude \"%s\";\n" % os.path.join(common.SOURCE, "meshes",
                                                                  "strip_footing_2d.geo"))
    extra += ["-mesh", wrapper]
common.run(os.path.join(common.SOURCE, "options", "strip_footing_2d.opts"), out, extra, ranks=args.ranks, timeout=600)

ts = common.read_timeseries(out)
time = common.column(ts, "time")
q = -common.column(ts, "footing.Fy") / B
settlement = case["settlement"] * np.minimum(time, 1.0)  # the ramp holds after t = 1
nc = closed_forms.prandtl_bearing_factor(case["phi"])
q_u = nc * C
print(f"  closed form: N_c = {nc:.4f}, q_u = {q_u:.1f} Pa")
print("  settlement [mm] / q [kPa] / q / q_u:")
for i in range(0, len(q), max(1, len(q) // 10)):
    print(f"    {1e3 * settlement[i]:7.2f}  {q[i] / 1e3:8.3f}  {q[i] / q_u:.4f}")
print(f"    {1e3 * settlement[-1]:7.2f}  {q[-1] / 1e3:8.3f}  {q[-1] / q_u:.4f}  (end)")

chk = common.Checks(f"strip footing, {args.case} (phi = {case['phi']:g} deg)"
                    f"{', quadrilaterals' if args.quads else ''}")
chk.check("|q_end / (N_c c) - 1|", abs(q[-1] / q_u - 1.0), 0.05)
i75 = int(np.argmin(np.abs(settlement - 0.75 * settlement[-1])))
chk.check("levelled off: (q_end - q(0.75 settlement)) / q_end", (q[-1] - q[i75]) / q[-1], 0.005)

its = common.column(ts, "newton_its")
last = newton_history.report(os.path.join(out, "log.txt"), its)
chk.check("every step's last Newton iteration reduces the residual >= 100 x (quadratic end)",
          max(last), 1e-2)
chk.finish()
