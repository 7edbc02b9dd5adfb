"""ParaView draws the order-2 displacement as the quadratic field it is.

At -displacement_order 2 fields.xmf holds XDMF quadratic cells (Quadrilateral_9,
Hexahedron_27; docs/outputs.md). Terzaghi's column, 2D and 3D (box cells, probes left out),
runs three steps at order 2; ParaView's XDMF 3 reader (the one scripts/render_fields uses)
then probes the displacement at 20 random points inside random cells, and each value must
equal the tensor-product Lagrange interpolation of the cell's 3^dim nodal values computed here
from fields.h5 by their coordinates (independent of any node order): relative difference
< 1e-5 (measured 1.1e-7 and 1.5e-7, ParaView's probe; a node in the wrong place of VTK's
order gives O(1)).
SKIPPED (exit 77) when pvpython is not installed: ParaView is not a dependency of poroseam.
"""
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
import common  # noqa: E402

SKIP = 77
PROBE = r'''
import sys, h5py, numpy as np
from paraview.simple import Xdmf3ReaderS, ProbeLocation
from paraview import servermanager as sm
from vtk.numpy_interface import dataset_adapter as dsa
d = sys.argv[1]
h = h5py.File(d + "/fields.h5", "r")
X = h["/geometry/vertices"][()]
C = h["/topology/cells"][()]
last = str(len(h["/fields/displacement"]) - 1)
U = h["/fields/displacement/" + last][()]
t = float(h["/fields/displacement/" + last].attrs["time"])
dim = X.shape[1]
reader = Xdmf3ReaderS(FileName=[d + "/fields.xmf"])
rng = np.random.default_rng(1)
worst = 0.0
for trial in range(20):
    c = C[rng.integers(len(C))]
    lo, hi = X[c].min(0), X[c].max(0)
    p = lo + rng.uniform(0.1, 0.9, dim) * (hi - lo)
    value = np.zeros(3)
    for k in c:
        w = 1.0
        for a in range(dim):
            g = np.unique(np.round(X[c][:, a], 9))
            assert len(g) == 3, g
            j = int(np.argmin(np.abs(g - X[k, a])))
            for m in range(3):
                if m != j:
                    w *= (p[a] - g[m]) / (g[j] - g[m])
        value += w * U[k]
    probe = ProbeLocation(Input=reader, ProbeType="Fixed Radius Point Source")
    probe.ProbeType.Center = list(p) + [0.0] * (3 - dim)
    probe.UpdatePipeline(time=t)
    shown = np.array(dsa.WrapDataObject(sm.Fetch(probe)).PointData["displacement"][0])
    worst = max(worst, float(np.max(np.abs(shown - value)) / np.max(np.abs(U))))
print("RESULT", worst)
'''


def scene_without_probes(name, out):
    """options/<name>.opts without its probes (order 2 has none yet), mesh path absolute."""
    src = os.path.join(common.SOURCE, "options", name + ".opts")
    dst = os.path.join(out, name + ".opts")
    with open(src) as f, open(dst, "w") as g:
        for line in f:
            if line.startswith("-probe_"):
                continue
            g.write(line.replace("../meshes/", os.path.join(common.SOURCE, "meshes") + "/"))
    return dst


def main():
    if shutil.which("pvpython") is None:
        print("SKIPPED: ParaView's pvpython is not installed (Debian: apt-get install paraview "
              "python3-paraview xvfb)")
        sys.exit(SKIP)
    chk = common.Checks("ParaView draws the order-2 displacement quadratically")
    script = os.path.join(common.output_dir("quadratic_fields_probe"), "probe.py")
    with open(script, "w") as f:
        f.write(PROBE)
    for name in ("terzaghi_2d", "terzaghi_3d"):
        out = common.output_dir("quadratic_fields_" + name)
        common.run(scene_without_probes(name, out), out,
                   ["-displacement_order", 2, "-ts_max_time", 0.6, "-output_fields_every", 1])
        r = subprocess.run(["pvpython", script, out], capture_output=True, text=True, timeout=300)
        lines = [l for l in r.stdout.splitlines() if l.startswith("RESULT")]
        if r.returncode != 0 or not lines:
            common.fail("pvpython failed:\n" + r.stdout[-2000:] + r.stderr[-2000:])
        chk.check(f"{name}: ParaView's probe against the Q2 interpolation (relative)",
                  float(lines[0].split()[1]), 1e-5)
    chk.finish()


if __name__ == "__main__":
    main()
