"""What curved cells (-mesh_geometry_order 2, docs/elements.md "Curved geometry") show outside
the computation: fields.h5's nodes and the interface penalty warning, against closed forms of
the circles the meshes are built on (a = 1, c = 1.5, b = 2 m, centre at the origin).

--case fields: fields.h5 (displacement order 2, quadratic XDMF cells) must draw the curved
    cells. The nodes on a circle are selected by construction, from the connectivity alone:
    the node of every cell edge (Quadrilateral_9, Triangle_6, Hexahedron_27) and of every
    hexahedron face whose corners all lie on one of the circles (the corners are mesh vertices,
    on the circle in either geometry). Curved: every such node at the circle's radius to 1e-9
    relative (quarter annuli of quadrilaterals with an interface on r = c, whose both faces'
    nodes are written; of triangles; a 3D slab of hexahedra on the cylinders), and every node
    of fields.h5 a node of the second-order mesh gmsh wrote (read with meshio, to 1e-12 of the
    diameter: the edge, face and cell nodes inside too). Straight-sided (the same mesh at
    -mesh_geometry_order 1): the same nodes are the chords' midpoints, r = R cos(dtheta / 2)
    (dtheta the angle an edge spans, pi / 16 here), 4.8e-3 inside the circle: the check above
    would fail on them.
--case penalty: the height h = volume / face length of the bulk cell beside an interface face,
    printed by the soft-penalty warning. Two rings joined on r = c (meshes/two_rings_plane.geo,
    one cell through each ring, 4 around the quarter: -mesh_size_factor 2; and its slab of
    hexahedra, meshes/two_rings_slab_3d.geo, one layer, the same h); the smallest h is
    the inner ring's, an annular sector of angle theta = pi / 8 between r = a and r = c over its
    arc: h = (c^2 - a^2) / (2 c) curved; the straight-sided trapezoid over its chord gives
    cos(theta / 2) times that (1.9e-2 less). Both within 2.5e-4 of their closed forms (h is
    printed with 4 digits: 1.2e-4; the isoparametric arcs: 3e-5, measured). On triangles
    (meshes/two_rings_plane_tri.geo, factor 2) the smallest h = 2 A / L is the outer ring's
    triangle over the joint's edge, compared with the closed form of the isoparametric triangle
    itself (its base the parabola through the edge's three nodes: 1.9e-4 off the circle's) and,
    straight-sided, (b - c) cos(theta / 2).
"""
import argparse
import glob
import math
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import common  # noqa: E402
from fields_reader import read_fields  # noqa: E402  (tests/support, on common's path)

A, C, B = 1.0, 1.5, 2.0

# The nodes of VTK's quadratic cells after the corners, each named by the corners it is the
# mean of (vtkQuadraticTriangle, vtkBiQuadraticQuad, vtkTriQuadraticHexahedron).
SPANS = {
    "Triangle_6": [(0, 1), (1, 2), (2, 0)],
    "Quadrilateral_9": [(0, 1), (1, 2), (2, 3), (3, 0), (0, 1, 2, 3)],
    "Hexahedron_27": [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4),
                      (1, 5), (2, 6), (3, 7), (0, 3, 7, 4), (1, 2, 6, 5), (0, 1, 5, 4),
                      (3, 2, 6, 7), (0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 2, 3, 4, 5, 6, 7)],
}
CORNERS = {"Triangle_6": 3, "Quadrilateral_9": 4, "Hexahedron_27": 8}


def nodes_on_circles(fields, circles):
    """{node index: the radius of the circle its corners lie on} for the edge nodes and (3D)
    the face nodes of a cylinder: selected by the connectivity and the corners only.
    `circles`: the radii of the model's circles (a mesh's inner circles of vertices have
    straight edges between them)."""
    x = fields.coordinates
    radius = np.hypot(x[:, 0], x[:, 1])
    kind = fields.topology_type
    on = {}
    for row in fields.connectivity:
        for k, span in enumerate(SPANS[kind]):
            if len(span) > 4:
                continue  # a cell's centre
            corner_r = radius[[row[i] for i in span]]
            for R in circles:
                if np.all(np.abs(corner_r - R) < 1e-12 * R):
                    on[int(row[CORNERS[kind] + k])] = R
    return on, radius


