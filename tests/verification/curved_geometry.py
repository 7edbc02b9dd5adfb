"""Curved cells (-mesh_geometry_order 2, docs/elements.md "Curved geometry") against closed
forms, straight-sided cells beside them on the same meshes, displacement order 2.

1. Weight of a quarter annulus (a = 1, b = 2 m, plane strain, rho_s = 2000 kg/m3 under
   g = 9.81): the reaction on y = 0 is rho_s g pi (b^2 - a^2) / 4 exactly when the cells fill
   the annulus. Straight-sided cells lose the segments between chord and arc (-0.64 % on the
   8 x 4 mesh); curved cells must be within 1e-5, and 100 times closer than straight ones.
2. Lame's thick cylinder under internal pressure P (plane strain):
       u_r(r) = (1 + nu) P a^2 / (E (b^2 - a^2)) [(1 - 2 nu) r + b^2 / r],
   u_r at r = a and r = b (vertices at 45 degrees): on the 8 x 4 mesh h, curved cells must be
   at least 20 times closer than straight-sided ones (measured 26: the polygon's error is
   second order); on h/2 within 3e-5 of u_r, at a rate of at least 2.8 from h (measured 3.2;
   straight-sided cells: 2.0, by hand).
3. Lame on curved triangles (P2 on the quarter annulus cut into triangles,
   meshes/thick_cylinder_plane_tri.geo; PETSc keeps a simplex's nodes on the cell): on h/2
   within 1.2e-4 of u_r (measured 9.0e-5), at a rate of at least 2.8 from h (measured 3.1;
   straight-sided triangles: 2.0, by hand).
4. The same cylinder cut by a stiff sticking interface on r = 1.5 m (curved interface faces,
   a frame at every integration point): within 3e-5 of Lame on the finer mesh, and a run on
   2 ranks equals the run on 1 (every time-series column to 1e-9 of its kind's scale).
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import common  # noqa: E402

E, NU, P, A, B, RHO, G = 1e8, 0.3, 1e5, 1.0, 2.0, 2000.0, 9.81


def lame(r):
    return (1 + NU) * P * A**2 / (E * (B**2 - A**2)) * ((1 - 2 * NU) * r + B**2 / r)


def radial(ts, probe):
    return float(np.hypot(ts[f"{probe}.ux"][-1], ts[f"{probe}.uy"][-1]))


def lame_errors(scene, name, factor, order, ranks=1):
    out = common.output_dir(f"curved_{name}_g{order}_{factor:g}")
    common.run(common.scene_path(scene), out,
               ["-mesh_size_factor", factor, "-mesh_geometry_order", order], ranks=ranks)
    ts = common.read_timeseries(out)
    return max(abs(radial(ts, "in") / lame(A) - 1), abs(radial(ts, "out") / lame(B) - 1)), ts


chk = common.Checks("curved cells (-mesh_geometry_order 2) against closed forms")

# 1. The weight of the annulus.
weight = RHO * G * np.pi * (B**2 - A**2) / 4
gravity = ["-gravity", G, "-bc_inner_pressure", 0, "-bc_sym_y_ux", 0]
errors = {}
for order in (1, 2):
    out = common.output_dir(f"curved_weight_g{order}")
    common.run(common.scene_path("curved_cylinder.opts"), out,
               gravity + ["-mesh_geometry_order", order])
    errors[order] = abs(common.read_timeseries(out)["sym_y.Fy"][-1] / weight - 1)
print(f"  weight: straight {errors[1]:.3e}, curved {errors[2]:.3e} of rho g pi (b^2 - a^2) / 4")
chk.check("weight, curved cells: |F_y / (rho g A) - 1|", errors[2], 1e-5)
chk.check("weight: curved error x 100 <= straight error", 100 * errors[2], errors[1])

# 2. Lame, straight against curved on h, curved on h/2.
straight, _ = lame_errors("curved_cylinder.opts", "lame", 1.0, 1)
coarse, _ = lame_errors("curved_cylinder.opts", "lame", 1.0, 2)
fine, _ = lame_errors("curved_cylinder.opts", "lame", 0.5, 2)
rate = np.log2(coarse / fine)
print(f"  Lame: h straight {straight:.3e}, curved {coarse:.3e}; h/2 curved {fine:.3e} of u_r "
      f"(rate {rate:.2f})")
chk.check("Lame, h: curved error x 20 <= straight error", 20 * coarse, straight)
chk.check("Lame, h/2, curved: max |u_r / u_r,exact - 1| at r = a, b", fine, 3e-5)
chk.check("Lame, curved: rate from h to h/2 (>= 2.8)", -rate, -2.8)

# 3. Lame on curved triangles, h and h/2.
TRI = ["-mesh", "meshes/thick_cylinder_plane_tri.geo"]


def lame_tri_errors(factor):
    out = common.output_dir(f"curved_lame_tri_{factor:g}")
    common.run(common.scene_path("curved_cylinder.opts"), out,
               TRI + ["-mesh_size_factor", factor, "-mesh_geometry_order", 2])
    ts = common.read_timeseries(out)
    return max(abs(radial(ts, "in") / lame(A) - 1), abs(radial(ts, "out") / lame(B) - 1))


tri_coarse, tri_fine = lame_tri_errors(1.0), lame_tri_errors(0.5)
tri_rate = np.log2(tri_coarse / tri_fine)
print(f"  Lame, curved triangles: h {tri_coarse:.3e}, h/2 {tri_fine:.3e} of u_r (rate {tri_rate:.2f})")
chk.check("Lame, h/2, curved triangles: max |u_r / u_r,exact - 1| at r = a, b", tri_fine, 1.2e-4)
chk.check("Lame, curved triangles: rate from h to h/2 (>= 2.8)", -tri_rate, -2.8)

# 4. The curved interface, 1 and 2 ranks.
one, ts1 = lame_errors("curved_rings.opts", "rings", 0.5, 2)
two, ts2 = lame_errors("curved_rings.opts", "rings_np2", 0.5, 2, ranks=2)
print(f"  two rings, curved interface, factor 0.5: {one:.3e} of u_r (2 ranks: {two:.3e})")
chk.check("two rings, curved interface: max |u_r / u_r,exact - 1|", one, 3e-5)
difference, where = common.largest_series_difference(ts1, ts2)
chk.check(f"two rings: 2 ranks against 1 (largest: {where})", difference, 1e-9)
chk.finish()
