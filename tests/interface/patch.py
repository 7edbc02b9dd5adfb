"""Patch test of the interface: uniform compression through a flat interface.

A block on a base of the same elastic material (E = 1e8 Pa, nu = 0.3), base bottom fixed,
uniform pressure q = 1e5 Pa on the block top, sides free: the stress is uniaxial and uniform,
both bodies expand sideways alike, so the effective contact pressure must be q at every
integration point (relative 1e-8), with no shear. Both integration rules, and penalties from
soft to very stiff: K_N h / E = 1e-2, 1, 1e2, 1e4 (h = 0.125 m, the element size), the range
where Gauss integration of stiff interfaces is known to oscillate on distorted states.
In 3D (patch_3d.opts) the element size is 0.25 m.
Reads the per-integration-point interface output (tests/support/interface_reader.py).
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

Q, E = 1e5, 1e8


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dim", type=int, choices=(2, 3), default=2)
    ap.add_argument("--ranks", type=int, default=1)
    args = ap.parse_args()
    scene = os.path.join(HERE, f"patch_{args.dim}d.opts")
    chk = common.Checks(f"interface patch test {args.dim}D, {args.ranks} rank(s)")
    worst = 0.0
    for rule in ("gauss", "nodal"):
        for ratio in (1e-2, 1.0, 1e2, 1e4):
            kn = ratio * E / (0.125 if args.dim == 2 else 0.25)
            out = common.output_dir(f"patch_{args.dim}d_{rule}_{ratio:g}_np{args.ranks}")
            extra = ["-interface_contact_integration", rule, "-interface_contact_KN", kn,
                     "-interface_contact_KT", kn, "-region_base_nu", 0.3, "-region_block_nu", 0.3,
                     "-output_fields_every", 1]
            common.run(scene, out, extra, ranks=args.ranks)
            data = read_interfaces(out)
            p = data.point_fields[-1]["contact_pressure_effective"]
            tau = np.abs(data.point_fields[-1]["traction"])
            err = np.max(np.abs(p - Q)) / Q
            shear = np.max(tau[:, : args.dim - 1]) / Q
            worst = max(worst, err)
            chk.check(f"{rule:5s} K_N h/E = {ratio:<6g}: max |p'_N - q| / q over {len(p)} points", err, 1e-8)
            chk.check(f"{rule:5s} K_N h/E = {ratio:<6g}: max |tau| / q", shear, 1e-8)
    print(f"  worst patch-test error: {worst:.2e}")
    chk.finish()


if __name__ == "__main__":
    main()
