#!/usr/bin/python3
"""Reader and validator for poroseam's bulk field output (<basename>.xmf + <basename>.h5).

    from fields_reader import read_fields
    out = read_fields("run/output", basename="fields")
    out.times            # numpy array of the time values, in file order
    out.coordinates      # (Nv, cdim) vertex coordinates
    out.connectivity     # (Nc, nodes per cell) 0-based vertex indices (XDMF order)
    out.topology_type    # "Triangle", "Quadrilateral", "Tetrahedron" or "Hexahedron"
    out.fields[i]        # dict name -> array for time i, e.g. "displacement" (Nv, 3),
                         # "pressure" (Nv,), "excess_pressure" (Nv,), "steady_pressure" (Nv,) (NaN at vertices of
                         # non-porous regions only)
    out.cell_fields[i]   # dict name -> per-cell array for time i: "region" (Nc,),
                         # "effective_stress", "total_stress", "strain" (Nc, 3, 3)
    out.region_names     # the names behind the region ids
    out.units            # dict dataset name -> its "units" attribute

Command line: fields_reader.py <output_dir> [basename]  validates and prints a summary; the
exit status is non-zero on any inconsistency.
"""

import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

# Linear cells, and the quadratic cells of displacement order 2 (corners first, VTK order).
NODES_PER_CELL = {"Triangle": 3, "Quadrilateral": 4, "Tetrahedron": 4, "Hexahedron": 8,
                  "Triangle_6": 6, "Quadrilateral_9": 9, "Tetrahedron_10": 10, "Hexahedron_27": 27}
CORNERS = {t: {"Triangle_6": 3, "Quadrilateral_9": 4, "Tetrahedron_10": 4,
                 "Hexahedron_27": 8}.get(t, n) for t, n in NODES_PER_CELL.items()}
GEOMETRY_DIM = {"XY": 2, "XYZ": 3}


class FieldsError(Exception):
    """Inconsistent XDMF/HDF5 output."""


class Fields:
    def __init__(self):
        self.times = np.zeros(0)
        self.coordinates = None
        self.connectivity = None
        self.topology_type = None
        self.fields = []
        self.cell_fields = []
        self.region_names = []
        self.units = {}

    def vertices(self):
        """Boolean mask of the nodes that are cell corners (mesh vertices). At displacement
        order 2 the other nodes are edge, face and cell nodes of the quadratic displacement;
        the pressure there is interpolated from the corners, not an unknown."""
        mask = np.zeros(len(self.coordinates), dtype=bool)
        if self.connectivity is not None and len(self.connectivity):
            mask[self.connectivity[:, :CORNERS[self.topology_type]].ravel()] = True
        return mask

    def __repr__(self):
        return "Fields(%d times, %d vertices, %d %s cells, fields %s)" % (
            len(self.times),
            0 if self.coordinates is None else len(self.coordinates),
            0 if self.connectivity is None else len(self.connectivity),
            self.topology_type,
            sorted(self.fields[0]) if self.fields else [],
        )


def _dims(text):
    return tuple(int(x) for x in text.split())


def _read_item(item, xmf_dir, h5files, context, allow_nan=False, attrs=None):
    """Reads an HDF DataItem, checking that the dataset exists with the declared dimensions and
    has a "units" attribute; `attrs` (a dict), when given, receives the dataset's attributes."""
    if item is None:
        raise FieldsError("%s: missing DataItem" % context)
    if item.get("Format", "XML") != "HDF":
        raise FieldsError("%s: DataItem format %s is not HDF" % (context, item.get("Format")))
    ref = (item.text or "").strip()
    if ":" not in ref:
        raise FieldsError("%s: bad HDF reference '%s'" % (context, ref))
    fname, path = ref.split(":", 1)
    fpath = fname if os.path.isabs(fname) else os.path.join(xmf_dir, fname)
    if fpath not in h5files:
        if not os.path.isfile(fpath):
            raise FieldsError("%s: HDF5 file %s does not exist" % (context, fpath))
        h5files[fpath] = h5py.File(fpath, "r")
    h5 = h5files[fpath]
    if path not in h5:
        raise FieldsError("%s: dataset %s not in %s" % (context, path, fpath))
    data = h5[path]
    if not isinstance(data, h5py.Dataset):
        raise FieldsError("%s: %s is not a dataset" % (context, path))
    if "units" not in data.attrs:
        raise FieldsError("%s: %s has no 'units' attribute" % (context, path))
    if attrs is not None:
        attrs.update({k: (v.decode() if isinstance(v, bytes) else v) for k, v in data.attrs.items()})
    declared = _dims(item.get("Dimensions", ""))
    if tuple(data.shape) != declared:
        raise FieldsError(
            "%s: %s has shape %s, XDMF declares %s" % (context, path, data.shape, declared)
        )
    values = data[()]
    number_type = item.get("NumberType", "Float")
    if number_type in ("Int", "UInt") and not np.issubdtype(values.dtype, np.integer):
        raise FieldsError("%s: %s is %s, declared %s" % (context, path, values.dtype, number_type))
    if not np.all(np.isfinite(values) | (allow_nan & np.isnan(values))):
        raise FieldsError("%s: %s has non-finite values" % (context, path))
    return values


