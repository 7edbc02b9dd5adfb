"""Gravity and the K0 geostatic initial state, against statics.

A soil column (2D and 3D) with gravity, water level at the surface, the geostatic initial
state and no load must stay in equilibrium: no displacement, hydrostatic pressure, no flow.
Closed-form checks after a few steps:
  - |u| < 1e-12 m everywhere probed, p = rho_w g depth (relative 1e-9),
  - bottom vertical reaction = total weight rho_sat g H A (relative 1e-9): the sides are
    frictionless rollers, so the bottom carries everything,
  - no water crosses the drained top (|flux| < 1e-15 m3/s).
Then the same column with a surcharge q on top, drained (-drained): no pressure unknowns,
the bottom reaction is weight + q A and the top settles by q H / M_c at once (oedometer).
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402

g, rho_w, rho_s, n, H = 9.81, 1000.0, 2650.0, 0.36, 1.0
rho_sat = (1 - n) * rho_s + n * rho_w
failures = []


def check(name, ok, text):
    print(("  ok   " if ok else "  FAIL ") + text)
    if not ok:
        failures.append(name + ": " + text)


for dim in (2, 3):
    mesh = "meshes/terzaghi_column_2d.geo" if dim == 2 else "meshes/terzaghi_column_3d.geo"
    scene = os.path.join(HERE, f"geostatic_{dim}d.opts")
    area = 0.1 if dim == 2 else 0.1 * 0.1
    probes = ["0.05,0.5", "0.05,0.25"] if dim == 2 else ["0.05,0.05,0.5", "0.05,0.05,0.25"]
    depth = [0.5, 0.75]
    args = ["-mesh", mesh, "-ts_max_steps", 3]
    for i, x in enumerate(probes):
        args += [f"-probe_p{i}", x]
    out = common.output_dir(f"geostatic_{dim}d")
    common.run(scene, out, args + ["-bc_top_p", 0, "-mesh_size_factor", 2 if dim == 3 else 1])
    ts = common.read_timeseries(out)
    print(f"{dim}D column with gravity and the K0 state, no load:")
    umax = max(np.max(np.abs(ts[f"p{i}.u{c}"])) for i in range(2) for c in "xyz"[:dim])
    check("displacement", umax < 1e-12, f"max |u| at probes {umax:.2e} m < 1e-12 m")
    for i, d in enumerate(depth):
        p_exact = rho_w * g * d
        err = np.max(np.abs(ts[f"p{i}.p"] - p_exact)) / p_exact
        check("pressure", err < 1e-9, f"pressure at depth {d} m: relative error {err:.1e} < 1e-9")
    weight = rho_sat * g * H * area
    axis = "y" if dim == 2 else "z"
    err = np.max(np.abs(ts[f"bottom.F{axis}"] - weight)) / weight
    check("weight", err < 1e-9, f"bottom reaction {ts[f'bottom.F{axis}'][-1]:.6f} N vs weight {weight:.6f} N: {err:.1e}")
    flux = np.max(np.abs(ts["top.flux"]))
    check("flux", flux < 1e-15, f"outflow through the top {flux:.1e} m3/s < 1e-15")

    out = common.output_dir(f"geostatic_drained_{dim}d")
    q = 2e4
    traction = "0,-2e4" if dim == 2 else "0,0,-2e4"
    top = "0.05,1" if dim == 2 else "0.05,0.05,1"
    common.run(scene, out, args + ["-drained", "-bc_top_traction", traction, "-probe_top", top,
                                   "-mesh_size_factor", 2 if dim == 3 else 1])
    ts = common.read_timeseries(out)
    print(f"{dim}D drained column with a surcharge:")
    with open(os.path.join(out, "log.txt")) as f:
        log = f.read()
    check("fields", "field pressure" not in log and "field displacement" in log,
          "a drained scene has displacement unknowns only")
    E, nu = 1e7, 0.25
    M_c = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    settlement = -q * H / M_c
    err = abs(ts[f"top.u{axis}"][-1] - settlement) / abs(settlement)
    check("settlement", err < 1e-9, f"drained settlement {ts[f'top.u{axis}'][-1]:.6e} m vs q H / M_c = {settlement:.6e} m: {err:.1e}")
    expected = weight + q * area
    err = abs(ts[f"bottom.F{axis}"][-1] - expected) / expected
    check("drained", err < 1e-9, f"bottom reaction {ts[f'bottom.F{axis}'][-1]:.6f} N vs {expected:.6f} N: {err:.1e}")

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("geostatic: OK")
