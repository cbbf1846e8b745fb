# Renders one frame of a `rockfall simulate --vtk DIR` series to a PNG, for a look without the
# ParaView window. Optional (not in CI, not in scripts/install-deps.sh): needs ParaView from
# Debian (`apt-get install paraview`, which ships `pvbatch`; without a display run it under
# `xvfb-run -a`, from the `xvfb` package).
#
# Usage: pvbatch scripts/render-vtk.py DIR OUT.png [TIME_S|last] [scene|rocks] [WIDTH HEIGHT]
#   DIR     the --vtk directory (rocks.pvd, static.vtp)
#   TIME_S  simulated time of the frame, s (the frame at or before it); default 0, `last` for
#           the last frame
#   scene   the camera frames the whole static geometry from above its side (default); `rocks`
#           frames the rocks, nearly level from the side
#   WIDTH HEIGHT  of the PNG in pixels (default 1600 900)
# The rocks are coloured by speed (m/s), the static geometry grey and translucent with the
# lining darker; the camera looks from the slope's side (-y), z up.
# Without a display: xvfb-run -a -s "-screen 0 1920x1080x24" pvbatch scripts/render-vtk.py ...
import os
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetAnimationScene,
                             GetColorTransferFunction, GetScalarBar,
                             PVDReader, Render, SaveScreenshot, Show, Threshold,
                             XMLPolyDataReader)


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__ or "usage: pvbatch scripts/render-vtk.py DIR OUT.png [TIME_S|last]")
    directory, out = argv[1], argv[2]
    when = argv[3] if len(argv) > 3 else "0"
    focus = argv[4] if len(argv) > 4 else "scene"
    if focus not in ("scene", "rocks"):
        sys.exit("render-vtk.py: the fourth argument is scene or rocks, not '%s'" % focus)
    size = [int(argv[5]), int(argv[6])] if len(argv) > 6 else [1600, 900]

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = size
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 1

    scene = XMLPolyDataReader(FileName=[os.path.join(directory, "static.vtp")])
    # Solids (slabs, bars, walls) light grey and translucent, the lining darker; framing the
    # rocks, the side walls are left out (they stand between the camera and the rocks).
    def part(low, high, colour, opacity):
        shown = Show(Threshold(Input=scene, Scalars=["CELLS", "part"], LowerThreshold=low,
                               UpperThreshold=high), view)
        shown.ColorArrayName = ["CELLS", ""]
        shown.DiffuseColor = colour
        shown.Opacity = opacity

    part(0, 1, [0.8, 0.8, 0.8], 0.35)
    if focus == "scene":
        part(2, 2, [0.8, 0.8, 0.8], 0.35)
    part(3, 3, [0.7, 0.6, 0.5], 0.5)
    part(4, 7, [0.45, 0.45, 0.5], 1.0)

    rocks = PVDReader(FileName=os.path.join(directory, "rocks.pvd"))
    rocks.UpdatePipelineInformation()
    times = list(rocks.TimestepValues) if hasattr(rocks.TimestepValues, "__len__") else [
        rocks.TimestepValues]
    if when == "last":
        t = times[-1]
    else:
        wanted = float(when)
        t = max([x for x in times if x <= wanted + 1e-9] or [times[0]])
    scene_time = GetAnimationScene()
    scene_time.UpdateAnimationUsingDataTimeSteps()
    scene_time.AnimationTime = t
    view.ViewTime = t

    rocks_display = Show(rocks, view)
    ColorBy(rocks_display, ("CELLS", "speed_m_s"))
    lut = GetColorTransferFunction("speed_m_s")
    lut.ApplyPreset("Turbo", True)
    lut.RescaleTransferFunction(0.0, 5.0)
    bar = GetScalarBar(lut, view)
    bar.Title = "speed (m/s)"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    rocks_display.SetScalarBarVisibility(view, True)

    # The first render resets the camera (paraview.simple); place it after that.
    Render(view)
    # From the side of the slope (-y), above it, looking at its middle; z up.
    framed = scene if focus == "scene" else rocks
    framed.UpdatePipeline(t)
    b = framed.GetDataInformation().GetBounds()
    centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
    extent = max(b[1] - b[0], b[3] - b[2], b[5] - b[4])
    if focus == "rocks":
        extent = max(1.5 * extent, 1.0)
    view.CameraFocalPoint = centre
    # Framing the rocks: nearly level from the side, to see where they touch the surface.
    lift, side = (0.7, 1.1) if focus == "scene" else (0.12, 1.5)
    view.CameraPosition = [centre[0] + 0.35 * extent, centre[1] - side * extent,
                           centre[2] + lift * extent]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    Render(view)
    SaveScreenshot(out, view, ImageResolution=size)
    print("frame at t = %.3f s of %d written to %s" % (t, len(times), out))


main(sys.argv)
