"""Water mass balance over a whole consolidation run, 2D and 3D, on 1 and 2 ranks.

With incompressible grains and water (alpha = 1, 1/M = 0) every cubic metre of water that
leaves through the drained top is a cubic metre of settlement: sum_n dt_n top.flux_n equals
-(top settlement) x (top area). The discrete balance is exact: the test functions sum to one,
so the stabilisation term cancels in the sum and only round-off remains (checked to 1e-9
relative to the total outflow). A flux boundary condition is checked the same way: water
injected through the bottom of an unloaded column either leaves through the drained top or
swells the column, exactly.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402

failures = []
for dim, ranks in ((2, 1), (2, 2), (3, 1)):
    scene = common.scene_path(f"terzaghi_{dim}d.opts")
    area = 0.1 if dim == 2 else 0.01
    top = "0.05,1" if dim == 2 else "0.05,0.05,1"
    axis = "y" if dim == 2 else "z"
    out = common.output_dir(f"mass_balance_{dim}d_{ranks}")
    extra = ["-ts_max_time", 8, "-probe_top", top]  # 40 steps of 0.2 s
    if dim == 3:
        extra += ["-mesh_size_factor", 2]
    common.run(scene, out, extra, ranks=ranks)
    ts = common.read_timeseries(out)
    outflow = np.sum(ts["dt"] * ts["top.flux"])
    settled = -ts[f"top.u{axis}"][-1] * area
    err = abs(outflow - settled) / abs(settled)
    ok = err < 1e-9
    print(f"{'ok  ' if ok else 'FAIL'} {dim}D, {ranks} rank(s): water out {outflow:.9e} m3, settlement volume {settled:.9e} m3, relative difference {err:.1e}")
    if not ok:
        failures.append(f"{dim}D {ranks} ranks: {err:.1e}")

# Injection through the bottom (flux BC, negative = inflow) of an unloaded column.
scene = common.scene_path("terzaghi_2d.opts")
out = common.output_dir("mass_balance_injection")
inflow = -1e-7  # m/s outward, i.e. 1e-7 m/s into the soil
common.run(scene, out, ["-ts_max_time", 6, "-bc_top_traction", "0,0", "-bc_bottom_flux", inflow,
                        "-probe_top", "0.05,1"])
ts = common.read_timeseries(out)
injected = -inflow * 0.1 * ts["time"][-1]
out_top = np.sum(ts["dt"] * ts["top.flux"])
swelling = ts["top.uy"][-1] * 0.1
err = abs(injected - out_top - swelling) / injected
ok = err < 1e-9
print(f"{'ok  ' if ok else 'FAIL'} injection: in {injected:.6e} m3, out at top {out_top:.6e} m3, swelling {swelling:.6e} m3, imbalance {err:.1e}")
if not ok:
    failures.append(f"injection imbalance {err:.1e}")

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("mass balance: OK")
