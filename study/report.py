"""A study's outputs: study.csv (one row per run), study.md (the table to choose from),
work_precision.png (error against wall time and against unknowns, one panel pair per
quantity)."""

import csv
import datetime
import math
import os
import platform

import numpy as np

FIXED = ["path", "kind", "integrator", "solver", "ranks", "displacement_order", "index", "mesh_size_factor", "dt",
         "dt_initial", "varied", "parameter", "parameter_value", "status", "unknowns"]
COST = ["steps", "rejected", "wall_total_s", "wall_steps_s", "wall_per_step_s", "newton",
        "krylov", "peak_memory_mb_per_rank"]


def write(st, rows, summary, out, plots=True):
    write_csv(st, rows, os.path.join(out, "study.csv"))
    with open(os.path.join(out, "orders.csv"), "w", newline="") as f:
        cols = ["path", "kind", "displacement_order", "parameter", "quantity", "runs", "error_slope",
                "error_slope_finest_pair", "observed_order", "slope_vs_unknowns", "line"]
        w = csv.DictWriter(f, fieldnames=cols, extrasaction="ignore")
        w.writeheader()
        for o in summary["orders"]:
            w.writerow({c: _fmt(o.get(c, "")) for c in cols})
    write_md(st, rows, summary, os.path.join(out, "study.md"))
    if plots:
        plot(st, rows, summary, os.path.join(out, "work_precision.png"))


def write_csv(st, rows, path):
    unk = sorted({k for r in rows for k in r if k.startswith("unknowns_")})
    qcols = [f"{q}_{s}" for q in st.quantities for s in ("value", "error", "change_from_finest")]
    cols = FIXED + unk + COST + qcols + ["key"]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({c: _fmt(r.get(c, "")) for c in cols})


def _fmt(v):
    if isinstance(v, float):
        return "" if math.isnan(v) else f"{v:.10g}"
    return v


def settings(r):
    """The settings of a run in words."""
    s = [f"mesh factor {r['mesh_size_factor']:g}"]
    if r["kind"] == "adaptive":
        s.append(f"adaptive (dt0 {r['dt_initial']:g} s)")
    else:
        s.append(f"dt {r['dt']:g} s")
    if r["varied"]:
        s.append(r["varied"])
    s.append(r["integrator"])
    if "displacement_order" in r:
        s.append(f"order {r['displacement_order']}")
    s.append(r["solver"])
    s.append(f"{r['ranks']} rank{'s' if r['ranks'] > 1 else ''}")
    return ", ".join(s)


def machine():
    cpu = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"{cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}"


def _pct(x):
    if x is None or not np.isfinite(x):
        return "-"
    return f"{100 * x:.3g} %"


