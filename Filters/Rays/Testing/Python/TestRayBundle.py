"""vtkRiemannRayBundle from Python: the rays of chosen pixels as polylines.

Euclidean space, one sphere: every line is straight, starts at the camera and
runs along its unit direction with the arc length as parameter; lines that
hit end on the sphere at their HitPosition (the analytic intersection), the
others run to the maximum length. The cell arrays PixelIndex (n x 2), Hit
(n), HitPosition (n x 3, NaN without a hit), EndColor (n x 3, uint8), Length
(n) and the point array ArcLength exist with those shapes, read with numpy.
A strided pixel region gives the expected pixels; no metric is an error and
an empty output. No rendering: no window is opened.

Run by ctest with /usr/bin/python3 and PYTHONPATH set to the build tree's
package folder (see cmake/RiemannTesting.cmake).
"""

import sys

import numpy as np

import riemann
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkRenderingCore import vtkCamera

WIDTH, HEIGHT, N = 64, 48, 8
EYE = np.array([0.3, -0.2, 5.0])
MAX_LENGTH = 9.1

SCENE = """{
  "background": [0.4, 0.2, 0.0],
  "integrator": {"method": "rk4", "step": 0.3, "max_steps": 100, "max_length": %g},
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
               "material": {"type": "solid", "color": [0.2, 0.6, 1.0]}}]
}""" % MAX_LENGTH

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def cell_array(output, name):
    array = output.GetCellData().GetArray(name)
    check(array is not None, "cell array %s exists" % name)
    return None if array is None else vtk_to_numpy(array)


metric = riemann.vtkRiemannMetric()
check(metric.SetDefinition('{"type": "euclidean"}'), metric.GetLastError())
scene = riemann.vtkRiemannScene()
check(scene.SetDefinition(SCENE), scene.GetLastError())

camera = vtkCamera()
camera.SetPosition(*EYE)
camera.SetFocalPoint(0.05, 0.1, 0)
camera.SetViewUp(0, 1, 0)
camera.SetViewAngle(35)

bundle = riemann.vtkRiemannRayBundle()
errors = []
bundle.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
bundle.SetMetric(metric)
bundle.SetScene(scene)
bundle.SetCamera(camera)
bundle.SetWidth(WIDTH)
bundle.SetHeight(HEIGHT)
bundle.SetSubgridResolution(N)
bundle.Update()
check(not errors, "no VTK error: %s" % errors)
output = bundle.GetOutput()
n = N * N
check(output.GetNumberOfLines() == n, "%d lines, got %d" % (n, output.GetNumberOfLines()))

# The arrays and their shapes.
pixel_index = cell_array(output, "PixelIndex")
hit = cell_array(output, "Hit")
hit_position = cell_array(output, "HitPosition")
end_color = cell_array(output, "EndColor")
length = cell_array(output, "Length")
reason = cell_array(output, "ReasonForTermination")
arc = output.GetPointData().GetArray("ArcLength")
check(arc is not None, "point array ArcLength exists")
if failures:
    sys.exit(1)
arc = vtk_to_numpy(arc)
check(pixel_index.shape == (n, 2), "PixelIndex shape %s" % (pixel_index.shape,))
check(hit.shape == (n,), "Hit shape %s" % (hit.shape,))
check(hit_position.shape == (n, 3), "HitPosition shape %s" % (hit_position.shape,))
check(end_color.shape == (n, 3) and end_color.dtype == np.uint8,
      "EndColor shape %s dtype %s" % (end_color.shape, end_color.dtype))
check(length.shape == (n,) and reason.shape == (n,), "Length/ReasonForTermination shapes")
check(arc.shape == (output.GetNumberOfPoints(),), "ArcLength shape %s" % (arc.shape,))

# Pixels: the centres of N x N blocks, rows outer.
columns = (np.arange(N) + 0.5) * WIDTH // N
rows = (np.arange(N) + 0.5) * HEIGHT // N
expected_pixels = np.array([(c, r) for r in rows for c in columns], dtype=int)
check(np.array_equal(pixel_index, expected_pixels), "PixelIndex are the block centres")

# The polylines, from the cell array's offsets and connectivity.
points = vtk_to_numpy(output.GetPoints().GetData())
offsets = vtk_to_numpy(output.GetLines().GetOffsetsArray())
connectivity = vtk_to_numpy(output.GetLines().GetConnectivityArray())
check(len(offsets) == n + 1, "one offset per line, plus one")

hits = misses = 0
worst_straight = 0.0
for k in range(n):
    ids = connectivity[offsets[k]:offsets[k + 1]]
    p = points[ids]
    s = arc[ids]
    where = "line %d (pixel %s)" % (k, tuple(pixel_index[k]))
    check(len(p) >= 2, where + ": at least two points")
    check(np.allclose(p[0], EYE, atol=1e-12), where + ": starts at the camera")
    check(s[0] == 0.0 and np.all(np.diff(s) > 0), where + ": arc length starts at 0 and grows")
    check(abs(s[-1] - length[k]) < 1e-12, where + ": last arc length is Length")
    # Straight: p(s) = eye + s d, d the unit first direction.
    d = (p[1] - p[0]) / np.linalg.norm(p[1] - p[0])
    worst_straight = max(worst_straight, float(np.max(np.linalg.norm(p - (EYE + s[:, None] * d), axis=1))))
    # The analytic answer: |eye + t d| = 1.
    b = EYE.dot(d)
    disc = b * b - (EYE.dot(EYE) - 1.0)
    if abs(disc) < 1e-3:
        continue  # grazing
    if disc < 0:
        misses += 1
        check(hit[k] == 0, where + ": misses")
        check(np.all(np.isnan(hit_position[k])), where + ": HitPosition NaN")
        check(abs(length[k] - MAX_LENGTH) < 1e-9, where + ": runs to the maximum length")
        check(tuple(end_color[k]) == (102, 51, 0), where + ": background EndColor %s" % (end_color[k],))
    else:
        hits += 1
        t = -b - np.sqrt(disc)
        check(hit[k] == 1, where + ": hits")
        check(reason[k] == 9, where + ": reason 9 (hit)")
        check(np.linalg.norm(hit_position[k] - (EYE + t * d)) < 1e-9, where + ": analytic hit")
        check(np.allclose(p[-1], hit_position[k], atol=1e-12), where + ": ends at its hit")
        check(abs(length[k] - t) < 1e-9, where + ": Length is the distance")
        check(tuple(end_color[k]) == (51, 153, 255), where + ": sphere EndColor %s" % (end_color[k],))
check(worst_straight < 1e-9, "lines are straight (worst %.3g)" % worst_straight)
check(hits > 5 and misses > 5, "hits %d, misses %d" % (hits, misses))

# A strided region: columns 3, 6, 9; rows 2, 5.
bundle.UsePixelRegionOn()
bundle.SetPixelRegion(3, 10, 2, 7)
bundle.SetPixelStride(3)
bundle.Update()
pixels = vtk_to_numpy(bundle.GetOutput().GetCellData().GetArray("PixelIndex"))
check(pixels.tolist() == [[3, 2], [6, 2], [9, 2], [3, 5], [6, 5], [9, 5]],
      "strided region pixels %s" % pixels.tolist())

# No metric: an error, and an empty output.
bundle.SetMetric(None)
bundle.Update()
check(len(errors) == 1, "one error without a metric: %s" % errors)
check(bundle.GetOutput().GetNumberOfPoints() == 0 and bundle.GetOutput().GetNumberOfCells() == 0,
      "empty output without a metric")

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("TestRayBundle.py: all checks passed (%d hits, %d misses)" % (hits, misses))
