"""Quantities of interest from a run's outputs, their references and errors, observed orders,
Richardson extrapolation.

A quantity is a vector of values (one per `at` time; one value for "end" or a crossing):
    value(t)  = column of `file` at time t (linear interpolation between the two steps around
                t when t is not a step time, e.g. with adaptive steps)
    "end"     = the last row
    {column = C, value = V}: the quantity's column where C first reaches V (linear
                interpolation between the two rows around the crossing)
    subtract  = "initial": minus the row of step 0; "first_step": minus the row of step 1.
error = norm(values - reference) / scale, norm rms or max over the vector, scale a number or
"reference" (the largest |reference| of the vector)."""

import json
import math
import os

import numpy as np

from . import closed_forms
from .runs import read_csv


class MeasureError(Exception):
    pass


def quantity_values(q, run_dir):
    """(times, values) of quantity q in a run's output directory."""
    data = read_csv(os.path.join(run_dir, q.file))
    if data is None:
        raise MeasureError(f"{run_dir}: no {q.file}")
    return quantity_from_table(q, data)


def quantity_from_table(q, data):
    weights = q.column if isinstance(q.column, dict) else {q.column: 1.0}
    for c in weights:
        if c not in data:
            raise MeasureError(f"quantity {q.name}: {q.file} has no column '{c}' "
                               f"(columns: {', '.join(data)})")
    time = data.get("time")
    if time is None:
        raise MeasureError(f"quantity {q.name}: {q.file} has no column 'time'")
    col = sum(w * np.asarray(data[c], dtype=float) for c, w in weights.items())
    rows = np.arange(len(time))
    if "step" in data:
        steps = data["step"]
    else:
        steps = rows
    if q.at == "end":
        times, vals = np.array([time[-1]]), np.array([col[-1]])
    elif isinstance(q.at, dict):
        c = data.get(q.at["column"])
        if c is None:
            raise MeasureError(f"quantity {q.name}: {q.file} has no column '{q.at['column']}'")
        d = c - q.at["value"]
        hit = np.nonzero(np.sign(d[:-1]) * np.sign(d[1:]) <= 0)[0]
        hit = [i for i in hit if d[i] != d[i + 1] or d[i] == 0]
        if not hit:
            raise MeasureError(f"quantity {q.name}: column '{q.at['column']}' never reaches "
                               f"{q.at['value']:g} (range {c.min():g} .. {c.max():g})")
        i = hit[0]
        w = 0.0 if d[i] == 0 else d[i] / (d[i] - d[i + 1])
        times = np.array([time[i] + w * (time[i + 1] - time[i])])
        vals = np.array([col[i] + w * (col[i + 1] - col[i])])
    else:
        times = np.asarray(q.at, dtype=float)
        vals = np.empty(len(times))
        for k, t in enumerate(times):
            j = int(np.argmin(np.abs(time - t)))
            if abs(time[j] - t) <= 1e-9 * max(abs(t), 1.0):
                vals[k] = col[j]
            elif time[0] <= t <= time[-1]:
                vals[k] = np.interp(t, time, col)
            else:
                raise MeasureError(f"quantity {q.name}: t = {t:g} outside the run "
                                   f"({time[0]:g} .. {time[-1]:g})")
    if q.subtract:
        want = 0 if q.subtract == "initial" else 1
        j = np.nonzero(steps == want)[0]
        if not j.size:
            raise MeasureError(f"quantity {q.name}: no row of step {want} to subtract")
        vals = vals - col[j[0]]
    return times, vals


def error(q, vals, ref):
    """Relative error of a quantity (see the module docstring)."""
    vals, ref = np.asarray(vals, dtype=float), np.asarray(ref, dtype=float)
    if vals.shape != ref.shape:
        raise MeasureError(f"quantity {q.name}: {vals.size} values, {ref.size} reference values")
    scale = float(np.max(np.abs(ref))) if q.scale == "reference" else q.scale
    if scale == 0:
        raise MeasureError(f"quantity {q.name}: the reference is 0, give a scale")
    d = vals - ref
    e = math.sqrt(float(np.mean(d * d))) if q.norm == "rms" else float(np.max(np.abs(d)))
    return e / scale


def norm(q, d):
    d = np.asarray(d, dtype=float)
    return math.sqrt(float(np.mean(d * d))) if q.norm == "rms" else float(np.max(np.abs(d)))


def closed_form_reference(q, times, opts, step_times):
    r = q.reference
    return closed_forms.evaluate(r["closed_form"], times, opts, r, {"step_times": step_times})


