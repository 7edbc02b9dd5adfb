#!/usr/bin/python3
"""A crack that ends inside the mesh is split without duplicating its tips (label "interface").

    buried_crack.py --dim 2 | 3

Runs tests/interface_mpi/buried_crack_<dim>d.opts (meshes/buried_crack_<dim>d.geo, an
embedded crack "crack" in one region "rock") on 1 rank twice: without the interface and with
`-interfaces crack` (side1 rock, K_N = K_T = 1e10, friction 0.5). Checks

  - the printed "field displacement N unknowns" grows by exactly dim x (number of crack
    vertices not on the tip), where the crack vertices and the tip are counted from the
    gmsh mesh itself (OUTPUT/mesh/buried_crack_<dim>d.msh): in 2D the tips are the vertices
    that belong to one crack segment only, in 3D the rim is the vertices of the crack-triangle
    edges that belong to one crack triangle only. A split that ran past the tip (the
    buried-tip label missing) or duplicated the tip changes the count;
  - the mesh has tips at all (the crack does end inside) and interior crack vertices;
  - both runs finish their steps.
"""

import argparse
import collections
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, os.path.join(SOURCE, "tests", "verification"))
import common  # noqa: E402

CRACK_INTERFACE = ["-interfaces", "crack", "-interface_crack_side1", "rock",
                   "-interface_crack_KN", "1e10", "-interface_crack_KT", "1e10",
                   "-interface_crack_friction", "0.5"]
UNKNOWNS = re.compile(r"field displacement\s+(\d+) unknowns")


def displacement_unknowns(out_dir):
    with open(os.path.join(out_dir, "log.txt")) as f:
        m = UNKNOWNS.search(f.read())
    if not m:
        common.fail(f"no 'field displacement N unknowns' line in {out_dir}/log.txt")
    return int(m.group(1))


def crack_vertices(msh, name="crack"):
    """(all vertices, tip vertices) of the physical group `name` of a MSH 2.2 file."""
    with open(msh) as f:
        lines = f.read().split("\n")
    tag = None
    i = lines.index("$PhysicalNames")
    for line in lines[i + 2:i + 2 + int(lines[i + 1])]:
        parts = line.split()
        if parts[2].strip('"') == name:
            tag = int(parts[1])
    if tag is None:
        common.fail(f"{msh} has no physical group '{name}'")
    i = lines.index("$Elements")
    elements = []
    for line in lines[i + 2:i + 2 + int(lines[i + 1])]:
        v = [int(x) for x in line.split()]
        ntags = v[2]
        if v[3] == tag:
            elements.append(v[3 + ntags:])
    vertices = {n for e in elements for n in e}
    if all(len(e) == 2 for e in elements):  # 2D: segments; tips used by one segment
        count = collections.Counter(n for e in elements for n in e)
        tips = {n for n, c in count.items() if c == 1}
    else:  # 3D: triangles (or quads); rim = edges used by one face
        edges = collections.Counter()
        for e in elements:
            for k in range(len(e)):
                edges[tuple(sorted((e[k], e[(k + 1) % len(e)])))] += 1
        tips = {n for edge, c in edges.items() if c == 1 for n in edge}
    return vertices, tips


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dim", type=int, choices=[2, 3], required=True)
    a = ap.parse_args()
    scene = os.path.join(HERE, f"buried_crack_{a.dim}d.opts")
    plain = common.output_dir(f"buried_crack_{a.dim}d_plain")
    split = common.output_dir(f"buried_crack_{a.dim}d_split")
    common.run(scene, plain, [], ranks=1, timeout=120)
    common.run(scene, split, CRACK_INTERFACE, ranks=1, timeout=120)

    checks = common.Checks(f"buried crack {a.dim}D: split without duplicating the tips")
    n_plain, n_split = displacement_unknowns(plain), displacement_unknowns(split)
    vertices, tips = crack_vertices(os.path.join(split, "mesh", f"buried_crack_{a.dim}d.msh"))
    inner = len(vertices - tips)
    print(f"  crack: {len(vertices)} vertices, {len(tips)} on the tip, {inner} inside; "
          f"displacement unknowns {n_plain} without the interface, {n_split} with it "
          f"(+{n_split - n_plain}, expected +{a.dim} x {inner} = {a.dim * inner})")
    checks.check("the crack ends inside the mesh (tip vertices found)", 0 if tips else 1, 0)
    checks.check("the crack has vertices off the tip", 0 if inner > 0 else 1, 0)
    checks.check("added displacement unknowns - dim x (crack vertices off the tip)",
                 abs((n_split - n_plain) - a.dim * inner), 0)
    for d in (plain, split):
        rows = len(common.read_timeseries(d)["step"])
        checks.check(f"{os.path.basename(d)}: steps done (of 2)", abs(rows - 2), 0)
    checks.finish()


if __name__ == "__main__":
    main()
