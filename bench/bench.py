"""poroseam benchmark (issue 9): the caisson scenes over a ladder of mesh sizes, every solver
preset, 1 and 2 MPI ranks; per phase from PETSc's nested profile; strong scaling next to the
memory bandwidth ratio of the machine; a reference CG + GAMG elasticity solve of the same
size.

Writes to the output directory (default output/bench/): bench.csv (one row per run),
scaling.csv (1 -> 2 ranks per phase), machine.csv (triad bandwidth), *.png, and runs/ with
every run's output, progress log and profile (log_view.txt: a flame graph, e.g. for
https://speedscope.app)."""

import argparse
import glob
import os
import re
import sys
import time

import parse
import programs
import report

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Mesh size ladders (-mesh_size_factor; unknowns grow like factor^-dim). 3D quarter caisson:
# factor 1 is the scene's default mesh (37,334 unknowns), 0.5 gives 281,908 and 0.48 about
# 320,000 (the issue asks for >= 300k).
MODES = {
    "full": {"scenes": {"caisson_axisym_partially_drained": [1.0, 0.5, 0.25],
                        "caisson_partially_drained": [1.0, 0.8, 0.63, 0.48]},
             "steps": 3, "timeout": 900.0, "budget": 3600.0, "triad_doubles": 10_000_000,
             "reference_repeat": 3},
    "quick": {"scenes": {"caisson_axisym_partially_drained": [1.0],
                         "caisson_partially_drained": [2.0, 1.5]},
              "steps": 2, "timeout": 120.0, "budget": 300.0, "triad_doubles": 10_000_000,
              "reference_repeat": 3},
    # For the test suite: that everything runs and the files are written, in well under a
    # minute (1,755 unknowns).
    "smoke": {"scenes": {"caisson_axisym_partially_drained": [2.0]},
              "steps": 1, "timeout": 120.0, "budget": 150.0, "triad_doubles": 2_000_000,
              "reference_repeat": 1},
}


def scene_file(scene):
    return os.path.join(TOP, "options", scene + ".opts")


def scene_info(scene):
    """Time step and dimension of a scene from its options file. The dimension only predicts
    sizes before a run (unknowns ~ factor^-dim): 3 when any condition names a z component."""
    text = open(scene_file(scene)).read()
    m = re.search(r"^-ts_dt\s+(\S+)", text, re.M)
    if not m:
        sys.exit(f"bench: {scene_file(scene)} has no -ts_dt")
    dim = 3 if re.search(r"^-bc_\w+_uz\b", text, re.M) else 2
    return float(m.group(1)), dim


def arguments():
    presets_all = sorted(os.path.basename(p)[:-5]
                         for p in glob.glob(os.path.join(TOP, "options", "solvers", "*.opts")))
    p = argparse.ArgumentParser(
        prog="scripts/bench", description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="Modes: full (default; 3D caisson factors 1, 0.8, 0.63, 0.48 and axisymmetric 1, "
               "0.5, 0.25, 3 steps each, within an hour), --quick (3D factors 2 and 1.5, "
               "axisymmetric 1, 2 steps, within 5 minutes), --smoke (axisymmetric factor 2, "
               "1 step: that it all runs, for the test suite).")
    mode = p.add_mutually_exclusive_group()
    mode.add_argument("--quick", action="store_true", help="two small 3D sizes and the "
                      "axisymmetric default, 2 steps")
    mode.add_argument("--smoke", action="store_true", help="one tiny axisymmetric size, 1 step")
    p.add_argument("--presets", default=",".join(presets_all),
                   help="solver presets, files options/solvers/<preset>.opts (default: all: "
                   "%(default)s)")
    p.add_argument("--ranks", default="1,2", help="MPI rank counts (default %(default)s)")
    p.add_argument("--scene", action="append", metavar="NAME:F1,F2,...",
                   help="a scene options/NAME.opts and its -mesh_size_factor ladder, instead of "
                   "the mode's (repeatable)")
    p.add_argument("--steps", type=int, help="time steps per run (mode default: full 3, quick "
                   "2, smoke 1)")
    p.add_argument("--timeout", type=float, help="seconds before a run is killed and recorded "
                   "as a timeout (full 900, quick 120)")
    p.add_argument("--budget", type=float, help="total seconds: a run predicted to end later "
                   "is skipped (full 3600, quick 300)")
    p.add_argument("--direct-max-unknowns-3d", type=int, default=100_000,
                   help="skip the direct preset on 3D meshes predicted larger (LU memory and "
                   "time grow like N^2; default %(default)s)")
    p.add_argument("--output", default=os.path.join(TOP, "output", "bench"),
                   help="output directory (default output/bench)")
    p.add_argument("--no-plots", action="store_true", help="CSV and table only")
    a = p.parse_args()
    a.mode = "quick" if a.quick else "smoke" if a.smoke else "full"
    m = MODES[a.mode]
    a.presets = [s for s in a.presets.split(",") if s]
    for preset in a.presets:
        if not os.path.exists(os.path.join(TOP, "options", "solvers", preset + ".opts")):
            p.error(f"no preset options/solvers/{preset}.opts")
    a.ranks = [int(r) for r in a.ranks.split(",") if r]
    if a.scene:
        a.scenes = {}
        for spec in a.scene:
            name, _, factors = spec.partition(":")
            a.scenes[name] = [float(f) for f in factors.split(",") if f] or [1.0]
    else:
        a.scenes = m["scenes"]
    for scene in a.scenes:
        if not os.path.exists(scene_file(scene)):
            p.error(f"no scene {scene_file(scene)}")
    a.steps = a.steps or m["steps"]
    a.timeout = a.timeout or m["timeout"]
    a.budget = a.budget or m["budget"]
    a.triad_doubles = m["triad_doubles"]
    a.reference_repeat = m["reference_repeat"]
    return a


