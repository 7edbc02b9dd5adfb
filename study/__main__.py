"""scripts/study: work-precision studies (issue 10; docs/studies.md).

    scripts/study NAME [NAME ...] | all     studies/NAME.toml (or a path to a .toml file)
    scripts/study --list                    the studies and their titles
    scripts/study --check NAME|all          read and check the study files only

Each study writes output/study-NAME/: study.csv, study.md, work_precision.png,
reference.json; runs are cached by their settings in output/study_cache/."""

import argparse
import json
import os
import sys
import time

import numpy as np

from . import measure, report, runs, spec
from .spec import TOP, StudyError


def arguments(argv=None):
    p = argparse.ArgumentParser(prog="scripts/study", description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog="See docs/studies.md for the study file format.")
    p.add_argument("names", nargs="*", help="study names (studies/<name>.toml), .toml paths, "
                   "or all")
    p.add_argument("--list", action="store_true", help="list the studies")
    p.add_argument("--check", action="store_true", help="check the study files, run nothing")
    p.add_argument("--output", default=os.path.join(TOP, "output"),
                   help="where study-<name>/ is written (default output/)")
    p.add_argument("--cache", default=None, help="run cache (default <output>/study_cache)")
    p.add_argument("--rerun", action="store_true", help="run again what is cached")
    p.add_argument("--no-plots", action="store_true", help="no work_precision.png")
    a = p.parse_args(argv)
    a.cache = a.cache or os.path.join(a.output, "study_cache")
    return a, p


def all_names():
    d = os.path.join(TOP, "studies")
    return sorted(f[:-5] for f in os.listdir(d) if f.endswith(".toml"))


def executable():
    build = os.environ.get("POROSEAM_BUILD_DIR", os.path.join(TOP, "build"))
    exe = os.environ.get("POROSEAM_EXE", os.path.join(build, "poroseam"))
    if not os.path.isfile(exe):
        raise StudyError(f"no poroseam executable at {exe} (set POROSEAM_BUILD_DIR)")
    return exe


def run_study(st, a, exe, active=()):
    """Runs (what is not cached), measures, writes the outputs of one study. Returns the
    per-run rows and the summary."""
    out = os.path.join(a.output, f"study-{st.name}")
    os.makedirs(out, exist_ok=True)
    # references taken from other studies: those studies first
    for q in st.quantities.values():
        if q.reference["kind"] == "study":
            other = q.reference["study"]
            if other in active:
                raise StudyError(f"{st.file}: key 'quantities.{q.name}.reference.study': "
                                 f"a cycle of studies ({' -> '.join(active + (other,))})")
            f = os.path.join(a.output, f"study-{other}", "reference.json")
            if not os.path.isfile(f):
                print(f"study {st.name}: reference from study {other}, running it first")
                run_study(spec.load(other), a, exe, active + (st.name,))
    plan = runs.plan(st, exe, a.cache)
    todo, seen = [], set()  # the same settings on two paths: one run
    for r in plan:
        if r.key not in seen and (a.rerun or runs.cached(r) is None):
            todo.append(r)
        seen.add(r.key)
    same = len(plan) - len(seen)
    print(f"study {st.name}: {len(plan)} runs"
          + (f" ({same} with the settings of another)" if same else "")
          + f", {len(seen) - len(todo)} cached, {len(todo)} to run", flush=True)
    t0 = time.monotonic()
    done_keys = {}
    for i, r in enumerate(todo):
        print(f"  [{i + 1}/{len(todo)}] {r.line}: {r.parameter} {r.value:g}", end="", flush=True)
        res = runs.execute(r, exe, st)
        done_keys[r.key] = res
        print(f"  {res['status']}, {res['unknowns']} unknowns, {res['steps']} steps, "
              f"{res['wall_total_s']:.2f} s", flush=True)
    results = {}
    for r in plan:
        res = runs.cached(r)
        if res is None:
            f = os.path.join(r.dir, "result.json")
            res = json.load(open(f)) if os.path.isfile(f) else {"status": "not run"}
        results[r.key] = res
    rows, summary = evaluate(st, plan, results, a)
    report.write(st, rows, summary, out, plots=not a.no_plots)
    print(f"study {st.name}: {time.monotonic() - t0:.1f} s of runs; wrote {out}/study.csv, "
          f"study.md{'' if a.no_plots else ', work_precision.png'}", flush=True)
    return rows, summary


