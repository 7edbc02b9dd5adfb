"""Renders a poroseam output directory with ParaView: the excess pore pressure on the deformed
mesh (displacements scaled so that the deformation is visible; the factor is written in the
picture) with the interface state (open / stick / slip) drawn on the interfaces. Axisymmetric
runs are reflected about the axis (the full section through it). Also saves the pipeline as a
ParaView state file to open interactively: paraview --state=<state>.

    pvpython scripts/paraview/render.py OUTPUT_DIR [options]     (needs an X display:
    scripts/render_fields starts a virtual one, Xvfb, when there is none)

Options: --output PNG (default OUTPUT_DIR/fields.png), --state PVSM (default: the PNG's name
with .pvsm; 'none' for no state file), --time T (the output time nearest to T; default the
last), --scale S (displacement factor; default automatic), --reflect / --no-reflect (about
x = 0; default: when run.yaml says -axisymmetric), --view x0,x1,y0,y1 (the region shown, in
the picture's coordinates: (r, z) in 2D, (x or y, z) in a 3D section), --slice AXIS=VALUE
(3D: the section plane, default the middle of the mesh across y), --field NAME (default
excess_pressure, else pressure, else displacement_magnitude; cell fields too:
equivalent_plastic_strain, yield_state, region, and components of the tensors
effective_stress_xx ... _xz, total_stress_*, strain_* -- a wrong name lists what the output
has), --size WxH (pixels, default 1200x800), --title TEXT.
Prints one line: the PNG's path and what it shows.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poroseam_view import Pipeline, ViewError, new_view  # noqa: E402


def floats(text, n, what):
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        values = []
    if len(values) != n:
        raise argparse.ArgumentTypeError(f"{what}: expected {n} comma-separated numbers, got '{text}'")
    return values


def parse(argv):
    """(args, the keyword arguments of Pipeline) from the command line."""
    ap = argparse.ArgumentParser(prog="render_fields", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("output_dir")
    ap.add_argument("--output", help="PNG file (default OUTPUT_DIR/fields.png)")
    ap.add_argument("--state", help="ParaView state file (default: the PNG with .pvsm; 'none': none)")
    ap.add_argument("--time", type=float)
    ap.add_argument("--scale", type=float, help="displacement scale factor (default: automatic)")
    ap.add_argument("--reflect", dest="reflect", action="store_true", default=None)
    ap.add_argument("--no-reflect", dest="reflect", action="store_false")
    ap.add_argument("--view", type=lambda s: floats(s, 4, "--view x0,x1,y0,y1"))
    ap.add_argument("--slice", help="3D: section plane AXIS=VALUE, e.g. y=0.001")
    ap.add_argument("--field", help="what to colour by (see above)")
    ap.add_argument("--size", default="1200x800")
    ap.add_argument("--title")
    args = ap.parse_args(argv)

    slice_at = None
    if args.slice:
        axis, _, value = args.slice.partition("=")
        try:
            slice_at = (axis.strip().lower(), float(value))
        except ValueError:
            slice_at = None
        if slice_at is None or slice_at[0] not in ("x", "y", "z"):
            ap.error(f"--slice: expected AXIS=VALUE with AXIS x, y or z, got '{args.slice}'")
    try:
        width, height = (int(v) for v in args.size.lower().split("x"))
    except ValueError:
        ap.error(f"--size: expected WIDTHxHEIGHT in pixels, got '{args.size}'")
    if args.view is not None and (args.view[1] <= args.view[0] or args.view[3] <= args.view[2]):
        ap.error(f"--view: expected x0 < x1 and y0 < y1, got {args.view}")
    if args.scale is not None and args.scale < 0:
        ap.error(f"--scale: expected a factor >= 0, got {args.scale}")
    args.size = (width, height)
    options = dict(view=args.view, time=args.time, scale=args.scale, reflect=args.reflect,
                   slice_at=slice_at, field=args.field, title=args.title)
    return args, options


def main(argv):
    args, options = parse(argv)
    width, height = args.size
    png = args.output or os.path.join(args.output_dir, "fields.png")
    state = args.state or os.path.splitext(png)[0] + ".pvsm"
    try:
        pipeline = Pipeline(args.output_dir, **options)
    except ViewError as e:
        print(f"render.py: {e}", file=sys.stderr)
        return 2
    from paraview.simple import Delete, GetAnimationScene, Render, SaveScreenshot, SaveState

    view = new_view(width, height)
    pipeline.show(view)
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[width, height], TransparentBackground=0)
    if state.lower() != "none":
        # the state opens at the picture's time: the animation scene's time is what a state
        # restores (done here, not in the GUI's view.py, where this call blocks)
        animation = GetAnimationScene()
        animation.UpdateAnimationUsingDataTimeSteps()
        animation.AnimationTime = pipeline.time
        SaveState(state)
    print(f"{png}: {pipeline.caption().replace(chr(10), '; ')}"
          + ("" if state.lower() == "none" else f"; state {state}"))
    # Close the render window while the X connection is still open: otherwise it is closed
    # at interpreter exit, after Xvfb's context is gone, and the exit status becomes 1.
    Delete(view)
    del view
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