# Growth of a run's time with its unknowns, to predict the next size from the last one:
# sparse LU in 3D ~ N^2 (nested dissection), in 2D ~ N^1.5; an iterative solve ~ N^1.3
# (iterations grow too). Used only to skip runs that would not finish in time.
def growth_exponent(preset, dim):
    if preset == "direct":
        return 2.0 if dim == 3 else 1.5
    return 1.3


def run_name(scene, factor, preset, ranks):
    return f"{scene}__f{factor:g}__{preset}__r{ranks}"


def poroseam_command(exe, scene, factor, preset, ranks, steps, dt, run_dir):
    return ["mpiexec", "-n", str(ranks), exe,
            "-options_file", scene_file(scene),
            "-options_file", os.path.join(TOP, "options", "solvers", preset + ".opts"),
            "-mesh_size_factor", f"{factor:g}", "-ts_max_steps", str(steps),
            "-ts_max_time", repr(steps * dt), "-output_dir", run_dir,
            "-log_view", f":{os.path.join(run_dir, 'log_view.txt')}:ascii_flamegraph",
            "-memory_view"]


def measure(out, profile_text):
    """The row of bench.csv for a finished run, from its progress lines and profile."""
    info = parse.poroseam_stdout(out)
    prof = parse.flamegraph(profile_text)
    fields, steps = info["fields"], info["steps"]
    n = sum(fields.values())
    newton = sum(s["newton"] for s in steps)
    krylov = sum(s["krylov"] for s in steps)
    walls = [s["wall"] for s in steps]
    inc = prof["inclusive"]
    per = 1e6 / (n * newton) if n and newton else float("nan")  # us per unknown per Newton it
    row = {
        "unknowns": n,
        "unknowns_displacement": fields.get("displacement", 0),
        "unknowns_pressure": fields.get("pressure", 0),
        "unknowns_interface_pressure": fields.get("interface_pressure", 0),
        "steps": len(steps),
        "cut_backs": sum(s["cut_back"] for s in steps),
        "newton_total": newton,
        "krylov_total": krylov,
        "newton_per_step_mean": newton / len(steps) if steps else float("nan"),
        "krylov_per_newton_mean": krylov / newton if newton else float("nan"),
        "mesh_s": prof["mesh"],
        "distribution_s": prof["distribution"],
        "layout_s": prof["layout"],
        "first_jacobian_s": inc["PsFirstJacobian"],
        "setup_s": prof["mesh"] + prof["distribution"] + prof["layout"] + inc["PsFirstJacobian"],
        "step_median_s": parse.median(walls),
        "step_min_s": min(walls) if walls else float("nan"),
        "step_max_s": max(walls) if walls else float("nan"),
        "stepping_s": prof["stepping"],
        "assembly_s": prof["assembly"],
        "pc_setup_s": prof["pc_setup"],
        "solve_s": prof["solve"],
        "output_s": prof["output"],
        "other_s": prof["other"],
        "assembly_us_per_unknown_newton": prof["assembly"] * per,
        "pc_setup_us_per_unknown_newton": prof["pc_setup"] * per,
        "solve_us_per_unknown_newton": prof["solve"] * per,
        # one Jacobian per Newton iteration (newtonls), the first one included
        "jacobian_us_per_unknown_assembly": inc["PsJacobian"] * per,
        "jacobian_s": inc["PsJacobian"],
        "interface_jacobian_s": inc["PsIfaceJacobian"],
        "residual_s": inc["PsResidual"],
        "interface_residual_s": inc["PsIfaceResidual"],
        "peak_memory_mb_per_rank": (info["peak_memory_per_rank"] or float("nan")) / 1e6,
    }
    return row


