#!/usr/bin/python3
"""Hostile meshes and .geo files (issue 23, items 3, 4, 6, 7): poroseam must refuse each in
one line naming the file and the cells, nodes, group or line, exit 1, in seconds.

    hostile_meshes.py --case NAME      one case (one ctest each, label "input")
    hostile_meshes.py --list           the case names

Every mesh and .geo is written by this driver into the case's output directory (no committed
blobs): a small structured grid of the unit square (MSH 2.2 ASCII, quadrangles or triangles)
with one defect, or a .geo with one hostile command. The run and its checks (exit status, the
expected substrings, exactly one 'poroseam: error:' line, no crash signature, no PETSc
traceback, seconds) are those of tests/input/bad_input.py, imported from it. Cases marked ok
check that what is accepted still runs (the same grid without its defect; a .geo that only
mentions the commands in comments and strings).
"""

import argparse
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bad_input as bi  # noqa: E402  (the shared runner's helpers and constants)

SOURCE, EXE = bi.SOURCE, bi.EXE
TERZAGHI_GEO = os.path.join(SOURCE, "meshes", "terzaghi_column_2d.geo")

# A scene for the grid meshes: two elastic layers 'lower' (y < 0.5) and 'upper', an optional
# interface 'joint' on the face group 'crack', fixed bottom, a load on top, one step.
GRID_SCENE = """-mesh {mesh}
-regions lower,upper
-region_lower_material elastic
-region_lower_E 1e7
-region_lower_nu 0.25
-region_upper_material elastic
-region_upper_E 1e7
-region_upper_nu 0.25
-boundaries top,bottom,left,right
-bc_left_ux 0
-bc_right_ux 0
-bc_bottom_ux 0
-bc_bottom_uy 0
-bc_top_traction 0,-1e4
-ts_dt 1
-ts_max_time 1
-output_fields_every 0
-ksp_type preonly
-pc_type lu
"""
JOINT = """-interfaces joint
-interface_joint_surfaces crack
-interface_joint_side1 lower
-interface_joint_KN 1e10
-interface_joint_KT 1e10
-interface_joint_friction 0.5
"""