def evaluate(st, plan, results, a):
    """Quantities, references, errors per run; orders per path line; Richardson references."""
    values = {}  # (run key, quantity) -> (times, values)
    problems = []
    for r in plan:
        if results[r.key].get("status") != "ok":
            continue
        ts = runs.read_csv(os.path.join(r.dir, "timeseries.csv"))
        r.step_times = ts["time"][ts["step"] > 0] if ts is not None else np.array([])
        for q in st.quantities.values():
            try:
                values[(r.key, q.name)] = measure.quantity_values(q, r.dir)
            except measure.MeasureError as e:
                problems.append(str(e))
    for p in sorted(set(problems)):
        print("  warning: " + p)
    # references that do not depend on the run: Richardson and other studies
    shared = {}
    for q in st.quantities.values():
        ref = q.reference
        if ref["kind"] in ("richardson", "finest"):
            line = [r for r in plan if r.path == ref[ref["kind"]]
                    and r.integrator == ref.get("integrator", r.integrator)
                    and r.solver == ref.get("solver", r.solver)
                    and r.ranks == ref.get("ranks", r.ranks)
                    and r.displacement_order == ref.get("displacement_order",
                                                        r.displacement_order)]
            first = line[0] if line else None
            line = [r for r in line if r.line == first.line and (r.key, q.name) in values]
            if len(line) < 2:
                raise StudyError(f"{st.file}: quantities.{q.name}: the reference path "
                                 f"'{ref[ref['kind']]}' has fewer than 2 runs that finished")
            vals = [values[(r.key, q.name)][1] for r in line]
            if ref["kind"] == "finest":  # the last run; its error about the last change
                shared[q.name] = {"value": vals[-1], "estimated_error": np.abs(vals[-1] - vals[-2]),
                                  "times": values[(line[-1].key, q.name)][0],
                                  "method": f"the finest run of path {ref['finest']} "
                                            f"({line[-1].line}, {line[-1].parameter} "
                                            f"{line[-1].value:g})"}
                continue
            v, p_used, p_obs, est = measure.richardson([r.value for r in line], vals,
                                                       ref.get("order"))
            shared[q.name] = {"value": v, "estimated_error": est, "order_used": p_used,
                              "order_observed": p_obs, "times": values[(line[-1].key, q.name)][0],
                              "method": f"Richardson, path {ref['richardson']} ({line[0].line}), "
                                        f"{len(line)} runs, order {p_used:.2f}"
                                        + (" (declared)" if ref.get("order") else " (observed)")}
        elif ref["kind"] == "study":
            got = measure.other_study_reference(q, a.output)
            if got is None:
                raise StudyError(f"{st.file}: quantities.{q.name}: study {ref['study']} wrote no "
                                 "reference.json")
            v, est, e = got
            shared[q.name] = {"value": v, "estimated_error": est, "order_used": e.get("order_used"),
                              "order_observed": e.get("order_observed"), "times": e.get("times"),
                              "method": f"study {ref['study']}, quantity {ref['quantity']} x "
                                        f"{ref['scale']:g} ({e.get('method', '')})"}
        elif ref["kind"] == "value":
            shared[q.name] = {"value": np.asarray(ref["value"]), "estimated_error":
                              np.zeros(len(ref["value"])), "method": "given value"}
    rows = []
    for r in plan:
        res = results[r.key]
        row = {"path": r.path, "kind": r.kind, "integrator": r.integrator, "solver": r.solver,
               "ranks": r.ranks, "displacement_order": r.displacement_order,
               "index": r.index, "mesh_size_factor": r.point["mesh_size_factor"],
               "dt": r.point["dt"] if r.kind != "adaptive" else float("nan"),
               "dt_initial": r.point["dt"],
               "varied": " ".join(f"{k} {v}" for k, v in r.point["vary"].items()),
               "parameter": r.parameter, "parameter_value": r.value, "line": r.line,
               "status": res.get("status", "not run"), "key": r.key}
        for f, n in res.get("fields", {}).items():
            row[f"unknowns_{f}"] = n
        for k in ("unknowns", "steps", "rejected", "wall_total_s", "wall_steps_s",
                  "wall_per_step_s", "newton", "krylov", "peak_memory_mb_per_rank"):
            row[k] = res.get(k, float("nan"))
        for q in st.quantities.values():
            row[f"{q.name}_value"] = float("nan")
            row[f"{q.name}_error"] = float("nan")
            if (r.key, q.name) not in values:
                continue
            times, vals = values[(r.key, q.name)]
            row[f"{q.name}_value"] = float(vals[-1])
            try:
                if q.reference["kind"] == "closed_form":
                    ref = measure.closed_form_reference(q, times, r.opts, r.step_times)
                else:
                    ref = shared[q.name]["value"]
                row[f"{q.name}_error"] = measure.error(q, vals, ref)
            except Exception as e:  # noqa: BLE001  (reported, the row stays NaN)
                print(f"  warning: {r.line} {r.parameter} {r.value:g}: {q.name}: {e}")
        rows.append(row)
    # change from the finest run of the same line (a reference-free error of the path)
    for r, row in zip(plan, rows):
        line = [x for x in plan if x.line == r.line]
        for q in st.quantities.values():
            have = [x for x in line if (x.key, q.name) in values]  # the finest that finished
            a_ = values.get((r.key, q.name))
            b_ = values.get((have[-1].key, q.name)) if have else None
            row[f"{q.name}_change_from_finest"] = (
                measure.norm(q, a_[1] - b_[1]) / _scale(q, b_[1]) if a_ and b_ else float("nan"))
    summary = {"orders": orders(st, plan, rows, values), "references": shared}
    with open(os.path.join(a.output, f"study-{st.name}", "reference.json"), "w") as f:
        json.dump({k: {kk: (vv.tolist() if isinstance(vv, np.ndarray) else vv)
                       for kk, vv in v.items()} for k, v in shared.items()}, f, indent=1)
    return rows, summary


