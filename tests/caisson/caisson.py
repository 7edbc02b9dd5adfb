"""Suction caisson uplift (docs/caisson.md; paper section 3): the checks any correct model
must pass, on the scenes options/caisson_*.opts as they are, coarsened from the command line.

    caisson.py --case axisym_drained | axisym_partially_drained | quarter_partially_drained |
                      quarter_vs_axisym  [--ranks 2] [--factor F] [--order 2] [--plot]

Resistances are reported as the vertical force of the caisson on the soil (the soil-side
interface force of timeseries.csv, positive when it holds the caisson down); Delta is the change
since row 0 (the initial state). Axisymmetric runs report the full circle, 3D runs the quarter.

Vertical equilibrium of the caisson (every step >= 1). What acts on the caisson vertically:
the lid-top reaction R (prescribed displacement), its weight W = rho_s g V, and the interface
(all four parts, p3 included): R = F_if + W, F_if = <interface>.F (force on the soil). Nothing
else: lid_side is free (its column is 0: the reaction of the rim vertex is
lid_top's), the axis (2D) carries ux = 0 only, the symmetry planes (3D) are
rollers, and the lid is above the water level (no water pressure on lid_top or lid_side).
Row 0 is not an equilibrium state of the caisson: the geostatic state loads the soil only, the
row-0 lid_top reaction holds just the weight lumped on the lid-top vertices, and the caisson's
weight enters in step 1, into the lid-top reaction. So the "weight change" since row 0 is not
zero, and Delta F_tot = R(n) - W - F_if(0), compared with Delta F_if(n) = F_if(n) - F_if(0):
  * axisymmetric (exact geometry): W = rho_s g (pi R_o^2 t_lid + pi (R_o^2 - R_i^2) L) (full
    circle, 748 kN), |R - F_if - W| <= 0.5 % of Delta F_tot at every step;
  * 3D quarter: the faceted circle of the coarse mesh holds 0.64 % less steel than W / 4
    (factor 2: 8 chords per quarter, sin(t)/t): the implied weight R - F_if at step 1 against
    W / 4 within 1 %, and R - F_if constant from step 1 on within 0.5 % of Delta F_tot.

Drained plateau (axisym_drained): once every outer_skirt point in contact (p'_N > 0) slips,
the vertical outer-skirt force equals mu * sum(weight * p'_N) over the outer_skirt points
(vertical skirt: the shear is vertical; the initial shear is zero, so Delta F_ext = F_ext),
within 1 %. The uplift at which the outer skirt becomes fully mobilised is printed beside the
paper's 0.63 mm; it fails only if none is found or it lies outside [0.2, 2] mm.

Stationary phase (axisym_ and quarter_partially_drained): for uplift >= 2 mm,
rho_w * lid.storage_rate against rho_w v_up pi R_i^2 (full circle: 0.756 kg/s; quarter, / 4:
0.189 kg/s; the faceted coarse quarter mesh has 0.64 % less lid area) within 5 %.
rho_w * lid.flux1 (the transversal flux from the plug alone) is printed.

Quarter against axisymmetric (quarter_vs_axisym, drained): 4 x the quarter model's Delta F_tot,
Delta F_ext, Delta F_int against the axisymmetric ones (default mesh, same steps) at the end
(2 mm of uplift, both skirts sliding), within 5 %.

Mohr-Coulomb soil (axisym_drained_mohr_coulomb: options/caisson_axisym_drained_mohr_coulomb.opts,
0.2 mm steps to 2 mm): the same vertical equilibrium and drained plateau (the interface's Coulomb
law does not depend on the soil's), the plastic zone where the skirt shears the soil (yielded
cells in the plug and outside the skirt, none in the steel, none farther than 4 m from the
skirt or 1.5 m below its tip), the run ending at -ts_max_time after its cut-back, and Newton
iterations within the recorded counts (deterministic for a mesh and number of ranks).

--plot also runs scripts/plot_caisson on the outputs (must exit 0 and write its figures).
--order 2 (axisym_drained, axisym_partially_drained): -displacement_order 2, quadratic bodies
and interfaces; the same checks (the equilibrium and the drained plateau weigh the interface's
points with their ring weights, the storage rate integrates p3's balance over the lid).
"""
import argparse
import os
import re
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
import common  # noqa: E402  (tests/verification/common.py)
from interface_reader import read_interfaces  # noqa: E402

