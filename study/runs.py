"""The runs of a study: their option lists, the cache, running poroseam.

A run is identified by its settings: the full argument list given to poroseam (the output
directory left out), the content of every file it names (scene, solver preset, the mesh and
options files they name, generated tables), the rank count and the binary's identity (size,
modification time and SHA-256 of the executable). The SHA-256 of all that is the run's key;
its outputs and measurements live in <cache>/<key>/ (default output/study_cache/), shared by
all studies, so a study run again only runs what is new."""

import hashlib
import json
import os
import subprocess
import sys
import time

import numpy as np

from . import closed_forms
from .spec import TOP

sys.path.insert(0, os.path.join(TOP, "bench"))
import parse as bench_parse  # noqa: E402  (bench/parse.py: progress lines, -memory_view)

CACHE_VERSION = 1


def read_options(path, seen=None):
    """A PETSc options file as {"-name": "value"}, nested -options_file included (in place)."""
    seen = seen or set()
    opts = {}
    path = os.path.abspath(path)
    if path in seen:
        return opts
    seen.add(path)
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            parts = line.split(None, 1)
            val = parts[1].strip() if len(parts) > 1 else ""
            if parts[0] == "-options_file":
                opts.update(read_options(_resolve_in(path, val, preset=True), seen))
            else:
                opts[parts[0]] = val
    return opts


def _resolve(p):
    return p if os.path.isabs(p) else os.path.join(TOP, p)


def _resolve_in(options_file, p, preset=False):
    """A path named in an options file, as poroseam finds it (docs/scenes.md, "Options files
    and paths"): next to that file, else from the working directory (the repository root for
    studies), else for -options_file [options/]solvers/<name>.opts the solver preset."""
    if os.path.isabs(p):
        return p
    beside = os.path.normpath(os.path.join(os.path.dirname(options_file), p))
    if os.path.exists(beside) or not os.path.exists(_resolve(p)):
        if preset and not os.path.exists(beside):
            head, name = os.path.split(os.path.normpath(p))
            named = os.path.join(TOP, "options", "solvers", name)
            if head in ("solvers", os.path.join("options", "solvers")) and os.path.isfile(named):
                return named
        return beside
    return _resolve(p)


def options_of(args):
    """{"-name": "value"} of an argument list (later wins; -options_file read in place)."""
    opts = {}
    i = 0
    while i < len(args):
        a = args[i]
        nxt = args[i + 1] if i + 1 < len(args) else None
        has_val = nxt is not None and not (nxt.startswith("-") and not _is_number(nxt))
        if a == "-options_file" and nxt is not None:
            opts.update(read_options(_resolve(nxt)))
            i += 2
        elif has_val:
            opts[a] = nxt
            i += 2
        else:
            opts[a] = ""
            i += 1
    return opts


def _is_number(s):
    try:
        float(s)
        return True
    except ValueError:
        return False


class Run:
    """One run of a study: path, line (integrator, solver, ranks, element order),
    displacement_order, index on the path,
    point {mesh_size_factor, dt, vary}, args (without -output_dir), key, dir, result."""


def plan(study, exe, cache):
    """The runs of a study, in path order (coarse to fine), with their keys."""
    runs = []
    ident = binary_identity(exe)
    # the element order is named in the lines only where the study has the axis (old studies'
    # lines, legends and tables read as before)
    named = any(p.displacement_orders is not None for p in study.paths.values())
    for pname, path in study.paths.items():
        for order in path.displacement_orders or [None]:
            for integ in path.integrators:
                for solver in path.solvers:
                    for ranks in path.ranks:
                        for i, pt in enumerate(path.points):
                            runs.append(_run(study, path, pname, order, integ, solver, ranks,
                                             i, pt, named, ident, cache))
    return runs


def _run(study, path, pname, order, integ, solver, ranks, i, pt, named, ident, cache):
    r = Run()
    r.path, r.kind, r.integrator, r.solver, r.ranks = pname, path.kind, integ, solver, ranks
    r.index, r.point = i, pt
    r.parameter = path.parameter
    r.value = (pt[path.parameter] if path.parameter in ("mesh_size_factor", "dt")
               else float(pt["vary"][path.parameter]))
    r.args, r.tables = arguments(study, path, integ, solver, pt, order)
    r.opts = options_of(r.args)
    # the order the run has: the axis's, else the scene's own (poroseam's default 1)
    r.displacement_order = int(float(r.opts.get("-displacement_order", "1") or 1))
    r.line = (f"{pname}, {integ}, {solver}, {ranks} rank{'s' if ranks > 1 else ''}"
              + (f", order {r.displacement_order}" if named else ""))
    r.key = run_key(r.args, r.tables, ranks, ident)
    r.dir = os.path.join(cache, r.key)
    r.post, r.post_stamp = postprocess_command(study, r.dir)
    return r


