"""Engineering outputs (docs/outputs.md): stresses, strains and regions per cell in fields.h5,
NaN pressure outside porous regions, both faces' displacements on the interfaces, units, and
every XDMF file read by meshio.

    outputs.py --case geostatic | terzaghi | ranks | meshio | petsc_vtk

geostatic: the K0 column at rest (tests/physics/geostatic_2d.opts, one layer, and
    geostatic_layers_2d.opts, three layers of different density, K0 and alpha), water level at
    the surface. Closed form at depth d below the surface z_s: total vertical stress
    sigma_v = -g int_z^z_s rho_sat, pore pressure p = rho_w g d, effective
    sigma'_v = sigma_v + alpha p, sigma'_h = sigma'_zz = K0 sigma'_v (plane strain, index 2 out
    of plane), total sigma = sigma' - alpha p I. The written values are cell averages over the
    integration points; the closed form is linear in z within a layer (the mesh follows the
    layers), and the Gauss average of a linear field over an affine cell is its value at the
    centroid, so the closed form is taken at the centroid's depth. The column stays at rest
    (|u| < 1e-10 of the settlement scale, tests/physics/geostatic.py), so the elastic part adds
    at most E |u| / h ~ 1e-9 of |sigma_v|: tolerance 1e-8 of max |sigma_v|.
terzaghi: options/terzaghi_2d.opts (q = 10 kPa, M_c = 12 MPa, c_v = 0.012 m2/s) run to
    t = 400 s (T_v = 4.8) with dt = 2 s. Total vertical stress = -q in every cell: in this 1D
    problem the cell mean of the total stress is what the discrete equilibrium fixes exactly
    (tolerance 1e-8 q, Newton's). sigma'_v = -q + p_excess: backward Euler leaves of the slowest
    mode (4/pi) q / (1 + lambda_1 dt)^n = 1.3e-5 q with lambda_1 = pi^2 c_v / (4 H^2),
    n = 200: tolerance 5e-5 q; the same for the strain eps_yy = -q / M_c. sigma'_h = nu / (1 - nu)
    sigma'_v (oedometer, eps_xx = 0): relative 1e-9.
ranks: the layered column and Terzaghi (10 steps) on 2 ranks write, cell for cell (matched by
    centroid), the stresses, strains and regions of 1 rank: 1e-9 of the largest stress (strains:
    of that stress over the largest E), the direct solver's round-off; the cell order differs,
    the cells do not.
meshio: meshio (Debian python3-meshio) reads every XDMF file a run writes, all time steps, in
    a 2D plane-strain scene with an interface (tests/interface/patch_2d.opts), the axisymmetric
    caisson with steel, soil and flowing interfaces (coarse, 2 steps) and a 3D one
    (tests/interface/patch_3d.opts); every array meshio returns equals the HDF5 dataset h5py
    reads. Also: every HDF5 dataset has a units attribute, timeseries.csv.units names every
    CSV column, pressure is NaN exactly at the vertices no porous cell touches, and
    displacement_minus / displacement_plus equal the bulk displacement of a vertex of side 1 /
    side 2 at the same place. Skips (exit 77) when meshio is not installed.
petsc_vtk: -ts_monitor_solution_vtk on the coarse axisymmetric caisson (partially drained,
    2 steps, 2 ranks) writes the displacements and pressures of fields.h5: at every VTU
    point those of a fields.h5 vertex at the same place, exactly, NaN pressure on the steel
    (before, the residual's reactions, 1e8, showed at prescribed dofs, and the steel's
    displacement as its pressure). meshio reads the VTU files; skips without it.
"""
import argparse
import csv
import os
import re
import sys
import xml.etree.ElementTree as ET
from collections import defaultdict

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
import common  # noqa: E402
import fields_reader  # noqa: E402
from interface_reader import read_interfaces  # noqa: E402

SKIP = 77  # ctest SKIP_RETURN_CODE
g, rho_w = 9.81, 1000.0
PHYSICS = os.path.join(os.path.dirname(HERE), "physics")


def read_fields(out):
    try:
        return fields_reader.read_fields(out)
    except fields_reader.FieldsError as e:
        common.fail(f"{out}: {e}")


def centroids(f):
    return f.coordinates[f.connectivity].mean(axis=1)


