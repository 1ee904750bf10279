"""A run in ParaView: the state file that opens it ready to look at, and 3-D pictures of it.

    pvpython paraview_view.py state RUN_DIR [--out FILE]
        writes RUN_DIR/kessler.pvsm (File > Load State in ParaView)
    pvbatch paraview_view.py render RUN_DIR [--time T ...] [--every N] [--color FIELD] [--size W H] [--out DIR]
        draws the material points at the chosen output times (default: the last) as PNG files

Both build the same pipeline: the points of points.xdmf (ParaView's Xdmf3 reader), mirrored in the
deck's symmetry planes so that a quarter model shows whole, drawn as small spheres coloured by body
(each body its own colour, named in the legend) or by a field (temperature, pressure, ...), with
the simulated time written in the corner, seen obliquely from the side the projectile came from.
`kessler render` calls `render` (under xvfb-run when there is no display); `kessler run` writes
the state at its end (docs/python.md, docs/running.md).
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kessler_plots  # noqa: E402  (summary, symmetry planes and outputs of a run folder)

from paraview.simple import (AnnotateTime, ColorBy, CreateView, GetAnimationScene, GetColorTransferFunction,  # noqa: E402
                             GetScalarBar, GetTimeKeeper, Hide, Reflect, Render, SaveScreenshot, SaveState, SetActiveSource, Show,
                             Xdmf3ReaderS)


def pipeline(run, color):
    """The reader, the mirrored points and a render view showing them; returns (view, source, display)."""
    reader = Xdmf3ReaderS(registrationName="points.xdmf", FileName=[os.path.join(os.path.abspath(run), "points.xdmf")])
    reader.UpdatePipelineInformation()
    source = reader
    for axis in kessler_plots.symmetry_axes(run):
        plane = "XYZ"[axis]
        source = Reflect(registrationName=f"mirror in {plane.lower()} = 0", Input=source)
        source.Plane = plane
        source.CopyInput = 1
    view = CreateView("RenderView")
    view.OrientationAxesVisibility = 1
    view.Background = [1.0, 1.0, 1.0]
    try:  # ParaView >= 5.10 takes the background from its palette unless told otherwise
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    display = Show(source, view)
    display.SetRepresentationType("Points")
    display.PointSize = 3.0
    display.RenderPointsAsSpheres = 1
    ColorBy(display, ("POINTS", color))
    lut = GetColorTransferFunction(color)
    if color == "body":
        names = kessler_plots.body_names(kessler_plots.load_summary(run))
        lut.InterpretValuesAsCategories = 1
        annotations, colours = [], []
        palette = [(0.84, 0.15, 0.16), (0.12, 0.47, 0.71), (0.17, 0.63, 0.17), (1.0, 0.5, 0.05), (0.58, 0.4, 0.74),
                   (0.55, 0.34, 0.29)]
        for b, name in enumerate(names or ["body 0"]):
            annotations += [str(b), name]
            colours += list(palette[b % len(palette)])
        lut.Annotations = annotations
        lut.IndexedColors = colours
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    clock = AnnotateTime(registrationName="time")
    clock.Format = "t = {time:.3g} s"
    clock_display = Show(clock, view)
    clock_display.Color = [0.1, 0.1, 0.1]
    clock_display.WindowLocation = "Upper Left Corner"
    SetActiveSource(source)
    return view, source, display


def aim(view, source, display, color, time):
    """An oblique view of everything there is at `time` (the last output frames the whole cloud), and
    a field's colour range from there too, the same for every picture."""
    source.UpdatePipeline(time)
    if color != "body":
        display.RescaleTransferFunctionToDataRange(False, True)
    xmin, xmax, ymin, ymax, zmin, zmax = source.GetDataInformation().GetBounds()
    centre = [(xmin + xmax) / 2, (ymin + ymax) / 2, (zmin + zmax) / 2]
    radius = max(0.5 * math.dist((xmin, ymin, zmin), (xmax, ymax, zmax)), 1e-9)
    # Far enough that the sphere around everything fits the 30 degree view angle, with a margin for
    # the legend and the clock; no render is needed (pvpython writes the state without a display).
    direction = [0.55, -0.69, 0.38]
    distance = 1.1 * radius / math.sin(math.radians(15.0))
    view.CameraFocalPoint = centre
    view.CameraPosition = [c + distance * d / math.hypot(*direction) for c, d in zip(centre, direction)]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    view.ViewTime = time


def state(args):
    times = list(args.reader_times)
    view, source, display = pipeline(args.run, "body")
    aim(view, source, display, "body", times[-1])
    # The state opens at the last output, with the time slider on it. Setting the animation scene's
    # time would render (which needs a display): the property is written without being applied.
    GetTimeKeeper().Time = times[-1]
    GetAnimationScene().SMProxy.GetProperty("AnimationTime").SetElement(0, times[-1])
    out = args.out or os.path.join(args.run, "kessler.pvsm")
    SaveState(out)
    print(f"paraview_view.py: wrote {out}")


def render(args):
    times = list(args.reader_times)
    chosen = []
    if args.time:
        for wanted in args.time:  # the output nearest to each time asked for
            chosen.append(min(times, key=lambda t: abs(t - wanted)))
    elif args.every:
        chosen = times[::args.every] + ([times[-1]] if (len(times) - 1) % args.every else [])
    else:
        chosen = [times[-1]]
    view, source, display = pipeline(args.run, args.color)
    view.ViewSize = args.size
    aim(view, source, display, args.color, times[-1])
    out = args.out or os.path.join(args.run, "pictures")
    os.makedirs(out, exist_ok=True)
    steps = {t: step for t, step, _ in kessler_plots.point_outputs(args.run)}
    for t in sorted(set(chosen)):
        view.ViewTime = t
        source.UpdatePipeline(t)
        Render(view)
        step = steps.get(t)
        name = os.path.join(out, f"{args.color}_{step:08d}.png" if step is not None else f"{args.color}_{t:.6g}.png")
        SaveScreenshot(name, view, ImageResolution=args.size)
        print(f"paraview_view.py: wrote {name}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument("mode", choices=["state", "render"])
    parser.add_argument("run", help="the run folder")
    parser.add_argument("--out", help="state: the .pvsm file; render: the folder (default RUN/pictures)")
    parser.add_argument("--time", type=float, nargs="+", help="render: output times (s); the nearest output is drawn")
    parser.add_argument("--every", type=int, help="render: every Nth output (and the last)")
    parser.add_argument("--color", default="body", help="render: body or a point field (temperature, pressure, ...)")
    parser.add_argument("--size", type=int, nargs=2, default=[1280, 960], metavar=("W", "H"))
    args = parser.parse_args()
    points = os.path.join(args.run, "points.xdmf")
    if not os.path.exists(points):
        kessler_plots.fail(f"{points} not found: not a run folder with outputs")
    probe = Xdmf3ReaderS(FileName=[os.path.abspath(points)])
    probe.UpdatePipelineInformation()
    args.reader_times = list(probe.TimestepValues) or [0.0]
    probe.UpdatePipeline(args.reader_times[-1])
    fields = probe.PointData.keys()
    Hide(probe)
    if args.color not in fields:
        kessler_plots.fail(f"--color {args.color}: not a point field of this run (fields: {', '.join(fields)})")
    state(args) if args.mode == "state" else render(args)


if __name__ == "__main__":
    main()