def run_fields(name, scene, args):
    out = common.output_dir(f"curved_output_{name}")
    common.run(common.scene_path(scene), out, args + ["-output_fields_every", 1])
    return out, read_fields(out)


def fields_case(chk):
    slab = ["-mesh", "meshes/thick_cylinder_slab_3d.geo",
            "-boundaries", "inner,outer,sym_x,sym_y,bottom,top", "-bc_bottom_uz", 0,
            "-bc_top_uz", 0, "-probe_in", "0.7071067811865476,0.7071067811865476,0.1",
            "-probe_out", "1.4142135623730951,1.4142135623730951,0.1"]
    # Expected counts by construction: 8 edges round each quarter circle (4 divisions through
    # the wall, 2 n around), the interface's circle twice (both faces); the slab: 8 arcs at
    # z = 0 and z = T, 9 vertical edges and 8 faces on each cylinder.
    cases = [
        ("rings", "curved_rings.opts", [], "Quadrilateral_9", {A: 8, C: 16, B: 8}),
        ("triangles", "curved_cylinder.opts", ["-mesh", "meshes/thick_cylinder_plane_tri.geo"],
         "Triangle_6", {A: 8, B: 8}),
        ("hexahedra", "curved_cylinder.opts", slab, "Hexahedron_27", {A: 33, B: 33}),
    ]
    for name, scene, args, kind, counts in cases:
        out, f = run_fields(name, scene, args + ["-mesh_geometry_order", 2])
        chk.check(f"{name}: cells are {kind}", 0, 0, ok=f.topology_type == kind)
        on, radius = nodes_on_circles(f, tuple(counts))
        found = {R: sum(1 for r in on.values() if r == R) for R in counts}
        chk.check(f"{name}: nodes selected on the circles {found} (expected {counts})", 0, 0,
                  ok=found == counts)
        worst = max(abs(radius[i] / R - 1) for i, R in on.items())
        chk.check(f"{name}, curved: max |r / R - 1| of the nodes on the circles", worst, 1e-9)
        msh = glob.glob(os.path.join(out, "mesh", "*.msh"))
        import meshio  # Debian's python3-meshio: gmsh's file through another reader
        points = meshio.read(msh[0]).points[:, :f.coordinates.shape[1]]
        diameter = np.linalg.norm(points.max(axis=0) - points.min(axis=0))
        apart = max(np.min(np.linalg.norm(points - p, axis=1)) for p in f.coordinates)
        chk.check(f"{name}, curved: every fields.h5 node a node of gmsh's second-order mesh "
                  f"({len(f.coordinates)} nodes, {len(points)} in the .msh; distance / diameter)",
                  apart / diameter, 1e-12)

    # The same rings straight-sided: the edge nodes are the chords' midpoints.
    _, f = run_fields("rings_straight", "curved_rings.opts", ["-mesh_geometry_order", 1])
    on, radius = nodes_on_circles(f, (A, C, B))
    half_angle = (math.pi / 2) / 8 / 2
    inside = max(abs(radius[i] / R - 1) for i, R in on.items())
    chords = max(abs(radius[i] / (R * math.cos(half_angle)) - 1) for i, R in on.items())
    print(f"  straight-sided: the same nodes {inside:.3e} inside their circles "
          f"(1 - cos(pi / 32) = {1 - math.cos(half_angle):.3e})")
    chk.check("straight-sided: nodes on the chords' midpoints, |r / (R cos(dtheta / 2)) - 1|",
              chords, 1e-9)
    chk.check("straight-sided: the curved check fails on them (max |r / R - 1| > 1e-3)",
              -inside, -1e-3)


