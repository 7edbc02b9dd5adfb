"""What the benchmark reports: the CSV files, the printed tables and the plots.

How each number is taken (the tables say it in their headers):
  step time      median over the run's steps (min and max in bench.csv); a step is one line of
                 poroseam's progress output, its wall time
  set-up         one measurement per run: the mesh, distribution and layout phases and the
                 first Jacobian assembly (PsMesh, PsDistribution, PsLayout, PsFirstJacobian)
  per-phase      mean over the run's Newton iterations: the phase's time in the time stepping
  us/unknown     (exclusive, from PETSc's nested profile) / Newton iterations / unknowns
  iterations     means: Newton per step, Krylov (outer) per Newton iteration
  memory         peak resident memory of the largest rank (PETSc -memory_view)
  reference      minimum over repetitions of CG + GAMG on 3D elasticity, same size and ranks
  bandwidth      best of 20 triad repetitions (2 runs of 10)
Times are wall-clock seconds; a phase's time on several ranks is the slowest rank's."""

import csv
import math
import os

COLUMNS = [
    "scene", "dim", "mesh_size_factor", "preset", "ranks", "status", "note", "load_average",
    "unknowns", "unknowns_predicted", "unknowns_displacement", "unknowns_pressure", "unknowns_interface_pressure",
    "steps", "cut_backs", "newton_total", "krylov_total", "newton_per_step_mean",
    "krylov_per_newton_mean", "run_wall_s", "setup_s", "mesh_s", "distribution_s", "layout_s",
    "first_jacobian_s", "step_median_s", "step_min_s", "step_max_s", "stepping_s",
    "assembly_s", "pc_setup_s", "solve_s", "output_s", "other_s",
    "assembly_us_per_unknown_newton", "pc_setup_us_per_unknown_newton",
    "solve_us_per_unknown_newton", "jacobian_us_per_unknown_assembly", "jacobian_s",
    "interface_jacobian_s", "residual_s", "interface_residual_s", "peak_memory_mb_per_rank",
    "reference_unknowns", "reference_setup_s_min", "reference_solve_s_min",
    "reference_iterations", "solve_vs_reference", "setup_solve_vs_reference",
]

PHASES = ["setup", "assembly", "pc_setup", "solve", "step"]
SCALING_COLUMNS = (["scene", "mesh_size_factor", "preset", "unknowns"]
                   + [f"speedup_{p}" for p in PHASES]
                   + ["krylov_per_newton_r1", "krylov_per_newton_r2", "bandwidth_ratio",
                      "step_speedup_over_bandwidth_ratio"])