R_IN, R_OUT, SKIRT, LID = 3.8, 3.9, 4.0, 0.4
V_CAISSON = np.pi * R_OUT**2 * LID + np.pi * (R_OUT**2 - R_IN**2) * SKIRT  # full circle, m3
RHO_W = 1000.0
PAPER_MOBILISED_MM = 0.63


def scene(name):
    return os.path.join(common.SOURCE, "options", name)


def read_all_rows(out_dir):
    """timeseries.csv with row 0 kept (common.read_timeseries drops it)."""
    path = os.path.join(out_dir, "timeseries.csv")
    if not os.path.isfile(path):
        common.fail(f"no time series written: {path}")
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    if data.shape[0] < 2:
        common.fail(f"{path}: fewer than 2 rows")
    return {n.strip(): data[:, i] for i, n in enumerate(header)}


def col(ts, name):
    if name not in ts:
        common.fail(f"timeseries.csv has no column '{name}'")
    return ts[name]


class Run:
    """One run of a caisson scene: its options, time series and interface output."""

    def __init__(self, scene_file, name, overrides, ranks):
        self.opts = common.read_scene(scene_file)
        self.dim = 3 if "-bc_lid_top_uz" in self.opts else 2
        self.v = "z" if self.dim == 3 else "y"
        self.out = common.output_dir(name)
        self.wall = common.run(scene_file, self.out, overrides, ranks=ranks, timeout=600)
        self.ts = read_all_rows(self.out)
        u = float(self.opts[f"-bc_lid_top_u{self.v}"])
        ramp = float(self.opts[f"-bc_lid_top_u{self.v}_ramp"])
        self.v_up = u / ramp
        self.uplift = np.minimum(self.ts["time"], ramp) * self.v_up  # prescribed lid-top displacement
        self.mu = float(self.opts["-interface_caisson_friction"])
        self.weight = float(self.opts["-region_caisson_rho_s"]) * float(self.opts["-gravity"]) * V_CAISSON
        if self.dim == 3:
            self.weight /= 4.0
        self.ifc = None

    def F(self, part=""):
        return col(self.ts, f"caisson{'.' + part if part else ''}.F{self.v}")

    def reaction(self):
        return col(self.ts, f"lid_top.F{self.v}")

    def d_tot(self, weight=None):
        """Delta F_tot = R - W - F_if(0) (row 0: 0)."""
        w = self.weight if weight is None else weight
        d = self.reaction() - w - self.F()[0]
        d[0] = 0.0
        return d

    def interfaces(self):
        if self.ifc is None:
            self.ifc = read_interfaces(self.out)
            pf = self.ifc.point_fields[0]
            x = self.ifc.point_coordinates
            r = np.abs(x[:, 0]) if self.dim == 2 else np.hypot(x[:, 0], x[:, 1])
            nv = np.abs(pf["normal"][:, self.dim - 1])
            # outer skirt: vertical face (horizontal normal) at r = R_OUT
            self.outer = (nv < 0.5) & (np.abs(r - R_OUT) < 0.02) & (pf["interface"] == 0)
            if not self.outer.any():
                common.fail("no outer_skirt points in the interface output")
            # the surface index of those points must be one only
            if len(np.unique(pf["surface"][self.outer])) != 1:
                common.fail("outer skirt points belong to several surfaces")
        return self.ifc


