"""The plastic zone drawn by ParaView (scripts/render_fields --field equivalent_plastic_strain
and --field yield_state) on a small run of the axisymmetric drained caisson in Mohr-Coulomb
sand (options/caisson_axisym_drained_mohr_coulomb.opts at -mesh_size_factor 2, 20 steps: the
soil yields at the skirt tips).

What the pictures must show comes from fields.h5 (read by tests/support/fields_reader.py), not
from the picture itself:
  * --field equivalent_plastic_strain: exit 0, the caption's "largest" equals the largest cell
    value in fields.h5, and the top of the Viridis map (yellow) is drawn where some cell has
    it; the rest of the soil stays at the bottom of the map (dark purple) - more of it than of
    yellow;
  * --field yield_state: the caption's count of yielding cells equals the count of cells with a
    non-zero yield state in fields.h5;
  * a field the output does not have: exit 2 with one line listing the choices.
SKIPPED (exit 77) when pvpython is not installed: ParaView is not a dependency of poroseam.
"""
import os
import re
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
import common  # noqa: E402

SKIP = 77
RENDER = os.path.join(common.SOURCE, "scripts", "render_fields")
YELLOW = (253, 231, 37)   # the top of matplotlib's Viridis in ParaView's preset
PURPLE = (68, 1, 84)      # its bottom


def render(out, field, png):
    r = subprocess.run([RENDER, out, "--field", field, "--output", png, "--state", "none",
                        "--reflect", "--view=-9,9,-8.5,1.5"], capture_output=True, text=True,
                       timeout=300)
    return r.returncode, r.stdout, r.stderr


def near(img, rgb, tol):
    return int(np.sum(np.all(np.abs(img - np.array(rgb)) <= tol, axis=2)))


def main():
    if shutil.which("pvpython") is None:
        print("SKIPPED: ParaView's pvpython is not installed (Debian: apt-get install paraview "
              "python3-paraview xvfb)")
        sys.exit(SKIP)
    chk = common.Checks("pictures: the plastic zone of a caisson in Mohr-Coulomb sand")
    out = common.output_dir("pictures_plastic_zone")
    common.run(os.path.join(common.SOURCE, "options", "caisson_axisym_drained_mohr_coulomb.opts"),
               out, ["-mesh_size_factor", 2, "-ts_max_time", 120])
    import fields_reader

    fields = fields_reader.read_fields(out)
    eps = np.asarray(fields.cell_fields[-1]["equivalent_plastic_strain"]).ravel()
    state = np.asarray(fields.cell_fields[-1]["yield_state"]).ravel()
    largest, yielding = float(np.max(eps)), int(np.sum(state > 0))
    print(f"  fields.h5 at t = {fields.times[-1]:g} s: largest equivalent plastic strain "
          f"{largest:.3g}, {yielding} of {len(state)} cells yielding")
    chk.check("the run yields somewhere (largest equivalent plastic strain)", -largest, 0.0,
              ok=largest > 0)

    png = os.path.join(out, "plastic_zone.png")
    rc, so, se = render(out, "equivalent_plastic_strain", png)
    print("  " + (so.strip() or se.strip()[-400:]))
    m = re.search(r"axis, largest ([0-9.eE+-]+)|\), largest ([0-9.eE+-]+)", so)
    chk.check("--field equivalent_plastic_strain: exit 0 and the largest value in the caption",
              rc, 0, ok=rc == 0 and m is not None)
    if m:
        shown = float(m.group(1) or m.group(2))
        chk.check("caption's largest value = fields.h5's (relative; the caption has 3 digits)",
                  abs(shown - largest) / largest, 5e-3)
    if os.path.isfile(png):
        import matplotlib.image as mpimg

        img = np.round(255 * mpimg.imread(png)[:, :, :3]).astype(int)
        h, w = img.shape[:2]
        middle = img[int(0.1 * h):, int(0.13 * w):int(0.87 * w)]  # no legends, no caption
        yellow, purple = near(middle, YELLOW, 40), near(middle, PURPLE, 25)
        print(f"  pixels: {yellow} near the top of the map, {purple} near its bottom")
        chk.check("the most strained cells drawn in the map's top colour (pixels)", -yellow, -20)
        chk.check("elastic soil drawn in the map's bottom colour, more than the plastic zone",
                  -purple, -yellow, ok=purple > 10 * yellow)

    rc, so, se = render(out, "yield_state", os.path.join(out, "yield_state.png"))
    m = re.search(r"(\d+) of (\d+) cells yielding", so)
    print("  " + (so.strip() or se.strip()[-400:]))
    chk.check("--field yield_state: exit 0, caption's yielding cells = fields.h5's",
              int(m.group(1)) if m else -1, yielding,
              ok=rc == 0 and m is not None and int(m.group(1)) == yielding and int(m.group(2)) == len(state))

    rc, so, se = render(out, "no_such_field", os.path.join(out, "none.png"))
    lines = [ln for ln in se.splitlines() if ln.strip()]
    chk.check("an unknown --field: exit 2, one line listing equivalent_plastic_strain among the choices",
              rc, 2, ok=rc == 2 and len(lines) == 1 and "equivalent_plastic_strain" in lines[0])
    chk.finish()


if __name__ == "__main__":
    main()
