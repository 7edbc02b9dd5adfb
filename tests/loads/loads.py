#!/usr/bin/python3
"""Normal pressure (-bc_<b>_pressure) and supports on physical points (docs/scenes.md,
"Normal pressure", "Physical points: supports"), label `loads`.

    loads.py --case NAME      one case (one ctest each)
    loads.py --list           the case names

Cases (elastic, E = 1e8 Pa, nu = 0.3, P = 1e5 Pa; the scenes are tests/loads/*.opts):
  cylinder   Lame's thick cylinder a = 1, b = 2 m, plane strain, quarter annulus, internal
             pressure. Closed form u_r = (1 + nu) P a^2 / (E (b^2 - a^2)) [(1 - 2 nu) r + b^2/r].
             At orders 1 and 2, two meshes each: the largest vertex error of u_r / u_r(a)
             below a bound and decreasing at rate 2 (order 2 too: the straight-sided arcs
             keep it at the geometry's rate 2, 18 times below order 1), and the inner
             boundary's force exactly P a in x and in y (the pressure on a polygon whose ends
             lie on the axes: its resultant is P times the polygon's projections, a).
  sphere     Lame's hollow sphere a = 1, b = 2 m (an octant, tetrahedra, coarse), internal
             pressure: u_r = P a^3 / (E (b^3 - a^3)) [(1 - 2 nu) r + (1 + nu) b^3 / (2 r^2)];
             orders 1 and 2, two meshes: bounds and rates; inner.Fx equals P times the area
             of the mesh's polygonal quarter disc on x = 0 (from the output vertices) to
             round-off.
  slope      a pressure on an inclined face equals the traction vector -P n there, to
             round-off (time series, largest_series_difference, and the displacement field),
             orders 1 and 2.
  axisymmetric  the axisymmetric thick cylinder: a pressure on the bore equals the traction
             (P, 0) to round-off, and its resultant is P 2 pi a H (the ring factor).
  table      -bc_inner_pressure_table: each step's displacement field and force are the
             factor of the table times those of the step load (elastic: linear).
  floating   a square under pressure on all sides, held by two physical points only (one
             inside the mesh): uniform compression u = eps x, eps = -P (1 + nu)(1 - 2 nu)/E,
             exactly (linear fields); the points' reactions vanish (a balanced load). Order 1,
             order 2 on 1 and 2 ranks; a cube held by three points (the 3D recipe of
             docs/scenes.md), order 1; the cube held by a physical curve inside it and two
             points, order 1 (1 rank) and 2 (2 ranks).
"""

import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402  (runner, time-series reader, run-vs-run comparison)

E, NU, P = 1e8, 0.3, 1e5


def scene(name):
    return os.path.join(HERE, name)


def run(case, opts, args, ranks=1):
    out = common.output_dir(f"loads_{case}")
    common.run(scene(opts), out, args, ranks=ranks)
    return out


def fields(out, index=-1):
    t, x, f = common.vertex_fields(out, index)
    return x, np.asarray(f["displacement"])


def cylinder(chk):
    a, b = 1.0, 2.0

    def exact(r):
        return (1 + NU) * P * a**2 / (E * (b**2 - a**2)) * ((1 - 2 * NU) * r + b**2 / r)

    # Measured (triangles, n = 4 cells across the wall at factor 1): order 1 8.9e-2, 2.78e-2,
    # 8.1e-3 at factors 1, 0.5, 0.25 (rates 1.68, 1.77: nearing 2); order 2 6.7e-3, 1.58e-3,
    # 3.8e-4 (rates 2.09, 2.05: the straight-sided arc, a chord O(h^2) off the circle, keeps
    # P2 at the rate 2 of the geometry, 18 times below P1 on the same mesh). Bounds: these
    # with a margin; order 1 on its two finer meshes (the coarsest is not yet asymptotic).
    factors = {1: (0.5, 0.25), 2: (1.0, 0.5)}
    bounds = {1: (3.5e-2, 1e-2), 2: (8e-3, 2e-3)}
    min_rate = {1: 1.7, 2: 1.9}
    errs = {}
    for order in (1, 2):
        errs[order] = []
        for factor in factors[order]:
            out = run(f"cylinder_o{order}_{factor:g}", "cylinder.opts",
                      ["-displacement_order", order, "-mesh_size_factor", factor])
            x, u = fields(out)
            r = np.hypot(x[:, 0], x[:, 1])
            ur = (u[:, 0] * x[:, 0] + u[:, 1] * x[:, 1]) / r
            errs[order].append(np.max(np.abs(ur - exact(r))) / exact(a))
            ts = common.read_timeseries(out)
            for c in ("Fx", "Fy"):
                chk.check(f"order {order}, factor {factor:g}: |inner.{c} - P a| / (P a)",
                          abs(ts[f"inner.{c}"][-1] - P * a) / (P * a), 1e-9)
        e = errs[order]
        rate = np.log2(e[0] / e[1])
        print(f"  order {order}: max |u_r error| / u_r(a) = {e[0]:.3e} (factor "
              f"{factors[order][0]:g}), {e[1]:.3e} (factor {factors[order][1]:g}); rate {rate:.2f}")
        for k in (0, 1):
            chk.check(f"order {order}, factor {factors[order][k]:g}: max |u_r error| / u_r(a)",
                      e[k], bounds[order][k])
        chk.check(f"order {order}: observed rate (>= {min_rate[order]})", -rate, -min_rate[order])
    # the same mesh (factor 0.5): P2 is far closer
    chk.check("factor 0.5: order 2 error / order 1 error (< 0.1)", errs[2][1] / errs[1][0], 0.1)