def grid(n=2, quads=True, defect=None):
    """The unit square as an n x n grid (MSH 2.2 ASCII): physical curves bottom 1, right 2,
    top 3, left 4, crack 5 (the line y = 0.5 when n is even), surfaces lower 6 and upper 7;
    with one defect (see CASES)."""
    h = 1.0 / n
    nid = lambda i, j: j * (n + 1) + i + 1  # noqa: E731
    nodes = {nid(i, j): [i * h, j * h, 0.0] for j in range(n + 1) for i in range(n + 1)}
    lines = []  # (physical, a, b)
    for i in range(n):
        lines += [(1, nid(i, 0), nid(i + 1, 0)), (3, nid(i + 1, n), nid(i, n))]
        lines += [(5, nid(i, n // 2), nid(i + 1, n // 2))]
    for j in range(n):
        lines += [(2, nid(n, j), nid(n, j + 1)), (4, nid(0, j + 1), nid(0, j))]
    cells = []  # (physical, [nodes])
    for j in range(n):
        for i in range(n):
            q = [nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1)]
            region = 6 if j < n // 2 else 7
            if quads:
                cells.append((region, q))
            else:
                cells += [(region, [q[0], q[1], q[2]]), (region, [q[0], q[2], q[3]])]
    names = [(1, 1, "bottom"), (1, 2, "right"), (1, 3, "top"), (1, 4, "left"), (1, 5, "crack"),
             (2, 6, "lower"), (2, 7, "upper")]
    points = []  # (physical, node)
    c = n // 2
    if defect == "node_tag_2e9":  # the last node renumbered 2e9 (its cells follow it)
        last = max(nodes)
        nodes[2000000000] = nodes.pop(last)
        cells = [(r, [2000000000 if v == last else v for v in q]) for r, q in cells]
        lines = [(p, 2000000000 if a == last else a, 2000000000 if b == last else b)
                 for p, a, b in lines]
    if defect == "coincident_nodes":  # the second cell's copy of the first one's corner
        dup = max(nodes) + 1
        nodes[dup] = list(nodes[nid(1, 0)])
        r, q = cells[1]
        cells[1] = (r, [dup if v == nid(1, 0) else v for v in q])
    if defect == "degenerate_cell":  # the centre node moved onto the corner (0, 0)
        nodes[nid(c, c)] = list(nodes[nid(0, 0)])
    if defect == "folded_quad":  # the first quadrangle as a bow-tie (two nodes swapped)
        r, q = cells[0]
        cells[0] = (r, [q[0], q[1], q[3], q[2]])
    if defect == "z_nonzero":  # the centre node lifted off the plane
        nodes[nid(c, c)][2] = 0.25
    if defect == "empty_group":
        names.append((1, 8, "ghost"))
    if defect == "t_junction":  # the vertical centre line of the upper half joins the crack
        for j in range(c, n):
            lines.append((5, nid(c, j), nid(c, j + 1)))
    if defect == "non_edge":  # a diagonal of the first upper cell: no edge of the mesh
        lines.append((5, nid(0, c), nid(1, c + 1)))
    if defect == "point_group":  # a physical point 'tip' at the top centre
        points.append((9, nid(c, n)))
        names.append((0, 9, "tip"))
    if defect == "floating_block":  # the upper layer lifted by 0.5 onto its own nodes
        top = {}
        for j in range(c, n + 1):
            for i in range(n + 1):
                top[nid(i, j)] = max(nodes) + 1 + len(top)
        for k, v in top.items():
            nodes[v] = [nodes[k][0], nodes[k][1] + 0.5, 0.0]
        for j in range(c + 1, n + 1):  # the originals above the lower layer are unused now
            for i in range(n + 1):
                del nodes[nid(i, j)]
        upper_line = lambda p, a, b: p == 3 or (p in (2, 4) and min(a, b) >= nid(0, c) and
                                                 max(a, b) > nid(n, c))  # noqa: E731
        cells = [(r, [top[v] for v in q]) if r == 7 else (r, q) for r, q in cells]
        lines = [(p, top[a], top[b]) if upper_line(p, a, b) else (p, a, b) for p, a, b in lines]
    out = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(names))]
    out += [f'{d} {t} "{s}"' for d, t, s in names] + ["$EndPhysicalNames", "$Nodes", str(len(nodes))]
    out += [f"{k} {x!r} {y!r} {z!r}" for k, (x, y, z) in sorted(nodes.items())] + ["$EndNodes"]
    elements = [f"15 2 {p} {p} {v}" for p, v in points]
    elements += [f"1 2 {p} {p} {a} {b}" for p, a, b in lines]
    elements += [f"{3 if len(q) == 4 else 2} 2 {r} {r} " + " ".join(map(str, q)) for r, q in cells]
    out += ["$Elements", str(len(elements))]
    out += [f"{k + 1} {e}" for k, e in enumerate(elements)] + ["$EndElements"]
    return "\n".join(out) + "\n"


# a .geo that would mesh: the Terzaghi column with one extra text
def geo(extra, before=""):
    with open(TERZAGHI_GEO) as f:
        return before + f.read() + "\n" + extra + "\n"