def write_md(st, rows, summary, path):
    ok = [r for r in rows if r["status"] == "ok"]
    L = [f"# Study {st.name}: {st.title}", ""]
    if st.description:
        L += [st.description.strip(), ""]
    from .spec import TOP
    rel = os.path.relpath(st.file, TOP)
    L += [f"Study file `{st.file if rel.startswith('..') else rel}`; "
          f"{len(rows)} runs ({len(ok)} finished); written "
          f"{datetime.datetime.now().strftime('%Y-%m-%d %H:%M')} on {machine()}. Wall times are "
          "those measured when each run was made (the run cache keeps them); each is the whole "
          "run (mesh generation, set-up, steps, output) as the user waits for it.", ""]
    L += ["## Quantities and references", "",
          "| quantity | measured | error measure | reference | reference's own estimated error |",
          "|---|---|---|---|---|"]
    refs = summary["references"]
    for q in st.quantities.values():
        at = ("at the end" if q.at == "end" else
              f"where {q.at['column']} reaches {q.at['value']:g}" if isinstance(q.at, dict) else
              "at t = " + ", ".join(f"{t:g}" for t in q.at) + " s")
        cname = (" + ".join(f"{w:g} {c}" for c, w in q.column.items()) if isinstance(q.column, dict)
                 else q.column)
        meas = f"`{cname}` of {q.file} {at}" + (f", minus {q.subtract.replace('_', ' ')}" if q.subtract else "")
        err = f"{q.norm} of the difference, relative ({q.unit})"
        if q.reference["kind"] == "closed_form":
            params = ", ".join(f"{k} = {v}" for k, v in q.reference.items() if k not in ("kind", "closed_form"))
            ref, est = f"closed form `{q.reference['closed_form']}` ({params})", "exact (series to 1e-12)"
        else:
            info = refs.get(q.name, {})
            ref = info.get("method", q.reference["kind"])
            v = np.atleast_1d(info.get("value", [np.nan]))
            ref += f"; value {', '.join(f'{x:.6g}' for x in v)}"
            e = np.atleast_1d(info.get("estimated_error", [np.nan]))
            sc = float(np.max(np.abs(v))) if q.scale == "reference" else q.scale
            est = _pct(float(np.max(e)) / sc) if sc else "-"
        L.append(f"| **{q.name}**: {q.label} | {meas} | {err} | {ref} | {est} |")
    L += ["", "## What an accuracy costs", "",
          "The cheapest run found (least total wall time) whose error is at most the target "
          "and stays at most the target on every finer run of each path it is on (a run on "
          "a space, a time and a combined path must hold on all three); \"not reached\" "
          "gives the best error found. A run that meets a target only by a cancellation of errors "
          "(space against time: a finer run of its path misses the target) is not chosen; "
          "when it would have been cheaper it is named in brackets.", ""]
    L += ["| quantity | target | cheapest settings | unknowns | steps | wall time | per step | error |",
          "|---|---|---|---|---|---|---|---|"]
    for q in st.quantities.values():
        est = _reference_error(st, q, refs)
        for tgt in st.targets:
            c = cheapest(ok, q.name, tgt)
            note = " (below the reference's own error estimate)" if est is not None and tgt < est else ""
            if c["best"] is not None:
                b, lucky = c["best"], c["lucky"]
                if not c["robust"]:
                    note += (" (only by a cancellation of errors: finer runs of its path miss "
                             "the target)")
                elif lucky["wall_total_s"] < b["wall_total_s"]:
                    note += (f" (cheaper by a cancellation of errors, not kept: {settings(lucky)}, "
                             f"{lucky['wall_total_s']:.2f} s, {_pct(lucky[f'{q.name}_error'])}; "
                             "finer runs of its path miss the target)")
                L.append(f"| {q.name} | {_pct(tgt)} | {settings(b)}{note} | {b['unknowns']} | "
                         f"{b['steps']} | {b['wall_total_s']:.2f} s | {b['wall_per_step_s']:.3g} s | "
                         f"{_pct(b[f'{q.name}_error'])} |")
            elif c["closest"] is not None:
                b = c["closest"]
                e = b[f"{q.name}_error"]
                L.append(f"| {q.name} | {_pct(tgt)} | not reached{note}; best {_pct(e)}: "
                         f"{settings(b)} | {b['unknowns']} | {b['steps']} | "
                         f"{b['wall_total_s']:.2f} s | {b['wall_per_step_s']:.3g} s | {_pct(e)} |")
            else:
                L.append(f"| {q.name} | {_pct(tgt)} | no run measured it | | | | | |")
    L += by_order(st, ok)
    L += ["", "## Observed orders", "",
          "Per refinement path: *error slope* = least-squares slope of log(error) against "
          "log(parameter) (mesh size factor, proportional to h, or dt), and of the finest pair; "
          "*observed order* = from the changes between the last three runs, "
          "log(|Q1-Q2|/|Q2-Q3|)/log(ratio), which needs no reference and is blind to what the "
          "path keeps fixed (the time error on a space path); *vs unknowns* = slope of the "
          "error against the number of unknowns (in 2D, -1 per order 2 in h).", "",
          "| path | parameter | quantity | runs | error slope (fit / finest pair) | observed order | vs unknowns |",
          "|---|---|---|---|---|---|---|"]
    for o in summary["orders"]:
        f = lambda x: "-" if x is None or not np.isfinite(x) else f"{x:.2f}"
        L.append(f"| {o['line']} | {o['parameter']} | {o['quantity']} | {o['runs']} | "
                 f"{f(o['error_slope'])} / {f(o['error_slope_finest_pair'])} | "
                 f"{f(o['observed_order'])} | {f(o['slope_vs_unknowns'])} |")
    tol = [r for r in rows if r["kind"] == "tolerance"]
    if tol:
        L += ["", "## Tolerance paths: change from the tightest run", "",
              "Each path varies one solver tolerance and keeps the discretisation, so the "
              "change from its tightest run is the solver's own error; the error against the "
              "reference adds the discretisation error.", "",
              "| path | setting | wall [s] | Newton | Krylov | "
              + " | ".join(f"{q} change / error" for q in st.quantities) + " |",
              "|---|---|---|---|---|" + "---|" * len(st.quantities)]
        for r in tol:
            if r["status"] != "ok":
                L.append(f"| {r['path']} | {r['varied']} ({r['solver']}) | {r['status']} |"
                         + " |" * (2 + len(st.quantities)))
                continue
            L.append(f"| {r['path']} | {r['varied']} ({r['solver']}) | {r['wall_total_s']:.2f} | "
                     f"{r['newton']} | {r['krylov']} | "
                     + " | ".join(f"{_pct(r[f'{q}_change_from_finest'])} / {_pct(r[f'{q}_error'])}"
                                  for q in st.quantities) + " |")
    L += ["", "## Runs", "", "| path | settings | unknowns | steps | wall [s] | per step [s] | "
          "Newton | Krylov | peak MB/rank | " + " | ".join(f"{q} error" for q in st.quantities) + " |",
          "|---|---|---|---|---|---|---|---|---|" + "---|" * len(st.quantities)]
    for r in rows:
        if r["status"] != "ok":
            L.append(f"| {r['path']} | {settings(r)} | {r['status']} |" + " |" * (7 + len(st.quantities)))
            continue
        L.append(f"| {r['path']} | {settings(r)} | {r['unknowns']} | {r['steps']} | "
                 f"{r['wall_total_s']:.2f} | {r['wall_per_step_s']:.3g} | {r['newton']} | "
                 f"{r['krylov']} | {r['peak_memory_mb_per_rank']:.0f} | "
                 + " | ".join(_pct(r[f"{q}_error"]) for q in st.quantities) + " |")
    L.append("")
    with open(path, "w") as f:
        f.write("\n".join(L))