# ---------------------------------------------------------------------------------------------
def layers_of(opts, extents):
    """(name, bottom, top, rho, K0, alpha) of each layer from the scene's options."""
    out = []
    for name, (lo, hi) in extents.items():
        get = lambda key, default=None: opts.get(f"-region_{name}_{key}", default)  # noqa: E731
        n_ = float(get("porosity"))
        rho = (1 - n_) * float(get("rho_s")) + n_ * rho_w
        out.append((name, lo, hi, rho, float(get("K0")), float(get("biot_alpha", 1.0))))
    return out


def column_stress(layers, z, surface=1.0):
    """Closed-form effective and total stress tensors (tension positive) at elevation z, 2D."""
    sigma_v = 0.0
    for _, lo, hi, rho, _, _ in layers:
        top, bottom = min(hi, surface), max(lo, z)
        if top > bottom:
            sigma_v -= g * rho * (top - bottom)
    layer = next(lay for lay in layers if lay[1] <= z <= lay[2])
    p = rho_w * g * (surface - z)
    eff_v = sigma_v + layer[5] * p
    eff = np.diag([layer[4] * eff_v, eff_v, layer[4] * eff_v])
    return eff, eff - layer[5] * p * np.eye(3), p


def case_geostatic(chk):
    variants = [
        ("single", os.path.join(PHYSICS, "geostatic_2d.opts"), {"soil": (0.0, 1.0)}),
        ("layers", os.path.join(PHYSICS, "geostatic_layers_2d.opts"),
         {"deep": (0.0, 0.4), "middle": (0.4, 0.7), "shallow": (0.7, 1.0)}),
    ]
    for label, scene, extents in variants:
        out = common.output_dir(f"outputs_geostatic_{label}")
        common.run(scene, out, ["-bc_top_p", 0, "-ts_max_steps", 1, "-ts_max_time", 1,
                                "-output_fields_every", 1])
        f = read_fields(out)
        layers = layers_of(common.read_scene(scene), extents)
        zc = centroids(f)[:, 1]
        cells = f.cell_fields[-1]
        exact = [column_stress(layers, z) for z in zc]
        scale = abs(column_stress(layers, 0.0)[1][1, 1])
        eff = np.array([e[0] for e in exact])
        tot = np.array([e[1] for e in exact])
        chk.check(f"{label}: max |sigma' - closed form| / |sigma_v(bottom)|",
                  np.max(np.abs(cells["effective_stress"] - eff)) / scale, 1e-8)
        chk.check(f"{label}: max |sigma - closed form| / |sigma_v(bottom)|",
                  np.max(np.abs(cells["total_stress"] - tot)) / scale, 1e-8)
        names = [n for n in f.region_names]
        want = [list(extents).index(next(lay[0] for lay in layers if lay[1] <= z <= lay[2]))
                for z in zc]
        chk.check(f"{label}: cells whose region id is not their layer's ({', '.join(names)})",
                  float(np.sum(cells["region"] != np.array(want)) + (names != list(extents))), 0)
        units = {k: f.units[k] for k in ("effective_stress", "total_stress", "strain", "region")}
        chk.check(f"{label}: units {units}", 0, 0,
                  ok=units == {"effective_stress": "Pa", "total_stress": "Pa", "strain": "1",
                               "region": "1"})


# ---------------------------------------------------------------------------------------------
def case_terzaghi(chk):
    scene = os.path.join(common.SOURCE, "options", "terzaghi_2d.opts")
    opts = common.read_scene(scene)
    q = 1e4
    E, nu = float(opts["-region_soil_E"]), float(opts["-region_soil_nu"])
    Mc = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    out = common.output_dir("outputs_terzaghi")
    common.run(scene, out, ["-ts_dt", 2, "-ts_max_time", 400, "-ts_max_steps", 400,
                            "-output_fields_every", 50])
    f = read_fields(out)
    chk.check("fields written at t = 400 s", abs(f.times[-1] - 400.0), 1e-9)
    c = f.cell_fields[-1]
    eff, tot, eps = c["effective_stress"], c["total_stress"], c["strain"]
    chk.check("max |sigma_yy + q| / q (total)", np.max(np.abs(tot[:, 1, 1] + q)) / q, 1e-8)
    chk.check("max |sigma'_yy + q| / q at T_v = 4.8", np.max(np.abs(eff[:, 1, 1] + q)) / q, 5e-5)
    chk.check("max |eps_yy + q / M_c| / (q / M_c)", np.max(np.abs(eps[:, 1, 1] + q / Mc)) / (q / Mc),
              5e-5)
    ratio = nu / (1 - nu)
    chk.check("max |sigma'_xx - nu/(1-nu) sigma'_yy| / q",
              np.max(np.abs(eff[:, 0, 0] - ratio * eff[:, 1, 1])) / q, 1e-9)
    chk.check("max |sigma'_zz - nu/(1-nu) sigma'_yy| / q (out of plane)",
              np.max(np.abs(eff[:, 2, 2] - ratio * eff[:, 1, 1])) / q, 1e-9)
    off = np.abs(eff - np.einsum("nii->ni", eff)[:, :, None] * np.eye(3)).max()
    chk.check("max |shear stress| / q", off / q, 1e-9)


