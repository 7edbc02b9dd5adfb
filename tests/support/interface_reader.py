#!/usr/bin/python3
"""Reader and validator for poroseam's interface output (interface_cells.xmf +
interface_points.xmf, one grid each, over interfaces.h5).

    from interface_reader import read_interfaces
    out = read_interfaces("run/output")
    out.times              # numpy array of the time values, in file order
    out.dim                # 2 or 3
    out.topology_type      # "Polyline", "Triangle", "Quadrilateral" or "Mixed"
    out.cell_coordinates   # (Nn, dim) cell node coordinates (nodes duplicated per cell)
    out.cells              # list of Nc int arrays: node indices of each cell (face order)
    out.connectivity       # (Nc, n) array when every cell has n nodes, else None
    out.cell_fields[i]     # dict name -> array for time i (cell values: point averages;
                           # displacement_minus / _plus (Nn, 3) at the cell nodes)
    out.point_coordinates  # (Np, dim) integration point positions
    out.point_fields[i]    # dict name -> array for time i (integration point values)
    out.has_flow           # True when the hydraulic fields (FLOW_FIELDS) are present
  out.units[name]        # the "units" attribute of each dataset, by attribute name
  out.interface_names, out.part_names  # the names behind the interface and part ids
  Constant data (interface, surface, part, normal, area; points: cell, point, weight, ...) are in
  every time's dict too. Vectors are (N, 3); 2-component arrays (slip and shear_stress in 3D)
  are (N, 2); scalars (N,). The hydraulic fields (interface_pressure, aperture, aperture_rate,
  longitudinal_flux (N, 3), transversal_flux1, transversal_flux2) are written only when some
  interface has flow: all of them or none.

Command line: interface_reader.py <output_dir>  validates and prints a summary; the exit
status is non-zero on any inconsistency.
"""

import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

NODES_PER_CELL = {"Polyline": 2, "Triangle": 3, "Quadrilateral": 4}
MIXED_CODES = {4: 3, 5: 4}  # XDMF Mixed: Triangle, Quadrilateral
GEOMETRY_DIM = {"XY": 2, "XYZ": 3}
COLLECTIONS = ("interface_cells", "interface_points")  # each in <name>.xmf
NODE_FIELDS = ("displacement_minus", "displacement_plus")  # on the nodes of the cell grid
TIME_FIELDS = (
    "gap_normal",
    "opening",
    "slip",
    "slip_vector",
    "contact_pressure_effective",
    "shear_stress",
    "shear_traction",
    "traction",
    "mobilised_friction",
    "state",
    "displacement_minus",
    "displacement_plus",
)
# Written only when some interface of the scene has flow: all or none of them.
FLOW_FIELDS = (
    "interface_pressure",
    "aperture",
    "aperture_rate",
    "longitudinal_flux",
    "transversal_flux1",
    "transversal_flux2",
)


class InterfaceOutputError(Exception):
    """Inconsistent XDMF/HDF5 interface output."""


class Interfaces:
    def __init__(self):
        self.times = np.zeros(0)
        self.dim = 0
        self.topology_type = None
        self.cell_coordinates = None
        self.cells = []
        self.connectivity = None
        self.cell_fields = []
        self.point_coordinates = None
        self.point_fields = []
        self.has_flow = False
        self.units = {}
        self.interface_names = []
        self.part_names = []

    @property
    def num_cells(self):
        return len(self.cells)

    @property
    def num_points(self):
        return 0 if self.point_coordinates is None else len(self.point_coordinates)

    def __repr__(self):
        return "Interfaces(%d times, %d %s cells, %d points)" % (
            len(self.times),
            self.num_cells,
            self.topology_type,
            self.num_points,
        )


def _dims(text):
    return tuple(int(x) for x in text.split())


def _child(elem, tag):
    for c in elem:
        if c.tag.split("}")[-1] == tag:
            return c
    return None


def _children(elem, tag):
    return [c for c in elem if c.tag.split("}")[-1] == tag]


