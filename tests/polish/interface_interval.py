#!/usr/bin/python3
"""Interface output every -output_interfaces_every steps (docs/outputs.md, docs/scenes.md), on
its own count beside the fields', and continued by a restart (tests/interface/patch_2d.opts:
two elastic blocks in contact, 7 steps of 1 s, direct solver: about 1 s a run).

1. -output_fields_every 3 -output_interfaces_every 2: fields at steps 0, 3, 6, 7 (the last),
   interfaces at 0, 2, 4, 6, 7; counted in the HDF5 files (datasets per field) and in the
   XDMF indexes (Time entries), and their times equal the steps' times of timeseries.csv.
2. Defaults with -output_fields_every 3: interfaces with the fields (0, 3, 6, 7).
3. -output_fields_every 0: no interface files either (the default follows the fields).
4. The run of case 1 stopped at step 5 (-ts_max_steps 5, checkpoints every 2 steps; its last
   outputs at step 5) and restarted from its checkpoint of step 4 to step 7: interface times and values equal those
   of the uninterrupted run (output index k is the same output in both), fields likewise.
"""
import os
import re
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
import common  # noqa: E402
import h5py  # noqa: E402
from interface_reader import read_interfaces  # noqa: E402

SCENE = os.path.join(common.SOURCE, "tests", "interface", "patch_2d.opts")
STEPS = ["-ts_max_steps", 7, "-ts_max_time", 7, "-bc_top_traction", "0,-1e5",
         "-bc_top_traction_ramp", 7]
chk = common.Checks("interface output interval")


def xdmf_times(path):
    with open(path) as f:
        return [float(v) for v in re.findall(r'<Time Value="([^"]+)"', f.read())]


def field_outputs(out):
    with h5py.File(os.path.join(out, "fields.h5"), "r") as h5:
        return sorted(float(h5["fields/displacement"][k].attrs["time"]) for k in h5["fields/displacement"])


def interface_outputs(out):
    """Times of the interface outputs: per HDF5 dataset (gap_normal of the cells), per XDMF."""
    with h5py.File(os.path.join(out, "interfaces.h5"), "r") as h5:
        names = []
        h5.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) and
                      re.search(r"gap_normal/\d+$", n) and n.startswith("cells") else None)
        times = sorted(float(h5[n].attrs["time"]) for n in names)
    return times, [xdmf_times(os.path.join(out, f"{g}.xmf")) for g in ("interface_cells", "interface_points")]


def check_counts(label, out, fields_expected, interfaces_expected):
    f = field_outputs(out)
    chk.check(f"{label}: field output times {f} (expected {fields_expected})", 0, 0,
              ok=np.allclose(f, fields_expected))
    h5_times, (cells, points) = interface_outputs(out)
    chk.check(f"{label}: interface outputs in interfaces.h5 at {h5_times} (expected {interfaces_expected})",
              0, 0, ok=len(h5_times) == len(interfaces_expected) and np.allclose(h5_times, interfaces_expected))
    chk.check(f"{label}: interface_cells.xmf and interface_points.xmf list {len(cells)} and "
              f"{len(points)} times (expected {len(interfaces_expected)})", 0, 0,
              ok=cells == points and len(cells) == len(interfaces_expected) and np.allclose(cells, interfaces_expected))


# 1. Both intervals.
out1 = common.output_dir("polish_interface_interval")
common.run(SCENE, out1, STEPS + ["-output_fields_every", 3, "-output_interfaces_every", 2])
check_counts("every 3 / every 2", out1, [0, 3, 6, 7], [0, 2, 4, 6, 7])

# 2. Default: interfaces with the fields.
out2 = common.output_dir("polish_interface_default")
common.run(SCENE, out2, STEPS + ["-output_fields_every", 3])
check_counts("default", out2, [0, 3, 6, 7], [0, 3, 6, 7])

# 3. No field output: no interface output either.
out3 = common.output_dir("polish_interface_none")
common.run(SCENE, out3, STEPS + ["-output_fields_every", 0])
present = sorted(n for n in os.listdir(out3) if n.startswith("interface"))
chk.check(f"-output_fields_every 0: interface files written {present}", float(len(present)), 0)

# 4. Stopped at step 5 by the step limit (exit status non-zero, as documented), restarted from
#    its checkpoint of step 4.
out4 = common.output_dir("polish_interface_restart")
every = ["-output_fields_every", 3, "-output_interfaces_every", 2, "-checkpoint_every", 2]
cmd = [common.EXE, "-options_file", SCENE, "-output_dir", out4] + [str(a) for a in STEPS + every]
res = subprocess.run(cmd + ["-ts_max_steps", "5"], cwd=common.SOURCE, capture_output=True, text=True,
                     timeout=120)
chk.check("the run stopped by -ts_max_steps 5 says so", 0, 0,
          ok=res.returncode != 0 and "step limit -ts_max_steps 5" in res.stdout + res.stderr)
common.run(SCENE, out4, STEPS + every + ["-restart", out4, "-restart_step", 4])
check_counts("restarted at step 4", out4, [0, 3, 6, 7], [0, 2, 4, 6, 7])
a, b = read_interfaces(out1), read_interfaces(out4)
worst = 0.0
for k in range(len(a.times)):
    for name in ("gap_normal", "shear_stress", "contact_pressure_effective"):
        x, y = np.asarray(a.cell_fields[k][name]), np.asarray(b.cell_fields[k][name])
        scale = max(np.max(np.abs(x)), 1e-300)
        worst = max(worst, float(np.max(np.abs(x - y)) / scale))
chk.check("restarted run: interface values at each output index against the uninterrupted run "
          "(relative to each field's largest value)", worst, 1e-12)
chk.finish()
