"""Reading and checking a study file (studies/<name>.toml; the format is docs/studies.md).

Every problem is reported as one line naming the file, the key and what is expected
(StudyError); nothing is run before the whole file has been checked."""

import math
import os
import shlex
import tomllib

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PATH_KINDS = ("space", "time", "both", "adaptive", "tolerance")
REFERENCE_KINDS = ("closed_form", "value", "richardson", "finest", "study")
DEFAULT_TARGETS = [0.1, 0.01, 0.001]
DISPLACEMENT_ORDERS = (1, 2)  # poroseam's -displacement_order (docs/elements.md)


class StudyError(Exception):
    pass


class Study:
    """A checked study: name, file, title, scene, options, end_time, ranks, solvers,
    displacement_orders (None: the scene's own order, no -displacement_order given),
    integrators {name: [options]}, base {mesh_size_factor, dt}, probes {name: [x, y(, z)]},
    tables {option: {closed_form, ...}}, postprocess [args], paths {name: Path},
    quantities {name: Quantity}, targets, timeout."""


class Path:
    """A refinement path: kind, points (list of {mesh_size_factor, dt, vary: {option: value}}),
    parameter (the name of what is refined), options, integrators, solvers, ranks,
    displacement_orders (None: the scene's own)."""


class Quantity:
    """name, label, file, column, at ('end' | [times] | {'column', 'value'}), subtract,
    norm, scale ('reference' | number), unit, reference {kind, ...}."""


def _where(path, key):
    rel = os.path.relpath(path, os.getcwd())
    return f"{path if rel.startswith('..') else rel}: key '{key}'"


def _err(path, key, expected, got=None):
    more = f" (got {got!r})" if got is not None else ""
    return StudyError(f"{_where(path, key)}: expected {expected}{more}")


def _number(path, key, v, positive=False):
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise _err(path, key, "a number", v)
    if positive and v <= 0:
        raise _err(path, key, "a positive number", v)
    return float(v)


def _options(path, key, v):
    """Options as a list of strings: a string (split like a shell does, no expansion) or a
    list of strings/numbers."""
    if v is None:
        return []
    if isinstance(v, str):
        try:
            return shlex.split(v, comments=False, posix=True)
        except ValueError as e:
            raise _err(path, key, f"PETSc options as a string or a list ({e})")
    if isinstance(v, list) and all(isinstance(x, (str, int, float)) and not isinstance(x, bool)
                                   for x in v):
        return [x if isinstance(x, str) else repr(x) if isinstance(x, float) else str(x)
                for x in v]
    raise _err(path, key, "PETSc options as a string or a list of strings", v)


def _strings(path, key, v):
    if isinstance(v, str):
        return [v]
    if isinstance(v, list) and v and all(isinstance(x, str) for x in v):
        return list(v)
    raise _err(path, key, "a name or a non-empty list of names", v)


def _known(path, where, table, allowed):
    for k in table:
        if k not in allowed:
            raise StudyError(f"{_where(path, where + k if where else k)}: unknown key "
                             f"(expected one of: {', '.join(allowed)})")


def find(name):
    """The study file of a name (studies/<name>.toml) or a path to a .toml file."""
    if name.endswith(".toml") or os.sep in name:
        p = os.path.abspath(name)
    else:
        p = os.path.join(TOP, "studies", name + ".toml")
    if not os.path.isfile(p):
        avail = sorted(f[:-5] for f in os.listdir(os.path.join(TOP, "studies"))
                       if f.endswith(".toml")) if os.path.isdir(os.path.join(TOP, "studies")) else []
        raise StudyError(f"{p}: no such study file (studies: {', '.join(avail) or 'none'})")
    return p


