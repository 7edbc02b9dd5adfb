"""Gravity and the K0 geostatic initial state, against statics.

A soil column (2D and 3D) with gravity, water level at the surface, the geostatic initial
state and no load must stay in equilibrium: no displacement, hydrostatic pressure, no flow.
Closed-form checks after a few steps:
  - |u| < 1e-12 m everywhere probed, p = rho_w g depth (relative 1e-9),
  - bottom vertical reaction = total weight rho_sat g H A (relative 1e-9): the sides are
    frictionless rollers, so the bottom carries everything,
  - no water crosses the drained top (|flux| < 1e-15 m3/s).
Then the same column with a surcharge q on top, drained (-drained): no pressure unknowns,
the bottom reaction is weight + q A and the top settles by q H / M_c at once (oedometer).

Then every kind of ground the geostatic state accepts, each against the closed form of the
column (geostatic.hpp, re-derived here from the scene's own properties): total vertical stress
sigma_v(z) = -(q_w + g int_z^z_s rho), q_w = rho_w g max(0, h_w - z_s), pore pressure
p = rho_w g (h_w - z), effective sigma'_v = sigma_v + alpha p, sigma'_h = K0 sigma'_v. Each
variant must stay at rest over three steps, relative to the scales of its own state:
  - |u| / (|sigma_v(bottom)| H / M_c) < 1e-10 at probes in every layer (M_c the softest layer's
    constrained modulus: the settlement the column's weight would cause),
  - |p - p(z)| / max|p| < 1e-10 at the same probes,
  - |outflow through the top| / ((k/mu_w) rho_w g A) < 1e-10 (a unit hydraulic gradient),
  - bottom reaction = -sigma_v(0) A, and the force of the water load on the top = -q_w A,
  - side reaction = -W int_0^H sigma_h(z) dz with the total horizontal stress
    sigma_h = K0 sigma'_v - alpha p of each layer: the stress profile at depth, layer by layer,
  - with a joint: p'_N = -sigma_v(z_j) - p(z_j) at every integration point (the gap water
    carries p), relative to the same,
all relative 1e-10. Variants: alpha 0.8; water 2 m above the surface (its load through
-water_load_boundaries); water table 0.4 m below the surface (saturated with suction above
it); three layers with different densities, K0 and alpha (2D; 3D on 2 ranks with water above
the surface); a dry crust as a non-porous ground layer (-region_<r>_ground) over the table;
two layers with a flowing joint between them (alpha 0.8). Finally the ground the state cannot
make exact is refused with a one-line error (layers side by side, a gap, a region above the
surface, water above the surface without its load, a bad -region_<r>_ground).
"""
import subprocess
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
import common  # noqa: E402
from interface_reader import read_interfaces  # noqa: E402

g, rho_w, rho_s, n, H = 9.81, 1000.0, 2650.0, 0.36, 1.0
rho_sat = (1 - n) * rho_s + n * rho_w
failures = []


def check(name, ok, text):
    print(("  ok   " if ok else "  FAIL ") + text)
    if not ok:
        failures.append(name + ": " + text)