def equilibrium(chk, run, label):
    """Vertical equilibrium of the caisson at every step >= 1 (see the module docstring)."""
    R, Fif = run.reaction(), run.F()
    held = R - Fif
    print(f"  {label}: row 0: R = {R[0] / 1e3:.1f} kN, F_if = {Fif[0] / 1e3:.1f} kN (weight held in row 0: "
          f"{held[0] / 1e3:.1f} kN); R - F_if at step 1 = {held[1] / 1e3:.2f} kN; rho_s g V"
          f"{' / 4' if run.dim == 3 else ''} = {run.weight / 1e3:.2f} kN")
    if run.dim == 2:
        dtot = run.d_tot()
        err = (held - run.weight)[1:]
        rel = np.abs(err) / np.abs(dtot[1:])
        k = int(np.argmax(rel))
        print(f"  {label}: Delta F_tot from {dtot[1] / 1e3:.1f} to {dtot[-1] / 1e3:.1f} kN; worst step {k + 1}: "
              f"R - F_if - W = {err[k]:.4g} N")
        chk.check(f"{label}: vertical equilibrium every step, max |R - F_if - W| / |Delta F_tot|",
                  float(rel.max()), 5e-3)
        return
    chk.check(f"{label}: implied caisson weight R - F_if (step 1) against rho_s g V / 4 (faceted mesh), relative",
              abs(held[1] - run.weight) / run.weight, 1e-2)
    dtot = run.d_tot(weight=held[1])
    rel = np.abs(held[1:] - held[1]) / np.abs(dtot[1:])
    print(f"  {label}: Delta F_tot from {dtot[1] / 1e3:.1f} to {dtot[-1] / 1e3:.1f} kN")
    chk.check(f"{label}: vertical equilibrium every step, max |(R - F_if) - (R - F_if)(step 1)| / |Delta F_tot|",
              float(rel.max()), 5e-3)


def full_mobilisation(run):
    """Uplift [mm] (and the step before) at which every outer_skirt point in contact slips, and
    the open length at the top then; None if never."""
    ifc = run.interfaces()
    prev = None
    for k, t in enumerate(ifc.times):
        pf = ifc.point_fields[k]
        m = run.outer
        contact = m & (pf["contact_pressure_effective"] > 0)
        if t <= 0 or not contact.any():
            prev = t
            continue
        slip = np.all(pf["state"][contact] == 2)
        mob = np.all(pf["mobilised_friction"][contact] >= 0.99 * run.mu)
        if slip or mob:
            z = ifc.point_coordinates[m, run.dim - 1]
            open_len = -float(np.min(z[pf["state"][m] == 0])) if np.any(pf["state"][m] == 0) else 0.0
            u = float(np.interp(t, run.ts["time"], run.uplift)) * 1e3
            up = None if prev is None else float(np.interp(prev, run.ts["time"], run.uplift)) * 1e3
            return u, up, open_len, int(np.sum(contact)), int(np.sum(m))
        prev = t
    return None


def plot(chk, run, figures, stages=0):
    """scripts/plot_caisson on the run; with `stages`, figure 7 must show at least that many
    uplifts before the outer skirt is fully mobilised (the progressive mobilisation)."""
    exe = os.path.join(common.SOURCE, "scripts", "plot_caisson")
    for f in figures:
        p = os.path.join(run.out, f)
        if os.path.exists(p):
            os.remove(p)
    t0 = time.time()
    # fig 9a (ParaView) has its own test, label pictures: not drawn again here
    r = subprocess.run([sys.executable, exe, run.out, "--no-paraview"], capture_output=True, text=True)
    print("  plot_caisson (%.1f s):" % (time.time() - t0))
    for line in (r.stdout + r.stderr).strip().splitlines():
        print("    " + line)
    missing = [f for f in figures if not os.path.isfile(os.path.join(run.out, f))]
    chk.check(f"scripts/plot_caisson exits 0 and writes {len(figures)} figures (missing: {len(missing)})",
              float(len(missing) + (r.returncode != 0)), 0)
    if stages:
        m = re.search(r"fig7_mobilised_friction\.png: .* at \d+ uplifts \(([^)]*) mm\)", r.stdout)
        drawn = [float(v) for v in m.group(1).split(",")] if m else []
        with open(os.path.join(run.out, "caisson.csv")) as f:
            header = f.readline().strip().split(",")
            first = f.readline().strip().split(",")
        full = float(first[header.index("outer_skirt_mobilised_at_mm")])
        before = [u for u in drawn if u < full]
        chk.check(f"fig7 draws {len(before)} uplifts before full mobilisation at {full:.2f} mm "
                  f"({drawn} mm; at least {stages})", 0, 0, ok=len(before) >= stages)


def order_options(args):
    """The output-name suffix and options of --order."""
    return (f"_order{args.order}", ["-displacement_order", args.order]) if args.order > 1 else ("", [])


