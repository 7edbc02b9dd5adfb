#!/usr/bin/python3
"""One element of Mohr-Coulomb soil (-region_soil_material mohr_coulomb) loaded like a
laboratory sample, against the closed forms of perfect plasticity. The element is one
hexahedron (meshes/element_3d.geo) or one axisymmetric quadrilateral (meshes/element_2d.geo,
x = r: a cylindrical sample); symmetry planes are held normally, the lateral faces carry the
confining traction -p_c (a step at t = 0+), the top is displaced axially (ramped). Every
displacement field is then affine, so the state is the same at every integration point and the
closed forms hold to round-off.

    element.py --case compression | extension | axisymmetric | undrained | undrained_dilatant

Stresses below are tension positive as in poroseam; q = |sigma'_axial - sigma'_radial|,
p' = -(sigma'_a + 2 sigma'_r) / 3 (compression positive). Parameters: E = 50 MPa, nu = 0.3,
c = 10 kPa, phi = 30 deg, psi = 10 deg (0 for `undrained`), p_c = 100 kPa.

axisymmetric (drained triaxial compression of a cylinder; the axial stress the major principal
    compressive stress, the radial and hoop ones equal: the compression edge of the cone)
    - elastic phase: d sigma_a / d eps_a = E (constant confining stress);
    - after yield: q = 2 (p_c sin phi + c cos phi) / (1 - sin phi);
    - dilatancy: the stress no longer changes, so the strain increments are plastic; on the
      edge both planes flow equally, d eps_v / d eps_a = -2 sin psi / (1 - sin psi).
compression (3D, "true triaxial": confinement p_c on x and 1.5 p_c on y, so the principal
    stresses are distinct and the stress returns to a face, the one of sigma_a and sigma_x; the
    intermediate stress plays no part in Mohr-Coulomb): the same q and, from the face's flow
    (no strain along the intermediate axis), the same d eps_v / d eps_a = 1 - N_psi. (With equal
    confinements the 3D element sits on the edge, where any split of the flow between its two
    planes is a solution: the tangent is singular there, and the axisymmetric case covers the
    edge with the hoop strain tied to the radial one.)
extension (3D, the top pulled up from the confined state: the axial stress the minor compressive
    stress, the face of sigma_a and the larger confinement sigma_y = 1.5 p_c)
    - q = 2 (1.5 p_c sin phi + c cos phi) / (1 + sin phi), d eps_v / d eps_a = 2 sin psi /
      (1 + sin psi) (eps_a > 0 here: the sample lengthens and dilates).
undrained, undrained_dilatant (a Biot element, every boundary impervious, incompressible grains
    and water (storage 0): the volume cannot change, eps_v = 0 at every time step, for any dt).
    The confining step goes to the pore pressure (p = p_c, Skempton's B = 1), the effective
    stress starts at zero. Elastic phase: p' stays 0 (eps_v = 0), q = 3 G eps_a.
    - psi = 0 (undrained): the plastic strain has no volume, so neither has the elastic strain:
      p' = 0 for good and q stops at the yield value at p' = 0 on the compression edge,
      q_u = 6 c cos phi / (3 - sin phi);
    - psi > 0 (undrained_dilatant): the plastic dilation is cancelled by an elastic contraction,
      so p' grows and the effective stress climbs the yield line q = 6 (p' sin phi +
      c cos phi) / (3 - sin phi) at the rate (edge flow, consistency, eps_v = 0)
      d p' / d eps_a = 3 G K (N_psi - 1) / (G (2 + N_psi) + M K (N_psi - 1)), with
      N_psi = (1 + sin psi) / (1 - sin psi), M = 6 sin phi / (3 - sin phi), K = lambda + 2 G / 3;
    - in both, the pore pressure carries the rest of the total mean stress: p = p_c + q / 3 - p'.
Every case also bounds Newton's iterations per step (4): with the consistent tangent the last
iteration of a step lands on the solution to round-off once the return's branch is right.
"""
import argparse
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, HERE)
import common  # noqa: E402
import newton_history  # noqa: E402

E, NU = 5e7, 0.3
C, PHI, PSI = 1e4, 30.0, 10.0
PC = 1e5
PC_Y = 1.5e5  # 3D drained cases: the confinement on y (x has PC), see below
G = E / (2 * (1 + NU))
LAM = E * NU / ((1 + NU) * (1 - 2 * NU))
K = LAM + 2 * G / 3