for dim in (2, 3):
    mesh = "meshes/terzaghi_column_2d.geo" if dim == 2 else "meshes/terzaghi_column_3d.geo"
    scene = os.path.join(HERE, f"geostatic_{dim}d.opts")
    area = 0.1 if dim == 2 else 0.1 * 0.1
    probes = ["0.05,0.5", "0.05,0.25"] if dim == 2 else ["0.05,0.05,0.5", "0.05,0.05,0.25"]
    depth = [0.5, 0.75]
    args = ["-mesh", mesh, "-ts_max_steps", 3]
    for i, x in enumerate(probes):
        args += [f"-probe_p{i}", x]
    out = common.output_dir(f"geostatic_{dim}d")
    common.run(scene, out, args + ["-bc_top_p", 0, "-mesh_size_factor", 2 if dim == 3 else 1])
    ts = common.read_timeseries(out)
    print(f"{dim}D column with gravity and the K0 state, no load:")
    umax = max(np.max(np.abs(ts[f"p{i}.u{c}"])) for i in range(2) for c in "xyz"[:dim])
    check("displacement", umax < 1e-12, f"max |u| at probes {umax:.2e} m < 1e-12 m")
    for i, d in enumerate(depth):
        p_exact = rho_w * g * d
        err = np.max(np.abs(ts[f"p{i}.p"] - p_exact)) / p_exact
        check("pressure", err < 1e-9, f"pressure at depth {d} m: relative error {err:.1e} < 1e-9")
    weight = rho_sat * g * H * area
    axis = "y" if dim == 2 else "z"
    err = np.max(np.abs(ts[f"bottom.F{axis}"] - weight)) / weight
    check("weight", err < 1e-9, f"bottom reaction {ts[f'bottom.F{axis}'][-1]:.6f} N vs weight {weight:.6f} N: {err:.1e}")
    flux = np.max(np.abs(ts["top.flux"]))
    check("flux", flux < 1e-15, f"outflow through the top {flux:.1e} m3/s < 1e-15")

    out = common.output_dir(f"geostatic_drained_{dim}d")
    q = 2e4
    traction = "0,-2e4" if dim == 2 else "0,0,-2e4"
    top = "0.05,1" if dim == 2 else "0.05,0.05,1"
    common.run(scene, out, args + ["-drained", "-bc_top_traction", traction, "-probe_top", top,
                                   "-mesh_size_factor", 2 if dim == 3 else 1])
    ts = common.read_timeseries(out)
    print(f"{dim}D drained column with a surcharge:")
    with open(os.path.join(out, "log.txt")) as f:
        log = f.read()
    check("fields", "field pressure" not in log and "field displacement" in log,
          "a drained scene has displacement unknowns only")
    E, nu = 1e7, 0.25
    M_c = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    settlement = -q * H / M_c
    err = abs(ts[f"top.u{axis}"][-1] - settlement) / abs(settlement)
    check("settlement", err < 1e-9, f"drained settlement {ts[f'top.u{axis}'][-1]:.6e} m vs q H / M_c = {settlement:.6e} m: {err:.1e}")
    expected = weight + q * area
    err = abs(ts[f"bottom.F{axis}"][-1] - expected) / expected
    check("drained", err < 1e-9, f"bottom reaction {ts[f'bottom.F{axis}'][-1]:.6f} N vs {expected:.6f} N: {err:.1e}")



# ---------------------------------------------------------------------------------------------
# Every kind of ground: the closed form of the column from the scene's own properties.
class Column:
    """Horizontal layers [(name, bottom, top, rho, K0, alpha)], surface z_s, water level h_w."""

    def __init__(self, layers, surface, water):
        self.layers, self.zs, self.hw = layers, surface, water

    def p(self, z):
        return rho_w * g * (self.hw - z)

    def q_w(self):
        return rho_w * g * max(0.0, self.hw - self.zs)

    def sigma_v(self, z):
        w = self.q_w()
        for _, lo, hi, rho, _, _ in self.layers:
            w += rho * g * max(0.0, hi - max(lo, z))
        return -w

    def layer(self, z):
        for lay in self.layers:
            if lay[1] <= z <= lay[2]:
                return lay
        raise ValueError(z)

    def sigma_h(self, z, lay):
        _, _, _, _, k0, alpha = lay
        return k0 * (self.sigma_v(z) + alpha * self.p(z)) - alpha * self.p(z)

    def side_integral(self):
        """int_0^H sigma_h dz: linear in each layer, so the trapezoid rule is exact."""
        return sum(0.5 * (hi - lo) * (self.sigma_h(lo, lay) + self.sigma_h(hi, lay))
                   for lay in self.layers for lo, hi in [(lay[1], lay[2])])


def layers_of(opts, extents):
    """The column's layers from a scene's options (rho_sat of porous regions, rho_s of others)."""
    out = []
    for name, (lo, hi) in extents.items():
        get = lambda key, default=None: opts.get(f"-region_{name}_{key}", default)  # noqa: E731
        rs, nu = float(get("rho_s", 0)), float(get("nu"))
        porous = get("material") == "biot"
        n_ = float(get("porosity", 0)) if porous else 0.0
        rho = (1 - n_) * rs + n_ * rho_w if porous else rs
        k0 = float(get("K0", nu / (1 - nu)))
        alpha = float(get("biot_alpha", 1.0)) if porous else 0.0
        out.append((name, lo, hi, rho, k0, alpha))
    return out


def constrained_modulus(opts, name):
    E, nu = float(opts[f"-region_{name}_E"]), float(opts[f"-region_{name}_nu"])
    return E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))


