"""Integration rule of stiff interfaces at order 2 (docs/elements.md, "Quadratic interfaces").

    quad_rule.py [--measure]

Stiff penalties make Gauss-integrated interface tractions oscillate from one integration point
to the next (Day and Potts 1994); the linear elements use the nodal rule against it. This test
runs a block on a base (tests/interface/patch_2d.opts, 8 x 4 cells per body, h = 0.125 m;
patch_3d.opts, 4 x 4 x 2, h = 0.25 m) at K_N h / E = K_T h / E = 1e3, at -displacement_order 2:

uniform   the patch test (uniform pressure q = 1e5 Pa on the block top, rollers): p'_N = q at
          every point to 1e-8 relative, for the rule that is recommended (nodal: Simpson on the
          3 nodes of each quadratic face) and for Gauss;
bonded    a non-uniform state: the base's bottom fixed in both directions and the block 10 x
          stiffer than the base (E = 1e9 against 1e8 Pa, nu = 0.3 both), so the two bodies
          expand sideways differently and the contact pressure varies along the interface,
          with a corner singularity at the free ends. The normal traction is sorted by x and
          its roughness measured by the sign changes of its slope (in 3D along the row of
          points nearest the symmetry plane y = 0): the physical profile falls towards the
          free end and rises at the corner (one change), a zig-zag adds two per oscillation.
          The recommended rule (nodal on segments and quadrilaterals, Gauss on triangles) must
          have one. Measured (--measure, docs/elements.md): Gauss on P2 segments and Q2
          quadrilaterals zig-zags over the last two cells from K_N h / E = 1e3 on.
--measure prints both rules at orders 1 and 2 (the table of docs/elements.md) without checks.
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
import common  # noqa: E402
from interface_reader import read_interfaces  # noqa: E402

Q, E, H = 1e5, 1e8, 0.125
RATIO = 1e3


def run(case, rule, order, ratio=RATIO, dim=2, mesh=None):
    """p'_N along the interface sorted by x; in 3D along the row of points nearest to the
    symmetry plane y = 0."""
    h = H if dim == 2 else 0.25
    kn = ratio * E / h
    name = f"{dim}d_{os.path.splitext(os.path.basename(mesh))[0]}" if mesh else f"{dim}d"
    out = common.output_dir(f"quad_rule_{name}_{case}_{rule}_order{order}_{ratio:g}")
    extra = ["-interface_contact_integration", rule, "-interface_contact_KN", kn,
             "-interface_contact_KT", kn, "-region_base_nu", 0.3, "-region_block_nu", 0.3,
             "-output_fields_every", 1, "-displacement_order", order]
    if case == "bonded":
        extra += ["-bc_bottom_ux", 0, "-region_block_E", 10 * E, "-interface_contact_friction", 10]
        if dim == 3:
            extra += ["-bc_bottom_uy", 0]
    if mesh:
        extra += ["-mesh", mesh]
    common.run(os.path.join(HERE, f"patch_{dim}d.opts"), out, extra)
    data = read_interfaces(out)
    x = data.point_coordinates[:, 0]
    p = data.point_fields[-1]["contact_pressure_effective"]
    if dim == 3:
        y = data.point_coordinates[:, 1]
        row = y < y.min() + 1e-9
        x, p = x[row], p[row]
    order_x = np.argsort(x, kind="stable")
    return x[order_x], p[order_x]


def slope_changes(x, p):
    """Sign changes of the slope of p along x (points at one x, where two cells meet at a node,
    count once). The physical profile has one: p'_N falls towards the free end and rises
    again at the corner (the corner singularity of the stiffer block); a zig-zag adds two per
    oscillation."""
    keep = np.r_[True, np.diff(x) > 1e-12]
    d = np.diff(p[keep])
    d = d[np.abs(d) > 1e-9 * Q]
    return int(np.sum(np.sign(d[1:]) != np.sign(d[:-1])))


def measure():
    print("p'_N along the interface, block 10 x stiffer than the base, base bottom fixed "
          "(sign changes of its slope: 1 is the physical profile)")
    cases = [(2, None, ratio) for ratio in (1.0, 1e3, 1e4)] + [(3, None, 1e3)]
    for dim, mesh, ratio in cases:
        print(f"{dim}D{', ' + mesh if mesh else ''}:")
        for order in (1, 2):
            for rule in ("gauss", "nodal"):
                x, p = run("bonded", rule, order, ratio, dim, mesh)
                xu, pu = run("uniform", rule, order, ratio, dim, mesh)
                print(f"  K_N h/E = {ratio:g}, order {order} {rule:5s}: {len(p):3d} points, "
                      f"p'_N / q in [{p.min() / Q:.4f}, {p.max() / Q:.4f}], "
                      f"{slope_changes(x, p)} slope sign changes; uniform: max |p'_N - q| / q "
                      f"= {np.max(np.abs(pu - Q)) / Q:.1e}")
                print("      " + " ".join(f"{a:.3f}:{b / Q:.3f}" for a, b in zip(x, p)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--measure", action="store_true")
    args = ap.parse_args()
    if args.measure:
        return measure()
    chk = common.Checks(f"stiff quadratic interface (K_N h / E = {RATIO:g}), order 2")
    for dim, rules in ((2, ("nodal", "gauss")), (3, ("nodal", "gauss"))):
        for rule in rules:
            x, p = run("uniform", rule, 2, RATIO, dim)
            chk.check(f"{dim}D uniform, {rule}: max |p'_N - q| / q over {len(p)} points (a row in 3D)",
                      np.max(np.abs(p - Q)) / Q, 1e-8)
    # The recommended rules under the non-uniform state: nodal on segments and quadrilaterals,
    # Gauss on triangles (which have no nodal rule at order 2).
    for dim, rule, mesh in ((2, "nodal", None), (3, "nodal", None),
                            (3, "gauss", "meshes/block_on_base_3d_tet.geo")):
        x, p = run("bonded", rule, 2, RATIO, dim, mesh)
        print(f"  {dim}D bonded, {rule}{', ' + mesh if mesh else ''}: x:p'_N/q "
              + " ".join(f"{a:.3f}:{b / Q:.3f}" for a, b in zip(x, p)))
        chk.check(f"{dim}D bonded, {rule}{' (tetrahedra)' if mesh else ''}: sign changes of the "
                  f"slope of p'_N (1: no zig-zag)", slope_changes(x, p), 1)
    chk.finish()


if __name__ == "__main__":
    main()
