"""Stresses an engineer can read at a boundary: the recovered (continuous) stresses of
fields.h5 (recovered_effective_stress, recovered_total_stress: patch recovery from the
integration points, docs/outputs.md) against the closed form of a dry elastic column under
its own weight (tests/outputs/self_weight_column.opts: sigma_yy = -rho g (H - y),
sigma_xx = sigma_zz = nu / (1 - nu) sigma_yy).

  * order 2 (the stress is linear and exact at the integration points): the recovered stress
    at every node, the base included, equals the closed form to 1e-9 rho g H; the cell values
    of the bottom row are off by the half cell (h / 2H = 2.5 % of rho g H), which is why the
    recovered field exists;
  * order 1 (the stress is constant in each cell): exact at the vertices between the base
    and the top (the fit through the two cells' points of a 1D column); at the base, whose
    patch is one row of cells, no worse than the bottom cells (equal: 2.5 %);
  * 2 ranks write the same recovered fields as 1 rank (the patches of vertices on the
    partition boundary are summed over the ranks) to 1e-9 rho g H.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
import common  # noqa: E402
import fields_reader  # noqa: E402

RHO, G, H, NU = 2000.0, 10.0, 1.0, 0.25
SCENE = os.path.join(HERE, "self_weight_column.opts")


def run(order, ranks):
    out = common.output_dir(f"recovered_stress_o{order}_np{ranks}")
    common.run(SCENE, out, ["-displacement_order", order], ranks=ranks)
    return fields_reader.read_fields(out)


def exact(y):
    syy = -RHO * G * (H - y)
    return syy * NU / (1 - NU), syy


def main():
    chk = common.Checks("recovered stresses of a column under its own weight")
    scale = RHO * G * H
    results = {}
    for order in (2, 1):
        f = run(order, 1)
        results[order] = f
        xy = f.coordinates
        s = f.fields[-1]["recovered_total_stress"]
        sxx, syy = exact(xy[:, 1])
        err = np.maximum(np.abs(s[:, 0, 0] - sxx), np.abs(s[:, 1, 1] - syy)) / scale
        base = np.abs(xy[:, 1]) < 1e-9
        inner = f.vertices() & (xy[:, 1] > 1e-9) & (xy[:, 1] < H - 1e-9)
        # The bottom row of cells: their values against the closed form at the base.
        corners = f.connectivity[:, :4]
        bottom = np.any(np.abs(xy[corners, 1]) < 1e-9, axis=1)
        cell = f.cell_fields[-1]["total_stress"][bottom, 1, 1]
        cell_err = float(np.max(np.abs(cell - exact(0.0)[1]))) / scale
        if order == 2:
            chk.check("order 2: recovered stress at every node, |error| / rho g H",
                      float(np.max(err)), 1e-9)
            chk.check("order 2: bottom cells' values at the base are off by h/2H (> 1 %)",
                      cell_err, 0.0, ok=cell_err > 0.01)
        else:
            chk.check("order 1: recovered stress at interior vertices, |error| / rho g H",
                      float(np.max(err[inner])), 1e-9)
            chk.check("order 1: recovered stress at the base no worse than the bottom cells",
                      float(np.max(err[base])), cell_err * (1 + 1e-9))
        print(f"  order {order}: recovered at the base {np.max(err[base]):.2e}, bottom cells "
              f"{cell_err:.2e} (of rho g H)")
    f2 = run(2, 2)
    a = results[2].fields[-1]["recovered_effective_stress"]
    b = f2.fields[-1]["recovered_effective_stress"]
    same = a.shape == b.shape and np.allclose(results[2].coordinates, f2.coordinates, atol=1e-12)
    chk.check("2 ranks = 1 rank (recovered stress, same node order)",
              float(np.max(np.abs(a - b))) / scale if same else np.inf, 1e-9)
    chk.finish()


if __name__ == "__main__":
    main()
