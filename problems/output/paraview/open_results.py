"""Open a beamrotor results directory in ParaView the way an analyst looks at it.

    pvpython problems/output/paraview/open_results.py out/portal_frame               # a window
    pvpython problems/output/paraview/open_results.py out/cantilever --analysis modal --mode 2
    pvpython --force-offscreen-rendering problems/output/paraview/open_results.py \\
        out/portal_frame --scale 100 --png portal.png                              # a picture
    pvpython problems/output/paraview/open_results.py out/cantilever --analysis modal \\
        --state cantilever.pvsm                       # then in ParaView: File > Load State

What it shows:
- the line elements as tubes at the section's true size: each element's radius is the larger
  of its outer fibre distances `outer_y`, `outer_z` (cell data of the .vtu files, m), so a
  100 mm tube is drawn 100 mm across, a stepped shaft keeps its steps and an I-beam is a round
  tube as deep as the beam; older files without them get the radius of a circular section of
  their A and Iz (R^2 = (4 Iz / A + A / pi) / 2); a model without line elements (a rigid body
  on springs) is drawn as balls at its points;
- deformed by the displacement (static, transient) or the mode shape (modal; for rotors the
  real part of the complex shape) times --scale (default: a tenth of the model's size over the
  largest displacement, rounded to 1, 2 or 5 times a power of ten); the factor is written on
  the picture; a time series is shown at the moment of its largest displacement;
- coloured by each element's largest normal stress in MPa (static), by the displacement
  magnitude in mm (transient) or by the mode shape's magnitude (modal, normalised), with a
  colour legend naming the quantity and its unit;
- a modal or transient analysis (a .pvd collection) animated: its modes or time frames are
  ParaView's time steps (the Play button, after loading a --state file in ParaView); with --png,
  --frames N writes N pictures: a mode swinging (scale x sin(2 pi k / N)) or N moments of a
  time series.

It only reads the files beamrotor writes (README: results directory) and changes nothing.
Written for and run with ParaView 5.11 (Debian 12's paraview and python3-paraview).
"""
import argparse
import math
import pathlib
import sys

from paraview.simple import (Calculator, CellDatatoPointData, ColorBy, ExtractSurface,
                             GetActiveViewOrCreate,
                             GetAnimationScene, GetColorTransferFunction, GetScalarBar,
                             GetTimeKeeper, Interact, OpenDataFile, Render, ResetCamera,
                             SaveScreenshot, SaveState, Show, Shrink, Text, Tube,
                             UpdatePipeline, WarpByVector)


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", type=pathlib.Path, help="a results directory (solve --out)")
    parser.add_argument("--analysis", help="analysis name (default: the first with a .vtu)")
    parser.add_argument("--scale", type=float, help="deformation scale factor")
    parser.add_argument("--mode", type=int, default=1, help="mode to show (modal, from 1)")
    parser.add_argument("--png", type=pathlib.Path, help="save a picture instead of a window")
    parser.add_argument("--size", type=int, nargs=2, default=[1200, 700], metavar=("W", "H"),
                        help="picture size in pixels (default 1200 700)")
    parser.add_argument("--frames", type=int, default=0,
                        help="with --png: pictures of the mode swinging or the time series")
    parser.add_argument("--state", type=pathlib.Path,
                        help="also save a ParaView state file (File > Load State in ParaView)")
    return parser.parse_args()


def data_file(results, analysis):
    """The .pvd collection of an analysis (modes, time frames), else its .vtu."""
    if not results.is_dir():
        sys.exit(f"open_results.py: {results} is not a directory")
    patterns = [f"{analysis}.pvd", f"{analysis}.vtu"] if analysis else ["*.pvd", "*.vtu"]
    for pattern in patterns:
        found = sorted(p for p in results.glob(pattern) if "_orbits_" not in p.name)
        if found:
            return found[0]
    sys.exit(f"open_results.py: no .pvd or .vtu for {analysis or 'any analysis'} in {results}")


def vector_name(source):
    names = source.PointData.keys()
    for name in ("displacement", "mode_shape", "shape_real"):
        if name in names:
            return name
    sys.exit("open_results.py: the file has no displacement or mode shape point data")


