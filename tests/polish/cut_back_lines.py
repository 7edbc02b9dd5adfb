#!/usr/bin/python3
"""A step cut back says so as it happens (issue 24 item 11): one line per failed attempt, on
rank 0, before the step's own line, naming the step, why the attempt failed (Newton's reason
and iterations), its dt and the dt of the retry; the one-line-per-step format is kept.

Terzaghi 2D (options/terzaghi_2d.opts) with dt = 0.2 s, 3 steps, and the test hook
-test_fail_dt_above 0.03: every attempt above 0.03 s fails, as a diverging Newton solve would
(a function-domain error), so step 1 is cut three times (0.2 -> 0.1 -> 0.05 -> 0.025 s); the
cut step grows back by 2 per step, so steps 2 and 3 (trying 0.05 s) are cut once each. On
2 ranks, so that the lines come once (rank 0) and in order through mpiexec. About 2 s.
Expected on stdout, in this order:
    step 1: ... at dt 2.0000e-01 s, retrying with dt 1.0000e-01 s
    step 1: ... at dt 1.0000e-01 s, retrying with dt 5.0000e-02 s
    step 1: ... at dt 5.0000e-02 s, retrying with dt 2.5000e-02 s
    step    1 ...  (cut back) ...
    step 2: ... at dt 5.0000e-02 s, retrying with dt 2.5000e-02 s
    step    2 ...
    step 3: ...
    step    3 ...
"""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402

chk = common.Checks("cut-back lines")
scene = os.path.join(common.SOURCE, "options", "terzaghi_2d.opts")
out = common.output_dir("polish_cut_back_lines")
cmd = ["mpiexec", "-n", "2", common.EXE, "-options_file", scene, "-output_dir", out, "-ts_dt", "0.2",
       "-ts_max_time", "100", "-ts_max_steps", "3", "-test_fail_dt_above", "0.03"]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
res = subprocess.run(cmd, cwd=common.SOURCE, env=env, capture_output=True, text=True, timeout=120)
lines = res.stdout.splitlines()
print("\n".join(line for line in lines if line.lstrip().startswith("step")))
cut = re.compile(r"^  step (\d+): Newton failed \((DIVERGED_\w+) after (\d+) iterations?\) at dt "
                 r"(\S+) s, retrying with dt (\S+) s$")
step = re.compile(r"^step +(\d+) ")
events = []  # ("cut", step, dt, retry) or ("step", step)
for line in lines:
    m = cut.match(line)
    if m:
        events.append(("cut", int(m.group(1)), float(m.group(4)), float(m.group(5)), m.group(2)))
    elif step.match(line):
        events.append(("step", int(step.match(line).group(1))))
expected = [("cut", 1, 0.2, 0.1), ("cut", 1, 0.1, 0.05), ("cut", 1, 0.05, 0.025), ("step", 1),
            ("cut", 2, 0.05, 0.025), ("step", 2), ("cut", 3, 0.05, 0.025), ("step", 3)]
got = [e[:4] if e[0] == "cut" else e for e in events]
same = len(got) == len(expected) and all(
    a[:2] == b[:2] and (a[0] == "step" or (abs(a[2] - b[2]) < 1e-12 and abs(a[3] - b[3]) < 1e-12))
    for a, b in zip(got, expected))
chk.check(f"cut-back and step lines in order: {got} (expected {expected})", 0, 0, ok=same)
reasons = sorted({e[4] for e in events if e[0] == "cut"})
chk.check(f"the failure named as Newton's reason: {reasons}", 0, 0,
          ok=reasons == ["DIVERGED_FUNCTION_DOMAIN"])
step1 = [line for line in lines if step.match(line) and step.match(line).group(1) == "1"]
chk.check("the step line of step 1 still says (cut back), once", 0, 0,
          ok=len(step1) == 1 and "(cut back)" in step1[0])
# The run ends at its step limit (3 steps of the 100 s): a non-zero exit that says so.
chk.check("the run ended at its step limit", 0, 0,
          ok="step limit -ts_max_steps 3" in res.stdout + res.stderr)
chk.finish()
