#!/usr/bin/python3
"""The solver presets options/solvers/{direct,fieldsplit}.opts give the direct solution
(label "solvers").

    solver_presets.py --case terzaghi_2d | two_regions_2d  [--ranks N] [--rtol 1e-6]

Runs the scene (its own solver options: MUMPS LU) as the reference, then the scene followed by
`-options_file options/solvers/<preset>.opts` for each preset, on --ranks ranks, and checks
  - the run completes with no rejected (cut) step,
  - every timeseries.csv column except the counters (newton_its, ksp_its, rejected) and
    wall_time agrees with the reference to rtol, relative to the column's largest magnitude
    floored at 1e-3 of the largest magnitude of its quantity (forces, fluxes, probe
    displacements, probe pressures; see mpi_match.py): a column that is round-off in the
    direct solve (the flux through an impervious boundary, 1e-20 m3/s next to 2e-5 m3/s
    through the drained top) may carry 1e-9 of the quantity's scale from an iterative solve
    (-ksp_rtol 1e-10),
  - the fields (displacement, pressure) agree to rtol relative to the field's largest magnitude.
A case may add variants: a preset followed by extra options (joint_column_2d: the fieldsplit
preset unscaled, where the mass-balance Krylov test keeps the water), checked alike.
Prints the Krylov iterations per time step (mean, min, max) of each preset.
"""

import argparse
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(SOURCE, "tests", "verification"))
sys.path.insert(0, os.path.join(SOURCE, "tests", "support"))
import common  # noqa: E402
from fields_reader import read_fields  # noqa: E402
from mpi_match import compare_fields, quantity, read_csv  # noqa: E402

# The fieldsplit preset with the system left unscaled (options after the preset win).
UNSCALED = ["-ksp_diagonal_scale", "0", "-ksp_diagonal_scale_fix", "0"]