def arguments(study, path, integ, solver, pt, order=None):
    """poroseam's arguments for one run (order: scene, solver preset, study options,
    integrator, path options, the element order, the point's settings, probes, tables).
    Without an element order (a study without displacement_orders) no -displacement_order is
    given: the scene's own holds, and the arguments (so the cache keys) are those of before."""
    args = ["-options_file", study.scene,
            "-options_file", os.path.join(TOP, "options", "solvers", solver + ".opts")]
    args += study.options + study.integrators[integ] + path.options
    if order is not None:
        args += ["-displacement_order", str(order)]
    args += ["-mesh_size_factor", repr(pt["mesh_size_factor"]), "-ts_dt", repr(pt["dt"]),
             "-ts_max_time", repr(study.end_time)]
    if path.adaptive:
        args += ["-ts_max_steps", str(study.max_steps)]
    else:
        args += ["-ts_max_steps", str(int(round(study.end_time / pt["dt"])))]
    for opt, val in pt["vary"].items():
        args += [opt, val]
    for name, xyz in study.probes.items():
        args += [f"-probe_{name}", ",".join(repr(x) for x in xyz)]
    tables = {}
    if study.tables:
        opts = options_of(args)
        if path.adaptive:  # steps unknown in advance: a fine uniform grid
            times = np.linspace(0.0, study.end_time, 4001)
        else:
            n = int(round(study.end_time / pt["dt"]))
            times = pt["dt"] * np.arange(0, n + 6)  # a few beyond the end, as PETSc may ask
        for opt, spec in study.tables.items():
            vals = closed_forms.evaluate(spec["closed_form"], times, opts, spec, {})
            text = "time,factor\n" + "".join(f"{t:.17g},{v:.17g}\n" for t, v in zip(times, vals))
            tables[opt] = text
    return args, tables


_identity = {}


def binary_identity(exe):
    st = os.stat(exe)
    k = (exe, st.st_size, st.st_mtime_ns)
    if k not in _identity:
        h = hashlib.sha256()
        with open(exe, "rb") as f:
            for chunk in iter(lambda: f.read(1 << 20), b""):
                h.update(chunk)
        _identity[k] = h.hexdigest()
    return _identity[k]


def _file_digest(path, seen):
    """SHA-256 of a file and, for an options file, of the -mesh and -options_file files it
    names (a .geo's own includes are not followed)."""
    path = os.path.abspath(path)
    if path in seen or not os.path.isfile(path):
        return ""
    seen.add(path)
    with open(path, "rb") as f:
        data = f.read()
    parts = [hashlib.sha256(data).hexdigest()]
    if path.endswith(".opts"):
        for line in data.decode(errors="replace").splitlines():
            w = line.split("#", 1)[0].split()
            if len(w) == 2 and w[0] in ("-options_file", "-mesh"):
                nested = _resolve_in(path, w[1], preset=w[0] == "-options_file")
                parts.append(w[1] + ":" + _file_digest(nested, seen))
    return ",".join(parts)


def run_key(args, tables, ranks, ident):
    seen = set()
    items = [f"v{CACHE_VERSION}", f"binary {ident}", f"ranks {ranks}"]
    for i, a in enumerate(args):
        items.append(a)
        if i > 0 and args[i - 1] in ("-options_file", "-mesh") and os.path.isfile(_resolve(a)):
            items.append("content " + _file_digest(_resolve(a), seen))
    for opt in sorted(tables):
        items.append(f"table {opt} " + hashlib.sha256(tables[opt].encode()).hexdigest())
    return hashlib.sha256("\n".join(items).encode()).hexdigest()[:20]


def postprocess_command(study, run_dir):
    """The study's postprocess command for a run ({run_dir} filled in, a repository script
    made absolute) and its stamp: the command and the script's content. Not part of the run's
    key: a changed script re-runs the postprocessing of cached runs, not the runs."""
    if not study.postprocess:
        return [], ""
    pp = [a.replace("{run_dir}", run_dir) for a in study.postprocess]
    if pp and not os.path.isabs(pp[0]) and os.path.exists(os.path.join(TOP, pp[0])):
        pp[0] = os.path.join(TOP, pp[0])
    stamp = hashlib.sha256("\n".join(pp).encode())
    if os.path.isfile(pp[0]):
        with open(pp[0], "rb") as f:
            stamp.update(f.read())
    return pp, stamp.hexdigest()