def _read_item(item, xmf_dir, h5files, context):
    """Reads an HDF DataItem, checking that the dataset exists with the declared dimensions."""
    if item is None:
        raise InterfaceOutputError("%s: missing DataItem" % context)
    if item.get("Format", "XML") != "HDF":
        raise InterfaceOutputError("%s: DataItem format %s is not HDF" % (context, item.get("Format")))
    ref = (item.text or "").strip()
    if ":" not in ref:
        raise InterfaceOutputError("%s: bad HDF reference '%s'" % (context, ref))
    fname, path = ref.split(":", 1)
    fpath = fname if os.path.isabs(fname) else os.path.join(xmf_dir, fname)
    if fpath not in h5files:
        if not os.path.isfile(fpath):
            raise InterfaceOutputError("%s: HDF5 file %s does not exist" % (context, fpath))
        h5files[fpath] = h5py.File(fpath, "r")
    h5 = h5files[fpath]
    if path not in h5:
        raise InterfaceOutputError("%s: dataset %s not in %s" % (context, path, fpath))
    data = h5[path]
    if not isinstance(data, h5py.Dataset):
        raise InterfaceOutputError("%s: %s is not a dataset" % (context, path))
    if "units" not in data.attrs:
        raise InterfaceOutputError("%s: %s has no 'units' attribute" % (context, path))
    declared = _dims(item.get("Dimensions", ""))
    if tuple(data.shape) != declared:
        raise InterfaceOutputError(
            "%s: %s has shape %s, XDMF declares %s" % (context, path, data.shape, declared)
        )
    values = data[()]
    number_type = item.get("NumberType", "Float")
    if number_type in ("Int", "UInt") and not np.issubdtype(values.dtype, np.integer):
        raise InterfaceOutputError("%s: %s is %s, declared %s" % (context, path, values.dtype, number_type))
    if number_type == "Float" and not np.issubdtype(values.dtype, np.floating):
        raise InterfaceOutputError("%s: %s is %s, declared Float" % (context, path, values.dtype))
    if not np.all(np.isfinite(values)):
        raise InterfaceOutputError("%s: %s has non-finite values" % (context, path))
    return values


def _cells_from_topology(ttype, topo, nc, npe, ctx):
    """List of node index arrays from a uniform (Nc, n) or Mixed (L,) topology."""
    if ttype == "Mixed":
        if topo.ndim == 2 and topo.shape[1] == 1:
            topo = topo[:, 0]  # PETSc writes integer datasets as (L, 1)
        if topo.ndim != 1:
            raise InterfaceOutputError("%s: Mixed topology of shape %s" % (ctx, topo.shape))
        cells, i = [], 0
        while i < len(topo):
            code = int(topo[i])
            if code not in MIXED_CODES:
                raise InterfaceOutputError("%s: Mixed cell type code %d at %d" % (ctx, code, i))
            n = MIXED_CODES[code]
            if i + 1 + n > len(topo):
                raise InterfaceOutputError("%s: Mixed topology truncated" % ctx)
            cells.append(np.array(topo[i + 1 : i + 1 + n]))
            i += 1 + n
        if len(cells) != nc:
            raise InterfaceOutputError("%s: %d Mixed cells, NumberOfElements %d" % (ctx, len(cells), nc))
        return cells
    if ttype not in NODES_PER_CELL:
        raise InterfaceOutputError("%s: unsupported TopologyType %s" % (ctx, ttype))
    if npe != NODES_PER_CELL[ttype] or topo.shape != (nc, npe):
        raise InterfaceOutputError("%s: connectivity shape %s for %d %s" % (ctx, topo.shape, nc, ttype))
    return [np.array(row) for row in topo]


def _expected_shape(atype, n, ctx):
    if atype == "Scalar":
        return (n,)  # integers are stored (n, 1): squeezed before the check
    if atype == "Vector":
        return (n, 3)
    if atype == "Matrix":
        return None  # (n, k)
    raise InterfaceOutputError("%s: unsupported AttributeType %s" % (ctx, atype))