CASES = {
    "terzaghi_2d": dict(scene="tests/verification/terzaghi_2d.opts",
                        args=["-probe_p50", "0.05,0.5", "-probe_top", "0.1,1",
                              "-output_fields_every", "25"]),
    "two_regions_2d": dict(scene="options/two_regions_2d.opts",
                           args=["-output_fields_every", "10"]),
    # the Terzaghi column made elastic: no pressure field, the fieldsplit preset must still
    # work (its -fieldsplit_pressure_* options are then reported as unused)
    "elastic_2d": dict(scene="tests/verification/terzaghi_2d.opts", elastic=True,
                       args=["-probe_top", "0.1,1", "-ts_max_time", "1", "-output_fields_every", "1"]),
    # interfaces: friction (block shear), and hydraulics with three fields (u, p, p3): a stiff
    # joint (K_N h / E = 5000, T = 1e-3) in a consolidating column, and a gap storage scene
    "block_shear_2d": dict(scene="options/block_shear_2d.opts", args=["-output_fields_every", "10"]),
    # Its variant "fieldsplit_unscaled" runs the preset without its -ksp_diagonal_scale, so that
    # the Krylov norm is the residual as assembled and poroseam's mass-balance check of each
    # solve (include/poroseam/mass_balance_test.hpp) is what keeps the impervious bottom tight:
    # without it (-mass_balance_krylov_test 0) the bottom flux was 1.7e-6 off here (> 1e-6).
    "joint_column_2d": dict(scene="options/joint_column_2d.opts",
                            args=["-ts_max_time", "4", "-probe_low", "0.05,0.25", "-probe_high", "0.05,0.75", "-output_fields_every", "10"],
                            variants={"fieldsplit_unscaled": ("fieldsplit", UNSCALED)}),
    # the joint with caisson-like interface values (K_N = 1e10 Pa/m, T = 1e-8 m/(Pa s))
    "joint_realistic_2d": dict(scene="options/joint_column_2d.opts",
                               args=["-ts_max_time", "4", "-interface_joint_KN", "1e10",
                                     "-interface_joint_KT", "1e10", "-interface_joint_T1", "1e-8",
                                     "-interface_joint_T2", "1e-8", "-probe_low", "0.05,0.25",
                                     "-output_fields_every", "10"],
                               variants={"fieldsplit_unscaled": ("fieldsplit", UNSCALED)}),
    # order 2 (Taylor-Hood; docs/elements.md): the displacement nodes on edges and faces too,
    # in the node blocks of vertex_blocks and the rigid-body modes (keep_factor_tests.cmake)
    "terzaghi_3d_order2": dict(scene="tests/verification/terzaghi_3d.opts",
                               args=["-displacement_order", "2", "-ts_dt", "0.25",
                                     "-ts_max_time", "2", "-output_fields_every", "4"]),
    # order 2 with a frictional interface in 3D: the order coarsening of vertex_blocks
    # (src/solve/order_coarsening.hpp) must save at least 15 % of the Krylov iterations of the
    # same preset without it (measured on these first 4 steps: 23 % on 1 rank, 30 % on 2; over
    # the whole 20 steps, 344 against 1020). The run without it is compared on iterations only:
    # its contact force on 2 ranks is 1.8e-6 off MUMPS (the order-2 block's weaker V-cycle
    # leaves more in the force rows).
    "block_shear_3d_order2": dict(scene="options/block_shear_3d.opts",
                                  args=["-displacement_order", "2", "-ts_max_time", "2",
                                        "-output_fields_every", "4"],
                                  variants={"fieldsplit_no_order_coarsening": (
                                      "fieldsplit",
                                      ["-fieldsplit_displacement_vertex_blocks_order_coarsening",
                                       "0"])},
                                  fewer_krylov=("fieldsplit", "fieldsplit_no_order_coarsening", 0.85),
                                  iterations_only=["fieldsplit_no_order_coarsening"]),
    # order 2 with a thin stiff body: the 3D quarter caisson (steel 1000 times stiffer than the
    # soil) on its coarsest mesh, first step. The stiff bodies of vertex_blocks
    # (src/solve/stiff_bodies.hpp: the steel's nodes solved by LU after each cycle) must at
    # least halve the Krylov iterations of the same preset without them (measured: 185 against
    # 1080 on 1 rank, 188 against 1158 on 2, with 6 Newton iterations against 8).
    # Newton to 1e-11 of the force scale (default 1e-9) in every run: the caisson's horizontal
    # force is a thousandth of its vertical one, and at 1e-9 two converged runs differ there
    # by 1.3e-6 of the horizontal force, whatever the linear solver.
    "caisson_3d_order2": dict(scene="options/caisson_partially_drained.opts",
                              args=["-displacement_order", "2", "-mesh_size_factor", "4",
                                    "-snes_reference_rtol", "1e-11",
                                    "-ts_max_time", "12", "-output_fields_every", "1"],
                              variants={"fieldsplit_no_stiff_bodies": (
                                  "fieldsplit",
                                  ["-fieldsplit_displacement_vertex_blocks_stiff_ratio", "0"])},
                              fewer_krylov=("fieldsplit", "fieldsplit_no_stiff_bodies", 0.5),
                              iterations_only=["fieldsplit_no_stiff_bodies"]),
    "elastic_3d_order2": dict(scene="tests/verification/terzaghi_3d.opts", elastic=True,
                              args=["-displacement_order", "2", "-ts_dt", "0.25",
                                    "-ts_max_time", "0.5", "-output_fields_every", "1"]),
}


def elastic_scene(path, out_dir):
    """A copy of the scene with every biot region made elastic (pressure options dropped)."""
    new = os.path.join(out_dir, "elastic.opts")
    with open(path) as f, open(new, "w") as g:
        for line in f:
            words = line.split("#", 1)[0].split()
            if words and (words[0].endswith("_permeability") or words[0].endswith("_p")):
                continue
            if words and words[0].endswith("_material"):
                line = words[0] + " elastic\n"
            g.write(line)
    return new
PRESETS = ["direct", "fieldsplit"]
SKIP = ["wall_time", "newton_its", "ksp_its", "rejected"]