def at_rest(label, scene, dim, extents, water, args, ranks=1, joint=None, surface=1.0,
            extra_opts=None):
    """Runs a ground variant for three steps and checks it against its column."""
    opts = common.read_scene(scene)
    opts.update(extra_opts or {})
    col = Column(layers_of(opts, extents), surface, water)
    W, H = 0.1, surface
    area = W if dim == 2 else W * W
    axis = "xyz"[dim - 1]
    zs = [0.1, 0.35, 0.55, 0.75, 0.95]
    probes = []
    for i, z in enumerate(zs):
        probes += [f"-probe_z{i}", ("0.05," if dim == 2 else "0.05,0.05,") + str(z)]
    run_args = ["-water_level", water, "-ts_max_steps", 3, "-ts_max_time", 3] + args + probes
    # The side checked below last among the boundaries: a corner it shares with the fixed
    # bottom (both prescribe ux) then counts for the side (docs/outputs.md, "Forces and flows
    # through boundaries"), so its column is the whole side's reaction.
    side = "left" if dim == 2 else "xmin"
    names = opts["-boundaries"].split(",")
    if side in names:
        run_args += ["-boundaries", ",".join([n for n in names if n != side] + [side])]
    for key, value in (extra_opts or {}).items():
        run_args += [key, value]
    out = common.output_dir(f"geostatic_{label}")
    common.run(scene, out, run_args, ranks=ranks)
    ts = common.read_timeseries(out)
    print(f"{label}: {dim}D, {len(col.layers)} layer(s), water level {water}, {ranks} rank(s)")
    bottom = col.sigma_v(0.0)
    u_scale = abs(bottom) * H / min(constrained_modulus(opts, name) for name in extents)
    u = max(np.max(np.abs(ts[f"z{i}.u{c}"])) for i in range(len(zs)) for c in "xyz"[:dim])
    check(label, u / u_scale < 1e-10, f"max |u| / (|sigma_v| H / M_c) = {u / u_scale:.1e} < 1e-10 (|u| {u:.1e} m)")
    # Pressure where it is an unknown (porous layers of a scene that is not drained).
    drained = "-drained" in args
    porous_z = [(i, z) for i, z in enumerate(zs) if col.layer(z)[5] > 0 and not drained]
    if porous_z:
        p_scale = max(abs(col.p(0.0)), abs(col.p(surface)))
        err = max(np.max(np.abs(ts[f"z{i}.p"] - col.p(z))) for i, z in porous_z) / p_scale
        check(label, err < 1e-10, f"max |p - rho_w g (h_w - z)| / max|p| = {err:.1e} < 1e-10")
    if "top.flux" in ts:
        k = max(float(opts.get(f"-region_{n}_permeability", 0)) for n in extents)
        q_scale = k / 1e-3 * rho_w * g * area
        err = np.max(np.abs(ts["top.flux"])) / q_scale
        check(label, err < 1e-10, f"|top outflow| / ((k/mu_w) rho_w g A) = {err:.1e} < 1e-10")
    expected = -bottom * area
    err = np.max(np.abs(ts[f"bottom.F{axis}"] - expected)) / abs(expected)
    check(label, err < 1e-10, f"bottom reaction {ts[f'bottom.F{axis}'][-1]:.6f} N vs -sigma_v(0) A = {expected:.6f} N: {err:.1e}")
    if col.q_w() > 0:
        load = -col.q_w() * area
        err = np.max(np.abs(ts[f"top.F{axis}"] - load)) / abs(load)
        check(label, err < 1e-10, f"water load on the top {ts[f'top.F{axis}'][-1]:.6f} N vs -q_w A = {load:.6f} N: {err:.1e}")
    expected = -col.side_integral() * (1.0 if dim == 2 else W)
    err = np.max(np.abs(ts[f"{side}.Fx"] - expected)) / abs(expected)
    check(label, err < 1e-10, f"side reaction {ts[f'{side}.Fx'][-1]:.6f} N vs -int sigma_h = {expected:.6f} N: {err:.1e}")
    if joint:
        pts = read_interfaces(out).point_fields[-1]
        pn = pts["contact_pressure_effective"]
        exact = -col.sigma_v(joint) - col.p(joint)
        err = np.max(np.abs(pn - exact)) / exact
        check(label, err < 1e-10, f"joint p'_N vs -sigma_v - p = {exact:.3f} Pa: {err:.1e}")
    return col


def hydrostatic(z, water):
    return rho_w * g * (water - z)