def case_axisym_drained(args):
    suffix, order = order_options(args)
    chk = common.Checks(f"caisson, axisymmetric, drained (mesh factor {args.factor}, {args.ranks} ranks"
                        f"{', order ' + str(args.order) if suffix else ''})")
    # 0.1 mm per step to 2 mm; the scene's own output intervals: fields every 6 steps,
    # interfaces every step (the default of -output_interfaces_every, for the mobilisation)
    run = Run(scene("caisson_axisym_drained.opts"), "caisson_axisym_drained" + suffix,
              ["-mesh_size_factor", args.factor, "-ts_dt", 6, "-ts_max_time", 120, "-ts_max_steps", 20] + order,
              args.ranks)
    ts = run.ts
    chk.check("cut-backs", float(ts["rejected"].sum()), 0)
    equilibrium(chk, run, "drained")
    Fext = drained_plateau(chk, run)
    mob = full_mobilisation(run)
    if mob is None:
        chk.check("outer skirt fully mobilised within the run", 1.0, 0)
    else:
        u, up, open_len, nc, n = mob
        k_peak = int(np.argmax(Fext))
        print(f"  outer skirt fully mobilised (every contact point in slip) at {u:.2f} mm of uplift (not yet at "
              f"{up:.2f} mm); paper: {PAPER_MOBILISED_MM} mm. Then {nc} of {n} points in contact, the top "
              f"{open_len:.2f} m open; Delta F_ext peaks at {run.uplift[k_peak] * 1e3:.2f} mm")
        chk.check(f"uplift at full mobilisation of the outer skirt (reported; paper {PAPER_MOBILISED_MM} mm) "
                  "in [0.2, 2] mm", u, 2.0, ok=0.2 <= u <= 2.0, unit=" mm")
    if args.plot:
        plot(chk, run, ["fig6a_forces.png", "fig7_mobilised_friction.png", "fig9b_soil_uplift.png"], stages=3)
    chk.finish()


def drained_plateau(chk, run):
    """The drained plateau: F_ext = mu int p'_N over the fully mobilised output steps (1 %).
    Returns the outer skirt's vertical force per step."""
    ts = run.ts
    ifc = run.interfaces()
    Fext = run.F("outer_skirt")
    area = np.sum(ifc.point_fields[0]['weight'][run.outer])
    print(f"  outer skirt: initial vertical force F_ext(0) = {Fext[0]:.4g} N (no initial shear), "
          f"{int(run.outer.sum())} points, sum of weights {area:.3f} m2 "
          f"(2 pi R_o L = {2 * np.pi * R_OUT * SKIRT:.3f})")
    # The ring weights of the points add up to the skirt's area (any rule, either order).
    chk.check("outer skirt: |sum of the points' weights - 2 pi R_o L| / (2 pi R_o L)",
              abs(area - 2 * np.pi * R_OUT * SKIRT) / (2 * np.pi * R_OUT * SKIRT), 1e-9)
    rels, last = [], None
    for k, t in enumerate(ifc.times):
        pf = ifc.point_fields[k]
        contact = run.outer & (pf["contact_pressure_effective"] > 0)
        if t <= 0 or not contact.any() or not np.all(pf["state"][contact] == 2):
            continue
        i = int(np.argmin(np.abs(ts["time"] - t)))
        friction = run.mu * np.sum(pf["weight"][run.outer] * pf["contact_pressure_effective"][run.outer])
        rels.append(abs(Fext[i] - friction) / friction)
        last = (t, run.uplift[i], Fext[i], friction, Fext[i] - Fext[0])
    if last is None:
        chk.check("drained plateau: outer skirt fully mobilised at some step", 1.0, 0)
    else:
        t, u, F, fr, dF = last
        print(f"  plateau at {u * 1e3:.2f} mm: Delta F_ext = {dF / 1e3:.2f} kN, F_ext = {F / 1e3:.2f} kN, "
              f"mu int p'_N = {fr / 1e3:.2f} kN ({len(rels)} fully mobilised output steps)")
        chk.check("drained plateau: max |F_ext - mu int p'_N| / (mu int p'_N) over fully mobilised steps",
                  float(max(rels)), 1e-2)
    return Fext


