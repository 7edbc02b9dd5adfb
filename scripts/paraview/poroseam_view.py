"""The ParaView pipeline of a poroseam output directory (docs/viewing.md), shared by render.py
(pvpython, PNG + state file) and view.py (the ParaView GUI, `paraview --script`).

    bulk:      fields.xmf -> [3D: Slice] -> Warp By Vector (displacement x scale)
               -> excess pore pressure in kPa (or the pressure, or |u| of a drained scene)
               -> [Reflect about the picture's horizontal coordinate = 0: r = 0 in 2D];
               NaN (regions without pressure: the steel) dark grey
    interface: interface_cells.xmf, or the cell grid of interfaces.xmf -> [3D: Slice]
               -> warped with its own displacement_minus (side 1) when the output has it,
               else with the bulk displacement resampled at its nodes -> [Reflect]
               -> thick lines coloured by state (0 open, 1 stick, 2 slip)

Only paraview.simple is used here; this module runs inside pvpython or the ParaView GUI.
"""
import math
import os

from paraview import servermanager
from paraview.simple import (Calculator, ColorBy, CreateView, ExtractCellsByType,
                             GetColorTransferFunction, GetScalarBar, GetTimeKeeper,
                             PythonCalculator, Reflect, Render, ResampleWithDataset, SetActiveView,
                             Show, Slice, Text, Transform, WarpByVector, Xdmf3ReaderS)

STATE_NAMES = ("open", "stick", "slip")
# Interface state colours, apart from the cool-to-warm pressure map (blue - grey - red).
STATE_COLOURS = ((0.0, 0.0, 0.0), (0.0, 0.70, 0.0), (0.85, 0.0, 0.85))
NAN_GREY = (0.42, 0.43, 0.46)  # steel-like, darker than the map's light grey zero
# yield_state of Mohr-Coulomb cells (docs/outputs.md)
YIELD_NAMES = ("elastic", "face", "edge", "apex", "tension cut-off")
YIELD_COLOURS = ((0.88, 0.88, 0.88), (0.99, 0.75, 0.2), (0.9, 0.35, 0.1), (0.6, 0.0, 0.0),
                 (0.2, 0.3, 0.8))
# tensor cell fields [Nc, 9] (row by row) and their components: --field effective_stress_yy
TENSORS = ("effective_stress", "total_stress", "strain")
COMPONENTS = {c: 3 * "xyz".index(c[0]) + "xyz".index(c[1])
              for c in ("xx", "yy", "zz", "xy", "yz", "xz", "yx", "zy", "zx")}


def field_choices(point_arrays, cell_arrays):
    """What --field accepts for this output: point scalars, cell scalars and tensor components."""
    names = sorted(a for a in point_arrays if a in ("pressure", "excess_pressure", "steady_pressure"))
    names += ["displacement_magnitude"]
    names += sorted(a for a in cell_arrays if a in ("equivalent_plastic_strain", "yield_state", "region"))
    names += [f"{t}_{c}" for t in TENSORS if t in cell_arrays for c in ("xx", "yy", "zz", "xy", "yz", "xz")]
    return names


def cell_field(field, cell_arrays):
    """(array, component or None) when field is a cell field of this output, else None."""
    if field in cell_arrays and field not in TENSORS:
        return field, None
    for t in TENSORS:
        if field.startswith(t + "_") and field[len(t) + 1:] in COMPONENTS and t in cell_arrays:
            return t, COMPONENTS[field[len(t) + 1:]]
    return None


class ViewError(Exception):
    """A message for the user: the output directory lacks what the picture needs."""


def read_run_record(out_dir):
    """(axisymmetric, scene name) from run.yaml when present (the last segment's options)."""
    path = os.path.join(out_dir, "run.yaml")
    axisymmetric, scene = None, None
    if not os.path.isfile(path):
        return axisymmetric, scene
    try:
        import yaml

        with open(path) as f:
            record = yaml.safe_load(f) or {}
        segment = (record.get("segments") or [{}])[-1]
        options = segment.get("options") or {}
        if "-axisymmetric" in options:
            value = options["-axisymmetric"]
            axisymmetric = value is None or str(value).lower() in ("1", "true", "yes", "on")
        else:
            axisymmetric = False
        if segment.get("scene_file"):
            scene = os.path.splitext(os.path.basename(segment["scene_file"]))[0]
    except Exception:  # a damaged record: the caller's flags decide
        pass
    return axisymmetric, scene


