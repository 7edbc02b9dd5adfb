"""Cylindrical cavity expansion in Mohr-Coulomb soil against the small-strain closed form.

Scene tests/plasticity/cavity.opts: axisymmetric slice a = 1 m <= r <= b = 20 m, plane strain
along the axis, weightless stress-free soil (c = 10 kPa, phi = 30 deg, psi = 5 deg: the
non-associated flow enters the closed form through M = (1 + sin psi) / (1 - sin psi)), the
cavity wall pushed out to u_a = 3 % of a in 40 steps, outer radius traction-free.
Closed form: tests/plasticity/closed_forms.py, CylindricalCavity (the small-strain solution
of Carter, Booker and Yeung 1986 / Yu and Houlsby 1991 with the finite outer radius exact).
Checks: the cavity pressure p = inner.Fx / (2 pi a H) (full circle) of every step within 2 %
of the closed form p(u_a) (the issue's tolerance), in the elastic steps too; the closed
form's plastic radius at the end is at least 4 a (a developed plastic zone). Newton starts
every step from the last state (-ts_theta_initial_guess_extrapolate false; the extrapolated guess is almost
exact here and would leave one iteration to look at): with the consistent tangent every step
converges in at most 3 iterations (checked; the return is piecewise linear and the principal
axes do not rotate, so once the active planes are right Newton is exact to round-off). Prints
the Newton residual history; checks that every step's last iteration reduces the residual at
least 100-fold (measured: below 1e-10, down to round-off).
Options: --factor (mesh size factor; cells along r = 60 / factor), --ranks, --psi, --phi.
"""
import argparse
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, HERE)
import closed_forms  # noqa: E402
import common  # noqa: E402
import newton_history  # noqa: E402

E, NU, C, A, B, H, U_END = 1e7, 0.3, 1e4, 1.0, 20.0, 0.05, 0.03

parser = argparse.ArgumentParser()
parser.add_argument("--factor", type=float, default=1.0, help="-mesh_size_factor")
parser.add_argument("--ranks", type=int, default=1)
parser.add_argument("--phi", type=float, default=30.0)
parser.add_argument("--psi", type=float, default=5.0)
args = parser.parse_args()

out = common.output_dir(f"cavity_phi{args.phi:g}_psi{args.psi:g}_{args.factor:g}_np{args.ranks}")
common.run(os.path.join(HERE, "cavity.opts"), out,
           ["-mesh_size_factor", args.factor, "-region_soil_friction_angle", args.phi,
            "-region_soil_dilation_angle", args.psi, "-bc_inner_ux", U_END, "-snes_monitor",
            "-ts_theta_initial_guess_extrapolate", "false"],
           ranks=args.ranks, timeout=600)
ts = common.read_timeseries(out)
u_a = U_END * common.column(ts, "time")
p_fe = common.column(ts, "inner.Fx") / (2 * math.pi * A * H)

cavity = closed_forms.CylindricalCavity(E, NU, C, args.phi, args.psi, 0.0, A, B)
exact = np.array([cavity.pressure(u)[0] for u in u_a])
radius = np.array([cavity.pressure(u)[1] for u in u_a])
err = np.abs(p_fe / exact - 1.0)
print(f"  first yield at u_a = {1e3 * cavity.yield_displacement():.3f} mm")
print("  u_a [mm]  R/a   p FE [kPa]  p exact [kPa]  error")
for i in list(range(0, len(u_a), max(1, len(u_a) // 10))) + [len(u_a) - 1]:
    print(f"  {1e3 * u_a[i]:7.3f} {radius[i] / A:5.2f} {p_fe[i] / 1e3:11.4f} {exact[i] / 1e3:13.4f}"
          f"  {err[i]:.2e}")

chk = common.Checks(f"cylindrical cavity, phi = {args.phi:g}, psi = {args.psi:g} deg")
elastic = u_a <= cavity.yield_displacement()
if elastic.any():
    chk.check("elastic steps: max |p / p_exact - 1|", err[elastic].max(), 0.02)
chk.check("plastic steps: max |p / p_exact - 1|", err[~elastic].max(), 0.02)
chk.check("plastic radius at the end reaches 4 a (the test covers a developed plastic zone)",
          -radius[-1] / A, -4.0)

its = common.column(ts, "newton_its")
last = newton_history.report(os.path.join(out, "log.txt"), its)
chk.check("Newton iterations per step (consistent tangent)", its.max(), 3)
chk.check("every step's last Newton iteration reduces the residual >= 100 x (quadratic end)",
          max(last), 1e-2)
chk.finish()