def _read_collection(collection, output_dir, h5files, cells_grid, out, xmf):
    name = collection.get("Name")
    times, fields_per_time = [], []
    ref_mesh = None
    for i, grid in enumerate(_children(collection, "Grid")):
        ctx = "%s %s grid %d" % (xmf, name, i)
        if grid.get("GridType", "Uniform") != "Uniform":
            raise InterfaceOutputError("%s: grid is not Uniform" % ctx)
        time = _child(grid, "Time")
        if time is None:
            raise InterfaceOutputError("%s: missing Time" % ctx)
        times.append(float(time.get("Value")))
        topo_e, geom_e = _child(grid, "Topology"), _child(grid, "Geometry")
        if topo_e is None or geom_e is None:
            raise InterfaceOutputError("%s: missing Topology or Geometry" % ctx)
        gtype = geom_e.get("GeometryType")
        if gtype not in GEOMETRY_DIM:
            raise InterfaceOutputError("%s: unsupported GeometryType %s" % (ctx, gtype))
        xyz = _read_item(_child(geom_e, "DataItem"), output_dir, h5files, ctx + " geometry")
        if xyz.ndim != 2 or xyz.shape[1] != GEOMETRY_DIM[gtype]:
            raise InterfaceOutputError("%s: geometry shape %s for %s" % (ctx, xyz.shape, gtype))
        ttype = topo_e.get("TopologyType")
        n = int(topo_e.get("NumberOfElements", -1))
        topo = _read_item(_child(topo_e, "DataItem"), output_dir, h5files, ctx + " topology")
        nodes = xyz.shape[0]
        if cells_grid:
            npe = int(topo_e.get("NodesPerElement", NODES_PER_CELL.get(ttype, 0)))
            cells = _cells_from_topology(ttype, topo, n, npe, ctx)
            if gtype == "XY" and ttype != "Polyline" or gtype == "XYZ" and ttype == "Polyline":
                raise InterfaceOutputError("%s: %s cells with %s geometry" % (ctx, ttype, gtype))
            for c in cells:
                if c.min() < 0 or c.max() >= nodes or len(np.unique(c)) != len(c):
                    raise InterfaceOutputError("%s: bad cell connectivity %s" % (ctx, c))
        else:
            if ttype != "Polyvertex" or int(topo_e.get("NodesPerElement", 1)) != 1:
                raise InterfaceOutputError("%s: point grid topology %s" % (ctx, ttype))
            if topo.ndim == 2 and topo.shape[1] == 1:
                topo = topo[:, 0]
            if topo.shape != (n,) or n != nodes or not np.array_equal(topo, np.arange(n)):
                raise InterfaceOutputError("%s: Polyvertex topology is not 0..%d" % (ctx, nodes - 1))
            cells = None
        mesh = (ttype, xyz, cells)
        if ref_mesh is None:
            ref_mesh = mesh
        elif ttype != ref_mesh[0] or not np.array_equal(xyz, ref_mesh[1]) or (
            cells_grid and any(not np.array_equal(a, b) for a, b in zip(cells, ref_mesh[2]))
        ):
            raise InterfaceOutputError("%s: mesh differs from the first grid" % ctx)

        fields = {}
        for a in _children(grid, "Attribute"):
            aname = a.get("Name")
            actx = "%s attribute %s" % (ctx, aname)
            on_nodes = cells_grid and aname in NODE_FIELDS
            center = "Cell" if cells_grid and not on_nodes else "Node"
            count = nodes if on_nodes else n
            if a.get("Center", "Node") != center:
                raise InterfaceOutputError("%s: Center is not %s" % (actx, center))
            values = _read_item(_child(a, "DataItem"), output_dir, h5files, actx)
            ref = _child(a, "DataItem").text.strip().split(":", 1)
            fpath = ref[0] if os.path.isabs(ref[0]) else os.path.join(output_dir, ref[0])
            out.units[aname] = h5files[fpath][ref[1]].attrs["units"].decode()
            if aname in ("interface", "part"):
                names = h5files[fpath][ref[1]].attrs.get("names")
                if names is None:
                    raise InterfaceOutputError("%s: no 'names' attribute" % actx)
                setattr(out, aname + "_names", names.decode().split(","))
            atype = a.get("AttributeType", "Scalar")
            expected = _expected_shape(atype, count, actx)
            if atype == "Scalar" and values.ndim == 2 and values.shape[1] == 1:
                values = values[:, 0]  # PETSc writes integer datasets as (n, 1)
            if expected is None:
                ok = values.ndim == 2 and values.shape[0] == count
            else:
                ok = values.shape == expected
            if not ok:
                raise InterfaceOutputError("%s: %s of shape %s for %d entries" % (actx, atype, values.shape, count))
            if aname in fields:
                raise InterfaceOutputError("%s: duplicate attribute" % actx)
            fields[aname] = values
        missing = [f for f in TIME_FIELDS if f not in fields]
        if missing:
            raise InterfaceOutputError("%s: missing attributes %s" % (ctx, missing))
        if fields_per_time and sorted(fields) != sorted(fields_per_time[0]):
            raise InterfaceOutputError("%s: attributes %s differ from the first time" % (ctx, sorted(fields)))
        if np.any((fields["state"] < 0) | (fields["state"] > 2)):
            raise InterfaceOutputError("%s: state outside 0..2" % ctx)
        flow = [f for f in FLOW_FIELDS if f in fields]
        if flow and len(flow) != len(FLOW_FIELDS):
            raise InterfaceOutputError(
                "%s: hydraulic attributes %s without %s" % (ctx, flow, [f for f in FLOW_FIELDS if f not in flow])
            )
        if flow:
            for f in FLOW_FIELDS:
                want = (n, 3) if f == "longitudinal_flux" else (n,)
                if fields[f].shape != want:
                    raise InterfaceOutputError("%s: %s of shape %s, expected %s" % (ctx, f, fields[f].shape, want))
            if np.any(fields["aperture"] < 0):
                raise InterfaceOutputError("%s: negative aperture" % ctx)
        fields_per_time.append(fields)
    return np.array(times, dtype=float), fields_per_time, ref_mesh


