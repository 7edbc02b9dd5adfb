"""The element-order axis of scripts/study (docs/studies.md, "Element orders"), ctest
study.element_orders. No poroseam run: the study files are read and planned, the report is
given fabricated runs.

    spec    `displacement_orders` (study-wide, per path) multiplies the lines; each run's
            arguments carry -displacement_order of its order, its cache key differs between
            orders; a study without the key plans exactly as before (no -displacement_order,
            order 1 recorded from the scene); bad values and a -displacement_order among the
            options of a path with orders give one line naming the file and the key
    report  the cheapest run per order and target, the ratio of their wall times, the
            per-order table of study.md and the plot's line styles, on fabricated runs whose
            answer is known by construction (including a cheaper order-2 run that meets a
            target only by a cancellation of errors, an order that misses a target, and a run
            on two path lines that holds on one of them only)"""
import math
import os
import shutil
import subprocess
import sys

SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
HERE = os.path.join(SOURCE, "tests", "study")
SCRATCH = os.path.join(os.environ.get("POROSEAM_TEST_OUTPUT", "/tmp/poroseam-test-output"),
                       "study_element_orders")
sys.path.insert(0, SOURCE)
from study import report, runs, spec  # noqa: E402

failures = []


def check(name, ok, detail=""):
    print(f"  {'PASS' if ok else 'FAIL'}  {name}" + (f": {detail}" if detail else ""), flush=True)
    if not ok:
        failures.append(name)


with open(os.path.join(HERE, "terzaghi_orders.toml")) as f:
    BASE = f.read()


def write(name, text):
    p = os.path.join(SCRATCH, name + ".toml")
    with open(p, "w") as f:
        f.write(text)
    return p


def top(text, line):
    """The base study with a top-level line added (before the first table)."""
    return text.replace('solvers = ["direct"]\n', 'solvers = ["direct"]\n' + line + "\n", 1)


def in_path(text, path, line):
    return text.replace(f"[paths.{path}]\n", f"[paths.{path}]\n{line}\n", 1)


def order_arg(r):
    a = r.args
    got = [a[i + 1] for i in range(len(a) - 1) if a[i] == "-displacement_order"]
    return got


