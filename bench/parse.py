"""Reading what a benchmark run printed: poroseam's progress lines, PETSc's -memory_view
summary, the nested -log_view (ascii_flamegraph) profile, and the one-line reports of the
reference solve and the triad program."""

import re
import statistics

FIELD = re.compile(r"^field\s+(\S+)\s+(\d+)\s+unknowns")
# The step line: ... krylov K [(cut back)]  WALL s  eta ETA [checkpoint]
STEP = re.compile(r"^step\s+(\d+)\s+t\s+\S+\s+s\s+dt\s+\S+\s+load\s+\S+\s+newton\s+(\d+)\s+"
                  r"krylov\s+(\d+)(\s+\(cut back\))?\s+([0-9.eE+-]+)\s+s(\s+eta\s.*)?$")
MEMORY = re.compile(r"^Maximum \(over computational time\) process memory:\s+total\s+(\S+)\s+"
                    r"max\s+(\S+)\s+min\s+(\S+)")


def poroseam_stdout(text):
    """Unknowns per field, and per step: Newton and Krylov iterations, cut-back, wall time."""
    fields, steps = {}, []
    peak = None
    for line in text.splitlines():
        m = FIELD.match(line)
        if m:
            fields[m.group(1)] = int(m.group(2))
            continue
        m = STEP.match(line)
        if m:
            steps.append({"newton": int(m.group(2)), "krylov": int(m.group(3)),
                          "cut_back": bool(m.group(4)), "wall": float(m.group(5))})
            continue
        m = MEMORY.match(line)
        if m:
            peak = float(m.group(2))  # the largest rank's high-water mark [bytes]
    return {"fields": fields, "steps": steps, "peak_memory_per_rank": peak}


# Phases of the time stepping, each line of the profile counted in exactly one of them, in this
# order: what the output does (reactions included) is output; any PC set-up, also the one
# PETSc does lazily for the sub-solvers of a fieldsplit inside the first KSPSolve that needs
# it, is pc_setup; the rest of KSPSolve is solve; residuals and Jacobians (SNES's, and
# poroseam's own for its convergence test) are assembly; what is left (vector operations of
# Newton and TS, the line search's norms) is other.
def _stepping_phase(frames):
    if "PsOutput" in frames:
        return "output"
    if "PCSetUp" in frames:
        return "pc_setup"
    if "KSPSolve" in frames:
        return "solve"
    if any(f in frames for f in ("SNESFunctionEval", "SNESJacobianEval", "PsResidual",
                                 "PsJacobian")):
        return "assembly"
    return "other"


SETUP_PHASES = {"PsMesh": "mesh", "PsDistribution": "distribution", "PsLayout": "layout"}
EVENTS = ("PsResidual", "PsJacobian", "PsIfaceResidual", "PsIfaceJacobian", "PsFirstJacobian",
          "PsOutput", "SNESFunctionEval", "SNESJacobianEval", "PCSetUp", "KSPSolve")


def flamegraph(text):
    """Exclusive times [s] per phase from -log_view :file:ascii_flamegraph.

    Each line is a call path 'A;B;C <microseconds>': the time spent in C itself under A;B
    (PETSc writes the maximum over ranks of each path; paths below 0.01 % of the run are left
    out). Summing lines attributes every microsecond once, which -log_view's table cannot do:
    there PCSetUp of a fieldsplit's sub-solvers is counted inside KSPSolve too.
    Returns {'mesh', 'distribution', 'layout', 'stepping', 'assembly', 'pc_setup', 'solve',
    'output', 'other', 'outside'} and 'inclusive': {event: time including its children}."""
    phases = dict.fromkeys(["mesh", "distribution", "layout", "stepping", "assembly",
                            "pc_setup", "solve", "output", "other", "outside"], 0.0)
    inclusive = dict.fromkeys(EVENTS, 0.0)
    for line in text.splitlines():
        line = line.rstrip()
        if not line or " " not in line:
            continue
        path, value = line.rsplit(" ", 1)
        try:
            seconds = int(value) * 1e-6
        except ValueError:
            continue
        frames = [f.strip() for f in path.split(";")]
        for event in EVENTS:
            if event in frames:
                inclusive[event] += seconds
        top = frames[0]
        if top in SETUP_PHASES:
            phases[SETUP_PHASES[top]] += seconds
        elif top == "PsTimeStepping":
            phases["stepping"] += seconds
            phases[_stepping_phase(frames)] += seconds
        else:
            phases["outside"] += seconds  # initialisation, finalisation, option handling
    phases["inclusive"] = inclusive
    return phases


REFERENCE = re.compile(r"^reference_elasticity unknowns (\d+) grid (\d+) (\d+) (\d+) ranks (\d+) "
                       r"assembly_s (\S+) setup_s (\S+) solve_s (\S+) iterations (\d+) "
                       r"reason (\S+)")


def reference(text):
    """The reference solve's report line (bench/reference_elasticity.c), or None."""
    for line in text.splitlines():
        m = REFERENCE.match(line)
        if m:
            return {"unknowns": int(m.group(1)), "grid": tuple(int(m.group(i)) for i in (2, 3, 4)),
                    "ranks": int(m.group(5)), "assembly_s": float(m.group(6)),
                    "setup_s": float(m.group(7)), "solve_s": float(m.group(8)),
                    "iterations": int(m.group(9)), "reason": m.group(10)}
    return None


TRIAD = re.compile(r"^stream_triad ranks (\d+) array_mb (\S+) best_s (\S+) total_gbs (\S+) "
                   r"per_rank_gbs (\S+)")


def triad(text):
    """The triad program's report line (bench/stream_triad.c), or None."""
    for line in text.splitlines():
        m = TRIAD.match(line)
        if m:
            return {"ranks": int(m.group(1)), "array_mb": float(m.group(2)),
                    "total_gbs": float(m.group(4)), "per_rank_gbs": float(m.group(5))}
    return None


def median(values):
    return statistics.median(values) if values else float("nan")