class Ladder:
    """Runs the configurations in order (each scene's meshes from small to large), skipping a
    run predicted too long from the last size of the same scene, preset and rank count, and
    keeping the whole within the time budget."""

    def __init__(self, a, exe, reference_exe, work):
        self.a, self.exe, self.reference_exe, self.work = a, exe, reference_exe, work
        self.started = time.monotonic()
        self.history = {}     # (scene, preset, ranks) -> (unknowns, wall, status), last size
        self.first_size = {}  # scene -> (factor, unknowns) measured first
        self.references = {}  # (unknowns, ranks) -> reference solve

    def skip_reason(self, scene, dim, factor, preset, ranks):
        """Why not to run this configuration (None: run it), and the predicted unknowns."""
        a = self.a
        predicted_n = None
        if scene in self.first_size:
            f0, n0 = self.first_size[scene]
            predicted_n = n0 * (f0 / factor) ** dim
        last = self.history.get((scene, preset, ranks))
        if last and last[2] != "ok":
            said = {"skipped": "was skipped", "timeout": "timed out"}.get(last[2], last[2])
            return f"the next smaller mesh {said}", predicted_n
        if preset == "direct" and dim == 3 and predicted_n and \
                predicted_n > a.direct_max_unknowns_3d:
            return (f"about {predicted_n:.0f} unknowns > --direct-max-unknowns-3d "
                    f"{a.direct_max_unknowns_3d}"), predicted_n
        elapsed = time.monotonic() - self.started
        if last and predicted_n:
            wall = last[1] * (predicted_n / last[0]) ** growth_exponent(preset, dim)
            if wall > a.timeout:
                return f"predicted {wall:.0f} s > --timeout {a.timeout:g} s", predicted_n
            if elapsed + wall > a.budget:
                return f"predicted {wall:.0f} s, past the budget", predicted_n
        if a.budget - elapsed < min(30.0, a.timeout):
            return "the budget is spent", predicted_n
        return None, predicted_n

    def run(self, scene, factor, preset, ranks):
        """One configuration: its row of bench.csv."""
        a = self.a
        dt, dim = scene_info(scene)
        name = run_name(scene, factor, preset, ranks)
        row = {"scene": scene, "dim": dim, "mesh_size_factor": factor, "preset": preset,
               "ranks": ranks, "status": "", "note": ""}
        skip, predicted_n = self.skip_reason(scene, dim, factor, preset, ranks)
        if predicted_n:
            row["unknowns_predicted"] = round(predicted_n)
        if skip:
            row["status"], row["note"] = "skipped", skip
            self.history[(scene, preset, ranks)] = (predicted_n, None, "skipped")
            print(f"{name}: skipped: {skip}", flush=True)
            return row
        run_dir = os.path.join(self.work, name)
        os.makedirs(run_dir, exist_ok=True)
        profile = os.path.join(run_dir, "log_view.txt")
        if os.path.exists(profile):
            os.remove(profile)
        row["load_average"] = os.getloadavg()[0]
        # No run goes past the budget: one that could not be predicted is cut off at its end.
        limit = min(a.timeout, a.budget - (time.monotonic() - self.started))
        command = poroseam_command(self.exe, scene, factor, preset, ranks, a.steps, dt, run_dir)
        status, wall, out = programs.run(command, os.path.join(run_dir, "stdout.txt"), limit,
                                         cwd=TOP)
        row["status"], row["run_wall_s"] = status, wall
        if status == "ok" and os.path.exists(profile):
            row.update(measure(out, open(profile).read()))
            row.pop("unknowns_predicted", None)
            self.first_size.setdefault(scene, (factor, row["unknowns"]))
            self.history[(scene, preset, ranks)] = (row["unknowns"], wall, "ok")
            key = (row["unknowns"], ranks)
            if key not in self.references:
                self.references[key] = programs.reference(
                    self.reference_exe, ranks, row["unknowns"], a.reference_repeat, self.work,
                    timeout=max(60.0, a.timeout))
            report.add_reference(row, self.references[key])
        else:
            row["status"] = "timeout" if status == "timeout" else "failed"
            row["note"] = (f"killed after {wall:.0f} s"
                           + (", at the end of the budget" if limit < a.timeout else "")
                           if status == "timeout" else
                           " | ".join(out.strip().splitlines()[-2:])[:200])
            self.history[(scene, preset, ranks)] = (predicted_n, wall, row["status"])
        print(report.progress_line(name, row), flush=True)
        return row


