#!/usr/bin/python3
"""The linear solver keeps its factorisation (or preconditioner) while the Jacobian is unchanged
(-snes_keep_preconditioner, on by default; docs/performance.md), and only then.

Counts come from PETSc's own -log_view (MatLUFactorNum: numeric LU factorisations by MUMPS,
SNESJacobianEval: Jacobians assembled), not from poroseam. Every case also runs with
-snes_keep_preconditioner 0 (a factorisation per Jacobian, as before) and the time series must
agree to 1e-10 of each quantity's scale.

    keep_factor.py --case NAME      one case (one ctest each)
    keep_factor.py --list           the case names

Cases:
    linear          Terzaghi's 3D column (linear Biot) at a fixed step, 10 steps: 1 factorisation
    linear_order2   the same at -displacement_order 2
    linear_np2      the same on 2 ranks
    dt_change       9 steps of 0.25 s, then PETSc shares the 0.375 s left between two steps
                    (-ts_max_time 2.625; all times exact in binary): 2
    bdf2            BDF2: its start-up half step, its first step (uneven stencil), then the
                    even steps: 3
    iterative       the fieldsplit preset: its preconditioners (fieldsplit, vertex_blocks,
                    GAMG, the Schur complement's) set up once: PETSc's PCSetUp count is that
                    of one Jacobian of the run that rebuilds them
    interface       a contact interface (block_shear_2d, 8 steps): a factorisation for every
                    Jacobian, as many as without keeping
"""

import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402

COLUMN = common.scene_path("terzaghi_3d.opts")
FIXED = ["-ts_dt", "0.25", "-ts_max_time", "2.5", "-ts_max_steps", "100"]
CASES = {
    "linear": dict(scene=COLUMN, args=FIXED, factorisations=1),
    "linear_order2": dict(scene=COLUMN, args=FIXED + ["-displacement_order", "2"],
                          factorisations=1),
    "linear_np2": dict(scene=COLUMN, args=FIXED, factorisations=1, ranks=2),
    "dt_change": dict(scene=COLUMN, args=["-ts_dt", "0.25", "-ts_max_time", "2.625"],
                      factorisations=2),
    "bdf2": dict(scene=COLUMN, args=FIXED + ["-ts_type", "bdf", "-ts_bdf_order", "2"],
                 factorisations=3),
    "iterative": dict(scene=COLUMN, args=FIXED + [
        "-options_file", os.path.join(common.SOURCE, "options", "solvers", "fieldsplit.opts"),
        "-pc_factor_mat_solver_type", "mumps"], setups="once"),
    "interface": dict(scene=os.path.join(common.SOURCE, "options", "block_shear_2d.opts"),
                      args=["-ts_max_time", "4", "-output_fields_every", "0"],
                      factorisations="per jacobian"),
}


def log_count(path, event):
    """The count column of `event` in a -log_view file (0 when the event did not occur)."""
    with open(path) as f:
        for line in f:
            if re.match(re.escape(event) + r"\s", line):
                return int(line.split()[1])
    return 0


def main():
    if "--list" in sys.argv:
        print("\n".join(CASES))
        return 0
    name = sys.argv[sys.argv.index("--case") + 1]
    case = CASES[name]
    checks = common.Checks(f"keep factorisation: {name}")
    runs = {}
    for keep in (1, 0):
        out = common.output_dir(f"keep_factor_{name}_{keep}")
        log = os.path.join(out, "log_view.txt")
        common.run(case["scene"], out,
                   case["args"] + ["-snes_keep_preconditioner", keep, "-log_view", ":" + log],
                   ranks=case.get("ranks", 1))
        runs[keep] = dict(series=common.read_timeseries(out),
                          lu=log_count(log, "MatLUFactorNum"),
                          jacobians=log_count(log, "SNESJacobianEval"),
                          setups=log_count(log, "PCSetUp"))
        print(f"  keep {keep}: {runs[keep]['jacobians']} Jacobians, {runs[keep]['lu']} LU "
              f"factorisations, {runs[keep]['setups']} PC set-ups")
    kept, rebuilt = runs[1], runs[0]
    if "factorisations" in case:
        want = case["factorisations"]
        if want == "per jacobian":
            checks.check("factorisations kept = Jacobians", abs(kept["lu"] - kept["jacobians"]),
                         0)
            checks.check("factorisations kept = rebuilt", abs(kept["lu"] - rebuilt["lu"]), 0)
        else:
            checks.check(f"factorisations kept = {want}", abs(kept["lu"] - want), 0)
            # Without keeping: one per Jacobian, so that the count above is the change's doing.
            checks.check("factorisations rebuilt = Jacobians",
                         abs(rebuilt["lu"] - rebuilt["jacobians"]), 0)
            checks.check("more Jacobians than factorisations kept", want,
                         rebuilt["jacobians"] - 1)
    else:
        # The run that rebuilds sets every PC up at every Jacobian: the same number each time.
        per_jacobian = rebuilt["setups"] // max(rebuilt["jacobians"], 1)
        checks.check("PC set-ups rebuilt: a multiple of the Jacobians",
                     rebuilt["setups"] - per_jacobian * rebuilt["jacobians"], 0)
        checks.check(f"PC set-ups kept = those of one Jacobian ({per_jacobian})",
                     abs(kept["setups"] - per_jacobian), 0)
        checks.check("more than one Jacobian", 1, rebuilt["jacobians"] - 1)
    diff, where = common.largest_series_difference(rebuilt["series"], kept["series"],
                                                   skip=("wall_time", "time", "dt", "step"))
    checks.check(f"time series kept vs rebuilt (worst: {where})", diff, 1e-10)
    checks.check("same Newton iterations",
                 abs(kept["series"]["newton_its"].sum() - rebuilt["series"]["newton_its"].sum()), 0)
    checks.finish()


if __name__ == "__main__":
    sys.exit(main())
