"""Axisymmetric formulation (x = r, y = z): Lame's thick cylinder, drained and undrained.

A cylinder a <= r <= b under internal pressure P, plane strain along z.
  drained (k large, drained boundaries, one long step: the excess pressure has dissipated):
      u_r(r) = (1 + nu) P a^2 / (E (b^2 - a^2)) [(1 - 2 nu) r + b^2 / r]
  undrained (k tiny, incompressible grains and water, impervious boundaries: a drained
      boundary would add a pressure layer far thinner than an element): no volume change,
      u_r = C / r with C = P a^2 b^2 / (2 G (b^2 - a^2)).
Checks: radial displacement at five radii on three meshes (h, h/2, h/4): observed rate of
convergence >= 1.8 (linear elements: 2) and error on the finest mesh < 1e-3 of u_r(a); the
radial boundary force on r = a equals P 2 pi a H exactly (full circle).
--order 2 (Taylor-Hood: Lagrange Q2, or P2 with --triangles): probes also between the nodes
(the probe evaluates the quadratic field there), at r = a + (j + 1/3) h_0 (h_0 = (b - a) / 8,
the coarsest cells), which is 1/3 or 2/3 of the way across a cell on every mesh, where the
cubic term of the interpolation error has the same size: rate between the two finer meshes
>= 2.8 (expected 3; measured 3.1, and 2.6-2.8 from the coarsest mesh of 8 x 4 cells) and
finest-mesh error < 1e-5 of u_r(a); the ring force as above. (At the vertices the error
converges faster, about h^4.)
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import common  # noqa: E402

E, NU, P, A, B, H = 1e8, 0.3, 1e5, 1.0, 2.0, 0.5
G = E / (2 * (1 + NU))
parser = argparse.ArgumentParser()
parser.add_argument("--order", type=int, default=1, choices=(1, 2), help="-displacement_order")
parser.add_argument("--triangles", action="store_true", help="triangles instead of quadrilaterals")
args_ = parser.parse_args()
RADII = [1.0, 1.25, 1.5, 1.75, 2.0] + ([1 + 1 / 24, 1 + 1 / 3, 1 + 7 / 12, 1 + 11 / 12] if args_.order == 2 else [])
RATE, FINEST = (1.8, 1e-3) if args_.order == 1 else (2.8, 1e-5)


def drained(r):
    return (1 + NU) * P * A**2 / (E * (B**2 - A**2)) * ((1 - 2 * NU) * r + B**2 / r)


def undrained(r):
    return P * A**2 * B**2 / (2 * G * (B**2 - A**2)) / r


def run_case(name, exact, extra, chk):
    errors = []
    for factor in (1.0, 0.5, 0.25):
        tag = "" if args_.order == 1 else f"_order2{'_tri' if args_.triangles else ''}"
        out = common.output_dir(f"axisym_{name}{tag}_{factor:g}")
        args = ["-mesh_size_factor", factor, "-displacement_order", args_.order] + extra
        if args_.triangles:
            # the same .geo with triangles = 1, through a wrapper that sets it first
            wrapper = os.path.join(out, "thick_cylinder_triangles.geo")
            with open(wrapper, "w") as f:
                f.write("triangles = 1;\nInclude \"%s\";\n" % os.path.join(
                    common.SOURCE, "meshes", "thick_cylinder_axisym.geo"))
            args += ["-mesh", wrapper]
        for i, r in enumerate(RADII):
            args += [f"-probe_r{i}", f"{r},0.25"]
        common.run(common.scene_path("thick_cylinder.opts"), out, args)
        ts = common.read_timeseries(out)
        ur = np.array([ts[f"r{i}.ux"][-1] for i in range(len(RADII))])
        err = np.max(np.abs(ur - exact(np.array(RADII)))) / exact(A)
        errors.append(err)
        force = ts["inner.Fx"][-1]
        chk.check(f"{name}, factor {factor}: |inner.Fx - P 2 pi a H| / (P 2 pi a H)",
                  abs(force - P * 2 * np.pi * A * H) / (P * 2 * np.pi * A * H), 1e-9)
    rates = [np.log2(errors[i] / errors[i + 1]) for i in range(2)]
    print(f"  {name}: errors {', '.join(f'{e:.3e}' for e in errors)}; rates {', '.join(f'{r:.2f}' for r in rates)}")
    chk.check(f"{name}: finest-mesh error / u_r(a)", errors[-1], FINEST)
    observed = min(rates) if args_.order == 1 else rates[-1]
    chk.check(f"{name}: observed rate (>= {RATE})", -observed, -RATE)


chk = common.Checks("axisymmetric thick cylinder" + (
    f", displacement order 2 on {'triangles' if args_.triangles else 'quadrilaterals'}"
    if args_.order == 2 else ""))
run_case("drained", drained, ["-region_ring_permeability", 1e-9, "-bc_inner_p", 0, "-bc_outer_p", 0], chk)
run_case("undrained", undrained, ["-region_ring_permeability", 1e-22, "-ts_dt", 1e-3, "-ts_max_time", 1e-3], chk)
chk.finish()