def spec_checks():
    exe = sys.executable  # any file: the binary only enters the keys
    cache = os.path.join(SCRATCH, "cache")
    old = runs.plan(spec.load(write("old", BASE)), exe, cache)
    check("a study without displacement_orders: no -displacement_order, order 1 recorded",
          all(order_arg(r) == [] and r.displacement_order == 1 for r in old)
          and all("order" not in r.line for r in old), f"{len(old)} runs")
    st = spec.load(write("both", top(BASE, "displacement_orders = [1, 2]")))
    plan = runs.plan(st, exe, cache)
    check("displacement_orders = [1, 2] doubles the runs", len(plan) == 2 * len(old),
          f"{len(plan)} against {len(old)}")
    check("each run's arguments carry its order",
          all(order_arg(r) == [str(r.displacement_order)] for r in plan)
          and {r.displacement_order for r in plan} == {1, 2})
    key = {(r.path, r.index, r.displacement_order): r.key for r in plan}
    k1 = {r.key for r in plan if r.displacement_order == 1}
    k2 = {r.key for r in plan if r.displacement_order == 2}
    check("cache keys differ between the orders (no order-1 key is an order-2 key)",
          not (k1 & k2) and all(key[(p, i, 1)] != key[(p, i, 2)] for p, i, _ in key),
          f"{len(k1)} + {len(k2)} keys")
    check("line names carry the order", all(r.line.endswith(f"order {r.displacement_order}")
                                            for r in plan))
    st = spec.load(write("path", in_path(top(BASE, "displacement_orders = [1]"), "time",
                                         "displacement_orders = 2")))
    plan = runs.plan(st, exe, cache)
    check("a path's displacement_orders overrides the study's",
          {r.displacement_order for r in plan if r.path == "time"} == {2}
          and {r.displacement_order for r in plan if r.path == "space"} == {1})
    ref = BASE.replace('reference = { closed_form = "terzaghi.settlement", H = 1.0 }',
                       'reference = { richardson = "space", displacement_order = 2 }')
    spec.load(write("ref_ok", top(ref, "displacement_orders = [1, 2]")))
    bad = [
        ("order 3", top(BASE, "displacement_orders = [1, 3]"), "'displacement_orders'"),
        ("an order twice", top(BASE, "displacement_orders = [2, 2]"), "'displacement_orders'"),
        ("a string", top(BASE, 'displacement_orders = "2"'), "'displacement_orders'"),
        ("true", in_path(BASE, "space", "displacement_orders = true"),
         "'paths.space.displacement_orders'"),
        ("an empty list", in_path(BASE, "time", "displacement_orders = []"),
         "'paths.time.displacement_orders'"),
        ("-displacement_order in the path's options", in_path(
            top(BASE, "displacement_orders = [1, 2]"), "time",
            'options = "-displacement_order 2"'), "'paths.time.options'"),
        ("-displacement_order in the study's options", top(BASE.replace(
            'options = "-output_fields_every 0"',
            'options = "-output_fields_every 0 -displacement_order 2"'),
            "displacement_orders = [1, 2]"), "'options'"),
        ("a reference at an order its path lacks", top(ref, "displacement_orders = [1]"),
         "'quantities.settlement.reference.displacement_order'"),
        ("a reference order without orders", ref,
         "'quantities.settlement.reference.displacement_order'"),
    ]
    for what, text, key in bad:
        p = write("bad", text)
        try:
            spec.load(p)
            msg = None
        except spec.StudyError as e:
            msg = str(e)
        check(f"rejected: {what}", msg is not None and "bad.toml" in msg and key in msg
              and len(msg.splitlines()) == 1, msg or "accepted")
    # the same through the driver: exit 2, one line on stderr
    d = subprocess.run([sys.executable, "-m", "study", "--check", p], cwd=SOURCE,
                       env=dict(os.environ, PYTHONPATH=SOURCE), capture_output=True, text=True,
                       timeout=60)
    check("scripts/study --check on a bad order: exit 2, one line", d.returncode == 2
          and len(d.stderr.strip().splitlines()) == 1 and "displacement_order" in d.stderr,
          d.stderr.strip())
    # a study with -displacement_order in its options and no axis stays valid (old files)
    st = spec.load(write("old_opt", BASE.replace('options = "-output_fields_every 0"',
                                                 'options = "-output_fields_every 0 '
                                                 '-displacement_order 2"')))
    plan = runs.plan(st, exe, cache)
    check("no axis, -displacement_order 2 in the options: accepted, order 2 recorded",
          {r.displacement_order for r in plan} == {2})


def run(path, order, index, error, wall, unknowns=100, key=None):
    """A fabricated finished run on line `path, order` (finer with index)."""
    return {"key": key or f"{path}-{order}-{index}","path": path, "kind": "space", "integrator": "beuler", "solver": "direct",
            "ranks": 1, "displacement_order": order, "index": index, "line": f"{path}, {order}",
            "mesh_size_factor": 2.0 ** -index, "dt": 0.1, "dt_initial": 0.1, "varied": "",
            "parameter": "mesh_size_factor", "parameter_value": 2.0 ** -index, "status": "ok",
            "unknowns": unknowns, "steps": 10, "wall_total_s": wall, "wall_per_step_s": wall / 10,
            "newton": 10, "krylov": 10, "peak_memory_mb_per_rank": 1.0, "q_error": error,
            "q_change_from_finest": 0.0}


