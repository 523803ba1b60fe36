# Renders the views a user wants of the example runs to PNG, with ParaView's Python
# (pvbatch; scripts/render-pictures.sh installs it and runs this under a virtual X
# display). Usage: pvbatch render.py OUT_DIR PICTURE_DIR [VIEW ...]
#   rbc          the red-blood-cell run's cross-section (y = 0 plane): von Mises stress
#                and the director as line glyphs
#   adhesion     the adhered cell seen from below, coloured by its height above the
#                substrate's top: the flat contact patch is the part near zero
#   crawling     the substrate seen from above, coloured by its stiffness factor
#                (seed Eq. 18), with the cell's centroid track from history.csv
#                (magnified 100 times: the drift is tens of nanometres)
#   spread_cell  the spread cell on its substrate, seen from above at an angle, the
#                substrate coloured by its displacement
# Each view reads OUT_DIR/<view>/frames.pvd at its last time and writes
# PICTURE_DIR/<view>.png; a view whose run is missing is skipped with a message.
# After writing, each picture is checked not to be blank: at least 1,000 distinct
# colours (a uniform background has one).
import os
import sys

import csv

from paraview.simple import (Calculator, ColorBy, CreateRenderView, GetColorTransferFunction, GetScalarBar, Glyph,
                             PolyLineSource, PVDReader, SaveScreenshot, Show, Slice, Text, Threshold)
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


def aim_and_save(view, png, position, focal_point, up, parallel=False, parallel_scale=None):
    view.CameraPosition = position
    view.CameraFocalPoint = focal_point
    view.CameraViewUp = up
    view.CameraParallelProjection = 1 if parallel else 0
    view.ResetCamera()
    if parallel_scale is not None:
        view.CameraParallelScale = parallel_scale
    SaveScreenshot(png, view, ImageResolution=[WIDTH, HEIGHT])


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
    aim_and_save(view, png, [0.0, -30e-6, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0], parallel=True)


def spread_cell(pvd, png):
    reader, t = last_frame(pvd)
    view = new_view(t)
    shown = Show(body(reader, 1), view)
    colour(shown, view, 'displacement', 'substrate displacement [m]')
    cell_shown = Show(body(reader, 0), view)
    cell_shown.ColorArrayName = ['POINTS', '']
    cell_shown.DiffuseColor = [0.85, 0.85, 0.85]
    cell_shown.Opacity = 0.35
    aim_and_save(view, png, [0.0, -30e-6, 25e-6], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0])


def body(reader, body_id):
    part = Threshold(Input=reader)
    part.Scalars = ['POINTS', 'body_id']
    part.LowerThreshold = body_id - 0.5
    part.UpperThreshold = body_id + 0.5
    return part


def adhesion(pvd, png):
    reader, t = last_frame(pvd)
    view = new_view(t)
    height = Calculator(Input=body(reader, 0))
    height.ResultArrayName = 'height'
    height.Function = 'coordsZ - %g' % SUBSTRATE_TOP
    shown = Show(height, view)
    ColorBy(shown, ('POINTS', 'height'))
    lut = GetColorTransferFunction('height')
    lut.RescaleTransferFunction(0.0, 2e-6)
    shown.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = 'height above the substrate [m]'
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    aim_and_save(view, png, [0.0, 0.0, -40e-6], [0.0, 0.0, 5e-6], [0.0, 1.0, 0.0], parallel=True)


def crawling(pvd, png):
    reader, t = last_frame(pvd)
    view = new_view(t)
    # Stiffness factor grade_a (y - y_min) / L0 + grade_b of examples/crawling/crawling.toml,
    # at each particle's reference y (current y minus its displacement).
    stiffness = Calculator(Input=body(reader, 1))
    stiffness.ResultArrayName = 'stiffness_factor'
    stiffness.Function = '%g * (coordsY - displacement_Y - (%g)) / %g + %g' % (GRADE_A, Y_MIN, GRADE_LENGTH, GRADE_B)
    shown = Show(stiffness, view)
    colour(shown, view, 'stiffness_factor', 'substrate stiffness factor (Eq. 18)')
    cell = Show(body(reader, 0), view)
    cell.ColorArrayName = ['POINTS', '']
    cell.DiffuseColor = [0.85, 0.85, 0.85]
    cell.Opacity = 0.3
    # The drift is tens of nanometres against a 10 um cell: the track is drawn from the
    # centroid's start with its displacements magnified TRACK_MAGNIFICATION times.
    with open(os.path.join(os.path.dirname(pvd), 'history.csv')) as f:
        rows = [(float(r['centroid_x']), float(r['centroid_y'])) for r in csv.DictReader(f)]
    x0, y0 = rows[0]
    points = []
    for x, y in rows:
        points += [x0 + TRACK_MAGNIFICATION * (x - x0), y0 + TRACK_MAGNIFICATION * (y - y0), TRACK_HEIGHT]
    track = PolyLineSource(Points=points)
    dx, dy = rows[-1][0] - x0, rows[-1][1] - y0
    label = Text(Text='centroid track (black), magnified %gx: %.1f nm along x, %.1f nm along y (stiffer: +y)'
                      % (TRACK_MAGNIFICATION, dx * 1e9, dy * 1e9))
    caption = Show(label, view)
    caption.WindowLocation = 'Upper Left Corner'
    caption.Color = [0.0, 0.0, 0.0]
    caption.FontSize = 14
    line = Show(track, view)
    line.ColorArrayName = ['POINTS', '']
    line.AmbientColor = line.DiffuseColor = [0.0, 0.0, 0.0]
    line.LineWidth = 4.0
    aim_and_save(view, png, [0.0, 0.0, 60e-6], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0], parallel=True, parallel_scale=8e-6)


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


# The substrate of examples/adhesion and examples/crawling: its top face and the
# grading of crawling.toml.
SUBSTRATE_TOP = 4.5e-6
Y_MIN, GRADE_LENGTH, GRADE_A, GRADE_B = -18.75e-6, 37.5e-6, 4.0, 0.5
TRACK_HEIGHT = 12e-6   # above the cell, so the track is not hidden
TRACK_MAGNIFICATION = 100.0

VIEWS = {'rbc': rbc, 'adhesion': adhesion, 'crawling': crawling, 'spread_cell': spread_cell}


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