def _collection(output_dir, name):
    """The temporal collection of <output_dir>/<name>.xmf, its only Domain grid."""
    xmf = os.path.join(output_dir, name + ".xmf")
    if not os.path.isfile(xmf):
        raise InterfaceOutputError("%s does not exist" % xmf)
    try:
        root = ET.parse(xmf).getroot()
    except ET.ParseError as e:
        raise InterfaceOutputError("%s: XML error: %s" % (xmf, e))
    domain = _child(root, "Domain")
    if domain is None:
        raise InterfaceOutputError("%s: no Domain" % xmf)
    grids = _children(domain, "Grid")
    if len(grids) != 1 or grids[0].get("Name") != name:
        raise InterfaceOutputError("%s: Domain grids %s, expected one, %s" % (xmf, [g.get("Name") for g in grids], name))
    g = grids[0]
    if g.get("GridType") != "Collection" or g.get("CollectionType") != "Temporal":
        raise InterfaceOutputError("%s: Domain grid %s is not a temporal collection" % (xmf, name))
    return g, xmf


def read_interfaces(output_dir):
    """Parses <output_dir>/interface_cells.xmf and interface_points.xmf, checks them against the
    HDF5 file, returns Interfaces."""
    collections, files = {}, {}
    for name in COLLECTIONS:
        collections[name], files[name] = _collection(output_dir, name)
    xmf = files["interface_cells"]

    out = Interfaces()
    h5files = {}
    try:
        ctimes, cfields, cmesh = _read_collection(
            collections["interface_cells"], output_dir, h5files, True, out, files["interface_cells"]
        )
        ptimes, pfields, pmesh = _read_collection(
            collections["interface_points"], output_dir, h5files, False, out, files["interface_points"]
        )
    finally:
        for f in h5files.values():
            f.close()
    if not np.array_equal(ctimes, ptimes):
        raise InterfaceOutputError("%s: cell times %s differ from point times %s" % (xmf, ctimes, ptimes))
    if len(ctimes) > 1 and np.any(np.diff(ctimes) < 0):
        raise InterfaceOutputError("%s: times are not non-decreasing: %s" % (xmf, ctimes))
    out.times = ctimes
    out.cell_fields = cfields
    out.point_fields = pfields
    out.has_flow = bool(cfields) and "aperture" in cfields[0]
    if any(("aperture" in f) != out.has_flow for f in cfields + pfields):
        raise InterfaceOutputError("%s: hydraulic attributes on some grids only" % xmf)
    if cmesh is not None:
        out.topology_type, out.cell_coordinates, out.cells = cmesh
        out.dim = out.cell_coordinates.shape[1]
        sizes = {len(c) for c in out.cells}
        if len(sizes) == 1:
            out.connectivity = np.array(out.cells)
        out.point_coordinates = pmesh[1]
        if out.point_coordinates.shape[1] != out.dim:
            raise InterfaceOutputError("%s: point and cell geometry dimensions differ" % xmf)
        nc, npts = len(out.cells), len(out.point_coordinates)
        for i, (cf, pf) in enumerate(zip(cfields, pfields)):
            t = out.dim - 1
            for fields, n in ((cf, nc), (pf, npts)):
                for name in ("slip", "shear_stress"):
                    want = (n,) if t == 1 else (n, t)
                    if fields[name].shape != want:
                        raise InterfaceOutputError(
                            "%s time %d: %s of shape %s, expected %s" % (xmf, i, name, fields[name].shape, want)
                        )
            if "cell" in pf and (pf["cell"].min() < 0 or pf["cell"].max() >= nc):
                raise InterfaceOutputError("%s time %d: point cell index out of range" % (xmf, i))
    return out


def main(argv):
    if len(argv) != 2:
        print("usage: %s <output_dir>" % argv[0], file=sys.stderr)
        return 2
    try:
        out = read_interfaces(argv[1])
    except (InterfaceOutputError, OSError) as e:
        print("INVALID: %s" % e, file=sys.stderr)
        return 1
    print("%s/interface_cells.xmf, interface_points.xmf: valid" % argv[1])
    print("  interfaces: %s; parts: %s" % (", ".join(out.interface_names), ", ".join(out.part_names)))
    print(
        "  %dD, %d %s cells (%d nodes), %d integration points"
        % (
            out.dim,
            out.num_cells,
            out.topology_type,
            0 if out.cell_coordinates is None else len(out.cell_coordinates),
            out.num_points,
        )
    )
    print("  %d times: %s" % (len(out.times), " ".join("%g" % t for t in out.times)))
    print("  hydraulic fields: %s" % ("yes" if out.has_flow else "no"))
    for label, per_time in (("cells", out.cell_fields), ("points", out.point_fields)):
        if not per_time:
            continue
        print("  %s, last time:" % label)
        for name in sorted(per_time[-1]):
            last = per_time[-1][name]
            print("    %-28s shape %-10s min %.6g max %.6g" % (name, last.shape, last.min(), last.max()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
