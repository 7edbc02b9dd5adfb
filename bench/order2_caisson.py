"""The 3D quarter caisson at order 2 (issue 25): iterative preset against MUMPS, one sitting.

For each mesh factor (small first) runs options/caisson_partially_drained.opts on 2 ranks for
the first --steps time steps with -displacement_order K and each of the presets fieldsplit and
direct, alternated, --repeats times; each run under /usr/bin/time -v (peak resident memory of
each rank, summed over the ranks). Reports unknowns, Newton iterations, outer Krylov iterations
per Newton iteration (fieldsplit) and their growth per refinement, the time per step of both
presets (minimum over the repeats of each run's median step) and their ratio, and memory.
Timings are only comparable within one sitting (the machine may be shared): read the ratio.

    scripts/bench --order2-caisson                       # order 2, factors 2 and 1.5, 3 steps
    scripts/bench --order2-caisson --factors 2,1.5,1 --steps 2 --repeats 2
    scripts/bench --order2-caisson --order 1 --factors 2,1.5,1
    scripts/bench --order2-caisson --fieldsplit-options "-fieldsplit_displacement_..._x 1"
    scripts/bench --order2-caisson --options "-mesh_geometry_order 2" --factors 2,1.5,1.25

Writes <output>/order2_caisson.csv (one row per run) and <output>/order2_caisson_table.csv (one
row per mesh), and keeps each run's output in <output>/runs/."""

import argparse
import csv
import os
import re
import shlex
import statistics
import sys

import parse
import programs

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(TOP, "options", "caisson_partially_drained.opts")
RSS = re.compile(r"Maximum resident set size \(kbytes\):\s+(\d+)")
DT = 12.0  # the scene's -ts_dt