def run_postprocess(run, timeout, env=None):
    """Runs the postprocess command of a run; returns "ok" or why not."""
    done = subprocess.run(run.post, cwd=TOP, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=timeout)
    if done.returncode == 0:
        return "ok"
    with open(os.path.join(run.dir, "postprocess.txt"), "w") as f:
        f.write(done.stdout)
    return f"postprocess failed (exit {done.returncode})"


def cached(run, timeout=600):
    f = os.path.join(run.dir, "result.json")
    if os.path.isfile(f):
        with open(f) as fh:
            res = json.load(fh)
        if res.get("status") == "ok":
            post = getattr(run, "post", [])
            if post and res.get("post_stamp") != run.post_stamp:
                if run_postprocess(run, timeout) != "ok":
                    return None
                res["post_stamp"] = run.post_stamp
                with open(f, "w") as fh:
                    json.dump(res, fh, indent=1)
            return res
    return None


def execute(run, exe, study, log=print):
    """Runs poroseam for one run (argument list, no shell), measures it, writes result.json."""
    os.makedirs(run.dir, exist_ok=True)
    args = list(run.args)
    for opt, text in run.tables.items():
        tf = os.path.join(run.dir, opt.lstrip("-") + ".csv")
        with open(tf, "w") as f:
            f.write(text)
        args += [opt, tf]
    cmd = [exe] + args + ["-output_dir", run.dir, "-memory_view"]
    if run.ranks > 1:
        cmd = ["mpiexec", "-n", str(run.ranks)] + cmd
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    with open(os.path.join(run.dir, "command.json"), "w") as f:
        json.dump(cmd, f, indent=0)
    t0 = time.monotonic()
    status = "ok"
    try:
        done = subprocess.run(cmd, cwd=TOP, env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True, timeout=study.timeout)
        out = done.stdout
        if done.returncode != 0:
            status = f"failed (exit {done.returncode})"
    except subprocess.TimeoutExpired as e:
        out = e.stdout.decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        status = f"timeout ({study.timeout:g} s)"
    wall = time.monotonic() - t0
    with open(os.path.join(run.dir, "stdout.txt"), "w") as f:
        f.write(out)
    if status == "ok" and getattr(run, "post", []):
        status = run_postprocess(run, study.timeout, env)
    res = measure(out, run.dir, wall)
    res["status"] = status
    res["post_stamp"] = getattr(run, "post_stamp", "")
    res["command"] = cmd
    with open(os.path.join(run.dir, "result.json"), "w") as f:
        json.dump(res, f, indent=1)
    if status != "ok":
        tail = "\n".join(out.strip().splitlines()[-5:])
        log(f"  {status}: {run.dir}/stdout.txt ends:\n{tail}")
    return res


def measure(out, run_dir, wall):
    """What a run cost: unknowns per field, steps, wall times, iterations, peak memory."""
    info = bench_parse.poroseam_stdout(out)
    res = {"fields": info["fields"], "unknowns": sum(info["fields"].values()),
           "wall_total_s": wall, "peak_memory_mb_per_rank":
               (info["peak_memory_per_rank"] or float("nan")) / 1e6}
    ts = read_csv(os.path.join(run_dir, "timeseries.csv"))
    if ts is not None and "step" in ts:
        keep = ts["step"] > 0
        walls = ts["wall_time"][keep] if "wall_time" in ts else np.array([])
        res.update(steps=int(keep.sum()), wall_steps_s=float(walls.sum()),
                   wall_per_step_s=float(np.median(walls)) if walls.size else float("nan"),
                   newton=int(ts["newton_its"][keep].sum()), krylov=int(ts["ksp_its"][keep].sum()),
                   rejected=int(ts["rejected"][keep].sum()) if "rejected" in ts else 0)
    else:
        res.update(steps=0, wall_steps_s=float("nan"), wall_per_step_s=float("nan"),
                   newton=0, krylov=0, rejected=0)
    return res


def read_csv(path):
    """A CSV of numbers as {column: array}, or None when missing."""
    if not os.path.isfile(path):
        return None
    with open(path) as f:
        header = [h.strip() for h in f.readline().strip().split(",")]
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    if data.size == 0:
        return {h: np.array([]) for h in header}
    return {h: data[:, i] for i, h in enumerate(header)}