# name: dict(mesh=(n, quads, defect) | geo=text, files={name: text}, scene="grid"|"grid_joint"|
#            "terzaghi", args=[...], expect=[...], ok=False, absent=[paths], fake_gmsh=script)
CASES = {
    # --- item 6: a .geo is a program
    "geo_systemcall": dict(geo=geo('SystemCall "touch {out}/pwned";'),
                           expect=["hostile.geo", "line 39", "'SystemCall' runs a program"],
                           absent=["{out}/pwned"]),
    "geo_system": dict(geo=geo('System "touch {out}/pwned";'),
                       expect=["hostile.geo", "'System' runs a program"], absent=["{out}/pwned"]),
    "geo_onelab_run": dict(geo=geo('OnelabRun "client", "touch {out}/pwned";'),
                           expect=["hostile.geo", "'OnelabRun' runs a program"]),
    "geo_printf_to_file": dict(geo=geo('Printf("x") > "{out}/written.txt";'),
                               expect=["hostile.geo", "writes a file"],
                               absent=["{out}/written.txt"]),
    "geo_save": dict(geo=geo('Save "{out}/elsewhere.msh";'),
                     expect=["hostile.geo", "'Save' writes"], absent=["{out}/elsewhere.msh"]),
    # the command hides in an included file, two levels down
    "geo_include_systemcall": dict(
        geo=geo('Include "parts/a.geo";'),
        files={"parts/a.geo": 'Include "b.geo";\n',
               "parts/b.geo": 'x = 1;\nSystemCall "touch {out}/pwned";\n'},
        expect=["b.geo", "line 2", "Include in", "a.geo", "'SystemCall'"], absent=["{out}/pwned"]),
    "geo_include_computed_name": dict(geo=geo('Include StrCat("par", "ts.geo");'),
                                      expect=["hostile.geo", "'Include'", "literal"]),
    "geo_include_missing": dict(geo=geo('Include "nowhere.geo";'),
                                expect=["nowhere.geo", "does not exist", "Include in"]),
    # a comment /* ... */ spanning lines, then the command: its line is still right
    "geo_after_block_comment": dict(geo=geo('/* a\nblock\ncomment */ SystemCall "true";'),
                                    expect=["hostile.geo", "line 41", "'SystemCall'"]),
    # ok: the words in comments and strings only, and a string holding "//"
    "geo_words_in_comments_ok": dict(
        geo=geo('// SystemCall "rm -rf /"\n/* OnelabRun */ Printf("Save // SystemCall");'),
        scene="terzaghi", ok=True, expect=["poroseam: 1 steps"]),
    "geo_include_ok": dict(geo='Include "parts/column.geo";\n',
                           files={"parts/column.geo": "@terzaghi"}, scene="terzaghi", ok=True,
                           expect=["poroseam: 1 steps"]),
    # --- item 3: gmsh's time limit, and its memory
    "geo_endless_loop": dict(geo=geo("x = 0;\nFor i In {1:2}\n  i = 1;\n  x = x + 1;\nEndFor"),
                             args=["-mesh_time_limit", "2"],
                             expect=["hostile.geo", "-mesh_time_limit 2", "stopped"]),
    "gmsh_killed_oom": dict(geo=geo(""), fake_gmsh="kill -9 $$\n",
                            expect=["out of memory while meshing", "hostile.geo",
                                    "-mesh_size_factor 1", "SIGKILL"]),
    "gmsh_bad_alloc": dict(geo=geo(""),
                           fake_gmsh="echo \"terminate called after throwing an instance of "
                                     "'std::bad_alloc'\" >&2\nkill -ABRT $$\n",
                           expect=["out of memory while meshing", "hostile.geo",
                                   "-mesh_size_factor 1"]),
    # --- item 7: the 3D caisson at a factor whose estimate exceeds this machine's memory
    "memory_estimate_refused": dict(scene="caisson", memory="refuse",
                                    expect=["caisson_quarter_3d.geo", "unknowns", "GB",
                                            "-mesh_memory_check 0", "MemAvailable"]),
    # insisting passes the memory check: gmsh then starts and meets the time limit
    "memory_check_off": dict(scene="caisson", memory="insist",
                             expect=["-mesh_time_limit 1", "caisson_quarter_3d.geo"],
                             absent_text=["-mesh_memory_check 0"]),
    # --- items 3 and 4: the .msh
    "grid_ok": dict(mesh=(2, True, None), scene="grid", ok=True, expect=["poroseam: 1 steps"]),
    "grid_joint_ok": dict(mesh=(2, True, None), scene="grid_joint", ok=True,
                          expect=["poroseam: 1 steps"]),
    "node_tag_2e9": dict(mesh=(2, True, "node_tag_2e9"), scene="grid",
                         expect=["hostile.msh", "node tag 2000000000", "number the nodes"]),
    "coincident_nodes": dict(mesh=(2, True, "coincident_nodes"), scene="grid",
                             expect=["hostile.msh", "nodes 2 and 10 coincide", "(0.5, 0, 0)"]),
    "degenerate_triangle": dict(mesh=(2, False, "degenerate_cell"), scene="grid",
                                expect=["hostile.msh", "triangle element 11", "degenerate",
                                        "area is zero"]),
    "degenerate_quadrangle": dict(mesh=(2, True, "degenerate_cell"), scene="grid",
                                  expect=["hostile.msh", "quadrangle element 11", "degenerate",
                                          "area is zero"]),
    "folded_quadrangle": dict(mesh=(2, True, "folded_quad"), scene="grid",
                              expect=["hostile.msh", "quadrangle element 11", "folded"]),
    "z_nonzero_2d": dict(mesh=(2, True, "z_nonzero"), scene="grid",
                         expect=["hostile.msh", "node 5", "z = 0.25", "plane z = 0"]),
    "empty_physical_group": dict(mesh=(2, True, "empty_group"), scene="grid",
                                 expect=["hostile.msh", "'ghost'", "no elements"]),
    "interface_t_junction": dict(mesh=(4, True, "t_junction"), scene="grid_joint",
                                 expect=["interface 'joint'", "'crack'", "T-junction",
                                         "(0.5, 0.5"]),
    "interface_non_edge": dict(mesh=(2, True, "non_edge"), scene="grid_joint",
                               expect=["hostile.msh", "line element 11", "physical group 'crack'",
                                       "not an edge"]),
    # an isolated point given as a part of the interface
    "interface_point_group": dict(mesh=(2, True, "point_group"), scene="grid_joint",
                                  args=["-interface_joint_surfaces", "crack,tip"],
                                  expect=["'tip'", "dimension 1"]),
    "floating_body": dict(mesh=(2, True, "floating_block"), scene="grid",
                          expect=["'upper'", "no displacement", "rigid"]),
    "floating_body_np2": dict(mesh=(2, True, "floating_block"), scene="grid", ranks=2,
                              expect=["'upper'", "no displacement", "rigid"]),
}


