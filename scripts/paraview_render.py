"""One PNG of one snapshot of a sluice run, drawn by ParaView: the pvbatch script behind
`scripts/plot paraview` (which picks the display: see there).

    pvbatch paraview_render.py RESULTS/snapshots.xmf STEP FIELD OUT.png

STEP counts the series from 0 (negative: from the end). The fluid's particles are discs
(spheres in 3-D) one particle spacing across, coloured by FIELD (a vector by its magnitude) on
the fluid's range at that step; wall particles are grey in 2-D, and in 3-D, where they would
hide the fluid, only their outline is drawn. Without a `kind` array every particle is
coloured. 2-D runs are seen along -z, 3-D runs from the -y side, somewhat above, z up.
Exit code 2 for a step or field the file does not have.
"""
import os
import sys

from paraview import simple
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkCommonDataModel import vtkStaticPointLocator

xmf, step, field, out = os.path.abspath(sys.argv[1]), int(sys.argv[2]), sys.argv[3], sys.argv[4]
reader = simple.XDMFReader(FileNames=[xmf])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues) or [0.0]
if not -len(times) <= step < len(times):
    print(f"paraview: step {step} not in the series (0 to {len(times) - 1})", file=sys.stderr)
    sys.exit(2)
t = times[step]
reader.UpdatePipeline(t)
data = reader.GetClientSideObject().GetOutputDataObject(0)
point_data = data.GetPointData()
names = [point_data.GetArrayName(i) for i in range(point_data.GetNumberOfArrays())]
if field not in names:
    print(f"paraview: no field '{field}' in the snapshots (there are: {', '.join(names)})",
          file=sys.stderr)
    sys.exit(2)
xmin, xmax, ymin, ymax, zmin, zmax = data.GetBounds()
flat = zmax - zmin <= 1e-12 * max(xmax - xmin, ymax - ymin, 1e-300)


def spacing(points):
    """The particle spacing: the median distance to the nearest other particle, of up to 200."""
    locator = vtkStaticPointLocator()
    locator.SetDataSet(points)
    locator.BuildLocator()
    ids, gaps = vtkIdList(), []
    n = points.GetNumberOfPoints()
    for i in range(0, n, max(n // 200, 1)):
        p = points.GetPoint(i)
        locator.FindClosestNPoints(2, p, ids)
        if ids.GetNumberOfIds() == 2:
            q = points.GetPoint(ids.GetId(1) if ids.GetId(0) == i else ids.GetId(0))
            gaps.append(sum((a - b) ** 2 for a, b in zip(p, q)) ** 0.5)
    gaps.sort()
    return gaps[len(gaps) // 2] if gaps else 1.0


dx = spacing(data)
view = simple.CreateView("RenderView")
view.ViewSize = [1000, 700]
view.ViewTime = t
view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]
view.OrientationAxesVisibility = 0


def kind_only(k):
    only = simple.Threshold(Input=reader, Scalars=["POINTS", "kind"], ThresholdMethod="Between")
    only.LowerThreshold = only.UpperThreshold = k  # after Scalars, which resets them to its range
    return only


fluid, walls = (kind_only(0), kind_only(1)) if "kind" in names else (reader, None)
if walls is not None:  # 2-D: the wall particles; 3-D: their outline, which hides no fluid
    shown = simple.Show(walls if flat else simple.Outline(Input=walls), view)
    shown.ColorArrayName = ["POINTS", ""]
    shown.AmbientColor = shown.DiffuseColor = [0.6, 0.6, 0.6]
    if flat:
        shown.SetRepresentationType("Point Gaussian")
        shown.GaussianRadius = 0.45 * dx
        shown.ShaderPreset = "Plain circle"
shown = simple.Show(fluid, view)
shown.SetRepresentationType("Point Gaussian")
shown.GaussianRadius = 0.5 * dx
shown.ShaderPreset = "Plain circle" if flat else "Sphere"
simple.ColorBy(shown, ("POINTS", field, "Magnitude"))
shown.RescaleTransferFunctionToDataRange(False, True)
shown.SetScalarBarVisibility(view, True)
bar = simple.GetScalarBar(simple.GetColorTransferFunction(field), view)
bar.Title = field
vector = point_data.GetArray(field).GetNumberOfComponents() > 1
bar.ComponentTitle = "magnitude" if vector else ""
bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
label = simple.Text(Text=f"{os.path.basename(os.path.dirname(xmf))}: t = {t:.4g} s, "
                    f"step {step % len(times)} of {len(times)}")
note = simple.Show(label, view)
note.Color = [0.1, 0.1, 0.1]
note.WindowLocation = "Upper Center"
note.FontSize = 14

camera = view.GetActiveCamera()
centre = [(xmin + xmax) / 2, (ymin + ymax) / 2, (zmin + zmax) / 2]
if flat:
    view.CameraParallelProjection = 1
    camera.SetFocalPoint(centre)
    camera.SetPosition(centre[0], centre[1], centre[2] + 1.0)
    camera.SetViewUp(0, 1, 0)
else:
    camera.SetFocalPoint(centre)
    camera.SetPosition(centre[0], centre[1] - 1.0, centre[2])
    camera.SetViewUp(0, 0, 1)
    camera.Elevation(25)
    camera.Azimuth(-30)
simple.ResetCamera(view)
simple.SaveScreenshot(out, view, ImageResolution=view.ViewSize)