single = {"soil": (0.0, 1.0)}
three = {"deep": (0.0, 0.4), "middle": (0.4, 0.7), "shallow": (0.7, 1.0)}
scene2 = os.path.join(HERE, "geostatic_2d.opts")
layers2 = os.path.join(HERE, "geostatic_layers_2d.opts")
layers3 = os.path.join(HERE, "geostatic_layers_3d.opts")
at_rest("alpha08_2d", scene2, 2, single, 1.0, ["-bc_top_p", 0],
        extra_opts={"-region_soil_biot_alpha": "0.8"})
at_rest("water_above_2d", scene2, 2, single, 3.0,
        ["-water_load_boundaries", "top", "-bc_top_p", hydrostatic(1.0, 3.0)],
        extra_opts={"-region_soil_biot_alpha": "0.8"})
at_rest("water_below_2d", scene2, 2, single, 0.6, ["-bc_top_p", hydrostatic(1.0, 0.6)])
at_rest("water_below_drained_2d", scene2, 2, single, 0.6, ["-drained"],
        extra_opts={"-region_soil_biot_alpha": "0.8"})
at_rest("layers_2d", layers2, 2, three, 0.8, ["-bc_top_p", hydrostatic(1.0, 0.8)])
at_rest("layers_3d_2ranks", layers3, 3, three, 3.0,
        ["-water_load_boundaries", "top", "-bc_top_p", hydrostatic(1.0, 3.0),
         "-mesh_size_factor", 2], ranks=2)
# Dry crust: the shallow layer above the water table (y = 0.7) as a non-porous ground layer of
# dry density (1 - n) rho_s, the deep layers saturated below the table.
at_rest("dry_crust_2d", layers2, 2, three, 0.7, [],
        extra_opts={"-region_shallow_material": "elastic", "-region_shallow_ground": "true",
                    "-region_shallow_rho_s": str((1 - 0.45) * 2600)})
# Two layers with a joint between them that carries water (p3), alpha 0.8 in both.
joint_extra = {"-region_lower_rho_s": "2750", "-region_lower_K0": "0.8",
               "-region_lower_biot_alpha": "0.8", "-region_upper_biot_alpha": "0.8",
               "-region_lower_permeability": "1e-12", "-region_upper_permeability": "1e-12",
               "-interface_joint_flow": "", "-interface_joint_D0": "1e-5",
               "-interface_joint_T1": "1e-8", "-interface_joint_T2": "1e-8",
               "-drained": "false"}
at_rest("joint_flow_2d", os.path.join(HERE, "geostatic_joint.opts"), 2,
        {"lower": (0.0, 0.5), "upper": (0.5, 1.0)}, 1.0, ["-bc_top_p", 0], joint=0.5,
        extra_opts=joint_extra)

# What the geostatic state cannot make exact is refused, with one line naming the option.
print("refusals:")
two_regions = os.path.join(common.SOURCE, "options", "two_regions_2d.opts")
refusals = [
    ("a gap in the column", layers2, ["-region_middle_ground", "false"],
     "no ground region between z = 0.4 and 0.7"),
    ("a region above the surface", layers2, ["-surface_elevation", 0.9],
     "ground region 'shallow' reaches z = 1 above the soil surface 0.9"),
    ("a surface that is not horizontal (footing as ground)", two_regions,
     ["-region_block_ground", "true", "-surface_elevation", 2.5],
     "upward-facing outer boundary face"),
    ("water above the surface without its load", scene2, ["-water_level", 2],
     "name the boundaries it stands on with -water_load_boundaries"),
    ("water load on an unknown boundary", scene2, ["-water_load_boundaries", "lid"],
     "-water_load_boundaries: boundary 'lid' is not a physical group"),
    ("a bad -region_<r>_ground", scene2, ["-region_soil_ground", "maybe"],
     "-region_soil_ground maybe: expected true or false"),
]
for what, scene, args, expected in refusals:
    out = common.output_dir("geostatic_refused")
    cmd = [common.EXE, "-options_file", scene, "-output_dir", out] + [str(a) for a in args]
    res = subprocess.run(cmd, cwd=common.SOURCE, capture_output=True, text=True, timeout=120)
    text = res.stdout + res.stderr
    lines = [ln for ln in text.splitlines() if expected in ln]
    ok = res.returncode != 0 and len(lines) == 1 and lines[0].startswith("poroseam: error:")
    check("refused", ok, f"{what}: exit {res.returncode}, " +
          (lines[0] if lines else "message not found in: " + text[-300:]))

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("geostatic: OK")