def sphere(chk):
    a, b = 1.0, 2.0

    def exact(r):
        return P * a**3 / (E * (b**3 - a**3)) * ((1 - 2 * NU) * r + (1 + NU) * b**3 / (2 * r**2))

    # Measured (tetrahedra, 197 vertices at factor 1, 443 at 0.7), largest vertex error of
    # u_r / u_r(a): order 1 0.172, 0.113 (0.072 at factor 0.5); order 2 0.050, 0.027: a coarse
    # mesh, the largest errors on the faceted inner surface. Bounds: these with a margin;
    # rates over the factor 1/0.7 (order 1 1.2, order 2 1.7: not yet asymptotic).
    factors = (1.0, 0.7)
    bounds = {1: (0.2, 0.13), 2: (0.06, 0.032)}
    min_rate = {1: 1.0, 2: 1.5}
    errs = {}
    for order in (1, 2):
        errs[order] = []
        for factor in factors:
            out = run(f"sphere_o{order}_{factor:g}", "sphere.opts",
                      ["-displacement_order", order, "-mesh_size_factor", factor])
            x, u = fields(out)
            r = np.linalg.norm(x, axis=1)
            ur = np.sum(u * x, axis=1) / r
            errs[order].append(np.max(np.abs(ur - exact(r))) / exact(a))
            chk.check(f"order {order}, factor {factor:g}: max |u_r error| / u_r(a)",
                      errs[order][-1], bounds[order][len(errs[order]) - 1])
            # the polygonal quarter disc the mesh's inner surface ends on at x = 0
            on = (np.abs(x[:, 0]) < 1e-9) & (np.abs(r - a) < 1e-6 * a)
            yz = x[on][:, 1:3]
            yz = yz[np.argsort(np.arctan2(yz[:, 1], yz[:, 0]))]
            area = 0.5 * np.sum(yz[:-1, 0] * yz[1:, 1] - yz[1:, 0] * yz[:-1, 1])
            ts = common.read_timeseries(out)
            chk.check(f"order {order}, factor {factor:g}: |inner.Fx - P A| / (P A), "
                      f"A = {area:.6f} m2 (pi/4 = 0.785398)",
                      abs(ts["inner.Fx"][-1] - P * area) / (P * area), 1e-9)
        rate = np.log(errs[order][0] / errs[order][1]) / np.log(factors[0] / factors[1])
        chk.check(f"order {order}: observed rate (>= {min_rate[order]})", -rate, -min_rate[order])
    chk.check("factor 0.7: order 2 error / order 1 error (< 0.3)", errs[2][1] / errs[1][1], 0.3)


def slope(chk):
    n = np.array([2.0, 1.0]) / np.sqrt(5.0)
    t = -P * n
    for order in (1, 2):
        base = ["-displacement_order", order]
        a = run(f"slope_pressure_o{order}", "slope.opts", base + ["-bc_slope_pressure", P])
        b = run(f"slope_traction_o{order}", "slope.opts",
                base + ["-bc_slope_traction", f"{t[0]:.17g},{t[1]:.17g}"])
        ta, tb = common.read_timeseries(a), common.read_timeseries(b)
        worst, where = common.largest_series_difference(ta, tb)
        chk.check(f"order {order}: pressure vs traction -P n, time series ({where})", worst, 1e-10)
        _, ua = fields(a)
        _, ub = fields(b)
        chk.check(f"order {order}: pressure vs traction -P n, displacements",
                  np.max(np.abs(ua - ub)) / np.max(np.abs(ub)), 1e-10)
        chk.check(f"order {order}: slope.Fx = -P n_x L (L = sqrt(1.25))",
                  abs(ta["slope.Fx"][-1] - t[0] * np.sqrt(1.25)) / P, 1e-10)