def arguments():
    p = argparse.ArgumentParser(prog="scripts/bench --order2-caisson",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("--order", type=int, default=2, choices=(1, 2),
                   help="-displacement_order (default %(default)s)")
    p.add_argument("--factors", default="2,1.5", help="-mesh_size_factor list (default "
                   "%(default)s; 1 is 240k unknowns at order 2, hours on a loaded machine)")
    p.add_argument("--steps", type=int, default=3, help="time steps per run (default "
                   "%(default)s; the iteration counts of the first steps, not the whole uplift)")
    p.add_argument("--repeats", type=int, default=1, help="runs of each configuration; the "
                   "time per step is the minimum over them (default %(default)s)")
    p.add_argument("--presets", default="fieldsplit,direct", help="default %(default)s")
    p.add_argument("--ranks", type=int, default=2, help="MPI ranks (default %(default)s)")
    p.add_argument("--options", default="", help="extra options for every run (e.g. "
                   "\"-mesh_geometry_order 2\", or another -mesh)")
    p.add_argument("--fieldsplit-options", default="", help="extra options for the fieldsplit "
                   "runs (to try a variant of the preset)")
    p.add_argument("--timeout", type=float, default=7200.0, help="seconds per run (default "
                   "%(default)s)")
    p.add_argument("--output", default=os.path.join(TOP, "output", "bench-order2"),
                   help="output directory (default output/bench-order2)")
    a = p.parse_args()
    a.factors = [float(f) for f in a.factors.split(",") if f]
    a.presets = [s for s in a.presets.split(",") if s]
    return a


def one_run(a, factor, preset, repeat, build):
    name = f"o{a.order}_f{factor:g}_{preset}_r{repeat}"
    run_dir = os.path.join(a.output, "runs", name)
    os.makedirs(run_dir, exist_ok=True)
    command = ["mpiexec", "-n", str(a.ranks), "/usr/bin/time", "-v",
               os.path.join(build, "poroseam"), "-options_file", SCENE,
               "-solver_preset", preset, "-displacement_order", str(a.order),
               "-mesh_size_factor", f"{factor:g}", "-ts_max_time", repr(a.steps * DT),
               "-output_fields_every", "1000", "-output_dir", run_dir,
               "-log_view", f":{os.path.join(run_dir, 'log_view.txt')}"]
    command += shlex.split(a.options)
    if preset == "fieldsplit":
        command += shlex.split(a.fieldsplit_options)
    status, wall, out = programs.run(command, os.path.join(run_dir, "stdout.txt"), a.timeout,
                                     cwd=TOP)
    row = {"order": a.order, "mesh_size_factor": factor, "preset": preset, "repeat": repeat,
           "status": status, "run_wall_s": round(wall, 2), "load_average": os.getloadavg()[0]}
    info = parse.poroseam_stdout(out)
    steps = info["steps"]
    rss = [int(k) * 1024 for k in RSS.findall(out)]
    newton = sum(s["newton"] for s in steps)
    krylov = sum(s["krylov"] for s in steps)
    row.update({
        "unknowns": sum(info["fields"].values()),
        "steps": len(steps),
        "newton": newton,
        "krylov": krylov,
        "krylov_per_newton": krylov / newton if newton else float("nan"),
        "krylov_per_newton_max_step": max((s["krylov"] / s["newton"] for s in steps
                                           if s["newton"]), default=float("nan")),
        "step_median_s": statistics.median(s["wall"] for s in steps) if steps else float("nan"),
        "peak_rss_mb_sum": sum(rss) / 1e6 if len(rss) == a.ranks else float("nan"),
        "peak_rss_mb_max_rank": max(rss) / 1e6 if rss else float("nan"),
    })
    if status != "ok":
        errors = [l for l in out.splitlines() if "error" in l.lower()]
        row["note"] = (errors[0] if errors else " | ".join(out.strip().splitlines()[-2:]))[:200]
        print(f"{name}: {status}: {row['note']}", flush=True)
        return row
    print(f"{name}: {status}, {row['unknowns']} unknowns, {len(steps)} steps, Newton {newton}, "
          f"Krylov {krylov} ({row['krylov_per_newton']:.1f} per Newton), median step "
          f"{row['step_median_s']:.2f} s, memory {row['peak_rss_mb_sum']:.0f} MB (sum of ranks)",
          flush=True)
    return row


def table(a, rows):
    """One row per mesh: the fieldsplit iterations, both presets' best time per step."""
    out, last = [], None
    for factor in a.factors:
        mine = [r for r in rows if r["mesh_size_factor"] == factor and r["status"] == "ok"]
        fs = [r for r in mine if r["preset"] == "fieldsplit"]
        lu = [r for r in mine if r["preset"] == "direct"]
        t = {"order": a.order, "mesh_size_factor": factor,
             "unknowns": (fs or lu)[0]["unknowns"] if (fs or lu) else float("nan"),
             "steps": (fs or lu)[0]["steps"] if (fs or lu) else float("nan")}
        nan = float("nan")
        t["newton_fieldsplit"] = fs[0]["newton"] if fs else nan
        t["newton_direct"] = lu[0]["newton"] if lu else nan
        t["krylov_per_newton"] = fs[0]["krylov_per_newton"] if fs else nan
        t["krylov_per_newton_max_step"] = fs[0]["krylov_per_newton_max_step"] if fs else nan
        t["growth"] = t["krylov_per_newton"] / last if last else nan
        last = t["krylov_per_newton"] if fs else None
        t["step_fieldsplit_s"] = min(r["step_median_s"] for r in fs) if fs else nan
        t["step_direct_s"] = min(r["step_median_s"] for r in lu) if lu else nan
        t["ratio_fieldsplit_direct"] = t["step_fieldsplit_s"] / t["step_direct_s"]
        t["memory_fieldsplit_mb"] = max(r["peak_rss_mb_sum"] for r in fs) if fs else nan
        t["memory_direct_mb"] = max(r["peak_rss_mb_sum"] for r in lu) if lu else nan
        out.append(t)
    return out


def write_csv(path, rows):
    if not rows:
        return
    with open(path, "w", newline="") as f:
        names = list(dict.fromkeys(k for r in rows for k in r))  # failed runs have fewer
        w = csv.DictWriter(f, fieldnames=names, restval="")
        w.writeheader()
        w.writerows(rows)


def main():
    a = arguments()
    build = os.environ.get("POROSEAM_BUILD_DIR", os.path.join(TOP, "build"))
    if not os.path.exists(os.path.join(build, "poroseam")):
        sys.exit(f"bench: no {build}/poroseam: run scripts/setup")
    os.makedirs(os.path.join(a.output, "runs"), exist_ok=True)
    # What scripts/bench exports, for a direct start of this file (mpiexec as root, 2 cores).
    for k in ("OMPI_ALLOW_RUN_AS_ROOT", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM",
              "OMPI_MCA_rmaps_base_oversubscribe"):
        os.environ.setdefault(k, "1")
    print(f"3D quarter caisson, order {a.order}, {a.ranks} ranks, {a.steps} steps per run, "
          f"factors {', '.join(f'{f:g}' for f in a.factors)}, {a.repeats} repeat(s), presets "
          f"{', '.join(a.presets)} alternated; load average {os.getloadavg()[0]:.1f}", flush=True)
    rows = []
    for factor in a.factors:
        for repeat in range(a.repeats):
            for preset in a.presets:
                rows.append(one_run(a, factor, preset, repeat, build))
    write_csv(os.path.join(a.output, "order2_caisson.csv"), rows)
    t = table(a, rows)
    write_csv(os.path.join(a.output, "order2_caisson_table.csv"), t)
    print(f"\norder | factor | unknowns | Newton FS / LU | Krylov/Newton (max step) | growth | "
          f"step FS s | step LU s | FS/LU | memory FS / LU MB (sum of {a.ranks} ranks)")
    for r in t:
        print(f"{r['order']} | {r['mesh_size_factor']:g} | {r['unknowns']} | "
              f"{r['newton_fieldsplit']} / {r['newton_direct']} | {r['krylov_per_newton']:.1f} "
              f"({r['krylov_per_newton_max_step']:.1f}) | {r['growth']:.2f} | "
              f"{r['step_fieldsplit_s']:.1f} | {r['step_direct_s']:.1f} | "
              f"{r['ratio_fieldsplit_direct']:.2f} | {r['memory_fieldsplit_mb']:.0f} / "
              f"{r['memory_direct_mb']:.0f}")
    print(f"\nload average at the end {os.getloadavg()[0]:.1f}; results in {a.output}/")


if __name__ == "__main__":
    main()