def case_axisym_drained_mohr_coulomb(args):
    """The drained axisymmetric caisson with Mohr-Coulomb soil, coarse (see the module docstring)."""
    import fields_reader  # tests/support
    chk = common.Checks(f"caisson, axisymmetric, drained, Mohr-Coulomb soil (mesh factor {args.factor}, "
                        f"{args.ranks} ranks)")
    # 0.2 mm per step to 2 mm; interface and field output every step
    end = 120.0
    run = Run(scene("caisson_axisym_drained_mohr_coulomb.opts"), "caisson_axisym_drained_mohr_coulomb",
              ["-mesh_size_factor", args.factor, "-ts_dt", 12, "-ts_max_time", end, "-ts_max_steps", 20,
               "-output_fields_every", 1], args.ranks)
    ts = run.ts
    newton = np.asarray(ts["newton_its"][1:], float)
    print(f"  Newton iterations per step (cut attempts included): {' '.join(str(int(n)) for n in newton)}; "
          f"{int(newton.sum())} in all; cut-backs {int(ts['rejected'].sum())}")
    # Recorded on this mesh (factor 2, 2 ranks): the first step (0.2 mm, the caisson's weight
    # and the onset of yield together) is cut once: at its second Newton iterate no point of
    # the direction lowers the residual (8.4e4 N; 8.9e4 just past the first contact kink at
    # lambda = 1e-4, and at every halving to 1/1024), the non-smoothness of points switching
    # between the plastic and the elastic branch; the 6 s step converges in 6 iterations.
    # Then 40 Newton iterations in all (7 9 6 7 5 1 1 1 1 1 1), the elastic scene 21 in 10
    # steps. Bounds: the cut-back count, the largest step, the total + 10 %.
    chk.check("cut-backs (recorded: 1, the first step)", float(ts["rejected"].sum()), 1)
    chk.check("most Newton iterations of a step (recorded 9)", float(newton.max()), 9)
    chk.check("Newton iterations in all (recorded 40, bound + 10 %)", float(newton.sum()), 44)
    # after the cut-back the steps grow back to the nominal size and land on -ts_max_time
    chk.check("the run ends at -ts_max_time, |t_end - 120 s|", abs(float(ts["time"][-1]) - end), 1e-9, unit=" s")
    equilibrium(chk, run, "drained, plastic")
    drained_plateau(chk, run)
    # The plastic zone: the soil the skirt shears, inside (at the tip) and outside the skirt;
    # not in the steel, nowhere far from the skirt.
    try:
        f = fields_reader.read_fields(run.out)
    except fields_reader.FieldsError as e:
        common.fail(f"{run.out}: {e}")
    cells = f.cell_fields[-1]
    centre = f.coordinates[f.connectivity].mean(axis=1)
    r, z = centre[:, 0], centre[:, 1]
    plastic = cells["equivalent_plastic_strain"].ravel() > 0
    region = cells["region"].astype(int).ravel()
    steel = f.region_names.index("caisson")
    states = np.bincount(cells["yield_state"].astype(int).ravel(), minlength=5)
    print(f"  last step: {int(plastic.sum())} of {len(plastic)} cells have yielded (max equivalent plastic strain "
          f"{np.max(cells['equivalent_plastic_strain']):.3g}), r {r[plastic].min():.2f}-{r[plastic].max():.2f} m, "
          f"z {z[plastic].min():.2f}-{z[plastic].max():.2f} m; yielding now: face {states[1]}, edge {states[2]}, "
          f"apex {states[3]}, cut-off {states[4]}")
    chk.check("yielded cells in the plug (r < R_int), negated", -float(np.sum(plastic & (r < R_IN))), -1)
    chk.check("yielded cells outside the skirt (r > R_o), negated", -float(np.sum(plastic & (r > R_OUT))), -1)
    chk.check("yielded cells in the steel", float(np.sum(plastic & (region == steel))), 0)
    far = plastic & ((np.abs(r - 0.5 * (R_IN + R_OUT)) > 4.0) | (z < -SKIRT - 1.5))
    chk.check("yielded cells farther than 4 m from the skirt or 1.5 m below its tip", float(np.sum(far)), 0)
    # scripts/plot_plastic_caisson runs on it (compared with itself: every ratio is 1)
    exe = os.path.join(common.SOURCE, "scripts", "plot_plastic_caisson")
    figures = ["plastic_caisson_forces.png", "plastic_caisson_gap.png", "plastic_caisson_newton.png",
               "plastic_caisson.csv", "plastic_caisson_newton.csv"]
    plots = os.path.join(run.out, "compare")
    r = subprocess.run([sys.executable, exe, "--drained", run.out, run.out, "--out", plots],
                       capture_output=True, text=True)
    print("\n".join("    " + line for line in (r.stdout + r.stderr).strip().splitlines()[-6:]))
    missing = [f for f in figures if not os.path.isfile(os.path.join(plots, f))]
    chk.check(f"scripts/plot_plastic_caisson exits 0 and writes {len(figures)} files (missing: {len(missing)})",
              float(len(missing) + (r.returncode != 0)), 0)
    chk.finish()