def compare_timeseries(checks, label, ref, run, rtol):
    h1, d1 = ref
    h2, d2 = run
    if h1 != h2 or d1.shape != d2.shape:
        checks.check(f"{label}: same timeseries columns and rows", 1, 0)
        return
    group_max = {}
    for i, name in enumerate(h1):
        if name not in SKIP and np.any(np.isfinite(d1[:, i])):
            group_max[quantity(name)] = max(group_max.get(quantity(name), 0.0),
                                            np.nanmax(np.abs(d1[:, i])))
    worst, worst_name = 0.0, ""
    for i, name in enumerate(h1):
        if name in SKIP:
            continue
        x, y = d1[:, i], d2[:, i]
        if np.any(np.isnan(x) != np.isnan(y)):
            checks.check(f"{label}: {name} NaN in one run only", 1, 0)
            continue
        ok = np.isfinite(x)
        if not np.any(ok):
            continue
        ref_mag = max(np.max(np.abs(x[ok])), 1e-3 * group_max.get(quantity(name), 0.0))
        if ref_mag == 0.0:
            continue
        rel = np.max(np.abs(x[ok] - y[ok])) / ref_mag
        if rel > rtol:
            checks.check(f"{label}: timeseries {name} relative difference", rel, rtol)
        if rel >= worst:
            worst, worst_name = rel, name
    checks.check(f"{label}: timeseries largest relative difference ({worst_name})", worst, rtol)


def check_split_names(checks, preset, log_path):
    """Every -fieldsplit_* option of the preset is used exactly when its split exists: the
    splits displacement, pressures (pressure, interface_pressure) are named as the preset
    says. A split exists when the run reports unknowns of its field."""
    with open(log_path) as f:
        log = f.read()
    fields = set(re.findall(r"^field (\w+) +[1-9]\d* unknowns", log, re.M))
    unused = set(re.findall(r"option -(fieldsplit_\w+) .*never used", log))
    expected = set()
    for option in common.read_scene(os.path.join(SOURCE, "options", "solvers", preset + ".opts")):
        name = option[1:]
        if (name.startswith("fieldsplit_pressures") and "pressure" not in fields) or (
                "interface_pressure" in name and "interface_pressure" not in fields):
            expected.add(name)
    print(f"  {preset}: fields {sorted(fields)}; unused split options {sorted(unused)}")
    checks.check(f"{preset}: split options used exactly for the fields present "
                 f"(unexpectedly unused {sorted(unused - expected)}, "
                 f"unexpectedly used {sorted(expected - unused)})",
                 len(unused ^ expected), 0)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True, choices=sorted(CASES))
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--rtol", type=float, default=1e-6)
    a = ap.parse_args()
    case = CASES[a.case]
    scene = os.path.join(SOURCE, case["scene"])
    ref_dir = common.output_dir(f"solvers_{a.case}_np{a.ranks}_reference")
    if case.get("elastic"):
        scene = elastic_scene(scene, ref_dir)
    common.run(scene, ref_dir, case["args"], ranks=a.ranks, timeout=120)
    ref = read_csv(ref_dir)
    checks = common.Checks(f"solver presets on {a.case}, {a.ranks} rank(s), vs the scene's MUMPS LU")
    runs = [(p, p, []) for p in PRESETS]
    runs += [(label, preset, extra) for label, (preset, extra) in case.get("variants", {}).items()]
    krylov = {}
    for label, preset, extra in runs:
        d = common.output_dir(f"solvers_{a.case}_np{a.ranks}_{label}")
        opts = os.path.join(SOURCE, "options", "solvers", preset + ".opts")
        common.run(scene, d, case["args"] + ["-options_file", opts] + extra, ranks=a.ranks,
                   timeout=120)
        run = read_csv(d)
        h = run[0]
        its = run[1][1:, h.index("ksp_its")]  # row 0 is the initial state
        rejected = run[1][1:, h.index("rejected")]
        krylov[label] = its.sum()
        print(f"  {label}: Krylov iterations per step: mean {its.mean():.1f}, min {its.min():.0f}, "
              f"max {its.max():.0f} over {len(its)} steps; Newton per step max "
              f"{run[1][1:, h.index('newton_its')].max():.0f}", flush=True)
        checks.check(f"{label}: rejected (cut) steps", rejected.sum(), 0)
        if label in case.get("iterations_only", []):
            continue
        if preset.startswith("fieldsplit"):
            check_split_names(checks, preset, os.path.join(d, "log.txt"))
        compare_timeseries(checks, label, ref, run, a.rtol)
        compare_fields(checks, label, read_fields(ref_dir), read_fields(d), a.rtol,
                       names=("displacement", "pressure"))
    if "fewer_krylov" in case:
        better, worse, factor = case["fewer_krylov"]
        checks.check(f"Krylov iterations of {better} / those of {worse} (at most {factor})",
                     krylov[better] / krylov[worse], factor)
    checks.finish()


if __name__ == "__main__":
    main()