def _reference_error(st, q, refs):
    """The reference's own estimated error, relative, or None (a closed form)."""
    if q.name in refs and q.reference["kind"] in ("richardson", "finest", "study"):
        v = np.atleast_1d(refs[q.name]["value"])
        sc = float(np.max(np.abs(v))) if q.scale == "reference" else q.scale
        return float(np.max(np.atleast_1d(refs[q.name]["estimated_error"]))) / sc
    return None


def cheapest(ok, name, tgt):
    """The choice for one quantity and target among finished runs `ok`: {"best": the least
    total wall time among the runs whose error is at most tgt and stays so on every finer run
    of their path line (if none: the cheapest that meets it at all), "robust": whether best
    is such a run, "lucky": the cheapest that meets it at all, "closest": the run of least
    error (for "not reached")}; None where there is no such run."""
    errs = [(r, r[f"{name}_error"]) for r in ok if np.isfinite(r[f"{name}_error"])]
    good = [r for r, e in errs if e <= tgt]
    robust = [r for r in good if _holds(r, name, tgt, errs)]
    wall = lambda r: r["wall_total_s"]  # noqa: E731
    return {"best": min(robust or good, key=wall) if good else None, "robust": bool(robust),
            "lucky": min(good, key=wall) if good else None,
            "closest": min(errs, key=lambda x: x[1])[0] if errs else None}


def cheapest_by_order(ok, name, tgt):
    """{element order: cheapest(...)} over the runs of each displacement order."""
    orders = sorted({r["displacement_order"] for r in ok})
    return {o: cheapest([r for r in ok if r["displacement_order"] == o], name, tgt)
            for o in orders}


def by_order(st, ok):
    """study.md's per-order table: for each quantity and target the cheapest run at each
    element order and the ratio of their wall times (empty with one order)."""
    orders = sorted({r["displacement_order"] for r in ok})
    if len(orders) < 2:
        return []
    L = ["", "## What an accuracy costs at each element order", "",
         "The same choice among the runs of one displacement order at a time (order 1: "
         "linear displacement, stabilised; order 2: quadratic displacement, linear pressure, "
         "Taylor-Hood). The ratio is the wall time of the cheapest order-" + str(orders[-1])
         + " run over that of the cheapest order-" + str(orders[0]) + " run (below 1 the "
         "higher order is cheaper), then the cheaper order. Only the runs the study tried: a coarser mesh than its "
         "coarsest might have met a target more cheaply.", "",
         "| quantity | target | " + " | ".join(f"cheapest order-{o} run | wall time" for o in orders)
         + f" | ratio {orders[-1]} / {orders[0]}, cheaper order |",
         "|---|---|" + "---|---|" * len(orders) + "---|"]
    for q in st.quantities.values():
        for tgt in st.targets:
            got = cheapest_by_order(ok, q.name, tgt)
            cells = []
            for o in orders:
                c = got[o]
                if c["best"] is not None:
                    b = c["best"]
                    cells.append(f"{_short(b)}, {b['unknowns']} unknowns, "
                                 f"{_pct(b[f'{q.name}_error'])}"
                                 + ("" if c["robust"] else " (by a cancellation)")
                                 + f" | {b['wall_total_s']:.2f} s")
                elif c["closest"] is not None:
                    cells.append(f"not reached (best {_pct(c['closest'][f'{q.name}_error'])}) | -")
                else:
                    cells.append("- | -")
            L.append(f"| {q.name} | {_pct(tgt)} | " + " | ".join(cells)
                     + f" | {_verdict(got, orders)} |")
    return L


