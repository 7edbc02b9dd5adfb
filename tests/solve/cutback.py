"""Step cut-back: a step whose Newton solve fails is cut and retried, and a run never
continues from an unconverged state.

The failures are forced with the test hook -test_fail_dt_above DT (every step attempt with a
larger dt fails with a function-domain error, as a diverging Newton solve would). Checks:
1. Terzaghi 2D with dt = 0.2 s and failures above 0.06 s: every step is cut (to 0.05 s), the
   run completes, and the pressure at mid-depth matches the backward-Euler series evaluated
   at the *actual* step times to 1e-3 q (the spatial error of this mesh is ~1e-4 q).
2. Failures above 0.03 s with -ts_max_reject 2 (two cuts reach only 0.05 s): the run stops with a
   non-zero exit and a message naming the failed step, and timeseries.csv holds no row past
   the initial state.
"""
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402
from common import analytic  # noqa: E402

SCENE = common.scene_path("terzaghi_2d.opts")
q, H, E, nu, k, mu = 1e4, 1.0, 1e7, 0.25, 1e-12, 1e-3
failures = []

out = common.output_dir("cutback")
common.run(SCENE, out, ["-ts_max_time", 1, "-test_fail_dt_above", 0.06, "-probe_mid", "0.05,0.5"])
ts = common.read_timeseries(out)
dt = ts["dt"]
rejected = ts["rejected"]
print(f"steps {dt.size}, dt used {np.unique(np.round(dt, 12))}, rejections per step {np.unique(rejected)}")
# Every step tries 0.1 s (the cut step grows back by 2) and fails, except the last: it is
# clipped to the 0.05 s left before -ts_max_time, which it must reach exactly.
if not np.all(dt <= 0.06) or not np.all(rejected[:-1] >= 1):
    failures.append("expected every step but the last to be cut below 0.06 s")
if abs(ts["time"][-1] - 1.0) > 1e-12:
    failures.append(f"expected the run to end at -ts_max_time 1 s, not {ts['time'][-1]!r}")
times = ts["time"]
M_c = analytic.constrained_modulus(E, nu)
p_be = analytic.terzaghi_pressure_be([H - 0.5], times, q, H, M_c, k / mu)[:, 0]
err = np.max(np.abs(ts["mid.p"] - p_be)) / q
print(f"mid-depth pressure vs backward-Euler series at the actual step times: max error {err:.2e} q")
if err > 1e-3:
    failures.append(f"pressure error {err:.2e} q > 1e-3 q after cut-backs")

out2 = common.output_dir("cutback_fail")
cmd = [common.EXE, "-options_file", SCENE, "-output_dir", out2, "-ts_max_steps", "5",
       "-test_fail_dt_above", "0.03", "-ts_max_reject", "2"]
res = subprocess.run(cmd, cwd=common.SOURCE, capture_output=True, text=True, timeout=120)
text = res.stdout + res.stderr
print(text.strip().splitlines()[-1] if text.strip() else "(no output)")
if res.returncode == 0:
    failures.append("a run whose step cannot converge exited with status 0")
if "step 1 failed" not in text or "did not converge" not in text:
    failures.append("the error does not name the failed step")
with open(os.path.join(out2, "timeseries.csv")) as f:
    rows = [line for line in f.read().splitlines()[1:] if line.strip()]
if len(rows) != 1:
    failures.append(f"timeseries.csv has {len(rows)} rows after a failed first step (expected only the initial state)")

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("cut-back: OK")