def _child(elem, tag):
    for c in elem:
        if c.tag.split("}")[-1] == tag:
            return c
    return None


def _children(elem, tag):
    return [c for c in elem if c.tag.split("}")[-1] == tag]


def read_fields(output_dir, basename="fields"):
    """Parses <output_dir>/<basename>.xmf, checks it against the HDF5 file and returns Fields."""
    xmf = os.path.join(output_dir, basename + ".xmf")
    if not os.path.isfile(xmf):
        raise FieldsError("%s does not exist" % xmf)
    try:
        root = ET.parse(xmf).getroot()
    except ET.ParseError as e:
        raise FieldsError("%s: XML error: %s" % (xmf, e))
    domain = _child(root, "Domain")
    collection = _child(domain, "Grid") if domain is not None else None
    if collection is None or collection.get("GridType") != "Collection" or collection.get(
        "CollectionType"
    ) != "Temporal":
        raise FieldsError("%s: no temporal collection Domain/Grid" % xmf)
    grids = _children(collection, "Grid")
    if not grids:
        raise FieldsError("%s: the temporal collection has no grids" % xmf)

    out = Fields()
    h5files = {}
    times = []
    try:
        for i, grid in enumerate(grids):
            ctx = "%s grid %d" % (xmf, i)
            if grid.get("GridType", "Uniform") != "Uniform":
                raise FieldsError("%s: grid is not Uniform" % ctx)
            topo = _child(grid, "Topology")
            geom = _child(grid, "Geometry")
            if topo is None or geom is None:
                raise FieldsError("%s: missing Topology or Geometry" % ctx)
            ttype = topo.get("TopologyType")
            if ttype not in NODES_PER_CELL:
                raise FieldsError("%s: unsupported TopologyType %s" % (ctx, ttype))
            cells = _read_item(_child(topo, "DataItem"), output_dir, h5files, ctx + " topology")
            nc = int(topo.get("NumberOfElements", -1))
            npe = int(topo.get("NodesPerElement", NODES_PER_CELL[ttype]))
            if cells.ndim != 2 or cells.shape != (nc, npe) or npe != NODES_PER_CELL[ttype]:
                raise FieldsError("%s: connectivity shape %s for %d %s" % (ctx, cells.shape, nc, ttype))
            gtype = geom.get("GeometryType")
            if gtype not in GEOMETRY_DIM:
                raise FieldsError("%s: unsupported GeometryType %s" % (ctx, gtype))
            xyz = _read_item(_child(geom, "DataItem"), output_dir, h5files, ctx + " geometry")
            if xyz.ndim != 2 or xyz.shape[1] != GEOMETRY_DIM[gtype]:
                raise FieldsError("%s: geometry shape %s for %s" % (ctx, xyz.shape, gtype))
            nv = xyz.shape[0]
            if cells.size and (cells.min() < 0 or cells.max() >= nv):
                raise FieldsError("%s: connectivity out of range [0, %d)" % (ctx, nv))
            if cells.size and np.any(np.diff(np.sort(cells, axis=1), axis=1) == 0):
                raise FieldsError("%s: a cell has repeated vertices" % ctx)
            if out.coordinates is None:
                out.coordinates, out.connectivity, out.topology_type = xyz, cells, ttype
            elif (
                ttype != out.topology_type
                or not np.array_equal(cells, out.connectivity)
                or not np.array_equal(xyz, out.coordinates)
            ):
                raise FieldsError("%s: mesh differs from the first grid" % ctx)

            time = _child(grid, "Time")
            attrs = _children(grid, "Attribute")
            if time is None:
                if len(grids) == 1 and not attrs:
                    continue  # mesh only, no time written yet
                raise FieldsError("%s: missing Time" % ctx)
            times.append(float(time.get("Value")))
            fields, cell_fields = {}, {}
            for a in attrs:
                name = a.get("Name")
                actx = "%s attribute %s" % (ctx, name)
                meta = {}
                values = _read_item(
                    _child(a, "DataItem"), output_dir, h5files, actx,
                    allow_nan=name in ("pressure", "excess_pressure", "steady_pressure"), attrs=meta,
                )
                out.units[name] = meta["units"]
                atype = a.get("AttributeType", "Scalar")
                if a.get("Center", "Node") == "Cell":
                    nc = len(cells)
                    if atype == "Scalar" and values.shape in ((nc,), (nc, 1)):
                        values = values.reshape(nc)
                    elif atype == "Tensor" and values.shape == (nc, 9):
                        values = values.reshape(nc, 3, 3)
                    else:
                        raise FieldsError("%s: cell %s of shape %s" % (actx, atype, values.shape))
                    if name == "region":
                        out.region_names = meta.get("names", "").split(",")
                        if values.min() < 0 or values.max() >= len(out.region_names):
                            raise FieldsError("%s: region ids outside the %d names" % (actx, len(out.region_names)))
                    if name in cell_fields:
                        raise FieldsError("%s: duplicate attribute" % actx)
                    cell_fields[name] = values
                    continue
                if a.get("Center", "Node") != "Node":
                    raise FieldsError("%s: Center is neither Node nor Cell" % actx)
                expected = {"Vector": (nv, 3), "Scalar": (nv,), "Tensor": (nv, 9)}.get(atype)
                if values.shape != expected:
                    raise FieldsError("%s: %s of shape %s" % (actx, atype, values.shape))
                if atype == "Tensor":
                    values = values.reshape(nv, 3, 3)
                if name in fields:
                    raise FieldsError("%s: duplicate attribute" % actx)
                fields[name] = values
            if "displacement" not in fields:
                raise FieldsError("%s: no displacement" % ctx)
            if ("pressure" in fields) != ("excess_pressure" in fields):
                raise FieldsError("%s: pressure without excess_pressure or vice versa" % ctx)
            if out.fields and sorted(fields) != sorted(out.fields[0]):
                raise FieldsError("%s: fields %s differ from the first time" % (ctx, sorted(fields)))
            if out.cell_fields and sorted(cell_fields) != sorted(out.cell_fields[0]):
                raise FieldsError("%s: cell fields %s differ from the first time" % (ctx, sorted(cell_fields)))
            out.fields.append(fields)
            out.cell_fields.append(cell_fields)
    finally:
        for f in h5files.values():
            f.close()
    out.times = np.array(times, dtype=float)
    if len(out.times) > 1 and np.any(np.diff(out.times) < 0):
        raise FieldsError("%s: times are not non-decreasing: %s" % (xmf, out.times))
    return out


def main(argv):
    if len(argv) not in (2, 3):
        print("usage: %s <output_dir> [basename]" % argv[0], file=sys.stderr)
        return 2
    basename = argv[2] if len(argv) == 3 else "fields"
    try:
        out = read_fields(argv[1], basename)
    except (FieldsError, OSError) as e:
        print("INVALID: %s" % e, file=sys.stderr)
        return 1
    print("%s/%s: valid" % (argv[1], basename))
    print(
        "  %d vertices (%dD coordinates), %d %s cells"
        % (len(out.coordinates), out.coordinates.shape[1], len(out.connectivity), out.topology_type)
    )
    print("  %d times: %s" % (len(out.times), " ".join("%g" % t for t in out.times)))
    for per_time in (out.fields, out.cell_fields):
        for name in sorted(per_time[0]) if per_time else []:
            last = per_time[-1][name]
            print(
                "  %-16s shape %-10s [%s] last time: min %.6g max %.6g"
                % (name, last.shape, out.units[name], np.nanmin(last), np.nanmax(last))
            )
    if out.region_names:
        print("  regions: %s" % ", ".join("%d %s" % r for r in enumerate(out.region_names)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