def main():
    a = arguments()
    started = time.monotonic()
    os.makedirs(os.path.join(a.output, "runs"), exist_ok=True)
    build = os.environ.get("POROSEAM_BUILD_DIR", os.path.join(TOP, "build"))
    exe = os.path.join(build, "poroseam")
    if not os.path.exists(exe):
        sys.exit(f"bench: no {exe}: run scripts/setup (or scripts/bench, which does)")
    triad_exe = programs.build(os.path.join(TOP, "bench", "stream_triad.c"),
                               os.path.join(build, "bench", "stream_triad"))
    reference_exe = programs.build(os.path.join(TOP, "bench", "reference_elasticity.c"),
                                   os.path.join(build, "bench", "reference_elasticity"),
                                   petsc=True)
    work = os.path.join(a.output, "runs")

    print(f"poroseam bench ({a.mode}): presets {', '.join(a.presets)}, ranks "
          f"{', '.join(map(str, a.ranks))}, {a.steps} step(s) per run, timeout {a.timeout:g} s "
          f"per run, budget {a.budget:g} s", flush=True)
    machine = {"mode": a.mode, "load_average_start": os.getloadavg()[0]}
    for r in (1, 2):
        t = programs.triad(triad_exe, r, a.triad_doubles, work)
        machine[f"triad_gbs_r{r}"] = t["total_gbs"] if t else float("nan")
        machine["triad_array_mb"] = t["array_mb"] if t else float("nan")
    machine["bandwidth_ratio_2_1"] = machine["triad_gbs_r2"] / machine["triad_gbs_r1"]
    print(f"triad (best of 20): 1 rank {machine['triad_gbs_r1']:.1f} GB/s, 2 ranks "
          f"{machine['triad_gbs_r2']:.1f} GB/s, ratio {machine['bandwidth_ratio_2_1']:.2f}",
          flush=True)

    ladder = Ladder(a, exe, reference_exe, work)
    rows = [ladder.run(scene, factor, preset, ranks)
            for scene, factors in a.scenes.items()
            for factor in sorted(factors, reverse=True)  # small meshes first
            for preset in a.presets for ranks in a.ranks]

    scaling = report.scaling(rows, machine["bandwidth_ratio_2_1"])
    machine["wall_s"] = time.monotonic() - started
    machine["load_average_end"] = os.getloadavg()[0]
    report.write_csv(os.path.join(a.output, "bench.csv"), rows, report.COLUMNS)
    report.write_csv(os.path.join(a.output, "scaling.csv"), scaling, report.SCALING_COLUMNS)
    report.write_csv(os.path.join(a.output, "machine.csv"), [machine], list(machine))
    report.print_tables(rows, scaling, machine, a.steps)
    if not a.no_plots:
        report.plots(a.output, rows, scaling, machine)
    print(f"\nbench: {len(rows)} configurations in {machine['wall_s']:.0f} s; results in "
          f"{a.output}/ (bench.csv, scaling.csv, machine.csv"
          f"{'' if a.no_plots else ', *.png'}, runs/)")


if __name__ == "__main__":
    main()