def _scale(q, ref):
    return float(np.max(np.abs(ref))) if q.scale == "reference" else q.scale


def orders(st, plan, rows, values):
    """Per line of each path and quantity: the slope of the error against the path's
    parameter (least squares and finest pair), the observed order from the changes (last
    three runs, reference-free), and the slope against the unknowns."""
    out = []
    lines = []
    for r in plan:
        if r.line not in lines:
            lines.append(r.line)
    for ln in lines:
        idx = [i for i, r in enumerate(plan) if r.line == ln]
        rs = [plan[i] for i in idx]
        for q in st.quantities.values():
            ok = [i for i in idx if np.isfinite(rows[i][f"{q.name}_error"])]
            params = [plan[i].value for i in ok]
            errs = [rows[i][f"{q.name}_error"] for i in ok]
            fit, last = measure.fit_order(params, errs)
            unk = [rows[i]["unknowns"] for i in ok]
            fit_n = (measure.fit_order(unk, errs)[0] if len(set(unk)) > 1 else float("nan"))
            have = [i for i in idx if (plan[i].key, q.name) in values]
            so = measure.self_order(q, [plan[i].value for i in have],
                                    [values[(plan[i].key, q.name)][1] for i in have])
            out.append({"line": ln, "path": rs[0].path, "kind": rs[0].kind,
                        "displacement_order": rs[0].displacement_order,
                        "parameter": rs[0].parameter, "quantity": q.name, "runs": len(ok),
                        "error_slope": fit, "error_slope_finest_pair": last,
                        "observed_order": so, "slope_vs_unknowns": fit_n})
    return out


def main(argv=None):
    a, p = arguments(argv)
    try:
        if a.list:
            for n in all_names():
                st = spec.load(n)
                print(f"{n:28s} {st.title}")
            return 0
        names = a.names
        if not names:
            p.error("name a study (or all); --list shows them")
        if names == ["all"]:
            names = all_names()
        studies = [spec.load(n) for n in names]  # check every file before running anything
        if a.check:
            for st in studies:
                n = sum(len(x.points) * len(x.integrators) * len(x.solvers) * len(x.ranks)
                        * len(x.displacement_orders or [None]) for x in st.paths.values())
                print(f"{st.file}: ok ({n} runs)")
            return 0
        exe = executable()
        done = set()
        t0 = time.monotonic()
        for st in studies:
            if st.name in done:
                continue
            run_study(st, a, exe)
            done.add(st.name)
        print(f"scripts/study: {len(done)} stud{'y' if len(done) == 1 else 'ies'} in "
              f"{time.monotonic() - t0:.0f} s")
        return 0
    except StudyError as e:
        print(f"scripts/study: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
