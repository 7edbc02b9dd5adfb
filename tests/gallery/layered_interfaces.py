#!/usr/bin/env python3
"""Interfaces in layered ground and sealed interfaces (issue 24, item 10).

    layered_interfaces.py --case recipe | refused_split | refused_layers | sealed | barrier

recipe          tests/gallery/faulted_layers_2d.opts: a vertical fault through two elastic
                layers as two interfaces, one per layer, meeting end to end at the layer
                boundary (docs/interface_parameters.md, "Interfaces in layered ground"). Both
                layers are in uniaxial strain under the top load q: sigma_xx = -q nu / (1 - nu),
                so the force on each interface's side 1 (west) is Fx = -q nu / (1 - nu) h with
                h its length (0.4 m, 0.6 m), and Fy = 0 (no shear). The penalty closure
                perturbs this by about E / (K_N W) = 4e-5 of it: tolerance 2e-4.
refused_split   the same fault as ONE interface (both face groups) with side 1 lower_west: side
                1 does not border the upper part. Refused, the message naming the interface,
                the face group, and the regions there by name ('upper_west', 'upper_east'), and
                the way out (one interface per layer).
refused_layers  the same with one region per layer on both sides of the fault (split_sides = 0):
                the message names 'upper' (on both sides).
junction_flow   the recipe's two interfaces with flow (D0 = 1e-4 m, impervious sides T1 = T2 = 0,
                porous layers): p3 prescribed at the bottom (P = 10 kPa) and the top (0). The
                water passes the junction: the steady flow along the whole fault is
                Poiseuille's Q = D0^3 / (12 mu_w) P / L (L = 1 m) out of the top, into the bottom
                and through both interfaces alike, and p3 is linear along the fault (its
                force on each interface is the mean p3 times the length: P (1 - 0.2) 0.4 and
                P (1 - 0.7) 0.6). Exact on any mesh (the gap is uniform): tolerance 1e-6.
sealed          options/joint_column_2d.opts with T1 = T2 = 0 and no p3: refused, and the advice
                names -interface_joint_flow 0 as the perfect barrier.
barrier         the advice followed: -interface_joint_flow 0 (with T1 = T2 = 0 still given) runs,
                and the joint is a perfect barrier: the lower layer (impervious base, barrier
                above, incompressible grains and water) cannot drain, so its pore pressure stays
                at the load q (1e-6), while the upper layer drains through the top.
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402

SCENE = os.path.join(HERE, "faulted_layers_2d.opts")
GEO = os.path.join(common.SOURCE, "meshes", "faulted_layers_2d.geo")
JOINT = os.path.join(common.SOURCE, "options", "joint_column_2d.opts")
Q = 1e5
NU = 0.25
LENGTH = {"fault_lower": 0.4, "fault_upper": 0.6}


def refused(out, scene, args):
    """Runs a scene that must be refused; returns (exit status, the error text)."""
    cmd = [common.EXE, "-options_file", scene, "-output_dir", out] + [str(a) for a in args]
    res = subprocess.run(cmd, cwd=common.SOURCE, capture_output=True, text=True, timeout=120)
    text = res.stdout + res.stderr
    print("  " + "\n  ".join(text.strip().splitlines()[-3:]))
    return res.returncode, text


def one_interface_scene(out, split_sides):
    """faulted_layers_2d.opts with its two interfaces replaced by one over both face groups."""
    lines = []
    with open(SCENE) as f:
        for line in f:
            if line.startswith("-interface") or line.startswith("-mesh"):
                continue
            if not split_sides and line.startswith("-region"):
                continue
            lines.append(line)
    geo = GEO
    if not split_sides:
        geo = os.path.join(out, "faulted_layers_by_layer.geo")
        with open(geo, "w") as f:
            f.write('split_sides = 0;\nInclude "%s";\n' % GEO)
        lines += ["-regions lower,upper\n"] + [
            f"-region_{r}_material elastic\n-region_{r}_E 1e7\n-region_{r}_nu 0.25\n"
            for r in ("lower", "upper")]
    lines += [f"-mesh {geo}\n", "-interfaces fault\n",
              "-interface_fault_surfaces fault_lower,fault_upper\n",
              f"-interface_fault_side1 {'lower_west' if split_sides else 'lower'}\n",
              "-interface_fault_KN 1e12\n-interface_fault_KT 1e12\n-interface_fault_friction 0.5\n"]
    path = os.path.join(out, "one_interface.opts")
    with open(path, "w") as f:
        f.writelines(lines)
    return path


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True,
                    choices=["recipe", "refused_split", "refused_layers", "junction_flow", "sealed",
                             "barrier"])
    a = ap.parse_args()
    out = common.output_dir("layered_interfaces_" + a.case)
    chk = common.Checks("layered interfaces: " + a.case)
    if a.case == "recipe":
        common.run(SCENE, out)
        ts = common.read_timeseries(out)
        for name, h in LENGTH.items():
            expected = -Q * NU / (1 - NU) * h
            fx = common.column(ts, f"{name}.Fx")[-1]
            fy = common.column(ts, f"{name}.Fy")[-1]
            print(f"  {name}: Fx = {fx:.6g} N/m (closed form {expected:.6g}), Fy = {fy:.3g}")
            chk.check(f"{name}: |Fx - (-q nu/(1-nu) h)| / |expected|", abs(fx - expected) / abs(expected), 2e-4)
            chk.check(f"{name}: |Fy| / |expected Fx|", abs(fy) / abs(expected), 2e-4)
    elif a.case == "junction_flow":
        P, L, D0 = 1e4, 1.0, 1e-4
        scene = os.path.join(out, "faulted_layers_flow.opts")
        with open(SCENE) as f:
            text = f.read().replace("_material elastic", "_material biot")
        text = text.replace("-mesh ../../meshes/", "-mesh " + os.path.join(common.SOURCE, "meshes") + "/")
        for r in ("lower_west", "lower_east", "upper_west", "upper_east"):
            text += f"-region_{r}_permeability 1e-12\n"
        for i in LENGTH:
            text += f"-interface_{i}_flow\n-interface_{i}_D0 {D0}\n-interface_{i}_T1 0\n-interface_{i}_T2 0\n"
        text += f"-bc_bottom_p3 {P}\n-bc_top_p3 0\n-bc_top_p 0\n-ts_max_time 5\n-ts_max_steps 20\n"
        with open(scene, "w") as f:
            f.write(text)
        common.run(scene, out)
        ts = common.read_timeseries(out)
        q = D0 ** 3 / (12 * 1e-3) * P / L
        print(f"  Poiseuille Q = {q:.6g} m2/s")
        for col, sign in (("top.interface_outflow", 1), ("bottom.interface_outflow", -1),
                          ("fault_upper.outflow", 1), ("fault_lower.outflow", -1)):
            v = common.column(ts, col)[-1]
            print(f"  {col} = {v:.6g}")
            chk.check(f"{col} = {'+' if sign > 0 else '-'}Q: relative error", abs(v - sign * q) / q, 1e-6)
        for name, mean in (("fault_lower", P * (1 - 0.2)), ("fault_upper", P * (1 - 0.7))):
            v = common.column(ts, f"{name}.p3_force")[-1]
            chk.check(f"{name}.p3_force = mean p3 x length: relative error",
                      abs(v - mean * LENGTH[name]) / (mean * LENGTH[name]), 1e-6)
    elif a.case in ("refused_split", "refused_layers"):
        split = a.case == "refused_split"
        rc, text = refused(out, one_interface_scene(out, split), [])
        names = ("'upper_west'", "'upper_east'") if split else ("'upper' and 'upper'",)
        chk.check("exit status is non-zero", 0.0, 0.0, ok=rc != 0)
        chk.check("the message names the interface and its side 1", 0.0, 0.0,
                  ok="interface 'fault'" in text and "-interface_fault_side1 " in text)
        chk.check("the message names the face group", 0.0, 0.0, ok="'fault_upper'" in text)
        chk.check(f"the message names the regions there: {' '.join(names)}", 0.0, 0.0,
                  ok=all(n in text for n in names))
        chk.check("no bare tags in the message", 0.0, 0.0, ok="tags" not in text)
        chk.check("the way out: one interface per layer", 0.0, 0.0,
                  ok="one interface per layer" in text)
        chk.check("no crash", 0.0, 0.0, ok="Segmentation" not in text and "signal" not in text)
    elif a.case == "sealed":
        rc, text = refused(out, JOINT, ["-interface_joint_T1", 0, "-interface_joint_T2", 0,
                                         "-ts_max_time", 0.4])
        chk.check("exit status is non-zero", 0.0, 0.0, ok=rc != 0)
        chk.check("the error names the sealed interface", 0.0, 0.0, ok="interface 'joint' is sealed" in text)
        chk.check("the advice: -interface_joint_flow 0 makes a perfect barrier", 0.0, 0.0,
                  ok="-interface_joint_flow 0" in text and "perfect barrier" in text)
        chk.check("p3 only where it ends on a boundary", 0.0, 0.0,
                  ok="ends inside the mesh" in text)
    else:  # barrier
        common.run(JOINT, out, ["-interface_joint_T1", 0, "-interface_joint_T2", 0,
                                "-interface_joint_flow", 0, "-ts_max_time", 2,
                                "-probe_low", "0.05,0.25", "-probe_high", "0.05,0.75"])
        ts = common.read_timeseries(out)
        low, high = common.column(ts, "low.p")[-1], common.column(ts, "high.p")[-1]
        print(f"  t = {common.column(ts, 'time')[-1]:g} s: p(lower) = {low:.8g} Pa, p(upper) = {high:.6g} Pa")
        chk.check("lower layer undrained: |p - q| / q", abs(low - 1e4) / 1e4, 1e-6)
        chk.check("upper layer drains: p / q", high / 1e4, 0.9)
    chk.finish()


if __name__ == "__main__":
    main()