def case_partially_drained(args, quarter):
    model = "3D quarter" if quarter else "axisymmetric"
    suffix, order = order_options(args)
    chk = common.Checks(f"caisson, {model}, partially drained (mesh factor {args.factor}, {args.ranks} ranks"
                        f"{', order ' + str(args.order) if suffix else ''})")
    name = "caisson_partially_drained.opts" if quarter else "caisson_axisym_partially_drained.opts"
    # 0.2 mm per step to 3 mm
    run = Run(scene(name), name[:-5] + suffix,
              ["-mesh_size_factor", args.factor, "-ts_dt", 12, "-ts_max_time", 180, "-ts_max_steps", 15,
               "-output_fields_every", 5] + order, args.ranks)
    ts = run.ts
    chk.check("cut-backs", float(ts["rejected"].sum()), 0)
    if quarter and common.SOLVER == "fieldsplit":
        # Guard of the iterative preset (iteration counts are deterministic for a given mesh and
        # number of ranks): outer Krylov iterations per Newton iteration recorded on this mesh
        # (factor 2, 2 ranks) with one GAMG V-cycle on the displacement per outer iteration,
        # every Newton solve at most 0.01 and the target known from a step's first solve
        # (newton_forcing.hpp), Chebyshev on [0.05, 1.05] of the largest eigenvalue, GAMG's
        # coarse levels rebuilt every 10 set-ups and one BoomerAMG sweep per level on the
        # pressures: worst step 32.50 (a one-Newton step, solved to 0.01 of its target), mean
        # 21.26 (58 Newton and 1233 outer iterations in 15 steps). Bounds 10 % above. Before
        # the coarse lag and the single sweep (until 2026-11-24): 32.17 and 20.73; before the
        # Chebyshev interval: 33.83 and 21.82. Earlier presets: 15-36 (bs = 1 GAMG,
        # 15 inner iterations), then worst 21.6, mean 15.9 (vertex_blocks, pressures split by
        # split), then 19 and 11.84 (every solve to 1e-8), then 15 and 8.43 (inner GMRES of 8
        # GAMG iterations, forcing up to 0.1).
        per_newton = np.asarray(ts["ksp_its"][1:], float) / np.asarray(ts["newton_its"][1:], float)
        chk.check("fieldsplit: max over steps of Krylov iterations per Newton iteration",
                  float(per_newton.max()), 35.8)
        chk.check("fieldsplit: Krylov iterations per Newton iteration over the run",
                  float(np.sum(ts["ksp_its"][1:]) / np.sum(ts["newton_its"][1:])), 23.4)
    equilibrium(chk, run, "partially drained")
    dpw = -(col(ts, "caisson.lid.p3_force") - ts["caisson.lid.p3_force"][0])
    scope = "quarter" if quarter else "full circle"
    print(f"  end ({scope}): Delta F_ext {(run.F('outer_skirt')[-1] - run.F('outer_skirt')[0]) / 1e3:.1f} kN, "
          f"Delta F_int {(run.F('inner_skirt')[-1] - run.F('inner_skirt')[0]) / 1e3:.1f} kN, "
          f"Delta F_pw {dpw[-1] / 1e3:.1f} kN")
    target = RHO_W * run.v_up * np.pi * R_IN**2 / (4 if quarter else 1)
    rate = RHO_W * col(ts, "caisson.lid.storage_rate")
    flux = RHO_W * col(ts, "caisson.lid.flux1")
    late = run.uplift >= 2e-3 - 1e-9
    if not late.any():
        common.fail("the run does not reach 2 mm of uplift")
    for k in np.nonzero(late)[0]:
        print(f"  uplift {run.uplift[k] * 1e3:.2f} mm: rho_w lid.storage_rate {rate[k]:.4f} kg/s, "
              f"rho_w lid.flux1 {flux[k]:.4f} kg/s")
    print(f"  rho_w v_up pi R_i^2{' / 4' if quarter else ''} = {target:.4f} kg/s ({scope})")
    chk.check("stationary phase (uplift >= 2 mm): max |rho_w lid.storage_rate - rho_w v_up pi R_i^2"
              f"{' / 4' if quarter else ''}| / target", float(np.max(np.abs(rate[late] - target)) / target), 5e-2)
    if args.plot:
        plot(chk, run, ["fig8a_forces.png", "fig7_mobilised_friction.png", "fig9b_lid_flux.png",
                        "fig10_flux_vs_opening.png"])
    chk.finish()


