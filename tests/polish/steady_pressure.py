#!/usr/bin/python3
"""Steady and excess pore pressure kept apart when the water conditions change (docs/outputs.md,
"Steady and excess pore pressure"; issue 24 item 11), on tests/polish/rising_water_column.opts:
a saturated column at rest under gravity, drained at its top, whose base pressure rises from
hydrostatic (9810 Pa) to 29430 Pa within 20 s and then stays. The steady pressure at time t is
closed-form, p_steady(y) = p_base(t) (1 - y) (uniform permeability, the water's weight
included), and linear elements hold it exactly. About 5 s (200 steps).

1. timeseries.csv: <probe>.p_steady equals p_base(t) (1 - y) at every step (1e-9 of p_base);
   <probe>.p = <probe>.p_steady + <probe>.p_excess to round-off (1e-12 of p);
   the excess is large while the base rises (over 20 % of the rise at mid-height) and
   dissipates: below 1e-6 of its peak at t = 400 s (4.8 consolidation times H^2 / c_v).
2. fields.h5: steady_pressure equals the closed form at every vertex and output, and
   excess_pressure = pressure - steady_pressure.
3. A closed column (no pressure prescribed anywhere: the steady state is undefined) loaded on
   its top: steady_pressure is the initial pressure, and excess_pressure the change since then
   (as before this split), the undrained response to the load.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
import common  # noqa: E402
from fields_reader import read_fields  # noqa: E402

SCENE = os.path.join(HERE, "rising_water_column.opts")
chk = common.Checks("steady and excess pore pressure")


def p_base(t):
    return 29430.0 * np.minimum(1.0, 1.0 / 3.0 + (2.0 / 3.0) * np.asarray(t) / 20.0)


out = common.output_dir("polish_steady_pressure")
common.run(SCENE, out)
ts = common.read_timeseries(out)
t = ts["time"]
peak = 0.0
for probe, y in (("low", 0.25), ("mid", 0.5), ("high", 0.75)):
    p, steady, excess = ts[f"{probe}.p"], ts[f"{probe}.p_steady"], ts[f"{probe}.p_excess"]
    chk.check(f"{probe}: max |p_steady - p_base(t) (1 - y)| / 29430 Pa",
              float(np.max(np.abs(steady - p_base(t) * (1 - y)))) / 29430.0, 1e-9)
    chk.check(f"{probe}: max |p - p_steady - p_excess| / max |p|",
              float(np.max(np.abs(p - steady - excess)) / np.max(np.abs(p))), 1e-12)
    peak = max(peak, float(np.max(np.abs(excess))))
    chk.check(f"{probe}: |p_excess| at t = {t[-1]:g} s / its peak", abs(excess[-1]) / np.max(np.abs(excess)), 1e-6)
mid_peak = float(np.max(np.abs(ts["mid.p_excess"])))
chk.check(f"mid: peak excess {mid_peak:.0f} Pa against the rise of the steady pressure there "
          f"(9810 Pa): over 20 %", 0, 0, ok=mid_peak > 0.2 * 9810)

f = read_fields(out)
worst_steady = worst_split = 0.0
y = f.coordinates[:, 1]
for k, tk in enumerate(f.times):
    fk = f.fields[k]
    worst_steady = max(worst_steady, float(np.max(np.abs(fk["steady_pressure"] - p_base(tk) * (1 - y)))))
    worst_split = max(worst_split, float(np.max(np.abs(fk["pressure"] - fk["steady_pressure"] - fk["excess_pressure"]))))
chk.check(f"fields.h5, {len(f.times)} outputs: max |steady_pressure - p_base(t) (1 - y)| / 29430 Pa",
          worst_steady / 29430.0, 1e-9)
chk.check("fields.h5: max |pressure - steady_pressure - excess_pressure| / 29430 Pa", worst_split / 29430.0, 1e-12)

# 3. Closed column: no pressure prescribed (the base and top conditions left out).
closed = common.output_dir("polish_steady_pressure_closed")
scene = os.path.join(closed, "closed_column.opts")
with open(SCENE) as src, open(scene, "w") as dst:
    for line in src:
        if line.startswith(("-bc_top_p", "-bc_bottom_p")):
            continue
        if line.startswith(("-mesh ", "-options_file ")):
            key, path = line.split()
            line = f"{key} {os.path.normpath(os.path.join(HERE, path))}\n"
        dst.write(line)
    dst.write("-bc_top_traction 0,-1e4\n")
common.run(scene, closed, ["-ts_max_time", 4, "-ts_max_steps", 2, "-output_fields_every", 1])
f = read_fields(closed)
initial = f.fields[0]["pressure"]
worst = max(float(np.max(np.abs(fk["steady_pressure"] - initial))) for fk in f.fields)
loaded = float(np.max(np.abs(f.fields[-1]["excess_pressure"])))
chk.check("closed column: max |steady_pressure - initial pressure| [Pa]", worst, 0.0)
chk.check(f"closed column: the load's excess pressure ({loaded:.0f} Pa) is kept (excess over the "
          f"initial pressure)", 0, 0, ok=loaded > 5e3)
chk.finish()