def round_scale(value):
    """1, 2 or 5 times a power of ten, at most value: a factor a reader can quote."""
    if value <= 0 or not math.isfinite(value):
        return 1.0
    power = 10.0 ** math.floor(math.log10(value))
    return max(m * power for m in (1, 2, 5) if m * power <= value * (1 + 1e-12))


def model_size(source):
    bounds = source.GetDataInformation().GetBounds()
    return math.dist(bounds[0::2], bounds[1::2]), bounds


def peak(source, vectors, times):
    """The largest displacement (or mode shape) magnitude over all time steps, and its time."""
    largest, when = 0.0, None
    for t in times or [None]:
        if t is not None:
            source.UpdatePipeline(t)
        value = source.PointData[vectors].GetRange(-1)[1]
        if value > largest:
            largest, when = value, t
    return largest, when


def place_camera(view, bounds):
    """Global y is up in beamrotor's decks: a planar model is seen square on, a 3D one from
    above at an angle."""
    extent = [bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]]
    size = max(extent) or 1.0
    centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
              (bounds[4] + bounds[5]) / 2]
    if extent[2] <= 1e-6 * size:
        direction = (0.0, 0.0, 1.0)          # in the x-y plane: look along z
    elif extent[1] <= 1e-6 * size and extent[0] <= 1e-6 * size:
        direction = (1.0, 0.0, 0.0)
    else:
        direction = (0.9, 0.8, 1.6)           # 3D: from the front right, above
    view.CameraFocalPoint = centre
    view.CameraPosition = [c + 3 * size * d for c, d in zip(centre, direction)]
    view.CameraViewUp = [0.0, 1.0, 0.0] if direction != (0.0, 1.0, 0.0) else [0.0, 0.0, -1.0]
    view.CameraParallelProjection = 1
    ResetCamera(view)
    view.CameraParallelScale *= 0.8  # ParaView leaves a wide margin around the model


def label(view, text, corner):
    """A text in a corner of the view (ParaView 5.11 spells corners with spaces)."""
    source = Text(Text=text)
    display = Show(source, view)
    for name in (corner, corner.replace(" ", "")):
        try:
            display.WindowLocation = name
            break
        except ValueError:
            continue
    display.FontSize = 14
    display.Color = [0.1, 0.1, 0.1]
    return source


def colour(display, view, array, title):
    """Colour by a cell or point array with a legend whose title names quantity and unit."""
    association, name = array[0], array[1]
    ColorBy(display, array)
    lut = GetColorTransferFunction(name)
    try:
        lut.ApplyPreset("Rainbow Uniform", True)
    except Exception:  # an older preset list: ParaView's default map still shows the values
        pass
    display.RescaleTransferFunctionToDataRange(False, True)
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    bar.TitleFontSize, bar.LabelFontSize = 16, 14
    bar.RangeLabelFormat = "%-#6.3g"
    bar.ScalarBarLength = 0.6
    return lut


