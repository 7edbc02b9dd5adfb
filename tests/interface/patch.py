"""Patch test of the interface: uniform compression through a flat interface.

A block on a base of the same elastic material (E = 1e8 Pa, nu = 0.3), base bottom fixed,
uniform pressure q = 1e5 Pa on the block top, sides free: the stress is uniaxial and uniform,
both bodies expand sideways alike, so the effective contact pressure must be q at every
integration point (relative 1e-8), with no shear. Both integration rules, and penalties from
soft to very stiff: K_N h / E = 1e-2, 1, 1e2, 1e4 (h = 0.125 m, the element size), the range
where Gauss integration of stiff interfaces is known to oscillate on distorted states.
In 3D (patch_3d.opts) the element size is 0.25 m. --order 2: quadratic bodies and interfaces
(-displacement_order 2; on tetrahedra Gauss only, triangular faces have no nodal rule there).
--axisymmetric: the 2D mesh as a solid cylinder (x = r, the left sides on the axis): the same
uniform state, and the interface force q pi R^2 (R = 1 m) checks the ring weights 2 pi r (at
order 2 also the lumped nodal weights of the 3-node segments). --ratios: a subset of K_N h / E.
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


def parts(args):
    """Patch test with the contact in two parts: each carries half of q A, exactly."""
    scene = os.path.join(HERE, "patch_2d.opts")
    out = common.output_dir(f"patch_parts_np{args.ranks}")
    common.run(scene, out, ["-mesh", "meshes/block_on_base_parts_2d.geo",
                            "-interface_contact_surfaces", "contact_left,contact_right"], ranks=args.ranks)
    ts = common.read_timeseries(out)
    chk = common.Checks(f"interface forces per part, {args.ranks} rank(s)")
    for part in ("contact_left", "contact_right"):
        chk.check(f"|{part}.Fy + q A / 2| / (q A / 2)", abs(ts[f"contact.{part}.Fy"][-1] + Q / 2) / (Q / 2), 1e-8)
    total = ts["contact.contact_left.Fy"][-1] + ts["contact.contact_right.Fy"][-1]
    chk.check("|sum of parts - total| / q A", abs(total - ts["contact.Fy"][-1]) / Q, 1e-12)
    chk.finish()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dim", type=int, choices=(2, 3), default=2)
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--mesh", default=None, help="another mesh of the same geometry (triangles, tetrahedra)")
    ap.add_argument("--axisymmetric", action="store_true",
                    help="2D mesh as an axisymmetric solid cylinder (x = r): interface force q pi R^2")
    ap.add_argument("--order", type=int, choices=(1, 2), default=1,
                    help="-displacement_order (2: quadratic bodies and interfaces)")
    ap.add_argument("--ratios", default="1e-2,1,1e2,1e4",
                    help="the values of K_N h / E, comma-separated (default: all four)")
    ap.add_argument("--parts", action="store_true",
                    help="the contact in two named parts: forces per part and their sum")
    args = ap.parse_args()
    if args.parts:
        return parts(args)
    scene = os.path.join(HERE, f"patch_{args.dim}d.opts")
    chk = common.Checks(f"interface patch test {args.dim}D{' axisymmetric' if args.axisymmetric else ''}"
                        f"{', order 2' if args.order == 2 else ''}, "
                        f"{args.mesh or 'default mesh'}, {args.ranks} rank(s)")
    worst = 0.0
    triangles = args.mesh and ("tri" in args.mesh or "tet" in args.mesh)
    # At order 2 a triangular face has no nodal rule (its vertices would weigh nothing).
    rules = ("gauss",) if args.order == 2 and triangles and args.dim == 3 else ("gauss", "nodal")
    for rule in rules:
        for ratio in (float(r) for r in args.ratios.split(",")):
            kn = ratio * E / (0.125 if args.dim == 2 else 0.25)
            # the mesh in the name: ctest runs the same case on other meshes in parallel
            mesh = os.path.splitext(os.path.basename(args.mesh))[0] if args.mesh else "default"
            order = f"_order{args.order}" if args.order > 1 else ""
            out = common.output_dir(f"patch_{args.dim}d{'_axi' if args.axisymmetric else ''}{order}_{mesh}_{rule}_{ratio:g}_np{args.ranks}")
            extra = ["-interface_contact_integration", rule, "-interface_contact_KN", kn,
                     "-interface_contact_KT", kn, "-region_base_nu", 0.3, "-region_block_nu", 0.3,
                     "-output_fields_every", 1]
            if args.mesh:
                extra += ["-mesh", args.mesh]
            if args.axisymmetric:
                extra += ["-axisymmetric"]  # the left sides (x = 0) are the axis: ux = 0 there
            if args.order > 1:
                extra += ["-displacement_order", args.order]
            common.run(scene, out, extra, ranks=args.ranks)
            data = read_interfaces(out)
            p = data.point_fields[-1]["contact_pressure_effective"]
            tau = np.abs(data.point_fields[-1]["traction"])
            err = np.max(np.abs(p - Q)) / Q
            shear = np.max(tau[:, : args.dim - 1]) / Q
            worst = max(worst, err)
            chk.check(f"{rule:5s} K_N h/E = {ratio:<6g}: max |p'_N - q| / q over {len(p)} points", err, 1e-8)
            chk.check(f"{rule:5s} K_N h/E = {ratio:<6g}: max |tau| / q", shear, 1e-8)
            if args.axisymmetric:
                fy = common.read_timeseries(out)["contact.Fy"][-1]
                chk.check(f"{rule:5s} K_N h/E = {ratio:<6g}: |F_y + q pi R^2| / (q pi R^2)",
                          abs(fy + Q * np.pi) / (Q * np.pi), 1e-8)
    print(f"  worst patch-test error: {worst:.2e}")
    chk.finish()


if __name__ == "__main__":
    main()