def _verdict(got, orders):
    """The ratio cell: "0.65, order 2" (the ratio and the cheaper order), "order 2 only" when
    only one order meets the target, "-" when neither."""
    lo, hi = got[orders[0]]["best"], got[orders[-1]]["best"]
    if lo is not None and hi is not None and lo["wall_total_s"] > 0:
        ratio = hi["wall_total_s"] / lo["wall_total_s"]
        return f"{ratio:.2f}, order {orders[-1] if ratio < 1 else orders[0]}"
    met = [o for o in orders if got[o]["best"] is not None]
    return f"order {met[0]} only" if len(met) == 1 else "-"


def order_ratio(ok, name, tgt):
    """Wall time of the cheapest highest-order run over that of the cheapest lowest-order run
    for one quantity and target (nan when either order misses the target)."""
    got = cheapest_by_order(ok, name, tgt)
    orders = sorted(got)
    lo, hi = got[orders[0]]["best"], got[orders[-1]]["best"]
    if lo is None or hi is None or len(orders) < 2:
        return float("nan")
    return hi["wall_total_s"] / lo["wall_total_s"]


def _short(r):
    """A run's settings in few words (the per-order table): path, mesh factor, dt."""
    s = f"{r['path']} f{r['mesh_size_factor']:g}"
    s += f" dt0 {r['dt_initial']:g}" if r["kind"] == "adaptive" else f" dt {r['dt']:g}"
    if r["varied"]:
        s += f" {r['varied']}"
    return s + f" {r['integrator']}"


def _holds(r, name, tgt, errs):
    """True when every finer run also has an error <= tgt: later on the run's path line, and
    on every other line that has the same run (the same settings, one cache key: a time
    path's run that is also on the space and the combined path must hold on all three, or
    its error is a cancellation of space against time)."""
    key = r.get("key")
    at = [(x["line"], x["index"]) for x, _ in errs
          if x is r or (key is not None and x.get("key") == key)]
    return all(e <= tgt for x, e in errs for line, index in at
               if x["line"] == line and x["index"] > index)


def _label(r):
    if r["parameter"] == "mesh_size_factor":
        return f"f{r['mesh_size_factor']:g}" + (f"/dt{r['dt']:g}" if r["kind"] == "both" else "")
    if r["parameter"] == "dt":
        return f"dt{r['dt']:g}"
    return f"{r['parameter_value']:g}"


class _Labels:
    """Point labels of one log-log axes that do not print over each other: a label is left
    out when an earlier one sits within `gap` decades in both directions (the legend and the
    study.csv name every run; the labels only orient the eye)."""

    def __init__(self, ax, gap=0.07):
        self.ax, self.gap, self.placed = ax, gap, []

    def add(self, text, x, y, color):
        lx, ly = math.log10(x), math.log10(y)
        if any(abs(lx - px) < self.gap and abs(ly - py) < self.gap for px, py in self.placed):
            return
        self.placed.append((lx, ly))
        self.ax.annotate(text, (x, y), fontsize=7, xytext=(3, 3), textcoords="offset points",
                         color=color)


ORDER_STYLES = ["o-", "s--", "^:", "D-."]  # element order 1, 2, ...: line style and marker


def line_styles(rows):
    """How each line of the plot is drawn: ({line: colour index}, {line: matplotlib format},
    {element order: format}). One line style and marker per displacement order (order 1
    solid with circles, order 2 dashed with squares); one colour per the k-th line of a kind,
    integrator, solver and ranks at its order, so that a path and its order-2 twin (space
    and space_o2) share a colour and differ in style."""
    elem = sorted({r.get("displacement_order", 1) for r in rows})
    styles = {o: s for o, s in zip(elem, ORDER_STYLES)}
    hue, line_hue, line_style, nth = {}, {}, {}, {}
    for r in rows:
        if r["line"] in line_hue:
            continue
        o = r.get("displacement_order", 1)
        like = (r["kind"], r["integrator"], r["solver"], r["ranks"])
        k = nth.setdefault((like, o), [])
        k.append(r["line"])
        line_style[r["line"]] = styles.get(o, "o-")
        line_hue[r["line"]] = hue.setdefault((like, len(k)), len(hue))
    return line_hue, line_style, styles


