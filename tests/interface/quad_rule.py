"""Integration rule of stiff interfaces at order 2 (docs/elements.md, "Quadratic interfaces").

    quad_rule.py [--measure]

Stiff penalties make Gauss-integrated interface tractions oscillate from one integration point
to the next (Day and Potts 1994); the linear elements use the nodal rule against it. This test
runs a block on a base (tests/interface/patch_2d.opts, 8 x 4 cells per body, h = 0.125 m) at
K_N h / E = K_T h / E = 1e3, at -displacement_order 2:

uniform   the patch test (uniform pressure q = 1e5 Pa on the block top, rollers): p'_N = q at
          every point to 1e-8 relative, for the rule that is recommended (nodal: Simpson on the
          3 nodes of each quadratic face) and for Gauss;
bonded    a non-uniform state: the base's bottom fixed in both directions and the block 10 x
          stiffer than the base (E = 1e9 against 1e8 Pa, nu = 0.3 both), so the two bodies
          expand sideways differently and the contact pressure varies along the interface,
          with a corner singularity at the free ends. The normal traction is sorted by x and
          its roughness measured: the largest second difference |p_(i-1) - 2 p_i + p_(i+1)| / q
          among successive points, and the number of sign changes of the first difference
          (a zig-zag has one at every point). The recommended rule must not oscillate: at most
          2 sign changes (the profile goes down and up once near each end), away from the two
          end cells.
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


def run(case, rule, order, ratio=RATIO):
    kn = ratio * E / H
    out = common.output_dir(f"quad_rule_{case}_{rule}_order{order}_{ratio:g}")
    extra = ["-interface_contact_integration", rule, "-interface_contact_KN", kn,
             "-interface_contact_KT", kn, "-region_base_nu", 0.3, "-region_block_nu", 0.3,
             "-output_fields_every", 1, "-displacement_order", order]
    if case == "bonded":
        extra += ["-bc_bottom_ux", 0, "-region_block_E", 10 * E, "-interface_contact_friction", 10]
    common.run(os.path.join(HERE, "patch_2d.opts"), out, extra)
    data = read_interfaces(out)
    x = data.point_coordinates[:, 0]
    p = data.point_fields[-1]["contact_pressure_effective"]
    order_x = np.argsort(x, kind="stable")
    return x[order_x], p[order_x]


def roughness(x, p, skip=0.125 * 1.0001):
    """Largest second difference / q and sign changes of the first difference, away from the
    end cells (x within `skip` of 0 or 1)."""
    keep = (x > skip) & (x < 1.0 - skip)
    x, p = x[keep], p[keep]
    d = np.diff(p)
    d = d[np.abs(d) > 1e-9 * Q]  # equal values (points at one x) are no change
    changes = int(np.sum(np.sign(d[1:]) != np.sign(d[:-1])))
    second = np.max(np.abs(p[:-2] - 2 * p[1:-1] + p[2:])) / Q if len(p) > 2 else 0.0
    return second, changes, len(p)


def measure():
    print(f"K_N h / E = {RATIO:g}: roughness of p'_N along the interface (block 10 x stiffer, "
          f"base bottom fixed), interior points")
    for order in (1, 2):
        for rule in ("gauss", "nodal"):
            x, p = run("bonded", rule, order)
            second, changes, n = roughness(x, p)
            print(f"  order {order} {rule:5s}: {n:3d} points, p'_N / q in [{p.min() / Q:.4f}, "
                  f"{p.max() / Q:.4f}], max second difference {second:.3e} q, "
                  f"{changes} sign changes of the slope")
            xu, pu = run("uniform", rule, order)
            print(f"      uniform: max |p'_N - q| / q = {np.max(np.abs(pu - Q)) / Q:.2e}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--measure", action="store_true")
    args = ap.parse_args()
    if args.measure:
        return measure()
    chk = common.Checks(f"stiff quadratic interface (K_N h / E = {RATIO:g}), order 2")
    for rule in ("nodal", "gauss"):
        x, p = run("uniform", rule, 2)
        chk.check(f"uniform, {rule}: max |p'_N - q| / q over {len(p)} points",
                  np.max(np.abs(p - Q)) / Q, 1e-8)
    x, p = run("bonded", "nodal", 2)
    second, changes, n = roughness(x, p)
    print(f"  bonded, nodal: {n} interior points, max second difference {second:.3e} q")
    chk.check("bonded, nodal: sign changes of the slope of p'_N (no zig-zag)", changes, 2)
    chk.finish()


if __name__ == "__main__":
    main()
