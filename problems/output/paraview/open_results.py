"""Open a beamrotor results directory in ParaView the way an analyst looks at it.

    pvpython problems/output/paraview/open_results.py out/pump_rod            # static, window
    pvpython problems/output/paraview/open_results.py out/cantilever --analysis modal --scale 0.05
    pvpython problems/output/paraview/open_results.py out/pump_rod --png bending.png   # headless

What it shows:
- the line elements as tubes of the true outer radius of a circular section (solid or hollow),
  from the cell data A and Iz the .vtu files carry: I = A (R^2 + r^2) / 4 and A = pi (R^2 - r^2)
  give R^2 = (4 Iz / A + A / pi) / 2 (for other shapes the radius of a circle of the same A and
  Iz, an approximation);
- deformed by the displacement (static, transient) or the mode shape (modal) times --scale
  (default: a tenth of the model's size over the largest displacement, so the deformation shows
  whatever the units);
- coloured by the largest normal stress (`stress`, Pa) of each element, or by the displacement
  magnitude for modes;
- a modal or transient analysis (a .pvd collection) animated: its modes (or time steps) are
  ParaView's time steps, and `--frames N` writes N pictures of one mode swinging
  (scale x sin(2 pi k / N)) next to --png.

It only reads the files beamrotor writes (README: results directory) and changes nothing.
Written for ParaView 5.10 or later (paraview.simple). Not run by beamrotor's tests: Debian's
paraview package cannot be installed beside libvtk9-dev (see README).
"""
import argparse
import math
import pathlib
import sys

from paraview.simple import (Calculator, CellDatatoPointData, ColorBy, GetActiveViewOrCreate,
                             GetAnimationScene, OpenDataFile, Render, ResetCamera,
                             SaveScreenshot, Show, Tube, UpdatePipeline, WarpByVector, Interact)


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", type=pathlib.Path, help="a results directory (solve --out)")
    parser.add_argument("--analysis", help="analysis name (default: the first with a .vtu)")
    parser.add_argument("--scale", type=float, help="deformation scale factor")
    parser.add_argument("--mode", type=int, default=1, help="mode to show (modal, from 1)")
    parser.add_argument("--png", type=pathlib.Path, help="save a picture instead of a window")
    parser.add_argument("--frames", type=int, default=0, help="pictures of the mode swinging")
    return parser.parse_args()


def data_file(results, analysis):
    """The .pvd collection of an analysis (modes, time frames, sweep values), else its .vtu."""
    for pattern in ([f"{analysis}.pvd", f"{analysis}.vtu"] if analysis else ["*.pvd", "*.vtu"]):
        found = sorted(results.glob(pattern))
        if found:
            return found[0]
    sys.exit(f"open_results.py: no .pvd or .vtu for {analysis or 'any analysis'} in {results}")


def vector_name(source):
    names = source.PointData.keys()
    for name in ("displacement", "mode_shape"):
        if name in names:
            return name
    sys.exit("open_results.py: the file has neither displacement nor mode_shape point data")


def default_scale(source, vectors):
    """A tenth of the model's size over the largest displacement (1 when nothing moves)."""
    bounds = source.GetDataInformation().GetBounds()
    size = math.dist(bounds[0::2], bounds[1::2])
    largest = max(abs(v) for v in source.PointData[vectors].GetRange(-1))
    return 0.1 * size / largest if largest > 0 else 1.0


def main():
    args = arguments()
    source = OpenDataFile(str(data_file(args.results, args.analysis)))
    UpdatePipeline(proxy=source)
    vectors = vector_name(source)
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    if vectors == "mode_shape":
        times = source.TimestepValues or [0]
        scene.AnimationTime = times[min(max(args.mode, 1), len(times)) - 1]

    # Section properties are cell data; the tube radius must be point data.
    points = CellDatatoPointData(Input=source)
    points.PassCellData = 1
    radius = Calculator(Input=points, ResultArrayName="outer_radius",
                        Function="sqrt((4*Iz/A + A/3.141592653589793)/2)")
    scale = args.scale if args.scale is not None else default_scale(source, vectors)
    warp = WarpByVector(Input=radius, Vectors=["POINTS", vectors], ScaleFactor=scale)
    tube = Tube(Input=warp, Scalars=["POINTS", "outer_radius"], VaryRadius="By Absolute Scalar",
                NumberofSides=24, Capping=1)

    view = GetActiveViewOrCreate("RenderView")
    display = Show(tube, view)
    if "stress" in source.CellData.keys():
        ColorBy(display, ("CELLS", "stress"))
    else:
        ColorBy(display, ("POINTS", vectors, "Magnitude"))
    display.SetScalarBarVisibility(view, True)
    display.RescaleTransferFunctionToDataRange(True, False)
    ResetCamera(view)
    Render(view)

    if args.png and args.frames > 0:
        for k in range(args.frames):
            warp.ScaleFactor = scale * math.sin(2 * math.pi * k / args.frames)
            SaveScreenshot(str(args.png.with_name(f"{args.png.stem}_{k:03d}.png")), view,
                           ImageResolution=[1200, 700])
    elif args.png:
        SaveScreenshot(str(args.png), view, ImageResolution=[1200, 700])
    else:
        Interact(view)


if __name__ == "__main__":
    main()
