"""Pictures drawn with ParaView (docs/viewing.md): scripts/render_fields and figure 9a of
scripts/plot_caisson, on a small run of the axisymmetric caisson (options/caisson_axisym_
partially_drained.opts at -mesh_size_factor 3, 2 steps of 24 s: suction in the plug, the skirts
sliding, 928 unknowns, about a second).

Always (no ParaView needed):
  * without pvpython on the PATH, scripts/render_fields exits 3 with one line saying so, and
    scripts/plot_caisson draws its other figures, says in one line that fig 9a is skipped
    and exits 0 (ParaView is not a dependency of poroseam).
With pvpython (Debian packages paraview and xvfb), otherwise the test ends as SKIPPED (exit 77):
  * scripts/plot_caisson writes fig9a_excess_pressure.png and its ParaView state;
  * the picture is not blank and shows what it should, away from its legends (the middle of
    the picture below the caption): the pressure colour map's blues (the suction in the plug:
    the excess pore pressure there is negative, checked in fields.h5 first), the grey of the
    steel when the output writes NaN pressure there, and the colours of the interface states
    the output holds at that time (state counts read from the interface output), and not the
    colour of a state the output does not hold;
  * the state file names the run's fields.xmf and the picture's time (paraview --state opens
    the same view);
  * render_fields on a directory without fields.xmf exits 2 naming the missing file.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
import common  # noqa: E402
from interface_reader import read_interfaces  # noqa: E402

SKIP = 77  # ctest SKIP_RETURN_CODE (tests/pictures_tests.cmake)
SCRIPTS = os.path.join(common.SOURCE, "scripts")
# The colours of the interface states (scripts/paraview/poroseam_view.py STATE_COLOURS), 0-255.
STATE_RGB = {0: (0, 0, 0), 1: (0, 178, 0), 2: (217, 0, 217)}
STATE_NAMES = {0: "open", 1: "stick", 2: "slip"}
NAN_RGB = (107, 110, 117)  # poroseam_view.NAN_GREY: regions without pressure (the steel)


def run(cmd, env=None):
    r = subprocess.run(cmd, cwd=common.SOURCE, env=env, capture_output=True, text=True, timeout=300)
    return r.returncode, r.stdout, r.stderr


def path_without_pvpython():
    """A PATH with only what the scripts need besides ParaView (bash, dirname)."""
    d = tempfile.mkdtemp(prefix="nopv")
    for tool in ("bash", "dirname", "env"):
        os.symlink(shutil.which(tool), os.path.join(d, tool))
    return d


def pixels_near(img, rgb, tol=30):
    """Pixels within tol (0-255) of a colour in every channel (the lines are drawn flat; their
    anti-aliased edges blend with the background)."""
    return int(np.sum(np.all(np.abs(img - np.array(rgb)) <= tol, axis=2)))


def main():
    chk = common.Checks("pictures: ParaView rendering of the axisymmetric caisson")
    out = common.output_dir("pictures_caisson")
    common.run(os.path.join(common.SOURCE, "options", "caisson_axisym_partially_drained.opts"), out,
               ["-mesh_size_factor", 3, "-ts_dt", 24, "-ts_max_time", 48, "-output_fields_every", 1])

    # ---- without ParaView
    bindir = path_without_pvpython()
    env = dict(os.environ, PATH=bindir)
    env.pop("DISPLAY", None)
    rc, so, se = run([os.path.join(SCRIPTS, "render_fields"), out], env)
    lines = [ln for ln in se.splitlines() if ln.strip()]
    chk.check("render_fields without pvpython: exit 3 with one line naming pvpython "
              f"(exit {rc}: {lines[-1] if lines else ''})", rc, 3,
              ok=rc == 3 and len(lines) == 1 and "pvpython is not installed" in lines[0])
    rc, so, se = run(["/usr/bin/python3", os.path.join(SCRIPTS, "plot_caisson"), out], env)
    skipped = [ln for ln in so.splitlines() if ln.startswith("fig9a_excess_pressure.png: skipped")]
    print("  " + (skipped[0] if skipped else "(no fig9a line)"))
    chk.check("plot_caisson without pvpython: exit 0, its other figures, one line for fig 9a",
              rc, 0, ok=rc == 0 and len(skipped) == 1 and "pvpython is not installed" in skipped[0]
              and os.path.isfile(os.path.join(out, "fig8a_forces.png"))
              and not os.path.exists(os.path.join(out, "fig9a_excess_pressure.png")))
    shutil.rmtree(bindir)

    if shutil.which("pvpython") is None:
        print("SKIPPED: ParaView's pvpython is not installed (Debian: apt-get install paraview "
              "xvfb); the checks without it passed" if all(r[3] for r in chk.rows) else "")
        if all(r[3] for r in chk.rows):
            sys.exit(SKIP)
        chk.finish()

    # ---- what the picture must show, from the output files
    import fields_reader

    fields = fields_reader.read_fields(out)
    excess = np.asarray(fields.fields[-1]["excess_pressure"])
    x = np.asarray(fields.coordinates)
    plug = (x[:, 0] < 3.7) & (x[:, 1] < -0.05) & (x[:, 1] > -3.9)  # soil inside the skirt
    plug_excess = float(np.nanmax(excess[plug]))
    chk.check("the output has suction in the plug (max excess pore pressure there, Pa)",
              plug_excess, 0.0, ok=plug_excess < 0)
    ifc = read_interfaces(out)
    k = int(np.argmin(np.abs(np.asarray(ifc.times) - fields.times[-1])))
    states = np.bincount(np.asarray(ifc.cell_fields[k]["state"]).ravel().astype(int), minlength=3)
    print("  interface cells at t = %g s: %s" % (ifc.times[k], ", ".join(
        f"{n} {STATE_NAMES[s]}" for s, n in enumerate(states))))

    # ---- with ParaView: figure 9a through plot_caisson
    png = os.path.join(out, "fig9a_excess_pressure.png")
    rc, so, se = run(["/usr/bin/python3", os.path.join(SCRIPTS, "plot_caisson"), out])
    line = [ln for ln in so.splitlines() if ln.startswith(png)]
    print("  " + (line[0] if line else se.strip()[-500:]))
    chk.check("plot_caisson with pvpython: exit 0 and fig9a_excess_pressure.png", rc, 0,
              ok=rc == 0 and os.path.isfile(png) and len(line) == 1)
    if os.path.isfile(png):
        import matplotlib.image as mpimg

        img = mpimg.imread(png)
        img = np.round(255 * img[:, :, :3]).astype(int)
        h, w = img.shape[:2]
        colours = len(np.unique(img.reshape(-1, 3), axis=0))
        chk.check("picture not blank: distinct colours", -colours, -50)
        middle = img[int(0.1 * h):, int(0.13 * w):int(0.87 * w)]  # no legend, no caption
        r, g, b = (middle[:, :, i] for i in range(3))
        blue = int(np.sum((b - r > 40) & (b - g > 20)))
        chk.check("suction drawn: blue pixels of the colour map in the picture's middle",
                  -blue, -2000)
        steel = int(np.sum(np.isnan(excess)))
        if steel:  # outputs that write NaN pressure outside porous regions
            count = pixels_near(middle, NAN_RGB, tol=6)
            chk.check(f"the steel ({steel} vertices without pressure) drawn grey: pixels of the NaN colour",
                      -count, -500)
        for s, n in enumerate(states):
            count = pixels_near(middle, STATE_RGB[s])
            if n > 0:
                chk.check(f"interface state '{STATE_NAMES[s]}' ({n} cells) drawn: pixels of its colour",
                          -count, -100)
            else:
                chk.check(f"interface state '{STATE_NAMES[s]}' (no cell) not drawn: pixels of its colour",
                          count, 10)
    state = os.path.splitext(png)[0] + ".pvsm"
    text = open(state).read() if os.path.isfile(state) else ""
    chk.check("the ParaView state file exists and names the run's fields.xmf", 0, 0,
              ok=os.path.join(out, "fields.xmf") in text)
    m = re.search(r'name="AnimationTime"[^>]*>\s*<Element index="0" value="([^"]+)"', text)
    at = float(m.group(1)) if m else float("nan")
    chk.check(f"the state opens at the picture's time (AnimationTime {at:g} s, last output "
              f"{fields.times[-1]:g} s)", abs(at - fields.times[-1]), 1e-9 * max(1.0, fields.times[-1]))

    # ---- bad input
    empty = tempfile.mkdtemp(prefix="nofields")
    rc, so, se = run([os.path.join(SCRIPTS, "render_fields"), empty])
    lines = [ln for ln in se.splitlines() if "render.py:" in ln]
    print("  " + (lines[0] if lines else se.strip()[-300:]))
    chk.check("render_fields on a directory without fields.xmf: exit 2 naming the file", rc, 2,
              ok=rc == 2 and len(lines) == 1 and os.path.join(empty, "fields.xmf") in lines[0])
    shutil.rmtree(empty)
    chk.finish()


if __name__ == "__main__":
    main()