# ---------------------------------------------------------------------------------------------
def by_centroid(f, index=-1):
    key = [tuple(np.round(x, 9)) for x in centroids(f)]
    order = sorted(range(len(key)), key=lambda i: key[i])
    return np.array([key[i] for i in order]), {n: v[order] for n, v in f.cell_fields[index].items()}


def case_ranks(chk):
    runs = [
        ("layers", os.path.join(PHYSICS, "geostatic_layers_2d.opts"),
         ["-bc_top_p", 0, "-ts_max_steps", 1, "-ts_max_time", 1, "-output_fields_every", 1]),
        ("terzaghi", os.path.join(common.SOURCE, "options", "terzaghi_2d.opts"),
         ["-ts_max_steps", 10, "-ts_max_time", 2, "-output_fields_every", 10]),
    ]
    for label, scene, args in runs:
        fields = []
        for ranks in (1, 2):
            out = common.output_dir(f"outputs_ranks_{label}_np{ranks}")
            common.run(scene, out, args, ranks=ranks)
            fields.append(read_fields(out))
        (k1, c1), (k2, c2) = by_centroid(fields[0]), by_centroid(fields[1])
        chk.check(f"{label}: cells of 2 ranks not at the places of 1 rank's",
                  float(len(k1) != len(k2) or not np.array_equal(k1, k2)), 0)
        scale = np.max(np.abs(c1["total_stress"]))
        for name in ("effective_stress", "total_stress"):
            chk.check(f"{label}: max |{name} 2 ranks - 1 rank| / max|sigma|",
                      np.max(np.abs(c2[name] - c1[name])) / scale, 1e-9)
        # Strains against the strain of the largest stress in the stiffest region (the layered
        # column at rest has strains of round-off size only).
        opts = common.read_scene(scene)
        E = max(float(v) for k, v in opts.items() if re.fullmatch(r"-region_\w+_E", k))
        chk.check(f"{label}: max |strain 2 ranks - 1 rank| / (max|sigma| / E_max)",
                  np.max(np.abs(c2["strain"] - c1["strain"])) / (scale / E), 1e-9)
        chk.check(f"{label}: regions differ", float(np.sum(c2["region"] != c1["region"])), 0)


# ---------------------------------------------------------------------------------------------
def h5_items(xmf):
    """Every HDF5 reference of an XDMF file, by grid index: {grid: {name: (file, path)}}."""
    root = ET.parse(xmf).getroot()
    collection = root.find("Domain").find("Grid")
    out = []
    for grid in collection.findall("Grid"):
        refs = {}
        for a in grid.findall("Attribute"):
            fname, path = a.find("DataItem").text.strip().split(":", 1)
            refs[a.get("Name")] = (os.path.join(os.path.dirname(xmf), fname), path)
        for tag in ("Geometry", "Topology"):
            fname, path = grid.find(tag).find("DataItem").text.strip().split(":", 1)
            refs[tag] = (os.path.join(os.path.dirname(xmf), fname), path)
        out.append(refs)
    return out


def same(a, b):
    """Equal arrays of the same size (shapes may differ by unit axes), NaN equal to NaN."""
    a, b = np.asarray(a).reshape(-1), np.asarray(b).reshape(-1)
    if a.size != b.size:
        return False
    if a.dtype.kind == "f" or b.dtype.kind == "f":
        a, b = a.astype(float), b.astype(float)
        return bool(np.all((a == b) | (np.isnan(a) & np.isnan(b))))
    return bool(np.array_equal(a, b))