def load(name):
    path = find(name)
    try:
        with open(path, "rb") as f:
            d = tomllib.load(f)
    except tomllib.TOMLDecodeError as e:
        raise StudyError(f"{path}: not valid TOML: {e}")
    s = Study()
    s.file = path
    s.name = os.path.splitext(os.path.basename(path))[0]
    _known(path, "", d, ["title", "description", "scene", "options", "end_time", "ranks",
                         "solvers", "integrators", "base", "probes", "tables", "postprocess",
                         "paths", "quantities", "targets", "timeout", "max_steps",
                         "displacement_orders"])
    s.title = d.get("title", s.name)
    s.description = d.get("description", "")
    if not isinstance(s.title, str) or not isinstance(s.description, str):
        raise _err(path, "title/description", "text")
    if "scene" not in d or not isinstance(d["scene"], str):
        raise _err(path, "scene", "the base scene, a path to a PETSc options file relative to "
                   "the repository (e.g. \"options/terzaghi_2d.opts\")", d.get("scene"))
    s.scene = os.path.join(TOP, d["scene"])
    if not os.path.isfile(s.scene):
        raise _err(path, "scene", "an existing options file", d["scene"])
    s.options = _options(path, "options", d.get("options"))
    if "end_time" not in d:
        raise _err(path, "end_time", "the simulated end time [s] of every run")
    s.end_time = _number(path, "end_time", d["end_time"], positive=True)
    s.timeout = _number(path, "timeout", d.get("timeout", 600), positive=True)
    s.max_steps = int(_number(path, "max_steps", d.get("max_steps", 100000), positive=True))
    s.ranks = _ranks(path, "ranks", d.get("ranks", [1]))
    s.solvers = _solvers(path, "solvers", d.get("solvers", ["direct"]))
    s.displacement_orders = (_orders(path, "displacement_orders", d["displacement_orders"])
                             if "displacement_orders" in d else None)
    integ = d.get("integrators", {"beuler": "-ts_type beuler"})
    if not isinstance(integ, dict) or not integ:
        raise _err(path, "integrators", "a table name = \"options\" (e.g. beuler = \"-ts_type "
                   "beuler\")", integ)
    s.integrators = {k: _options(path, f"integrators.{k}", v) for k, v in integ.items()}
    base = d.get("base", {})
    if not isinstance(base, dict):
        raise _err(path, "base", "a table with mesh_size_factor and dt")
    _known(path, "base.", base, ["mesh_size_factor", "dt"])
    s.base = {"mesh_size_factor": _number(path, "base.mesh_size_factor",
                                          base.get("mesh_size_factor", 1.0), positive=True)}
    if "dt" not in base:
        raise _err(path, "base.dt", "the time step [s] of runs whose path does not set one")
    s.base["dt"] = _number(path, "base.dt", base["dt"], positive=True)
    s.probes = {}
    for k, v in d.get("probes", {}).items():
        if not (isinstance(v, list) and len(v) in (2, 3)):
            raise _err(path, f"probes.{k}", "coordinates [x, y] or [x, y, z]", v)
        s.probes[k] = [_number(path, f"probes.{k}", x) for x in v]
    s.tables = {}
    for k, v in d.get("tables", {}).items():
        if not k.startswith("-") or not isinstance(v, dict) or "closed_form" not in v:
            raise _err(path, f"tables.{k}", "an option name (\"-bc_top_uy_table\") = { "
                       "closed_form = \"name\", ... parameters }", v)
        s.tables[k] = dict(v)
    s.postprocess = _options(path, "postprocess", d.get("postprocess"))
    s.targets = d.get("targets", DEFAULT_TARGETS)
    if not (isinstance(s.targets, list) and s.targets):
        raise _err(path, "targets", "a list of relative errors, e.g. [0.1, 0.01, 0.001]")
    s.targets = [_number(path, "targets", t, positive=True) for t in s.targets]

    paths = d.get("paths")
    if not isinstance(paths, dict) or not paths:
        raise _err(path, "paths", "at least one refinement path, [paths.<name>]")
    s.paths = {k: _path(path, s, k, v) for k, v in paths.items()}
    qs = d.get("quantities")
    if not isinstance(qs, dict) or not qs:
        raise _err(path, "quantities", "at least one quantity of interest, [quantities.<name>]")
    s.quantities = {k: _quantity(path, s, k, v) for k, v in qs.items()}
    return s


def _ranks(path, key, v):
    if isinstance(v, int) and not isinstance(v, bool):
        v = [v]
    if not (isinstance(v, list) and v and all(isinstance(r, int) and not isinstance(r, bool)
                                              and r >= 1 for r in v)):
        raise _err(path, key, "a rank count or a list of them (positive integers)", v)
    return v


def _orders(path, key, v):
    """Element orders (-displacement_order): 1, 2 or a list of them, each a line of its own."""
    if isinstance(v, int) and not isinstance(v, bool):
        v = [v]
    if not (isinstance(v, list) and v and all(isinstance(o, int) and not isinstance(o, bool)
                                              and o in DISPLACEMENT_ORDERS for o in v)
            and len(set(v)) == len(v)):
        raise _err(path, key, "a displacement order or a list of distinct ones, from "
                   + ", ".join(str(o) for o in DISPLACEMENT_ORDERS)
                   + " (-displacement_order; e.g. [1, 2])", v)
    return v


def _no_order_option(path, key, opts):
    """Where a path has displacement_orders, the order is set there alone (a
    -displacement_order among the options would be overruled or overrule it, silently)."""
    if "-displacement_order" in opts:
        raise _err(path, key, "no -displacement_order here: displacement_orders (the "
                   "study's or the path's) sets the element order", " ".join(opts))