SLAB = ["-mesh", "meshes/two_rings_slab_3d.geo", "-boundaries",
        "inner,outer,sym_x,sym_y,bottom,top", "-bc_bottom_uz", 0, "-bc_top_uz", 0,
        "-probe_in", "0.7071067811865476,0.7071067811865476,0.1",
        "-probe_out", "1.4142135623730951,1.4142135623730951,0.1"]


def penalty_h(name, order, args):
    out = common.output_dir(f"curved_output_penalty_{name}_g{order}")
    common.run(common.scene_path("curved_rings.opts"), out,
               args + ["-mesh_geometry_order", order, "-interface_joint_KN", 1e5,
                       "-interface_joint_KT", 1e5])
    with open(os.path.join(out, "log.txt")) as log:
        text = log.read()
    found = re.search(r"K_N = \S+ Pa/m is soft for its mesh: .*?\(h = (\S+) m", text)
    if not found:
        common.fail(f"no soft-penalty warning for K_N in {out}/log.txt")
    return float(found.group(1))


def parabola_height(theta):
    """h = 2 area / base of the triangle of the outer ring beside the interface (base: the
    joint's edge, chord L = 2 c sin(theta / 2); apex on r = b, (b - c) cos(theta / 2) from the
    chord's line), curved: its base is the parabola through the edge's ends and its node on the
    arc (sagitta s = c (1 - cos(theta / 2))), which bulges into the triangle by the parabolic
    segment's area 2 L s / 3, over the parabola's length."""
    L = 2 * C * math.sin(theta / 2)
    s = C * (1 - math.cos(theta / 2))
    area = 0.5 * L * (B - C) * math.cos(theta / 2) - 2 * L * s / 3
    q = math.sqrt(L**2 + 16 * s**2)
    length = q / 2 + L**2 / (8 * s) * math.log((4 * s + q) / L)
    return 2 * area / length, (B - C) * math.cos(theta / 2)


def penalty_case(chk):
    exact = (C**2 - A**2) / (2 * C)
    theta = (math.pi / 2) / 4
    # Triangles: the smallest h is the outer ring's triangle over the joint's edge.
    tri_curved, tri_straight = parabola_height(theta)
    curved = penalty_h("triangles", 2, ["-mesh", "meshes/two_rings_plane_tri.geo",
                                        "-mesh_size_factor", 2])
    straight = penalty_h("triangles", 1, ["-mesh", "meshes/two_rings_plane_tri.geo",
                                          "-mesh_size_factor", 2])
    print(f"  triangles: h curved {curved}, straight {straight} m; closed forms "
          f"{tri_curved:.6f} (curved: 2 A / L), {tri_straight:.6f} (straight)")
    chk.check("triangles, curved: |h / (2 A / L of the parabola-sided triangle) - 1|",
              abs(curved / tri_curved - 1), 2.5e-4)
    chk.check("triangles, straight: |h / ((b - c) cos(theta / 2)) - 1|",
              abs(straight / tri_straight - 1), 2.5e-4)
    # The plane rings (one cell through each at factor 2) and their slab of hexahedra (one
    # layer: the same h over a quadrilateral face on the cylinder r = c).
    for name, args in (("quadrilaterals", ["-mesh_size_factor", 2]), ("hexahedra", SLAB)):
        curved, straight = penalty_h(name, 2, args), penalty_h(name, 1, args)
        print(f"  {name}: h curved {curved}, straight {straight} m; closed forms {exact:.6f} "
              f"(curved), {exact * math.cos(theta / 2):.6f} (straight)")
        chk.check(f"{name}, curved: |h / ((c^2 - a^2) / (2 c)) - 1|", abs(curved / exact - 1),
                  2.5e-4)
        chk.check(f"{name}, straight: |h / ((c^2 - a^2) / (2 c) cos(theta / 2)) - 1|",
                  abs(straight / (exact * math.cos(theta / 2)) - 1), 2.5e-4)


parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--case", choices=["fields", "penalty"], required=True)
case = parser.parse_args().case
chk = common.Checks(f"curved cells outside the computation: {case}")
(fields_case if case == "fields" else penalty_case)(chk)
chk.finish()
