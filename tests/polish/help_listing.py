#!/usr/bin/python3
"""`poroseam -options_file <scene> -help` without the clutter of PETSc's internal objects
(issue 24 item 11; src/app/help_filter.cpp), with "none" for optional values that are unset,
and a gmsh log that exists when the listing names it. About 3 s.

1. options/terzaghi_2d.opts and options/caisson_axisym_partially_drained.opts: exit 0; no
   viewer of an internal object (-is_view, -dm_fields_is_view, -global_section_view,
   -before_orient_interface_dm_view, -petscpartitioner_view*), no GPU-device, SEQAIJ or Gmsh
   reader section; every other viewer in one line (no "-<name> binary[" form lines); and still
   the options a user sets: scene, region, interface, boundary, output, TS, SNES, KSP, PC and
   the monitors (-ts_monitor, -snes_monitor, -ksp_monitor); fewer than 450 lines (693 before
   for terzaghi_2d).
2. The caisson's optional -interface_caisson_dilation_limit is shown as "<now none", not 0.
3. A .geo that gmsh cannot mesh, under -help: the error names gmsh's log, and that file exists
   (the scratch directory of the listing is removed except for it, and the record of the
   failed listing, run.yaml, written after).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402

chk = common.Checks("-help listing")
INTERNAL = ["is_view", "dm_fields_is_view", "global_section_view", "before_orient_interface_dm_view",
            "petscpartitioner_view", "petscpartitioner_view_graph"]
SECTIONS = ["PetscDevice Options:", "Root PetscDeviceContext Options:", "Options for SEQAIJ matrix:",
            "PetscViewer options:"]


def listing(scene, extra=(), tmpdir=None):
    env = dict(os.environ)
    if tmpdir:
        env["TMPDIR"] = tmpdir
    res = subprocess.run([common.EXE, "-options_file", scene, "-help"] + list(extra), cwd=common.SOURCE,
                         capture_output=True, text=True, timeout=120, env=env)
    return res.returncode, res.stdout + res.stderr


for name, wanted in (("terzaghi_2d", ["-region_soil_E", "-bc_top_traction", "-output_interfaces_every"]),
                     ("caisson_axisym_partially_drained",
                      ["-region_soil_E", "-interface_caisson_KN", "-interface_caisson_dilation_limit",
                       "-bc_lid_top_uy", "-output_interfaces_every", "-probe_plug_top"])):
    status, text = listing(os.path.join(common.SOURCE, "options", name + ".opts"))
    lines = text.splitlines()
    chk.check(f"{name}: -help exits 0", float(status), 0)
    shown = set(re.findall(r"^ *-(\w+)", text, re.M))
    internal = [v for v in INTERNAL if v in shown or f"Viewer (-{v})" in text]
    chk.check(f"{name}: internal viewers listed {internal}", float(len(internal)), 0)
    sections = [s for s in SECTIONS if s in lines]
    chk.check(f"{name}: internal sections listed {sections}", float(len(sections)), 0)
    forms = [line for line in lines if re.match(r"^  -\w+ (binary|draw|socket|saws)\b", line)]
    chk.check(f"{name}: viewer form lines left {forms[:2]}", float(len(forms)), 0)
    user = wanted + ["-ts_dt", "-ts_max_time", "-ts_monitor", "-snes_monitor", "-snes_rtol", "-ksp_type",
                     "-ksp_monitor", "-pc_type"]
    missing = [o for o in user if o[1:] not in shown]
    chk.check(f"{name}: user options missing {missing}", float(len(missing)), 0)
    chk.check(f"{name}: {len(lines)} lines", float(len(lines) >= 450), 0)
    if name.startswith("caisson"):
        m = re.search(r"-interface_caisson_dilation_limit <now (\S+) :", text)
        chk.check(f"{name}: dilation_limit shown as <now {m.group(1) if m else '?'}>", 0, 0,
                  ok=bool(m) and m.group(1) == "none")

# 3. gmsh fails under -help.
scratch = tempfile.mkdtemp(prefix="polish-help-")
try:
    geo = os.path.join(scratch, "broken.geo")
    with open(geo, "w") as f:
        f.write("Point(1) = {0, 0, 0, 1};\nLine(1) = {1, 2};\nnot gmsh at all\n")
    status, text = listing(os.path.join(common.SOURCE, "options", "terzaghi_2d.opts"), ["-mesh", geo],
                           tmpdir=scratch)
    m = re.search(r"see (\S+gmsh\.log)\)", text)
    chk.check("gmsh failure under -help: exit status 1 and the log named", 0, 0, ok=status == 1 and bool(m))
    kept = m and os.path.isfile(m.group(1)) and os.path.getsize(m.group(1)) > 0
    chk.check(f"the named log {m.group(1) if m else '?'} exists and is not empty", 0, 0, ok=bool(kept))
    if m:
        left = sorted(os.path.relpath(os.path.join(d, f), scratch) for d, _, fs in os.walk(scratch) for f in fs)
        # (run.yaml, the record of the failed listing, is written after the clean-up)
        left = [x for x in left if x != "broken.geo" and not x.endswith("/run.yaml")]
        chk.check(f"only the log is left of the listing's scratch directory: {left}", 0, 0,
                  ok=len(left) == 1 and left[0].endswith("mesh/gmsh.log"))
finally:
    shutil.rmtree(scratch, ignore_errors=True)
chk.finish()
