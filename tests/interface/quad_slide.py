"""Stick and slip of a quadratic interface (-displacement_order 2), 2D and 3D.

    quad_slide.py --dim 2|3 [--mesh MESH]

A near-rigid block on a near-rigid base (tests/interface/shear_2d.opts, shear_3d.opts:
E = 1e20 Pa, K_N = K_T = 1e10 Pa/m, mu = 0.5): the block top is pushed down by 1e-5 m
(p'_N = K_N 1e-5 = 1e5 Pa) and moved sideways by s in one step (in 3D along (1, 1)/sqrt 2).
The bodies take p H / E ~ 1e-15 m, so the gap is uniform: every integration point of every
quadratic cell must be in the same state,
  stick  s = 2e-6 m (below the onset mu p'_N / K_T = 5e-6 m): |tau| = K_T s = 2e4 Pa;
  slip   s = 2e-5 m: |tau| = mu p'_N = 5e4 Pa, tau along the slip;
with p'_N = 1e5 Pa, each to 1e-8 relative, for both integration rules (Gauss only on
triangular faces: --mesh meshes/block_on_base_3d_tet.geo).
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

K, MU, CLOSURE = 1e10, 0.5, 1e-5
PN = K * CLOSURE
STATES = {"stick": 1, "slip": 2}  # physics::ContactState


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dim", type=int, choices=(2, 3), default=2)
    ap.add_argument("--mesh", default=None)
    args = ap.parse_args()
    mesh = os.path.splitext(os.path.basename(args.mesh))[0] if args.mesh else "default"
    chk = common.Checks(f"stick and slip of a quadratic interface, {args.dim}D, {mesh} mesh")
    triangles = args.mesh and "tet" in args.mesh
    for rule in ("gauss",) if triangles else ("gauss", "nodal"):
        for state, s in (("stick", 2e-6), ("slip", 2e-5)):
            out = common.output_dir(f"quad_slide_{args.dim}d_{mesh}_{rule}_{state}")
            along = np.array([1.0, 0.0, 0.0]) if args.dim == 2 else np.array([1.0, 1.0, 0.0]) / np.sqrt(2)
            extra = ["-displacement_order", 2, "-interface_contact_integration", rule,
                     "-ts_max_steps", 1, "-output_fields_every", 1, "-bc_top_ux", s * along[0]]
            if args.dim == 3:
                extra += ["-bc_top_uy", s * along[1]]
            if args.mesh:
                extra += ["-mesh", args.mesh]
            common.run(os.path.join(HERE, f"shear_{args.dim}d.opts"), out, extra)
            f = read_interfaces(out).point_fields[-1]
            pn = f["contact_pressure_effective"]
            tau = f["shear_traction"][:, : args.dim]
            expected = K * s if state == "stick" else MU * PN
            label = f"{rule:5s} {state:5s}"
            chk.check(f"{label}: points not in the {state} state", int(np.sum(f["state"] != STATES[state])), 0)
            chk.check(f"{label}: max |p'_N - K_N 1e-5| / p'_N over {len(pn)} points",
                      np.max(np.abs(pn - PN)) / PN, 1e-8)
            err = np.max(np.linalg.norm(tau - expected * along[: args.dim], axis=1)) / expected
            chk.check(f"{label}: max |tau - {'K_T s' if state == 'stick' else 'mu p_N'} along the slip| / that",
                      err, 1e-8)
    chk.finish()


if __name__ == "__main__":
    main()