def fit_order(params, errors):
    """Least-squares slope of log(error) against log(parameter), and of the finest pair."""
    p = np.asarray(params, dtype=float)
    e = np.asarray(errors, dtype=float)
    ok = np.isfinite(e) & (e > 0)
    if ok.sum() < 2:
        return float("nan"), float("nan")
    slope = float(np.polyfit(np.log(p[ok]), np.log(e[ok]), 1)[0])
    i = np.nonzero(ok)[0][-2:]
    last = float(np.log(e[i[0]] / e[i[1]]) / np.log(p[i[0]] / p[i[1]]))
    return slope, last


def self_order(q, params, values):
    """Observed order from the last three runs of a path without a reference: the change
    between successive runs shrinks like parameter^p, so
    p = log(|Q1 - Q2| / |Q2 - Q3|) / log(r) for a constant ratio r = h1/h2 = h2/h3 (in general
    solved for p from (h1^p - h2^p)/(h2^p - h3^p) = |Q1-Q2|/|Q2-Q3| by bisection). What stays
    fixed along the path (the time error on a space path) cancels."""
    if len(values) < 3:
        return float("nan")
    h1, h2, h3 = params[-3:]
    d1 = norm(q, np.asarray(values[-3]) - np.asarray(values[-2]))
    d2 = norm(q, np.asarray(values[-2]) - np.asarray(values[-1]))
    if not (d1 > 0 and d2 > 0) or not (h1 > h2 > h3 > 0):
        return float("nan")
    target = d1 / d2
    f = lambda p: (h1 ** p - h2 ** p) / (h2 ** p - h3 ** p) - target
    lo, hi = 0.05, 8.0
    if f(lo) * f(hi) > 0:
        return float("nan")
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if f(lo) * f(mid) <= 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def richardson(params, values, order=None):
    """Richardson extrapolation to parameter 0 from the finest runs of a path.

    values: list of vectors (coarse to fine), params: the refinement parameter (h or dt).
    With three or more runs the order is observed from the finest three (self_order, per
    component through the vector norm of the differences, clamped to [0.5, 6]); a declared
    `order` is used for the extrapolation when given. Returns (reference vector, order used,
    observed order, estimated error of the reference as a vector): the estimate is the spread
    between extrapolations that should agree (declared vs observed order, and the finest pair
    vs the next pair), at least Roache's grid convergence index of the finest run."""
    P = np.asarray(params, dtype=float)
    V = [np.asarray(v, dtype=float) for v in values]
    observed = float("nan")
    if len(V) >= 3:
        class _Q:  # rms over the vector
            norm = "rms"
        observed = self_order(_Q, list(P), V)
    p = order if order is not None else observed
    if not np.isfinite(p):
        raise MeasureError("Richardson: no order (declare one, or give the path 3 runs whose "
                           "changes shrink)")
    p = min(max(p, 0.5), 6.0)

    def extrap(i, j, pp):  # runs i (coarser) and j (finer)
        r = (P[i] / P[j]) ** pp
        return V[j] + (V[j] - V[i]) / (r - 1.0)

    ref = extrap(-2, -1, p)
    spread = np.zeros_like(ref)
    if order is not None and np.isfinite(observed):
        spread = np.maximum(spread, np.abs(ref - extrap(-2, -1, min(max(observed, 0.5), 6.0))))
    if len(V) >= 3:
        spread = np.maximum(spread, np.abs(ref - extrap(-3, -2, p)) / max((P[-2] / P[-1]) ** p, 1.0))
    # With exactly three runs and the observed order, both extrapolations above agree by
    # construction and the spread is zero, which says nothing. Floor: Roache's grid convergence
    # index of the finest run, Fs |V_fine - V_coarse| / (r^p - 1), Fs = 1.25 with an order
    # observed from three runs, 3 otherwise (Roache 1998; ASME V&V 20): a conservative bound,
    # since the extrapolated value is usually closer than the finest run it is computed from.
    safety = 1.25 if (len(V) >= 3 and order is None) else 3.0
    r = (P[-2] / P[-1]) ** p
    if r > 1.0:
        spread = np.maximum(spread, safety * np.abs(V[-1] - V[-2]) / (r - 1.0))
    return ref, p, observed, spread


def other_study_reference(q, output_root):
    """A reference written by another study (reference.json of output/study-<name>/)."""
    r = q.reference
    f = os.path.join(output_root, f"study-{r['study']}", "reference.json")
    if not os.path.isfile(f):
        return None
    with open(f) as fh:
        d = json.load(fh)
    if r["quantity"] not in d:
        raise MeasureError(f"quantity {q.name}: study {r['study']} has no quantity "
                           f"'{r['quantity']}' in {f}")
    e = d[r["quantity"]]
    return (np.asarray(e["value"], dtype=float) * r["scale"],
            np.asarray(e["estimated_error"], dtype=float) * abs(r["scale"]), e)
