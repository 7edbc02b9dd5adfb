"""Newton residual histories from a poroseam log run with -snes_monitor: one list of residual
norms per step (the lines '  k SNES Function norm r' before each 'step ...' line), and the
reduction of the residual by each step's last Newton iteration."""

import re
import statistics

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


def last_reductions(hist):
    """r_n / r_(n-1) of the last iteration of every step that took at least one: Newton with the
    consistent tangent ends each step with a reduction by orders of magnitude (the digits
    double), a fixed-point-like iteration (wrong tangent) by a roughly constant factor."""
    return [res[-1] / res[-2] for _, res in hist if len(res) >= 2 and res[-2] > 0]


def describe(step, residuals):
    return f"step {step}: " + ", ".join(f"{r:.2e}" for r in residuals)


def report(log_path, newton_its):
    """Prints a run's Newton record (the last step's and the longest step's residuals, the
    iterations per step, the last iteration's reductions) and returns the reductions."""
    hist = histories(log_path)
    print("  Newton residual norms:")
    print("    " + describe(*hist[-1]))
    print("    " + describe(*max(hist, key=lambda h: len(h[1]))) + " (most iterations)")
    print(f"  Newton iterations per step: max {int(newton_its.max())}, mean {newton_its.mean():.2f}")
    last = last_reductions(hist)
    print(f"  last iteration's reduction r_n / r_n-1 over the steps: median "
          f"{statistics.median(last):.1e}, largest {max(last):.1e}")
    return last