def check_xdmf_with_meshio(chk, label, xmf):
    import meshio
    refs = h5_items(xmf)
    bad = []
    with meshio.xdmf.TimeSeriesReader(xmf) as reader:
        points, cells = reader.read_points_cells()
        with h5py.File(refs[0]["Geometry"][0], "r") as h5:
            if not same(points[:, : h5[refs[0]["Geometry"][1]].shape[1]], h5[refs[0]["Geometry"][1]][()]):
                bad.append("points")
        steps = reader.num_steps
        for k in range(steps):
            t, point_data, cell_data = reader.read_data(k)
            data = dict(point_data)
            data.update({n: v[0] for n, v in cell_data.items()})
            with h5py.File(refs[k]["Geometry"][0], "r") as h5:
                for name, (fname, path) in refs[k].items():
                    if name in ("Geometry", "Topology"):
                        continue
                    if name not in data:
                        bad.append(f"step {k}: {name} missing")
                    elif not same(data[name], h5[path][()]):
                        bad.append(f"step {k}: {name} differs from {path}")
    chk.check(f"{label}: {os.path.basename(xmf)}: {steps} steps read by meshio, arrays unlike h5py's "
              f"{bad[:3]}", float(len(bad)), 0, ok=not bad and steps > 0)


def check_units(chk, label, out):
    missing = []
    for name in ("fields.h5", "interfaces.h5"):
        path = os.path.join(out, name)
        if not os.path.isfile(path):
            continue
        with h5py.File(path, "r") as h5:
            h5.visititems(lambda n, o: missing.append(f"{name}:{n}")
                          if isinstance(o, h5py.Dataset) and "units" not in o.attrs else None)
    chk.check(f"{label}: HDF5 datasets without a units attribute {missing[:3]}", float(len(missing)), 0)
    with open(os.path.join(out, "timeseries.csv")) as f:
        header = f.readline().strip().split(",")
    with open(os.path.join(out, "timeseries.csv.units")) as f:
        rows = list(csv.reader(f))
    ok = rows[0] == ["column", "unit"] and [r[0] for r in rows[1:]] == header and all(r[1] for r in rows[1:])
    chk.check(f"{label}: timeseries.csv.units lists the {len(header)} columns with a unit", 0, 0, ok=ok)


def check_nan_pressure(chk, label, out, scene_opts):
    f = read_fields(out)
    if "pressure" not in f.fields[0]:
        return
    porous_regions = [i for i, n in enumerate(f.region_names)
                      if scene_opts.get(f"-region_{n}_material") == "biot"]
    touched = np.zeros(len(f.coordinates), bool)
    porous_cells = np.isin(f.cell_fields[0]["region"], porous_regions)
    touched[np.unique(f.connectivity[porous_cells])] = True
    wrong = sum(int(np.sum(np.isnan(fl["pressure"]) != ~touched)) for fl in f.fields)
    chk.check(f"{label}: vertices where NaN pressure <> no porous cell ({int(np.sum(~touched))} "
              f"vertices of {', '.join(n for i, n in enumerate(f.region_names) if i not in porous_regions)} only)",
              float(wrong), 0)


def check_faces(chk, label, out):
    """displacement_minus / _plus at each interface node = the bulk displacement of a vertex at
    the same place (the sides' own vertices; interface nodes are split in the bulk mesh)."""
    f = read_fields(out)
    ifc = read_interfaces(out)
    dim = f.coordinates.shape[1]
    at = defaultdict(list)
    for i, x in enumerate(f.coordinates):
        at[tuple(np.round(x, 9))].append(i)
    worst, missing = 0.0, 0
    for k in range(len(ifc.times)):
        u = f.fields[k]["displacement"]
        scale = max(np.max(np.abs(u)), 1e-300)
        for side in ("displacement_minus", "displacement_plus"):
            d = ifc.cell_fields[k][side]
            for n, x in enumerate(ifc.cell_coordinates):
                cands = at.get(tuple(np.round(x[:dim], 9)), [])
                if not cands:
                    missing += 1
                    continue
                worst = max(worst, min(np.max(np.abs(u[j] - d[n])) for j in cands) / scale)
    chk.check(f"{label}: interface nodes with no bulk vertex at their place", float(missing), 0)
    chk.check(f"{label}: max |displacement_minus/_plus - bulk displacement there| / max|u|", worst, 1e-12)
    chk.check(f"{label}: part names {ifc.part_names}, units of displacement_minus "
              f"'{ifc.units.get('displacement_minus')}'", 0, 0,
              ok=bool(ifc.part_names) and ifc.units.get("displacement_minus") == "m")


