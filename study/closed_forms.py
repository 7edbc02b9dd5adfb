"""The closed forms a study can name (reference = { closed_form = "<name>", ...parameters }).

Each function takes (times, opts, params, run) and returns one value per time:
    times   the times [s] at which the quantity was measured (its `at` times, or the time of
            the last step for at = "end")
    opts    the run's options as a dict {"-name": "value"} (scene, study and path options
            merged): the materials and the load are read from there, so a closed form always
            describes the scene that was run
    params  the other keys of the reference table (geometry, probe depth, region names)
    run     {"step_times": the end times of the run's steps} (for the time-discrete forms)
Tables (studies' [tables]) call them with times = the instants of the table.

Materials: -region_<region>_E, _nu, _permeability, -fluid_viscosity (default 1e-3 Pa s); the
load q from the last component of -bc_top_traction (compression positive)."""

import numpy as np

from . import analytic as A


class ClosedFormError(Exception):
    pass


def _get(opts, params, key, default=None):
    if key in params:
        return params[key]
    if default is not None:
        return default
    raise ClosedFormError(f"parameter '{key}' missing")


def _material(opts, region):
    try:
        E = float(opts[f"-region_{region}_E"])
        nu = float(opts[f"-region_{region}_nu"])
        k = float(opts[f"-region_{region}_permeability"])
    except KeyError as e:
        raise ClosedFormError(f"the scene sets no {e.args[0]} (parameter region = "
                              f"\"{region}\")")
    mu = float(opts.get("-fluid_viscosity", 1e-3))
    return E, nu, k / mu


def _load(opts):
    if "-bc_top_traction" not in opts:
        raise ClosedFormError("the scene sets no -bc_top_traction (the load q)")
    return -float(opts["-bc_top_traction"].split(",")[-1])


def _terzaghi(opts, params):
    E, nu, kappa = _material(opts, params.get("region", "soil"))
    return _load(opts), float(_get(opts, params, "H")), A.constrained_modulus(E, nu), kappa


def terzaghi_pressure(times, opts, params, run):
    """Pore pressure [Pa] at `depth` below the drained top of a column of height `H`."""
    q, H, Mc, kappa = _terzaghi(opts, params)
    z = float(_get(opts, params, "depth"))
    return np.array([float(A.terzaghi_pressure(z, t, q, H, Mc, kappa)) for t in times])


def terzaghi_settlement(times, opts, params, run):
    """Top displacement [m] (negative = down)."""
    q, H, Mc, kappa = _terzaghi(opts, params)
    return np.array([float(A.terzaghi_settlement(t, q, H, Mc, kappa)) for t in times])


def _step_times_to(run, times):
    st = np.asarray(run["step_times"], dtype=float)
    n = int(np.searchsorted(st, max(times) * (1 + 1e-9), side="right"))
    st = st[:max(n, 1)]
    idx = [int(np.argmin(np.abs(st - t))) for t in times]
    for i, t in zip(idx, times):
        if abs(st[i] - t) > 1e-6 * max(abs(t), 1e-300):
            raise ClosedFormError(f"the backward-Euler form needs t = {t:g} to be a step time")
    return st, idx


def terzaghi_pressure_be(times, opts, params, run):
    """The pressure of backward Euler in time, exact in space, on the run's own steps (the
    reference that leaves the spatial error alone)."""
    q, H, Mc, kappa = _terzaghi(opts, params)
    z = float(_get(opts, params, "depth"))
    st, idx = _step_times_to(run, times)
    p = A.terzaghi_pressure_be([z], st, q, H, Mc, kappa)[:, 0]
    return p[idx]


def terzaghi_settlement_be(times, opts, params, run):
    q, H, Mc, kappa = _terzaghi(opts, params)
    st, idx = _step_times_to(run, times)
    return A.terzaghi_settlement_be(st, q, H, Mc, kappa)[idx]