def interface_file(out_dir):
    """(path, combined): the interface cell grid's XDMF file, combined=True when the file
    also holds the integration points (the single interfaces.xmf of older outputs)."""
    split = os.path.join(out_dir, "interface_cells.xmf")
    if os.path.isfile(split):
        return split, False
    combined = os.path.join(out_dir, "interfaces.xmf")
    if os.path.isfile(combined):
        return combined, True
    return None, False


def nice_floor(x):
    """The largest 1, 2 or 5 x 10^k not above x (x > 0)."""
    k = math.floor(math.log10(x))
    for m in (5, 2, 1):
        if m * 10**k <= x:
            return m * 10**k
    return 10**k


def fetch_arrays(source, names, time, cells=False):
    """numpy arrays of the named point (or cell) arrays of a source at a time, all blocks
    concatenated (the data of this small pipeline fits on the client)."""
    import numpy as np
    from vtkmodules.numpy_interface import dataset_adapter as dsa

    source.UpdatePipeline(time)
    data = dsa.WrapDataObject(servermanager.Fetch(source))
    out = {}
    for name in names:
        array = (data.CellData if cells else data.PointData)[name]
        if isinstance(array, dsa.VTKNoneArray):
            out[name] = None
            continue
        if isinstance(array, dsa.VTKCompositeDataArray):
            parts = [np.asarray(a) for a in array.Arrays if not isinstance(a, dsa.VTKNoneArray)]
            out[name] = np.concatenate(parts) if parts else None
        else:
            out[name] = np.asarray(array)
    return out


def bounds(source, time):
    source.UpdatePipeline(time)
    return source.GetDataInformation().GetBounds()


