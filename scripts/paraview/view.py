"""Opens a poroseam output directory in the ParaView GUI with the pipeline of render.py
(docs/viewing.md): started by scripts/view_fields, which passes the directory and render.py's
options in the environment variable POROSEAM_VIEW (ParaView's --script takes no arguments):

    POROSEAM_VIEW="OUTPUT_DIR [options]" paraview --script=scripts/paraview/view.py

Every filter stays in the Pipeline Browser to change: the time (VCR controls), the warp's
Scale Factor, the reflection, the colours.
"""
import os
import shlex
import sys

try:
    here = os.path.dirname(os.path.abspath(__file__))
except NameError:  # the GUI runs the script's text without a file name
    here = os.environ.get("POROSEAM_PARAVIEW_DIR", "")
if not os.path.isfile(os.path.join(here, "poroseam_view.py")):
    raise SystemExit("view.py: set POROSEAM_PARAVIEW_DIR to the repository's scripts/paraview "
                     "(scripts/view_fields does)")
sys.path.insert(0, here)
from poroseam_view import Pipeline  # noqa: E402
from render import parse  # noqa: E402

from paraview.simple import GetActiveViewOrCreate, Render  # noqa: E402

args, options = parse(shlex.split(os.environ.get("POROSEAM_VIEW", "")))
view = GetActiveViewOrCreate("RenderView")
pipeline = Pipeline(args.output_dir, **options)
pipeline.show(view)
Render(view)