def _solvers(path, key, v):
    v = _strings(path, key, v)
    for p in v:
        if not os.path.isfile(os.path.join(TOP, "options", "solvers", p + ".opts")):
            raise _err(path, key, "presets with a file options/solvers/<preset>.opts", p)
    return v


def _path(path, s, name, t):
    k = f"paths.{name}"
    if not isinstance(t, dict):
        raise _err(path, k, "a table")
    _known(path, k + ".", t, ["kind", "mesh_size_factor", "dt", "vary", "options",
                              "integrators", "solvers", "ranks", "label",
                              "displacement_orders"])
    p = Path()
    p.name = name
    p.kind = t.get("kind")
    if p.kind not in PATH_KINDS:
        raise _err(path, k + ".kind", "one of " + ", ".join(PATH_KINDS), p.kind)
    p.label = t.get("label", name)
    p.options = _options(path, k + ".options", t.get("options"))
    p.integrators = _strings(path, k + ".integrators", t.get("integrators", list(s.integrators)))
    for i in p.integrators:
        if i not in s.integrators:
            raise _err(path, k + ".integrators", "names from [integrators]: "
                       + ", ".join(s.integrators), i)
    p.solvers = _solvers(path, k + ".solvers", t.get("solvers", s.solvers))
    p.ranks = _ranks(path, k + ".ranks", t.get("ranks", s.ranks))
    p.displacement_orders = (_orders(path, k + ".displacement_orders", t["displacement_orders"])
                             if "displacement_orders" in t else s.displacement_orders)
    if p.displacement_orders is not None:  # one place sets the order
        _no_order_option(path, "options", s.options)
        for i in p.integrators:
            _no_order_option(path, f"integrators.{i}", s.integrators[i])
        _no_order_option(path, k + ".options", p.options)
        _no_order_option(path, k + ".vary", list(t.get("vary", {})))
    ladders = {}
    fixed = dict(s.base)
    for key in ("mesh_size_factor", "dt"):
        if key in t:
            v = t[key]
            if isinstance(v, list):
                ladders[key] = [_number(path, f"{k}.{key}", x, positive=True) for x in v]
            else:
                fixed[key] = _number(path, f"{k}.{key}", v, positive=True)
    vary = t.get("vary", {})
    if not isinstance(vary, dict):
        raise _err(path, k + ".vary", "a table \"-option\" = [values]", vary)
    for opt, vals in vary.items():
        if not opt.startswith("-") or not isinstance(vals, list) or not vals:
            raise _err(path, f"{k}.vary.{opt}", "\"-option\" = [value, ...]", vals)

        ladders[opt] = [v if isinstance(v, str) else repr(float(v)) if isinstance(v, float)
                        else str(v) for v in vals]
    if not ladders:
        raise _err(path, k, "a ladder: a list under mesh_size_factor, dt or vary")
    n = {len(v) for v in ladders.values()}
    if len(n) != 1:
        raise _err(path, k, "ladders of the same length (they are refined together)",
                   {a: len(b) for a, b in ladders.items()})
    n = n.pop()
    p.adaptive = p.kind == "adaptive"
    if p.kind in ("space", "both") and "mesh_size_factor" not in ladders:
        raise _err(path, k + ".mesh_size_factor", f"a list (a {p.kind} path refines the mesh)")
    if p.kind in ("time", "both") and "dt" not in ladders:
        raise _err(path, k + ".dt", f"a list (a {p.kind} path refines the time step)")
    if p.kind in ("adaptive", "tolerance") and not vary:
        raise _err(path, k + ".vary", f"the option a {p.kind} path varies, e.g. "
                   "{\"-ts_rtol\" = [1e-2, 1e-3]}")
    p.parameter = ("mesh_size_factor" if p.kind in ("space", "both") else
                   "dt" if p.kind == "time" else next(iter(vary)))
    p.points = []
    for i in range(n):
        pt = {"mesh_size_factor": fixed["mesh_size_factor"], "dt": fixed["dt"], "vary": {}}
        for key, vals in ladders.items():
            if key in ("mesh_size_factor", "dt"):
                pt[key] = vals[i]
            else:
                pt["vary"][key] = vals[i]
        if not p.adaptive:
            steps = s.end_time / pt["dt"]
            if abs(steps - round(steps)) > 1e-6 * steps:
                raise _err(path, f"{k}.dt", f"time steps that divide end_time = {s.end_time:g}",
                           pt["dt"])
        p.points.append(pt)
    return p