def options(case):
    psi = 0.0 if case == "undrained" else PSI
    o = ["-regions", "soil", "-region_soil_material", "mohr_coulomb", "-region_soil_E", E,
         "-region_soil_nu", NU, "-region_soil_cohesion", C, "-region_soil_friction_angle", PHI,
         "-region_soil_dilation_angle", psi, "-region_soil_permeability", 1e-12,
         "-ts_dt", 0.025, "-ts_max_time", 1, "-ts_max_steps", 100, "-output_fields_every", 0,
         "-snes_monitor", "-snes_rtol", 1e-12, "-snes_atol", 1e-9, "-solver_preset", "direct"]
    if not case.startswith("undrained"):
        o += ["-drained"]
    if case == "axisymmetric":
        o += ["-mesh", "meshes/element_2d.geo", "-axisymmetric",
              "-boundaries", "left,right,bottom,top", "-bc_left_ux", 0, "-bc_bottom_uy", 0,
              "-bc_right_traction", f"{-PC},0", "-bc_top_uy", -0.02, "-bc_top_uy_ramp", 1,
              "-probe_corner", "1,1"]
    else:
        top = {"compression": -0.02, "extension": 0.004}.get(case, -0.01)
        o += ["-mesh", "meshes/element_3d.geo",
              "-boundaries", "x0,x1,y0,y1,bottom,top", "-bc_x0_ux", 0, "-bc_y0_uy", 0,
              "-bc_bottom_uz", 0, "-bc_x1_traction", f"{-PC},0,0",
              "-bc_y1_traction", f"0,{-(PC if case.startswith('undrained') else PC_Y)},0",
              "-bc_top_uz", top, "-bc_top_uz_ramp", 1,
              "-probe_corner", "1,1,1"]
    return o


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True,
                    choices=["compression", "extension", "axisymmetric", "undrained",
                             "undrained_dilatant"])
    case = ap.parse_args().case
    out = common.output_dir("element_" + case)
    # The options as arguments after an options file that only names the mesh.
    opts = options(case)
    scene = os.path.join(out, "element.opts")
    with open(scene, "w") as f:
        f.write(f"-mesh {opts[opts.index('-mesh') + 1]}\n")
    common.run(scene, out, opts)
    ts = common.read_timeseries(out)
    axisym = case == "axisymmetric"
    vertical = "y" if axisym else "z"
    area = math.pi if axisym else 1.0  # the top: forces are for the full circle when axisymmetric
    force = common.column(ts, f"top.F{vertical}")
    eps_a = common.column(ts, f"corner.u{vertical}")  # unit height, bottom fixed
    eps_r = common.column(ts, "corner.ux")
    # Axisymmetric: the hoop strain is u_r / r = eps_r. 3D: the lateral strains differ.
    eps_v = eps_a + (2 * eps_r if axisym else eps_r + common.column(ts, "corner.uy"))
    # Total axial stress: compressive throughout (the confining stress alone is), so its sign
    # is known and the reaction's sign convention does not matter.
    sigma_a = -np.abs(force) / area
    p = common.column(ts, "corner.p") if case.startswith("undrained") else np.zeros_like(force)
    # Effective stresses (alpha = 1), tension positive; sr: the confinement that sets q (the
    # smaller one in compression, the larger one in extension).
    sr = -(PC_Y if case == "extension" else PC) + p
    sa = sigma_a + p
    q = np.abs(sa - sr)
    pm = -(sa + 2 * sr) / 3
    sphi, cphi = math.sin(math.radians(PHI)), math.cos(math.radians(PHI))
    spsi = math.sin(math.radians(0.0 if case == "undrained" else PSI))
    chk = common.Checks(f"Mohr-Coulomb element, {case}")
    n = len(q)
    last = slice(n - 10, n)  # well after yield: the last quarter of the loading

    if case in ("compression", "extension", "axisymmetric"):
        if case == "extension":
            q_u = 2 * (PC_Y * sphi + C * cphi) / (1 + sphi)
            ratio = 2 * spsi / (1 + spsi)
        else:
            q_u = 2 * (PC * sphi + C * cphi) / (1 - sphi)
            ratio = -2 * spsi / (1 - spsi)
        elastic = np.where(q < (1 - 1e-6) * q_u)[0]  # below the strength: no plastic flow yet
        if len(elastic) < 3:
            common.fail(f"fewer than 3 elastic steps (q = {q})")
        i = elastic[1:]
        modulus = np.diff(sigma_a)[i - 1] / np.diff(eps_a)[i - 1]
        chk.check("elastic phase: d sigma_a / d eps_a vs E (relative)",
                  np.max(np.abs(modulus - E)) / E, 1e-8)
        conf = "1.5 p_c" if case == "extension" else "p_c"
        chk.check(f"peak q vs 2 ({conf} sin phi + c cos phi) / (1 {'+' if case == 'extension' else '-'} "
                  f"sin phi) = {q_u:.1f} Pa (relative)", np.max(np.abs(q[last] - q_u)) / q_u, 1e-8)
        dv, da = np.diff(eps_v)[n - 10:], np.diff(eps_a)[n - 10:]
        chk.check(f"dilatancy d eps_v / d eps_a vs {ratio:.6f} (absolute)",
                  np.max(np.abs(dv / da - ratio)), 1e-7)
        yield_step = int(np.argmax(q > (1 - 1e-6) * q_u))
        print(f"  yield reached at step {yield_step + 1} (eps_a = {eps_a[yield_step]:.3e})")
    else:
        m_slope = 6 * sphi / (3 - sphi)
        q_line = 6 * (pm * sphi + C * cphi) / (3 - sphi)
        q_u0 = 6 * C * cphi / (3 - sphi)
        chk.check("volume constant: max |eps_v| / max |eps_a|", np.max(np.abs(eps_v)) /
                  np.max(np.abs(eps_a)), 1e-9)
        elastic = np.where(q < 0.8 * q_u0)[0]
        chk.check("elastic phase: p' = 0 (|p'| / q_u)", np.max(np.abs(pm[elastic])) / q_u0, 1e-8)
        chk.check("elastic phase: q = 3 G eps_a (relative)",
                  np.max(np.abs(q[elastic] - 3 * G * np.abs(eps_a[elastic]))) / q_u0, 1e-8)
        chk.check("pore pressure p = p_c + q / 3 - p' (relative to p_c)",
                  np.max(np.abs(p - (PC + q / 3 - pm))) / PC, 1e-8)
        if case == "undrained":
            chk.check(f"after yield: q = q_u = 6 c cos phi / (3 - sin phi) = {q_u0:.1f} Pa (relative)",
                      np.max(np.abs(q[last] - q_u0)) / q_u0, 1e-8)
            chk.check("after yield: p' = 0 (|p'| / q_u)", np.max(np.abs(pm[last])) / q_u0, 1e-8)
        else:
            n_psi = (1 + spsi) / (1 - spsi)
            rate = 3 * G * K * (n_psi - 1) / (G * (2 + n_psi) + m_slope * K * (n_psi - 1))
            chk.check("after yield: on the yield line q = 6 (p' sin phi + c cos phi) / (3 - sin phi)"
                      " (relative)", np.max(np.abs(q[last] - q_line[last]) / q_line[last]), 1e-8)
            measured = np.diff(pm)[n - 10:] / np.abs(np.diff(eps_a)[n - 10:])
            chk.check(f"after yield: d p' / d |eps_a| vs {rate:.5g} Pa (relative)",
                      np.max(np.abs(measured - rate)) / rate, 1e-7)
    # Newton on one element: once the iterate has the right branch of the return (face, edge),
    # the element's equations are linear in it and the next iterate is exact to round-off
    # (the consistent tangent); shown for the steps that needed the most iterations. (The
    # quadratic rate where principal directions rotate is checked on a mesh: scene.py.)
    hist = sorted(newton_history.histories(os.path.join(out, "log.txt")), key=lambda h: -len(h[1]))
    for step, res in hist[:2]:
        print("  Newton " + newton_history.describe(step, res))
    chk.check("Newton: the most iterations of a step", max(len(r) - 1 for _, r in hist), 4)
    chk.check("steps cut back", float(np.sum(common.column(ts, "rejected"))), 0)
    chk.finish()


if __name__ == "__main__":
    main()