def main():
    args = arguments()
    path = data_file(args.results, args.analysis)
    analysis = path.stem
    source = OpenDataFile(str(path))
    UpdatePipeline(proxy=source)
    vectors = vector_name(source)
    modal = vectors != "displacement"
    times = list(source.TimestepValues) if path.suffix == ".pvd" else []
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    largest, largest_at = peak(source, vectors, times)
    if modal and times:
        mode = min(max(args.mode, 1), len(times))
        scene.AnimationTime = times[mode - 1]
    elif times:  # a time series: the picture shows the moment of the largest displacement
        scene.AnimationTime = largest_at if largest_at is not None else times[-1]
    size, _ = model_size(source)
    if args.scale is not None:
        scale = args.scale
    else:  # a tenth of the model's size over the largest displacement
        scale = round_scale(0.1 * size / largest) if largest > 0 else 1.0
    if times:
        source.UpdatePipeline(scene.AnimationTime)

    # The radius, element by element: Shrink with factor 1 gives every element its own end
    # points, so a point array taken from the cell data is that element's alone and a stepped
    # shaft keeps its steps. The radius is the larger outer fibre distance (outer_y, outer_z);
    # files without them get a circle of the element's A and Iz.
    lines = "A" in source.CellData.keys()  # files of models without line elements lack it
    radius_input, radius_name = source, "tube_radius"
    if lines:
        separate = Shrink(Input=source, ShrinkFactor=1.0)
        points = CellDatatoPointData(Input=separate)
        points.PassCellData = 1
        if "outer_y" in source.CellData.keys():
            formula = "(outer_y + outer_z + abs(outer_y - outer_z)) / 2"
        else:
            formula = "sqrt((4*Iz/A + A/3.141592653589793)/2)"
        radius_input = Calculator(Input=points, ResultArrayName=radius_name, Function=formula)
    warp = WarpByVector(Input=radius_input, Vectors=["POINTS", vectors], ScaleFactor=scale)
    if "stress" in source.CellData.keys():
        coloured = Calculator(Input=warp, AttributeType="Cell Data", Function="stress/1e6",
                              ResultArrayName="stress_MPa")
        array, title = ("CELLS", "stress_MPa"), "largest normal stress (MPa)"
    elif modal:
        coloured = Calculator(Input=warp, Function=f"mag({vectors})",
                              ResultArrayName="shape_magnitude")
        array, title = ("POINTS", "shape_magnitude"), "mode shape magnitude (normalised, -)"
    else:
        coloured = Calculator(Input=warp, Function=f"1000*mag({vectors})",
                              ResultArrayName="displacement_mm")
        array, title = ("POINTS", "displacement_mm"), "displacement magnitude (mm)"
    surface = ExtractSurface(Input=coloured)  # Tube takes polygonal data
    tube = Tube(Input=surface, Scalars=["POINTS", radius_name], VaryRadius="By Absolute Scalar",
                NumberofSides=24, Capping=1)

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = list(args.size)
    view.Background = [1.0, 1.0, 1.0]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.OrientationAxesVisibility = 1
    undeformed = Show(ExtractSurface(Input=source), view)
    undeformed.SetRepresentationType("Wireframe")
    undeformed.AmbientColor = undeformed.DiffuseColor = [0.45, 0.45, 0.45]
    undeformed.LineWidth = 1.5
    if lines:
        display = Show(tube, view)
        display.Specular = 0.3
    else:  # a rigid body or masses on springs: points, drawn as balls
        display = Show(coloured, view)
        display.SetRepresentationType("Points")
        display.RenderPointsAsSpheres = 1
        display.PointSize = 24
    colour(display, view, array, title)
    if times and not modal:  # one colour scale for the whole time series
        try:
            display.RescaleTransferFunctionToDataRangeOverTime()
        except AttributeError:
            pass

    what = {False: "deformed", True: "mode shape"}[modal]
    heading = f"{args.results.name}: {analysis}, {what} x {scale:g} (undeformed: grey line)"
    caption = label(view, heading, "Upper Left Corner")
    detail = label(view, "", "Lower Left Corner")

    def describe():
        """The mode's frequency or the frame's time, from the file's field data."""
        source.UpdatePipeline(scene.AnimationTime)
        fields = source.FieldData
        if modal and "frequency_hz" in fields.keys():
            number = int(fields["mode"].GetRange()[0]) if "mode" in fields.keys() else 0
            text = f"mode {number}: {fields['frequency_hz'].GetRange()[0]:.4g} Hz"
            if "whirl" in fields.keys():
                text += " (shape: real part)"
            return text
        if "time" in fields.keys():
            still = ", no point moves (rotations only: see the CSV histories)" if largest == 0 else ""
            return f"t = {fields['time'].GetRange()[0]:.4g} s{still}"
        return "tube radius = outer fibre distance of each element's section (true size)"

    _, bounds = model_size(source)
    place_camera(view, bounds)
    detail.Text = describe()
    Render(view)

    if args.state:
        SaveState(str(args.state))
    if args.png and args.frames > 0:
        for k in range(args.frames):
            if modal or not times:
                factor = scale * math.sin(2 * math.pi * k / args.frames)
                warp.ScaleFactor = factor
                caption.Text = (f"{args.results.name}: {analysis}, {what} x {factor:.3g} "
                                f"(frame {k + 1} of {args.frames})")
            else:
                scene.AnimationTime = times[round(k * (len(times) - 1) / max(args.frames - 1, 1))]
            detail.Text = describe()
            Render(view)
            SaveScreenshot(str(args.png.with_name(f"{args.png.stem}_{k:03d}.png")), view,
                           ImageResolution=list(args.size))
    elif args.png:
        SaveScreenshot(str(args.png), view, ImageResolution=list(args.size))
    elif not args.state:
        Interact(view)


if __name__ == "__main__":
    main()