def case_meshio(chk):
    try:
        import meshio  # noqa: F401
    except ImportError:
        print("SKIP: meshio is not installed (Debian package python3-meshio; scripts/setup "
              "installs it): the XDMF files cannot be checked with it")
        sys.exit(SKIP)
    interface = os.path.join(os.path.dirname(HERE), "interface")
    scenes = [
        ("2D plane strain", os.path.join(interface, "patch_2d.opts"),
         ["-ts_max_steps", 2, "-ts_max_time", 2, "-output_fields_every", 1]),
        ("axisymmetric caisson", os.path.join(common.SOURCE, "options", "caisson_axisym_partially_drained.opts"),
         ["-mesh_size_factor", 2, "-ts_dt", 12, "-ts_max_time", 24, "-output_fields_every", 1]),
        ("3D", os.path.join(interface, "patch_3d.opts"),
         ["-ts_max_steps", 2, "-ts_max_time", 2, "-output_fields_every", 1]),
    ]
    for label, scene, args in scenes:
        tag = re.sub(r"\W+", "_", label)
        out = common.output_dir(f"outputs_meshio_{tag}")
        common.run(scene, out, args)
        files = sorted(n for n in os.listdir(out) if n.endswith(".xmf"))
        chk.check(f"{label}: XDMF files {files}", 0, 0,
                  ok=files == ["fields.xmf", "interface_cells.xmf", "interface_points.xmf"])
        for name in files:
            check_xdmf_with_meshio(chk, label, os.path.join(out, name))
        check_units(chk, label, out)
        check_nan_pressure(chk, label, out, common.read_scene(scene))
        check_faces(chk, label, out)


def case_petsc_vtk(chk):
    try:
        import meshio
    except ImportError:
        print("SKIP: meshio is not installed (Debian package python3-meshio): cannot read the VTU files")
        sys.exit(SKIP)
    scene = os.path.join(common.SOURCE, "options", "caisson_axisym_partially_drained.opts")
    for ranks in (2,):  # PETSc's VTK writer gathers the ranks' pieces: the harder case
        out = common.output_dir(f"outputs_petsc_vtk_np{ranks}")
        common.run(scene, out, ["-mesh_size_factor", 2, "-ts_dt", 6, "-ts_max_time", 12, "-output_fields_every", 1,
                                "-ts_monitor_solution_vtk", os.path.join(out, "sol-%03d.vtu")], ranks=ranks)
        f = read_fields(out)
        at = defaultdict(list)
        for i, x in enumerate(f.coordinates):
            at[tuple(np.round(x, 9))].append(i)
        worst, scale, unmatched = 0.0, 0.0, 0
        for k in range(len(f.times)):
            u, p = f.fields[k]["displacement"], f.fields[k]["pressure"]
            m = meshio.read(os.path.join(out, "sol-%03d.vtu" % k))
            v = m.point_data["solutiondisplacement"]
            q = next(a for n, a in m.point_data.items() if n.startswith("solutionpressure")).reshape(-1)
            scale = max(scale, np.max(np.abs(u)))
            for i, x in enumerate(m.points):
                here = at[tuple(np.round(x[:2], 9))]
                worst = max(worst, min(np.max(np.abs(v[i, :2] - u[j, :2])) for j in here))
                unmatched += not any(q[i] == p[j] or (np.isnan(q[i]) and np.isnan(p[j])) for j in here)
        chk.check(f"{ranks} rank(s): max |u VTU - u fields.h5| over {len(f.times)} steps (max |u| {scale:.3g} m)",
                  worst, 0.0)
        chk.check(f"{ranks} rank(s): VTU pressures unlike fields.h5's there (NaN on the steel)",
                  float(unmatched), 0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--case", required=True, choices=["geostatic", "terzaghi", "ranks", "meshio", "petsc_vtk"])
    args = ap.parse_args()
    chk = common.Checks(f"outputs: {args.case}")
    {"geostatic": case_geostatic, "terzaghi": case_terzaghi, "ranks": case_ranks,
     "meshio": case_meshio, "petsc_vtk": case_petsc_vtk}[args.case](chk)
    chk.finish()


if __name__ == "__main__":
    main()
