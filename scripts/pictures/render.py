# Renders the views a user wants of the example runs to PNG, with ParaView's Python
# (pvbatch; scripts/render-pictures.sh installs it and runs this under a virtual X
# display). Usage: pvbatch render.py OUT_DIR PICTURE_DIR [VIEW ...]
#   rbc          the red-blood-cell run's cross-section (y = 0 plane): von Mises stress
#                and the director as line glyphs
#   spread_cell  the spread cell on its substrate, seen from above at an angle, the
#                substrate's top coloured by the in-plane displacement toward the cell
# Each view reads OUT_DIR/<view>/frames.pvd at its last time and writes
# PICTURE_DIR/<view>.png; a view whose run is missing is skipped with a message.
# After writing, each picture is checked not to be blank: at least 1,000 distinct
# colours (a uniform background has one).
import os
import sys

from paraview.simple import (ColorBy, CreateRenderView, GetColorTransferFunction, GetScalarBar, Glyph, PVDReader,
                             SaveScreenshot, Show, Slice, Threshold)
from vtkmodules.vtkIOImage import vtkPNGReader

WIDTH, HEIGHT = 1200, 800


def last_frame(pvd):
    reader = PVDReader(FileName=pvd)
    times = list(reader.TimestepValues)
    t = float(times[-1]) if times else 0.0
    reader.UpdatePipeline(t)
    return reader, t


def new_view(t):
    view = CreateRenderView()
    view.ViewSize = [WIDTH, HEIGHT]
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 1
    view.ViewTime = t
    return view


def colour(display, view, array, title):
    ColorBy(display, ('POINTS', array))
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(GetColorTransferFunction(array), view)
    bar.Title = title
    bar.ComponentTitle = ''
    bar.TitleColor = [0, 0, 0]
    bar.LabelColor = [0, 0, 0]


def rbc(pvd, png):
    reader, t = last_frame(pvd)
    view = new_view(t)
    cut = Slice(Input=reader)
    cut.SliceType = 'Plane'
    cut.SliceType.Origin = [0.0, 0.0, 0.0]
    cut.SliceType.Normal = [0.0, 1.0, 0.0]
    shown = Show(cut, view)
    colour(shown, view, 'von_mises', 'von Mises stress [Pa]')
    glyphs = Glyph(Input=cut, GlyphType='Line')
    glyphs.OrientationArray = ['POINTS', 'director']
    glyphs.ScaleArray = ['POINTS', 'No scale array']
    glyphs.ScaleFactor = 0.25e-6
    glyphs.GlyphMode = 'All Points'
    lines = Show(glyphs, view)
    lines.ColorArrayName = ['POINTS', '']
    lines.AmbientColor = lines.DiffuseColor = [0.0, 0.0, 0.0]
    view.CameraPosition = [0.0, -30e-6, 0.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera()
    view.CameraParallelProjection = 1
    SaveScreenshot(png, view, ImageResolution=[WIDTH, HEIGHT])


def spread_cell(pvd, png):
    reader, t = last_frame(pvd)
    view = new_view(t)
    substrate = Threshold(Input=reader)
    substrate.Scalars = ['POINTS', 'body_id']
    substrate.LowerThreshold = 0.5
    substrate.UpperThreshold = 1.5
    shown = Show(substrate, view)
    colour(shown, view, 'displacement', 'substrate displacement [m]')
    cell = Threshold(Input=reader)
    cell.Scalars = ['POINTS', 'body_id']
    cell.LowerThreshold = -0.5
    cell.UpperThreshold = 0.5
    cell_shown = Show(cell, view)
    cell_shown.ColorArrayName = ['POINTS', '']
    cell_shown.DiffuseColor = [0.85, 0.85, 0.85]
    cell_shown.Opacity = 0.35
    view.CameraPosition = [0.0, -30e-6, 25e-6]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera()
    SaveScreenshot(png, view, ImageResolution=[WIDTH, HEIGHT])


def distinct_colours(png):
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    components = scalars.GetNumberOfComponents()
    seen = set()
    for i in range(scalars.GetNumberOfTuples()):
        seen.add(tuple(int(scalars.GetComponent(i, c)) for c in range(min(components, 3))))
    return len(seen)


VIEWS = {'rbc': rbc, 'spread_cell': spread_cell}


def main(argv):
    if len(argv) < 3:
        print('usage: pvbatch render.py OUT_DIR PICTURE_DIR [VIEW ...]', file=sys.stderr)
        return 2
    out_dir, picture_dir = argv[1], argv[2]
    views = argv[3:] or list(VIEWS)
    os.makedirs(picture_dir, exist_ok=True)
    failed = 0
    for name in views:
        if name not in VIEWS:
            print('render.py: unknown view "%s" (expected one of %s)' % (name, ', '.join(VIEWS)), file=sys.stderr)
            return 2
        pvd = os.path.join(out_dir, name, 'frames.pvd')
        if not os.path.exists(pvd):
            print('render.py: %s: no run at %s, skipped' % (name, pvd))
            continue
        png = os.path.join(picture_dir, name + '.png')
        VIEWS[name](pvd, png)
        count = distinct_colours(png)
        verdict = 'ok' if count >= 1000 else 'BLANK'
        print('render.py: %s -> %s (%d distinct colours: %s)' % (name, png, count, verdict))
        failed += count < 1000
    return 1 if failed else 0


if __name__ == '__main__':
    code = main(sys.argv)
    # Leave without ParaView's teardown: under a virtual X display it ends with a GLX
    # error (after every picture is written and checked) that would mask the verdict.
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