class Pipeline:
    """Builds the sources and their displays in a render view; attributes: view, time,
    scale, field, label, dim, axisymmetric, notes (lines for the caption)."""

    def __init__(self, out_dir, view=None, time=None, scale=None, reflect=None, slice_at=None,
                 field=None, line_width=5.0, title=None):
        self.out_dir = os.path.abspath(out_dir)
        fields_xmf = os.path.join(self.out_dir, "fields.xmf")
        if not os.path.isfile(fields_xmf):
            raise ViewError(f"{fields_xmf}: no such file (not a poroseam output directory, "
                            "or a run with -output_fields_every 0)")
        axisymmetric, scene = read_run_record(self.out_dir)
        self.scene = scene or os.path.basename(self.out_dir.rstrip("/"))
        self.axisymmetric = bool(axisymmetric)
        self.notes = []

        bulk = Xdmf3ReaderS(registrationName="fields.xmf", FileName=[fields_xmf])
        bulk.UpdatePipelineInformation()
        times = list(bulk.TimestepValues) if bulk.TimestepValues else [0.0]
        if time is None:
            self.time = times[-1]
        else:
            self.time = min(times, key=lambda t: abs(t - time))
        b = bounds(bulk, self.time)
        self.dim = 3 if b[5] - b[4] > 0 else 2
        # Reflect about the picture's horizontal coordinate = 0 (the axis x = r = 0 of an
        # axisymmetric run, the symmetry plane x = 0 of a quarter model cut along y = 0),
        # by default only for axisymmetric runs.
        self.reflect = self.axisymmetric if reflect is None else reflect
        point_arrays = set(bulk.PointData.keys())

        # ---- the bulk: [slice], warp, [reflect]
        section = bulk
        if self.dim == 3:
            axis, value = slice_at if slice_at else ("y", 0.5 * (b[2] + b[3]))
            normal = {"x": [1, 0, 0], "y": [0, 1, 0], "z": [0, 0, 1]}[axis]
            origin = [0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])]
            origin["xyz".index(axis)] = value
            section = Slice(registrationName="section", Input=bulk)
            section.SliceType = "Plane"
            section.SliceType.Origin = origin
            section.SliceType.Normal = normal
            self.slice = (normal, origin)
            self.slice_axis = "xyz".index(axis)
            self.notes.append(f"section {axis} = {value:g} m")
        else:
            self.slice, self.slice_axis = None, None

        # the field shown
        cell_arrays = set(bulk.CellData.keys())
        if field is None:
            field = next((f for f in ("excess_pressure", "pressure") if f in point_arrays), None)
        if field == "displacement_magnitude":
            field = None
        choices = field_choices(point_arrays, cell_arrays)
        cell = cell_field(field, cell_arrays) if field is not None else None
        if field is not None and cell is None and field not in point_arrays:
            raise ViewError(f"--field {field}: not in {fields_xmf}; expected one of "
                            f"{', '.join(choices)}")
        if "displacement" not in point_arrays:
            raise ViewError(f"{fields_xmf}: no displacement array")
        values = fetch_arrays(section, ["displacement"] + ([field] if field and cell is None else []),
                              self.time)
        import numpy as np

        if field is not None and cell is None and values[field] is not None and np.ndim(values[field]) != 1:
            raise ViewError(f"--field {field}: a vector or tensor; expected one of {', '.join(choices)}")

        u = values["displacement"]
        umax = float(np.nanmax(np.linalg.norm(u, axis=1))) if u is not None and len(u) else 0.0
        sb = bounds(section, self.time)
        size = max(sb[1] - sb[0], sb[3] - sb[2], sb[5] - sb[4])
        self.view_box = view
        if view is not None:  # the region shown sets the scale of what must be visible
            size = max(view[1] - view[0], view[3] - view[2])
        self.umax = umax
        if scale is None:
            # the largest displacement drawn as about 5 % of the picture
            scale = nice_floor(0.05 * size / umax) if umax > 0 else 1.0
        self.scale = scale

        warped = WarpByVector(registrationName="deformed", Input=section)
        warped.Vectors = ["POINTS", "displacement"]
        warped.ScaleFactor = scale
        shown = warped
        self.association = "POINTS"
        self.categories = None
        if cell is not None:
            self.association = "CELLS"
            array, component = cell
            if component is not None:
                # a component of a tensor, stresses in kPa (tension positive, docs/physics.md)
                stress = array.endswith("stress")
                self.array = field + ("_kPa" if stress else "")
                shown = PythonCalculator(registrationName=field, Input=warped)
                shown.ArrayAssociation = "Cell Data"
                shown.ArrayName = self.array
                # ParaView reads the [Nc, 9] dataset as 3 x 3 tensors: flatten them back
                shown.Expression = f"{array}.reshape(-1, 9)[:, {component}]" + (" / 1000" if stress else "")
                what = {"effective_stress": "effective stress", "total_stress": "total stress",
                        "strain": "strain"}[array]
                self.label = f"{what} {field[-2:]}" + (" [kPa]" if stress else " [-]")
                v = fetch_arrays(shown, [self.array], self.time, cells=True)[self.array]
                finite = v[np.isfinite(v)] if v is not None else []
                vmax = float(np.max(np.abs(finite))) if len(finite) else 0.0
                self.range = (-vmax, vmax) if vmax > 0 else (-1.0, 1.0)
                self.diverging = True
            else:
                self.array = array
                v = fetch_arrays(section, [array], self.time, cells=True)[array]
                finite = v[np.isfinite(v)] if v is not None else []
                if array == "yield_state":
                    self.label = "Mohr-Coulomb yield state"
                    self.categories = (YIELD_NAMES, YIELD_COLOURS)
                    self.range = (0.0, float(len(YIELD_NAMES) - 1))
                    yielded = int(np.sum(finite > 0)) if len(finite) else 0
                    self.notes.append(f"{yielded} of {len(finite)} cells yielding")
                elif array == "region":
                    self.label = "region"
                    self.range = (0.0, float(np.max(finite)) if len(finite) else 1.0)
                else:  # equivalent_plastic_strain: 0 in elastic cells and regions
                    self.label = "equivalent plastic strain [-]"
                    vmax = float(np.max(finite)) if len(finite) else 0.0
                    self.range = (0.0, vmax if vmax > 0 else 1.0)
                    self.notes.append(f"largest {vmax:.3g}")
                self.diverging = False
        elif field is not None:
            kpa = field.endswith("pressure")
            self.label = {"excess_pressure": "excess pore pressure", "pressure": "pore pressure",
                          "steady_pressure": "steady pore pressure"}.get(field, field)
            self.array = field
            if kpa:
                self.label += " [kPa]"
                self.array = field + "_kPa"
                # numpy keeps NaN (no pressure: the steel) quietly; the Calculator filter
                # would replace it by 0, or report every NaN with ReplaceInvalidResults off
                shown = PythonCalculator(registrationName="kPa", Input=warped)
                shown.ArrayName = self.array
                shown.Expression = f"{field} / 1000"
            else:
                self.label = field
            v = values[field]
            finite = v[np.isfinite(v)] if v is not None else []
            vmax = float(np.max(np.abs(finite))) / (1000.0 if kpa else 1.0) if len(finite) else 0.0
            self.range = (-vmax, vmax) if vmax > 0 else (-1.0, 1.0)
            self.diverging = True
        else:  # drained, or asked for: |u|
            shown = Calculator(registrationName="displacement magnitude", Input=warped)
            self.label = "displacement magnitude [mm]"
            self.array = "displacement_magnitude_mm"
            shown.ResultArrayName = self.array
            shown.Function = "mag(displacement)*1000"
            self.range = (0.0, umax * 1000 if umax > 0 else 1.0)
            self.diverging = False
        self.field = field
        if self.reflect:
            shown = Reflect(registrationName="reflected", Input=shown)
            shown.Plane = "XYZ"[self.plane_axes()[0]]
            shown.Center = 0.0
            shown.CopyInput = 1
            shown.FlipAllInputArrays = 1
        self.bulk_out = shown

        self.interface_out = self.interfaces(section, scale, size)
        self.line_width = line_width
        self.title = title

    def interfaces(self, section, scale, size):
        """The interface pipeline (None for a scene without interfaces): the cell grid,
        [sectioned], warped with its side-1 face, moved towards the camera, [reflected]."""
        path, combined = interface_file(self.out_dir)
        if path is None:
            return None
        ifc = Xdmf3ReaderS(registrationName=os.path.basename(path), FileName=[path])
        ifc.UpdatePipelineInformation()
        cells = ifc
        if combined:  # keep the cell grid, drop the integration points (Polyvertex)
            cells = ExtractCellsByType(registrationName="interface cells", Input=ifc)
            cells.CellTypes = ["Line", "Polyline", "Triangle", "Quadrilateral", "Polygon"]
        ib = bounds(cells, self.time)
        if ib[0] > ib[1]:  # an empty grid
            return None
        if self.slice is not None:
            cells = Slice(registrationName="interface section", Input=cells)
            cells.SliceType = "Plane"
            cells.SliceType.Origin = self.slice[1]
            cells.SliceType.Normal = self.slice[0]
        if "displacement_minus" in ifc.PointData.keys():
            moved, vectors = cells, "displacement_minus"
        else:
            # Older outputs have no displacement on the interface: take the bulk's at its
            # nodes (from either side of the interface: a picture, not a measurement).
            moved = ResampleWithDataset(registrationName="bulk displacement",
                                        SourceDataArrays=section, DestinationMesh=cells)
            moved.PassCellArrays = 1
            vectors = "displacement"
            self.notes.append("interfaces warped with the bulk displacement")
        warped = WarpByVector(registrationName="interface deformed", Input=moved)
        warped.Vectors = ["POINTS", vectors]
        warped.ScaleFactor = scale
        # in front of the bulk faces they lie on: 1e-3 of the picture towards the camera
        lifted = Transform(registrationName="interface in front", Input=warped)
        lifted.Transform = "Transform"
        lifted.Transform.Translate = [-1e-3 * size * c for c in self.camera_direction()]
        if not self.reflect:
            return lifted
        reflected = Reflect(registrationName="interface reflected", Input=lifted)
        reflected.Plane = "XYZ"[self.plane_axes()[0]]
        reflected.Center = 0.0
        reflected.CopyInput = 1
        return reflected

    def camera_direction(self):
        """The direction the camera looks in: 2D -z; a 3D section face on, oriented so that
        the picture's horizontal axis (plane_axes) increases to the right."""
        if self.slice is None:
            return (0.0, 0.0, -1.0)
        return {0: (-1.0, 0.0, 0.0), 1: (0.0, 1.0, 0.0), 2: (0.0, 0.0, -1.0)}[self.slice_axis]

    def plane_axes(self):
        """(horizontal, vertical) coordinate indices of the picture."""
        if self.slice is None:
            return 0, 1
        return {0: (1, 2), 1: (0, 2), 2: (0, 1)}[self.slice_axis]

    def caption(self):
        lines = [self.title or f"{self.scene}: {self.label.split(' [')[0]}, t = {self.time:g} s"]
        deform = (f"displacements x {self.scale:g} (largest {self.umax * 1e3:.3g} mm)"
                  if self.umax > 0 else "undeformed (no displacement)")
        extra = []
        if self.reflect:
            extra.append("reflected about the axis" if self.axisymmetric
                         else f"reflected about {'xyz'[self.plane_axes()[0]]} = 0")
        lines.append(", ".join([deform] + extra + self.notes))
        return "\n".join(lines)

    def show(self, view):
        """Displays, colours, legends and camera in a render view."""
        SetActiveView(view)
        font = max(8, round(14 * view.ViewSize[0] / 1200.0))  # 14 pt at 1200 pixels across
        view.ViewTime = self.time
        # the time saved in a state file and shown in the GUI (the animation scene follows
        # the time keeper; its UpdateAnimationUsingDataTimeSteps() blocks in the GUI)
        GetTimeKeeper().Time = self.time
        view.OrientationAxesVisibility = 0
        view.Background = [1.0, 1.0, 1.0]
        try:  # ParaView >= 5.10 uses a palette unless told otherwise
            view.UseColorPaletteForBackground = 0
        except AttributeError:
            pass
        d = Show(self.bulk_out, view)
        d.Ambient, d.Diffuse = 1.0, 0.0  # unshaded: the colours of the colour bar
        ColorBy(d, (self.association, self.array))
        lut = GetColorTransferFunction(self.array)
        lut.ApplyPreset("Cool to Warm" if self.diverging else "Viridis (matplotlib)", True)
        if self.categories is not None:
            names, colours = self.categories
            lut.InterpretValuesAsCategories = 1
            lut.Annotations = [x for i, n in enumerate(names) for x in (str(i), n)]
            lut.IndexedColors = [c for rgb in colours for c in rgb]
        lut.RescaleTransferFunction(*self.range)
        lut.AutomaticRescaleRangeMode = "Never"
        lut.NanColor = list(NAN_GREY)
        d.SetScalarBarVisibility(view, True)
        bar = GetScalarBar(lut, view)
        bar.Title = self.label
        bar.ComponentTitle = ""
        bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
        bar.TitleFontSize = bar.LabelFontSize = font
        bar.RangeLabelFormat = "%-#.3g"
        bar.WindowLocation = "Any Location"
        bar.Orientation = "Vertical"
        bar.Position = [0.89, 0.25]
        bar.ScalarBarLength = 0.5
        if self.interface_out is not None:
            di = Show(self.interface_out, view)
            ColorBy(di, ("CELLS", "state"))
            slut = GetColorTransferFunction("state")
            slut.InterpretValuesAsCategories = 1
            slut.Annotations = [x for i, n in enumerate(STATE_NAMES) for x in (str(i), n)]
            slut.IndexedColors = [c for rgb in STATE_COLOURS for c in rgb]
            di.LineWidth = self.line_width
            di.Ambient, di.Diffuse = 1.0, 0.0  # flat: the legend's colours, unshaded
            try:
                di.RenderLinesAsTubes = 1
            except AttributeError:
                pass
            di.SetScalarBarVisibility(view, True)
            sbar = GetScalarBar(slut, view)
            sbar.Title = "interface"
            sbar.TitleColor = sbar.LabelColor = [0.0, 0.0, 0.0]
            sbar.TitleFontSize = sbar.LabelFontSize = font
            sbar.WindowLocation = "Any Location"
            sbar.TextPosition = "Ticks left/bottom, annotations right/top"
            sbar.Position = [0.03, 0.35]
            sbar.ScalarBarLength = 0.2
        text = Text(registrationName="caption")
        text.Text = self.caption()
        td = Show(text, view)
        td.WindowLocation = "Upper Center"
        td.Color = [0.0, 0.0, 0.0]
        td.FontSize = font
        td.Justification = "Center"
        self.place_camera(view)

    def place_camera(self, view):
        Render(view)  # the first render resets the camera: set it afterwards
        view.InteractionMode = "2D"
        view.CameraParallelProjection = 1
        cam = view.GetActiveCamera()
        look = self.camera_direction()
        h, v = self.plane_axes()
        up = [0.0, 0.0, 0.0]
        up[v] = 1.0
        if self.view_box is not None:
            x0, x1, y0, y1 = self.view_box
            centre = [0.0, 0.0, 0.0] if self.slice is None else list(self.slice[1])
            centre[h], centre[v] = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
            width, height = x1 - x0, y1 - y0
        else:
            self.bulk_out.UpdatePipeline(self.time)
            b = self.bulk_out.GetDataInformation().GetBounds()
            centre = [0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])]
            width, height = 1.1 * (b[2 * h + 1] - b[2 * h]), 1.1 * (b[2 * v + 1] - b[2 * v])
        distance = 10.0 * max(width, height, 1e-9)
        view.CameraFocalPoint = centre
        view.CameraPosition = [centre[i] - distance * look[i] for i in range(3)]
        view.CameraViewUp = list(up)
        size = view.ViewSize
        aspect = size[0] / float(size[1]) if size[1] else 1.0
        # the picture's middle 78 % across (legends either side), 85 % up (caption on top)
        view.CameraParallelScale = 0.5 * max(height / 0.85, width / (0.78 * aspect))
        cam.SetClippingRange(0.01 * distance, 100 * distance)


def new_view(width, height):
    view = CreateView("RenderView")
    view.ViewSize = [width, height]
    return view