def finite(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def add_reference(row, ref):
    """The reference solve of the same size next to the run, and the price ratios: the
    caisson's linear solve per unknown per Newton iteration over the reference's solve per
    unknown (and the same with the preconditioner set-up on both sides)."""
    if not ref:
        row["note"] = (row.get("note", "") + " reference failed").strip()
        return
    row["reference_unknowns"] = ref["unknowns"]
    row["reference_setup_s_min"] = ref["setup_s"]
    row["reference_solve_s_min"] = ref["solve_s"]
    row["reference_iterations"] = ref["iterations"]
    per_ref = ref["solve_s"] / ref["unknowns"] * 1e6
    per_ref_total = (ref["setup_s"] + ref["solve_s"]) / ref["unknowns"] * 1e6
    row["solve_vs_reference"] = row["solve_us_per_unknown_newton"] / per_ref
    row["setup_solve_vs_reference"] = (row["pc_setup_us_per_unknown_newton"]
                                       + row["solve_us_per_unknown_newton"]) / per_ref_total


def progress_line(name, row):
    if row["status"] != "ok":
        return f"{name}: {row['status']} {row.get('note', '')}"
    return (f"{name}: {row['unknowns']} unknowns, set-up {row['setup_s']:.1f} s, step "
            f"{row['step_median_s']:.2f} s (median), Newton {row['newton_per_step_mean']:.1f}/step,"
            f" Krylov {row['krylov_per_newton_mean']:.1f}/Newton, run {row['run_wall_s']:.0f} s")


def phase_times(row):
    """Per phase: set-up [s], and per Newton iteration [s] for assembly, PC set-up, solve; the
    median step [s]. Per Newton iteration, because 1 and 2 ranks may need different counts."""
    n = row["newton_total"]
    return {"setup": row["setup_s"], "assembly": row["assembly_s"] / n,
            "pc_setup": row["pc_setup_s"] / n, "solve": row["solve_s"] / n,
            "step": row["step_median_s"]}


def scaling(rows, bandwidth_ratio):
    """Strong scaling 1 -> 2 ranks for every (scene, size, preset) run on both."""
    ok = {(r["scene"], r["mesh_size_factor"], r["preset"], r["ranks"]): r
          for r in rows if r["status"] == "ok"}
    out = []
    for (scene, factor, preset, ranks), r2 in ok.items():
        r1 = ok.get((scene, factor, preset, 1))
        if ranks != 2 or not r1:
            continue
        t1, t2 = phase_times(r1), phase_times(r2)
        s = {"scene": scene, "mesh_size_factor": factor, "preset": preset,
             "unknowns": r2["unknowns"], "bandwidth_ratio": bandwidth_ratio,
             "krylov_per_newton_r1": r1["krylov_per_newton_mean"],
             "krylov_per_newton_r2": r2["krylov_per_newton_mean"]}
        for p in PHASES:
            s[f"speedup_{p}"] = t1[p] / t2[p] if t2[p] > 0 else float("nan")
        s["step_speedup_over_bandwidth_ratio"] = s["speedup_step"] / bandwidth_ratio
        out.append(s)
    return out


def write_csv(path, rows, columns):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


def short_scene(scene):
    return {"caisson_partially_drained": "3D caisson",
            "caisson_axisym_partially_drained": "axisym caisson"}.get(scene, scene)


def fmt(x, spec):
    return format(x, spec) if finite(x) else "-"


def print_tables(rows, scaling_rows, machine, steps):
    print(f"\nRuns ({steps} time step(s) each). step: median over the steps; set-up: one "
          "measurement; Newton/step, Krylov/Newton and us/unknown/Newton: means over the run; "
          "mem: peak of the largest rank; vs ref: solve us/unknown/Newton over the reference "
          "CG+GAMG solve us/unknown (minimum of its repetitions)")
    # (key, width, format, two header lines)
    cols = [("unknowns", 9, "d", "unknowns", ""), ("setup_s", 9, ".2f", "set-up s", "(1 run)"),
            ("step_median_s", 9, ".2f", "step s", "(median)"),
            ("newton_per_step_mean", 8, ".1f", "Newton", "/step"),
            ("krylov_per_newton_mean", 8, ".1f", "Krylov", "/Newton"),
            ("assembly_us_per_unknown_newton", 8, ".1f", "asm", "us/unkn"),
            ("pc_setup_us_per_unknown_newton", 8, ".1f", "PCsetup", "/Newton"),
            ("solve_us_per_unknown_newton", 8, ".1f", "solve", "(mean)"),
            ("jacobian_us_per_unknown_assembly", 8, ".1f", "Jac/asm", "(mean)"),
            ("solve_vs_reference", 7, ".1f", "vs ref", "(min)"),
            ("peak_memory_mb_per_rank", 7, ".0f", "mem MB", "(peak)")]
    lead = f"{'scene':<15}{'factor':>7} {'preset':<11}{'R':>2}"
    print(lead + "".join(f"{h1:>{w}}" for _, w, _, h1, _ in cols) + "  status")
    print(" " * len(lead) + "".join(f"{h2:>{w}}" for _, w, _, _, h2 in cols))
    for r in rows:
        ok = r["status"] == "ok"
        cells = "".join(f"{fmt(r.get(k), spec) if ok else '-':>{w}}" for k, w, spec, _, _ in cols)
        if not ok and r.get("unknowns_predicted"):  # what the size was expected to be
            cells = f"{'~' + str(r['unknowns_predicted']):>9}" + cells[9:]
        print(f"{short_scene(r['scene']):<15}{r['mesh_size_factor']:>7g} {r['preset']:<11}"
              f"{r['ranks']:>2}{cells}"
              f"  {r['status']}{(' (' + r['note'] + ')') if r.get('note') else ''}")
    print("  asm, PCsetup, solve: exclusive phases of the time stepping, us per unknown per Newton "
          "iteration; Jac/asm: poroseam's Jacobian (PsJacobian) in us per unknown per assembly")

    print(f"\nStrong scaling 1 -> 2 ranks (speedup = time on 1 rank / time on 2; set-up: one "
          f"run each, assembly, PC set-up, solve: per Newton iteration (mean), step: median "
          f"step). Memory bandwidth ratio 2/1 ranks (triad, best): "
          f"{fmt(machine['bandwidth_ratio_2_1'], '.2f')}")
    print(f"{'scene':<15}{'factor':>7} {'preset':<11}{'unknowns':>9}{'set-up':>7}{'asm':>6}"
          f"{'PCsetup':>8}{'solve':>6}{'step':>6}{'step/bw':>8}{'Krylov/Newton 1->2':>20}")
    for s in scaling_rows:
        print(f"{short_scene(s['scene']):<15}{s['mesh_size_factor']:>7g} {s['preset']:<11}"
              f"{s['unknowns']:>9d}{fmt(s['speedup_setup'], '7.2f')}"
              f"{fmt(s['speedup_assembly'], '6.2f')}{fmt(s['speedup_pc_setup'], '8.2f')}"
              f"{fmt(s['speedup_solve'], '6.2f')}{fmt(s['speedup_step'], '6.2f')}"
              f"{fmt(s['step_speedup_over_bandwidth_ratio'], '8.2f')}"
              f"{fmt(s['krylov_per_newton_r1'], '11.1f')} ->{fmt(s['krylov_per_newton_r2'], '6.1f')}")
    print(f"\nMachine: triad 1 rank {fmt(machine['triad_gbs_r1'], '.1f')} GB/s, 2 ranks "
          f"{fmt(machine['triad_gbs_r2'], '.1f')} GB/s (best of 20, arrays "
          f"{fmt(machine['triad_array_mb'], '.0f')} MB); load average (1 min) "
          f"{machine['load_average_start']:.1f} at the start, {machine['load_average_end']:.1f} "
          "at the end (2 cores: above ~0.1 someone else is running)")


def plots(out_dir, rows, scaling_rows, machine):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ok = [r for r in rows if r["status"] == "ok"]
    scenes = sorted({r["scene"] for r in ok})
    if not ok:
        return
    # 1. Time per step against unknowns, per preset and rank count (log-log).
    fig, axes = plt.subplots(1, len(scenes), figsize=(6 * len(scenes), 4.5), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        keys = sorted({(r["preset"], r["ranks"]) for r in ok if r["scene"] == scene})
        for preset, ranks in keys:
            pts = sorted((r["unknowns"], r["step_median_s"]) for r in ok
                         if r["scene"] == scene and r["preset"] == preset and r["ranks"] == ranks)
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-" if ranks > 1 else "s--",
                      label=f"{preset}, {ranks} rank{'s' if ranks > 1 else ''}")
        ax.set_xlabel("unknowns")
        ax.set_ylabel("time per step [s] (median)")
        ax.set_title(short_scene(scene))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "time_per_step.png"), dpi=120)
    plt.close(fig)

    # 2. Phase breakdown: each phase's share of the time stepping, the time per step on top.
    phases = [("assembly_s", "assembly"), ("pc_setup_s", "PC set-up"), ("solve_s", "solve"),
              ("output_s", "output"), ("other_s", "other")]
    fig, ax = plt.subplots(figsize=(max(6, 0.55 * len(ok) + 2), 5))
    labels = [f"{short_scene(r['scene'])} f{r['mesh_size_factor']:g}\n{r['preset']} "
              f"r{r['ranks']}" for r in ok]
    bottom = [0.0] * len(ok)
    for key, label in phases:
        h = [100.0 * r[key] / r["stepping_s"] for r in ok]
        ax.bar(range(len(ok)), h, bottom=bottom, label=label)
        bottom = [b + x for b, x in zip(bottom, h)]
    for k, r in enumerate(ok):
        ax.text(k, 101, f"{r['stepping_s'] / r['steps']:.3g} s", ha="center", va="bottom",
                fontsize=7)
    ax.set_xticks(range(len(ok)))
    ax.set_xticklabels(labels, rotation=90, fontsize=7)
    ax.set_ylim(0, 110)
    ax.set_ylabel("share of the time stepping [%]")
    ax.set_title("Where a time step goes (exclusive phases, slowest rank; on top: s per step, "
                 "mean)", fontsize=9)
    ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "phases.png"), dpi=120)
    plt.close(fig)

    # 3. Strong scaling per phase next to the bandwidth ratio.
    if scaling_rows:
        fig, ax = plt.subplots(figsize=(max(6, 1.2 * len(scaling_rows) + 2), 4.5))
        width = 0.8 / len(PHASES)
        for i, p in enumerate(PHASES):
            ax.bar([k + i * width for k in range(len(scaling_rows))],
                   [s[f"speedup_{p}"] if finite(s[f"speedup_{p}"]) else 0 for s in scaling_rows],
                   width, label=p.replace("_", " "))
        ax.axhline(machine["bandwidth_ratio_2_1"], color="k", ls="--",
                   label=f"triad bandwidth ratio {machine['bandwidth_ratio_2_1']:.2f}")
        ax.axhline(2.0, color="grey", ls=":", label="ideal 2")
        ax.set_xticks([k + 0.4 - width / 2 for k in range(len(scaling_rows))])
        ax.set_xticklabels([f"{short_scene(s['scene'])} f{s['mesh_size_factor']:g}\n"
                            f"{s['preset']}, {s['unknowns']}" for s in scaling_rows],
                           fontsize=7)
        ax.set_ylabel("speedup 1 -> 2 ranks")
        ax.set_title("Strong scaling 1 -> 2 ranks per phase", fontsize=10)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out_dir, "strong_scaling.png"), dpi=120)
        plt.close(fig)

    # 4. Cost per unknown per Newton iteration against size.
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    for ax, (key, title) in zip(axes, [("assembly_us_per_unknown_newton", "assembly"),
                                       ("pc_setup_us_per_unknown_newton", "PC set-up"),
                                       ("solve_us_per_unknown_newton", "solve")]):
        for scene in scenes:
            for preset, ranks in sorted({(r["preset"], r["ranks"]) for r in ok
                                         if r["scene"] == scene}):
                pts = sorted((r["unknowns"], r[key]) for r in ok if r["scene"] == scene
                             and r["preset"] == preset and r["ranks"] == ranks)
                ax.loglog([p[0] for p in pts], [max(p[1], 1e-3) for p in pts], "o-",
                          label=f"{short_scene(scene)}, {preset}, r{ranks}")
        ax.set_xlabel("unknowns")
        ax.set_ylabel("us per unknown per Newton iteration (mean)")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "cost_per_unknown.png"), dpi=120)
    plt.close(fig)