def caisson_factor(insist):
    """A factor whose estimated memory (fieldsplit, 1 rank) is twice this machine's:
    60.7 GB at factor 0.2 (the estimate grows as factor^-3)."""
    with open("/proc/meminfo") as f:
        info = {l.split(":")[0]: float(l.split()[1]) * 1024 for l in f}
    have = info.get("MemAvailable", info["MemTotal"]) / 1e9
    return min(0.2, 0.2 * (60.7 / (2 * have)) ** (1 / 3))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case")
    ap.add_argument("--list", action="store_true")
    a = ap.parse_args()
    if a.list or not a.case:
        print("\n".join(CASES))
        return 0
    case = CASES[a.case]
    out = os.path.join(bi.OUTPUT_ROOT, "hostile_meshes", a.case)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    for name, text in case.get("files", {}).items():
        path = os.path.join(out, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        if text == "@terzaghi":
            shutil.copy(TERZAGHI_GEO, path)
        else:
            with open(path, "w") as f:
                f.write(text.replace("{out}", out))
    mesh = None
    if "geo" in case:
        mesh = os.path.join(out, "hostile.geo")
        with open(mesh, "w") as f:
            f.write(case["geo"].replace("{out}", out))
    if "mesh" in case:
        mesh = os.path.join(out, "hostile.msh")
        with open(mesh, "w") as f:
            f.write(grid(*case["mesh"]))
    scene = case.get("scene", "terzaghi")
    args = []
    if scene.startswith("grid"):
        path = os.path.join(out, "scene.opts")
        with open(path, "w") as f:
            f.write(GRID_SCENE.format(mesh=mesh) + (JOINT if scene == "grid_joint" else ""))
        cmd = [EXE, "-options_file", path, "-output_dir", os.path.join(out, "run")]
    elif scene == "caisson":
        cmd = [EXE, "-options_file", os.path.join(SOURCE, "options", "caisson_partially_drained.opts"),
               "-output_dir", os.path.join(out, "run"), "-mesh_max_elements", "1000000000",
               "-mesh_size_factor", f"{caisson_factor(case['memory'] == 'insist'):.4f}"]
        if case["memory"] == "insist":
            cmd += ["-mesh_memory_check", "0", "-mesh_time_limit", "1"]
    else:
        cmd = [EXE, "-options_file", bi.BASE_SCENE, "-output_dir", os.path.join(out, "run"),
               "-ts_max_time", "0.2", "-mesh", mesh]
    cmd += [s.replace("{out}", out) for s in case.get("args", [])]
    if case.get("ranks", 1) > 1:
        cmd = ["mpiexec", "-n", str(case["ranks"])] + cmd
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    if "fake_gmsh" in case:  # a gmsh that dies as the kernel or bad_alloc would end it
        fake = os.path.join(out, "bin")
        os.makedirs(fake)
        with open(os.path.join(fake, "gmsh"), "w") as f:
            f.write("#!/bin/sh\n" + case["fake_gmsh"])
        os.chmod(os.path.join(fake, "gmsh"), 0o755)
        env["PATH"] = fake + ":" + env["PATH"]
    print("run:", " ".join(cmd), flush=True)
    t0 = time.time()
    try:
        p = subprocess.run(cmd, cwd=SOURCE, env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=bi.TIMEOUT)
        rc, text = p.returncode, p.stdout.decode(errors="replace")
    except subprocess.TimeoutExpired as e:
        rc, text = "timeout", (e.stdout or b"").decode(errors="replace")
    wall = time.time() - t0
    with open(os.path.join(out, "log.txt"), "w") as f:
        f.write(text)
    message = bi.strip_option_echo(text)
    failures = []
    if rc == "timeout":
        failures.append(f"no exit within {bi.TIMEOUT:.0f} s (hang)")
    elif case.get("ok") and rc != 0:
        failures.append(f"exit status {rc}, expected 0")
    elif not case.get("ok") and rc != 1:
        failures.append(f"exit status {rc}, expected 1")
    if wall > bi.MAX_SECONDS:
        failures.append(f"took {wall:.1f} s (> {bi.MAX_SECONDS:.0f} s)")
    for s in case["expect"]:
        if s not in message:
            failures.append(f"the output (options echo removed) does not contain '{s}'")
    for s in case.get("absent_text", []):
        if s in message:
            failures.append(f"the output contains '{s}'")
    for path in case.get("absent", []):
        if os.path.exists(path.replace("{out}", out)):
            failures.append(f"'{path.replace('{out}', out)}' exists: the .geo ran its command")
    for s in bi.CRASH:
        if bi.re.search(s, text):
            failures.append(f"crash signature '{s}' in the output")
    if not case.get("ok"):
        errors = [l for l in text.splitlines() if l.startswith("poroseam: error:")]
        if len(errors) != 1:
            failures.append(f"{len(errors)} 'poroseam: error:' lines, expected exactly 1")
        for s in ("PETSC ERROR", "MPI_ABORT", "Traceback"):
            if s in text:
                failures.append(f"the output contains '{s}'")
    shown = [l for l in message.splitlines() if l.strip()]
    print(f"exit {rc} after {wall:.2f} s; output (options echo removed):")
    print("    " + "\n    ".join(shown[-8:]))
    if failures:
        print(f"FAIL {a.case}:\n  " + "\n  ".join(failures))
        return 1
    print(f"PASS {a.case}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