def plot(st, rows, summary, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker  # noqa: F401
    qs = list(st.quantities.values())
    fig, axes = plt.subplots(len(qs), 2, figsize=(13, 4.6 * len(qs)), squeeze=False)
    lines = []
    for r in rows:
        if r["line"] not in lines:
            lines.append(r["line"])
    order = {(o["line"], o["quantity"]): o for o in summary["orders"]}
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    line_hue, line_style, styles = line_styles(rows)
    # second panel: against the unknowns, or (a study of tolerances only: one discretisation)
    # against the Krylov iterations, the work without the noise of a shared machine's clock
    tol_only = all(r["kind"] == "tolerance" for r in rows)
    work = "krylov" if tol_only else "unknowns"
    for qi, q in enumerate(qs):
        a1, a2 = axes[qi]
        labels1, labels2 = _Labels(a1), _Labels(a2)
        for li, ln in enumerate(lines):
            rs = [r for r in rows if r["line"] == ln and r["status"] == "ok"
                  and np.isfinite(r[f"{q.name}_error"]) and r[f"{q.name}_error"] > 0]
            if not rs:
                continue
            c = colors[line_hue[ln] % len(colors)]
            st_ = line_style[ln]
            e = [100.0 * r[f"{q.name}_error"] for r in rs]
            a1.loglog([r["wall_total_s"] for r in rs], e, st_, color=c, label=ln)
            for r in rs:
                labels1.add(_label(r), r["wall_total_s"], 100.0 * r[f"{q.name}_error"], c)
            o = order.get((ln, q.name), {})
            so = o.get("observed_order", float("nan"))
            sl = o.get("error_slope", float("nan"))
            a2.loglog([r[work] for r in rs], e, st_, color=c,
                      label=f"{ln}: error slope vs {rs[0]['parameter']} "
                            f"{sl:.2f}, observed order {so:.2f}"
                            if np.isfinite(so) and rs[0]["kind"] != "tolerance" else
                            f"{ln}: error slope vs {rs[0]['parameter']} {sl:.2f}")
            if tol_only:
                for r in rs:
                    labels2.add(_label(r), r[work], 100.0 * r[f"{q.name}_error"], c)
        # the targets: dashed, dark enough to read, named at the right edge of each panel
        for tgt in st.targets:
            for ax in (a1, a2):
                ax.axhline(100.0 * tgt, color="0.35", lw=1.0, ls="--", zorder=0.5)
                ax.annotate(f"{100.0 * tgt:g} %", (1.0, 100.0 * tgt), xycoords=("axes fraction", "data"),
                            xytext=(-2, 2), textcoords="offset points", ha="right", va="bottom",
                            fontsize=7, color="0.25")
        a1.set_xlabel("wall time of the run [s]")
        a1.set_ylabel(f"error of {q.name} [{q.unit}]")
        # wall times span one or two decades: label 2 and 5 between the powers of ten
        a1.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}"))
        lo, hi = a1.get_xlim()
        if hi / lo > 10:
            a1.xaxis.set_minor_formatter(matplotlib.ticker.FuncFormatter(
                lambda v, _: f"{v:g}" if round(v / 10 ** math.floor(math.log10(v))) in (2, 5) else ""))
        else:  # within a decade (quick runs): evenly spaced ticks, each labelled
            a1.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(5))
            a1.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:.3g}"))
            a1.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        a1.set_title(f"{q.label}", fontsize=10)
        if tol_only:
            a2.set_xlabel("Krylov iterations of the run (sum over its steps)")
            a2.set_title("error against linear iterations", fontsize=10)
            a2.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}"))
            a2.xaxis.set_minor_formatter(matplotlib.ticker.FuncFormatter(
                lambda v, _: f"{v:g}" if round(v / 10 ** math.floor(math.log10(v))) in (2, 5) else ""))
        else:
            a2.set_xlabel("unknowns")
            a2.set_title("error against unknowns (orders in the legend)", fontsize=10)
        a1.grid(True, which="both", alpha=0.3)
        a2.grid(True, which="both", alpha=0.3)
        a1.legend(fontsize=7)
        a2.legend(fontsize=7)
    title = f"study {st.name}: {st.title}"
    if len(styles) > 1:
        words = {"o-": "solid, circles", "s--": "dashed, squares", "^:": "dotted, triangles",
                 "D-.": "dash-dot, diamonds"}
        title += "\n" + "; ".join(f"displacement order {o}: {words[s]}" for o, s in styles.items())
    fig.suptitle(title, fontsize=12)
    fig.tight_layout(rect=(0, 0, 1, 1 - (0.45 if len(styles) < 2 else 0.7) / fig.get_figheight()))
    fig.savefig(path, dpi=110)
    plt.close(fig)