def case_quarter_vs_axisym(args):
    chk = common.Checks(f"caisson, 3D quarter (mesh factor {args.factor}) against axisymmetric (default mesh), "
                        f"drained, {args.ranks} ranks")
    steps = ["-ts_dt", 12, "-ts_max_time", 120, "-ts_max_steps", 10]  # 0.2 mm per step to 2 mm
    q = Run(scene("caisson_drained.opts"), "caisson_quarter_drained",
            ["-mesh_size_factor", args.factor, "-output_fields_every", 1] + steps, args.ranks)
    a = Run(scene("caisson_axisym_drained.opts"), "caisson_axisym_drained_reference",
            ["-output_fields_every", 0] + steps, args.ranks)
    chk.check("cut-backs (both runs)", float(q.ts["rejected"].sum() + a.ts["rejected"].sum()), 0)
    equilibrium(chk, q, "quarter")
    dtot_q = q.d_tot(weight=(q.reaction() - q.F())[1])
    equilibrium(chk, a, "axisymmetric reference")
    comps = {
        "Delta F_tot": (dtot_q[-1], a.d_tot()[-1]),
        "Delta F_ext": (q.F("outer_skirt")[-1] - q.F("outer_skirt")[0], a.F("outer_skirt")[-1] - a.F("outer_skirt")[0]),
        "Delta F_int": (q.F("inner_skirt")[-1] - q.F("inner_skirt")[0], a.F("inner_skirt")[-1] - a.F("inner_skirt")[0]),
    }
    print(f"  at {q.uplift[-1] * 1e3:.2f} mm (quarter x 4 / axisymmetric, full circle):")
    for name, (fq, fa) in comps.items():
        print(f"    {name}: {4 * fq / 1e3:9.1f} kN / {fa / 1e3:9.1f} kN")
    for name, (fq, fa) in comps.items():
        chk.check(f"plateau {name}: |4 x quarter - axisymmetric| / axisymmetric", abs(4 * fq - fa) / abs(fa), 5e-2)
    mob = full_mobilisation(q)
    if mob is not None:
        print(f"  quarter: outer skirt fully mobilised at {mob[0]:.2f} mm of uplift (not yet at {mob[1]:.2f} mm; 0.2 mm steps)")
    print(f"  wall times: quarter {q.wall:.1f} s, axisymmetric {a.wall:.1f} s")
    chk.finish()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True,
                    choices=["axisym_drained", "axisym_partially_drained", "quarter_partially_drained",
                             "quarter_vs_axisym", "axisym_drained_mohr_coulomb"])
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--factor", type=float, default=2.0, help="-mesh_size_factor (coarsening)")
    ap.add_argument("--plot", action="store_true", help="also run scripts/plot_caisson on the output")
    ap.add_argument("--order", type=int, choices=(1, 2), default=1,
                    help="-displacement_order (axisym_drained, axisym_partially_drained)")
    args = ap.parse_args()
    if args.order > 1 and args.case not in ("axisym_drained", "axisym_partially_drained"):
        common.fail(f"--order {args.order}: only the cases axisym_drained and axisym_partially_drained")
    {"axisym_drained": case_axisym_drained,
     "axisym_partially_drained": lambda a: case_partially_drained(a, False),
     "quarter_partially_drained": lambda a: case_partially_drained(a, True),
     "quarter_vs_axisym": case_quarter_vs_axisym,
     "axisym_drained_mohr_coulomb": case_axisym_drained_mohr_coulomb}[args.case](args)


if __name__ == "__main__":
    main()