def _mandel(opts, params):
    E, nu, kappa = _material(opts, params.get("region", "soil"))
    return A.Mandel(E, nu, kappa, float(_get(opts, params, "a")), float(_get(opts, params, "b")),
                    float(_get(opts, params, "F")))


def mandel_pressure(times, opts, params, run):
    """Pore pressure [Pa] at (x, any y) of Mandel's quarter model (rigid plates)."""
    m = _mandel(opts, params)
    return m.pressure(float(params.get("x", 0.0)), np.asarray(times, dtype=float))[:, 0]


def mandel_plate_uy(times, opts, params, run):
    """Displacement [m] of the rigid plate (0 at t = 0, the unloaded initial state)."""
    m = _mandel(opts, params)
    t = np.asarray(times, dtype=float)
    u = np.atleast_1d(m.plate_displacement(np.where(t > 0, t, 1.0)))
    return np.where(t > 0, u, 0.0)


def mandel_plate_force(times, opts, params, run):
    """The force of the plate on the quarter model [N/m] (the reaction top.Fy): -F at all times."""
    m = _mandel(opts, params)
    return np.full(len(times), -m.F)


def _joint(opts, params):
    E, nu, kappa = _material(opts, params.get("region", "lower"))
    E2, nu2, kappa2 = _material(opts, params.get("region_above", "upper"))
    if (E, nu, kappa) != (E2, nu2, kappa2):
        raise ClosedFormError("the joint closed form needs the same material on both sides")
    i = params.get("interface", "joint")
    try:
        T1, T2 = float(opts[f"-interface_{i}_T1"]), float(opts[f"-interface_{i}_T2"])
        KN = float(opts[f"-interface_{i}_KN"])
    except KeyError as e:
        raise ClosedFormError(f"the scene sets no {e.args[0]}")
    col = A.JointColumn(_load(opts), float(_get(opts, params, "H")),
                        float(_get(opts, params, "joint_depth")), A.constrained_modulus(E, nu),
                        kappa, 1.0 / T1 + 1.0 / T2, KN, T1=T1)
    return col


def joint_pressure(times, opts, params, run):
    """Pressure [Pa] at `depth` of a Terzaghi column crossed by a joint of finite
    transmissivity at `joint_depth` (analytic.JointColumn); at the joint's depth, `side` =
    "above" or "below" (default below)."""
    col = _joint(opts, params)
    return col.pressure(float(_get(opts, params, "depth")), times, side=params.get("side", "below"))


def joint_jump(times, opts, params, run):
    """Pressure drop across the joint [Pa], below minus above."""
    return _joint(opts, params).jump(times)


def joint_flux(times, opts, params, run):
    """Water through the joint [m3/s per m out of plane]: the upward flux per unit area times
    the column `width` (the interface's flux1 column)."""
    return _joint(opts, params).flux(times) * float(_get(opts, params, "width"))


def joint_settlement(times, opts, params, run):
    """Top displacement [m] (negative = down), the joint's penalty closure included."""
    return _joint(opts, params).settlement(times)


REGISTRY = {
    "terzaghi.pressure": terzaghi_pressure,
    "terzaghi.settlement": terzaghi_settlement,
    "terzaghi.pressure_be": terzaghi_pressure_be,
    "terzaghi.settlement_be": terzaghi_settlement_be,
    "mandel.pressure": mandel_pressure,
    "mandel.plate_uy": mandel_plate_uy,
    "mandel.plate_force": mandel_plate_force,
    "joint.pressure": joint_pressure,
    "joint.jump": joint_jump,
    "joint.flux": joint_flux,
    "joint.settlement": joint_settlement,
}


def evaluate(name, times, opts, params, run):
    params = {k: v for k, v in params.items() if k not in ("kind", "closed_form")}
    return np.asarray(REGISTRY[name](np.atleast_1d(np.asarray(times, dtype=float)), opts,
                                     params, run), dtype=float)