def _quantity(path, s, name, t):
    k = f"quantities.{name}"
    if not isinstance(t, dict):
        raise _err(path, k, "a table")
    _known(path, k + ".", t, ["label", "file", "column", "at", "subtract", "norm", "scale",
                              "unit", "reference"])
    q = Quantity()
    q.name = name
    q.label = t.get("label", name)
    q.file = t.get("file", "timeseries.csv")
    col = t.get("column")
    if isinstance(col, dict) and col and all(isinstance(w, (int, float)) and not isinstance(w, bool)
                                              for w in col.values()):
        q.column = {c: float(w) for c, w in col.items()}
    elif isinstance(col, str):
        q.column = col
    else:
        raise _err(path, k + ".column", "the name of a column of " + q.file + ", or a weighted "
                   "sum { \"a.p\" = 1, \"b.p\" = -1 }", col)
    at = t.get("at", "end")
    if at == "end":
        pass
    elif isinstance(at, list) and at:
        at = [_number(path, k + ".at", x) for x in at]
        if max(at) > s.end_time * (1 + 1e-9):
            raise _err(path, k + ".at", f"times up to end_time = {s.end_time:g}", max(at))
    elif isinstance(at, dict) and set(at) == {"column", "value"}:
        at = {"column": at["column"], "value": _number(path, k + ".at.value", at["value"])}
    else:
        raise _err(path, k + ".at", "\"end\", a list of times, or { column = \"name\", value = v } "
                   "(where that column first reaches v)", at)
    q.at = at
    q.subtract = t.get("subtract")
    if q.subtract not in (None, "initial", "first_step"):
        raise _err(path, k + ".subtract", "\"initial\" (the row of step 0) or \"first_step\"",
                   q.subtract)
    q.norm = t.get("norm", "rms")
    if q.norm not in ("rms", "max"):
        raise _err(path, k + ".norm", "\"rms\" or \"max\"", q.norm)
    q.scale = t.get("scale", "reference")
    if q.scale != "reference":
        q.scale = _number(path, k + ".scale", q.scale, positive=True)
    q.unit = t.get("unit", "% of |reference|" if q.scale == "reference" else f"% of {q.scale:g}")
    ref = t.get("reference")
    if not isinstance(ref, dict):
        raise _err(path, k + ".reference", "a table with one of " + ", ".join(REFERENCE_KINDS), ref)
    kinds = [x for x in REFERENCE_KINDS if x in ref]
    if len(kinds) != 1:
        raise _err(path, k + ".reference", "exactly one of " + ", ".join(REFERENCE_KINDS),
                   list(ref))
    r = dict(ref)
    r["kind"] = kinds[0]
    if r["kind"] == "closed_form":
        from . import closed_forms
        if r["closed_form"] not in closed_forms.REGISTRY:
            raise _err(path, k + ".reference.closed_form", "one of "
                       + ", ".join(sorted(closed_forms.REGISTRY)), r["closed_form"])
    elif r["kind"] == "value":
        v = r["value"]
        r["value"] = [_number(path, k + ".reference.value", x) for x in
                      (v if isinstance(v, list) else [v])]
    elif r["kind"] == "richardson":
        if r["richardson"] not in s.paths:
            raise _err(path, k + ".reference.richardson", "the name of a path of this study",
                       r["richardson"])
        if len(s.paths[r["richardson"]].points) < 2:
            raise _err(path, k + ".reference.richardson", "a path with at least 2 runs (3 "
                       "without a declared order)")
        if "order" in r:
            r["order"] = _number(path, k + ".reference.order", r["order"], positive=True)
        _known(path, k + ".reference.", r, ["kind", "richardson", "order", "integrator",
                                            "solver", "ranks", "displacement_order"])
        _reference_order(path, k, s.paths[r["richardson"]], r)
    elif r["kind"] == "finest":
        if r["finest"] not in s.paths:
            raise _err(path, k + ".reference.finest", "the name of a path of this study",
                       r["finest"])
        _known(path, k + ".reference.", r, ["kind", "finest", "integrator", "solver", "ranks",
                                            "displacement_order"])
        _reference_order(path, k, s.paths[r["finest"]], r)
    else:
        if not isinstance(r["study"], str) or "quantity" not in r:
            raise _err(path, k + ".reference", "{ study = \"name\", quantity = \"name\", "
                       "scale = factor }", ref)
        r["scale"] = _number(path, k + ".reference.scale", r.get("scale", 1.0))
    q.reference = r
    return q


def _reference_order(path, k, p, r):
    """A reference taken from a path's runs names one of the path's element orders (default:
    its first)."""
    if "displacement_order" not in r:
        return
    have = p.displacement_orders
    if have is None or r["displacement_order"] not in have:
        raise _err(path, k + ".reference.displacement_order", "one of the path's "
                   "displacement_orders" + (f" ({', '.join(str(o) for o in have)})" if have
                                           else " (it has none: give the path or the study "
                                           "displacement_orders)"), r["displacement_order"])