def report_checks():
    rows = [
        # order 1: errors 8 %, 2 %, 0.5 %, 0.3 % at 1, 2, 4, 8 s
        run("space", 1, 0, 0.08, 1.0), run("space", 1, 1, 0.02, 2.0),
        run("space", 1, 2, 0.005, 4.0), run("space", 1, 3, 0.003, 8.0),
        # a second order-1 line, cheaper to 10 % (0.8 s)
        run("time", 1, 0, 0.09, 0.8), run("time", 1, 1, 0.2, 0.9),
        # order 2: its coarsest meets 1 % by a cancellation (the next run misses), so the
        # 1 % choice is the 1.5 s run; it never reaches 0.1 %
        run("space_o2", 2, 0, 0.006, 0.5), run("space_o2", 2, 1, 0.015, 0.7),
        run("space_o2", 2, 2, 0.004, 1.5), run("space_o2", 2, 3, 0.002, 3.0),
    ]
    want = {  # target: (order-1 wall, order-2 wall) of the choice; None: not reached
        0.1: (1.0, 0.5),   # "time" misses 10 % on its finer run: not kept; order 2 holds
        0.01: (4.0, 1.5),
        0.001: (None, None),
    }
    for tgt, (w1, w2) in want.items():
        got = report.cheapest_by_order(rows, "q", tgt)
        g1 = got[1]["best"]["wall_total_s"] if got[1]["best"] else None
        g2 = got[2]["best"]["wall_total_s"] if got[2]["best"] else None
        check(f"cheapest per order at {100 * tgt:g} %", (g1, g2) == (w1, w2),
              f"order 1 {g1}, order 2 {g2}, expected {w1}, {w2}")
        ratio = report.order_ratio(rows, "q", tgt)
        expected = w2 / w1 if w1 and w2 else float("nan")
        check(f"wall-time ratio order 2 / order 1 at {100 * tgt:g} %",
              (math.isnan(ratio) and math.isnan(expected)) or abs(ratio - expected) < 1e-12,
              f"{ratio:.4g}, expected {expected:.4g}")
    check("the cancellation run is the order's lucky one at 1 %, not its choice",
          report.cheapest_by_order(rows, "q", 0.01)[2]["lucky"]["wall_total_s"] == 0.5)

    # one run (one key) on two lines: it must hold on both; here a finer run of the space
    # line misses 1 % (a cancellation), so the choice is the combined path's next run
    shared = [run("space", 1, 0, 0.005, 1.0, key="k"), run("space", 1, 1, 0.02, 2.0),
              run("both", 1, 0, 0.005, 1.0, key="k"), run("both", 1, 1, 0.001, 3.0)]
    c = report.cheapest(shared, "q", 0.01)
    check("a run on two lines must hold on both (else a cancellation, not chosen)",
          c["best"]["wall_total_s"] == 3.0 and c["lucky"]["wall_total_s"] == 1.0,
          f"chosen {c['best']['wall_total_s']} s")

    class Q:
        name, label, unit = "q", "a quantity", "%"

    class St:
        quantities = {"q": Q()}
        targets = [0.1, 0.01, 0.001]

    md = "\n".join(report.by_order(St(), rows))
    line = [x for x in md.splitlines() if x.startswith("| q | 1 % |")]
    check("study.md per-order row at 1 %: both choices, the ratio 0.38 and order 2 cheaper",
          len(line) == 1 and "space f0.25 " in line[0] and "4.00 s" in line[0]
          and "space_o2 f0.25 " in line[0] and "1.50 s" in line[0]
          and line[0].rstrip().endswith("| 0.38, order 2 |"), line[0] if line else md)
    line = [x for x in md.splitlines() if x.startswith("| q | 0.1 % |")]
    check("study.md per-order row at 0.1 %: not reached at either order, no ratio",
          len(line) == 1 and line[0].count("not reached") == 2
          and line[0].rstrip().endswith("| - |"), line[0] if line else md)
    order1_only = rows + [run("space", 1, 4, 0.0005, 20.0)]  # order 1 alone reaches 0.1 %
    line = [x for x in "\n".join(report.by_order(St(), order1_only)).splitlines()
            if x.startswith("| q | 0.1 % |")]
    check("study.md per-order row at 0.1 % when order 1 alone reaches it: 'order 1 only'",
          len(line) == 1 and "20.00 s" in line[0] and line[0].rstrip().endswith("| order 1 only |"),
          line[0] if line else "")
    check("one order only: no per-order table",
          report.by_order(St(), [r for r in rows if r["displacement_order"] == 1]) == [])
    hue, style, _ = report.line_styles(rows)
    check("plot: order 1 solid circles, order 2 dashed squares; a path and its order-2 twin "
          "share a colour", style["space, 1"] == "o-" and style["space_o2, 2"] == "s--"
          and hue["space, 1"] == hue["space_o2, 2"] and hue["time, 1"] != hue["space, 1"],
          f"{style}, {hue}")
    class Full(St):  # noqa: E306
        name, title, description = "fabricated", "fabricated runs", ""
        file = os.path.join(SCRATCH, "fabricated.toml")
    report.plot(Full(), rows, {"orders": []}, os.path.join(SCRATCH, "work_precision.png"))
    check("plot with two orders written",
          os.path.getsize(os.path.join(SCRATCH, "work_precision.png")) > 0)


def main():
    shutil.rmtree(SCRATCH, ignore_errors=True)
    os.makedirs(SCRATCH)
    spec_checks()
    report_checks()
    if failures:
        sys.exit(f"FAIL: {len(failures)} check(s): " + "; ".join(failures))
    print("all checks passed")


if __name__ == "__main__":
    main()
