"""Newton residual histories from a poroseam log run with -snes_monitor: one list of residual
norms per accepted or attempted step (the lines '  k SNES Function norm r' before each
'step ...' line), and the observed order of convergence near the end of each solve."""

import math
import re

NORM = re.compile(r"^\s*(\d+) SNES Function norm ([0-9.eE+-]+)")
STEP = re.compile(r"^step\s+(\d+)\s")


def histories(log_path):
    """[(step number, [r_0, r_1, ...]), ...] for every step line of the log (a cut-back
    step's failed attempts come before it and are kept in its list, separated by a restart at
    iteration 0: only the last attempt is returned)."""
    out, current = [], []
    with open(log_path) as f:
        for line in f:
            m = NORM.match(line)
            if m:
                if int(m.group(1)) == 0:
                    current = []
                current.append(float(m.group(2)))
                continue
            m = STEP.match(line)
            if m:
                out.append((int(m.group(1)), current))
                current = []
    return out


def orders(residuals, floor):
    """Observed orders log(r_k+1 / r_k) / log(r_k / r_k-1) for the iterations whose residuals
    are all above `floor` (below it round-off, not Newton, sets the residual)."""
    q = []
    for k in range(1, len(residuals) - 1):
        r0, r1, r2 = residuals[k - 1], residuals[k], residuals[k + 1]
        if min(r0, r1, r2) <= floor or r1 >= r0:
            continue
        q.append(math.log(r2 / r1) / math.log(r1 / r0))
    return q


def describe(step, residuals):
    return f"step {step}: " + ", ".join(f"{r:.2e}" for r in residuals)