def axisymmetric(chk):
    a, h = 1.0, 0.5
    pressure = run("axisym_pressure", "cylinder_axisym.opts", ["-bc_inner_pressure", P])
    traction = run("axisym_traction", "cylinder_axisym.opts", ["-bc_inner_traction", f"{P:g},0"])
    ta, tb = common.read_timeseries(pressure), common.read_timeseries(traction)
    worst, where = common.largest_series_difference(ta, tb)
    chk.check(f"pressure vs traction (P, 0) on the bore, time series ({where})", worst, 1e-10)
    _, ua = fields(pressure)
    _, ub = fields(traction)
    chk.check("pressure vs traction (P, 0) on the bore, displacements",
              np.max(np.abs(ua - ub)) / np.max(np.abs(ub)), 1e-10)
    chk.check("|inner.Fx - P 2 pi a H| / (P 2 pi a H) (the ring factor 2 pi r)",
              abs(ta["inner.Fx"][-1] - P * 2 * np.pi * a * h) / (P * 2 * np.pi * a * h), 1e-10)


def table(chk):
    path = os.path.join(common.output_dir("loads_table_file"), "pressure.csv")
    times, factors = [0.0, 1.0, 2.0, 3.0], [0.0, 0.5, -0.25, 2.0]
    with open(path, "w") as f:
        f.write("time,factor\n" + "".join(f"{t:g},{v:g}\n" for t, v in zip(times, factors)))
    ref = run("table_step", "cylinder.opts", [])
    _, u1 = fields(ref)
    f1 = common.read_timeseries(ref)["inner.Fx"][-1]
    out = run("table", "cylinder.opts",
              ["-bc_inner_pressure_table", path, "-ts_max_steps", 3, "-ts_dt", 1,
               "-ts_max_time", 3])
    ts = common.read_timeseries(out)
    for i, step_time in enumerate((1.0, 2.0, 3.0)):
        k = times.index(step_time)
        _, u = fields(out, i + 1)  # fields: output 0 is the initial state
        chk.check(f"t = {step_time:g} s (factor {factors[k]:g}): displacement / step load's",
                  np.max(np.abs(u - factors[k] * u1)) / np.max(np.abs(u1)), 1e-10)
        chk.check(f"t = {step_time:g} s: inner.Fx / step load's",
                  abs(ts["inner.Fx"][i] - factors[k] * f1) / abs(f1), 1e-10)


def floating(chk):
    eps = -P * (1 + NU) * (1 - 2 * NU) / E
    for order, ranks in ((1, 1), (2, 1), (2, 2)):
        out = run(f"floating_o{order}_np{ranks}", "floating.opts",
                  ["-displacement_order", order], ranks=ranks)
        x, u = fields(out)
        err = np.max(np.abs(u[:, :2] - eps * x[:, :2])) / abs(eps)
        chk.check(f"order {order}, {ranks} rank(s): |u - eps x| / |eps| (1 m)", err, 1e-9)
        ts = common.read_timeseries(out)
        worst = max(abs(ts[c][-1]) for c in ("centre.Fx", "centre.Fy", "east.Fy"))
        chk.check(f"order {order}, {ranks} rank(s): points' reactions / (P 2 m)",
                  worst / (2 * P), 1e-9)
    # 3D: a cube held by three points (all-round pressure: eps = -P (1 - 2 nu)/E)
    eps = -P * (1 - 2 * NU) / E
    out = run("floating_cube", "floating_cube.opts", [])
    x, u = fields(out)
    chk.check("cube, order 1: |u - eps x| / |eps| (1 m)",
              np.max(np.abs(u - eps * x)) / abs(eps), 1e-9)
    ts = common.read_timeseries(out)
    worst = max(abs(ts[c][-1]) for c in ("centre.Fx", "centre.Fy", "centre.Fz", "px.Fy",
                                          "px.Fz", "py.Fz"))
    chk.check("cube: points' reactions / (P 4 m2)", worst / (4 * P), 1e-9)
    # 3D: the cube held by a line (a physical curve inside it) and two points; order 2 on 2
    # ranks holds the line's edge nodes too
    for order, ranks in ((1, 1), (2, 2)):
        out = run(f"floating_cube_line_o{order}", "floating_cube_line.opts",
                  ["-displacement_order", order], ranks=ranks)
        x, u = fields(out)
        chk.check(f"cube held by a line, order {order}, {ranks} rank(s): |u - eps x| / |eps|",
                  np.max(np.abs(u - eps * x)) / abs(eps), 1e-9)
        ts = common.read_timeseries(out)
        worst = max(abs(ts[c][-1]) for c in ("axis.Fy", "axis.Fz", "centre.Fx", "py.Fz"))
        chk.check(f"cube held by a line, order {order}: reactions / (P 4 m2)",
                  worst / (4 * P), 1e-9)


CASES = {"cylinder": cylinder, "sphere": sphere, "slope": slope, "axisymmetric": axisymmetric,
         "table": table, "floating": floating}

if __name__ == "__main__":
    if "--list" in sys.argv:
        print("\n".join(CASES))
        sys.exit(0)
    name = sys.argv[sys.argv.index("--case") + 1]
    checks = common.Checks(f"loads: {name}")
    CASES[name](checks)
    checks.finish()
