"""vtkRiemannCameraPath from Python: a flight through curved space.

- The twist (a pulled-back flat metric, Phi(x, y, z) = rotation of (x, y) by
  z): the geodesic flight's points are Phi^-1 of the straight line
  Phi(x0) + s J(x0) v0, and each frame vector is J(x)^-1 J(x0) X0, the
  pull-back of a constant vector, to 1e-8; the frames are g-orthonormal in
  the metric the filter was given to 1e-9 (vtkRiemannMetric's tensor).
- A spline through three keys starts at the first and ends at the last.
- ApplyFrame puts a vtkCamera at a frame: position, focal point one unit
  ahead, view up.
- Fewer than 2 keys: a VTK error, GetLastError says why, the output is empty.
"""

import sys

import numpy as np

import riemann
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkRenderingCore import vtkCamera

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def twist(p):
    c, s = np.cos(p[2]), np.sin(p[2])
    return np.array([c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]])


def twist_inverse(q):
    c, s = np.cos(q[2]), np.sin(q[2])
    return np.array([c * q[0] + s * q[1], -s * q[0] + c * q[1], q[2]])


def jacobian(p):
    c, s = np.cos(p[2]), np.sin(p[2])
    return np.array([[c, -s, -s * p[0] - c * p[1]],
                     [s, c, c * p[0] - s * p[1]],
                     [0.0, 0.0, 1.0]])


metric = riemann.vtkRiemannMetric()
check(metric.SetDefinition('{"type": "diffeo", "preset": "twist", "rate": 1.0}'),
      metric.GetLastError())

path = riemann.vtkRiemannCameraPath()
errors = []
path.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
path.SetMetric(metric)
path.SetPosition(1.0, 0.0, -1.0)
path.SetLookAt(1.3, 1.0, -0.5)
path.SetViewUp(0.0, 0.0, 1.0)
path.SetLength(4.0)
path.SetNumberOfFrames(30)
path.Update()
check(not errors, "no VTK error: %s" % path.GetLastError())
out = path.GetOutput()
check(out.GetNumberOfPoints() == 30 and out.GetNumberOfLines() == 1, "30 frames on one line")
if failures:
    sys.exit(1)

points = vtk_to_numpy(out.GetPoints().GetData())
data = out.GetPointData()
forward, up, right = (vtk_to_numpy(data.GetArray(n)) for n in ("Forward", "Up", "Right"))
arc = vtk_to_numpy(data.GetArray("ArcLength"))
check(np.allclose(arc, np.linspace(0.0, 4.0, 30), atol=1e-12), "frames evenly spaced in arc length")

x0 = points[0]
j0 = jacobian(x0)
worst_position = worst_frame = worst_orthonormal = 0.0
for k in range(30):
    straight = twist(x0) + arc[k] * j0 @ forward[0]
    worst_position = max(worst_position, np.linalg.norm(points[k] - twist_inverse(straight)))
    pull = np.linalg.solve(jacobian(points[k]), j0)
    for vectors in (forward, up, right):
        worst_frame = max(worst_frame, np.linalg.norm(vectors[k] - pull @ vectors[0]))
    g = [0.0] * 9
    check(metric.EvaluateMetricTensor(list(points[k]), g), "g at frame %d" % k)
    e = np.column_stack((forward[k], up[k], right[k]))
    gram = e.T @ np.array(g).reshape(3, 3) @ e
    worst_orthonormal = max(worst_orthonormal, np.abs(gram - np.eye(3)).max())
print("twist: position %.2e, frame %.2e, orthonormality %.2e"
      % (worst_position, worst_frame, worst_orthonormal))
check(worst_position < 1e-8, "positions are Phi^-1 of a line: %g" % worst_position)
check(worst_frame < 1e-8, "frames are pull-backs of a constant frame: %g" % worst_frame)
check(worst_orthonormal < 1e-9, "frames g-orthonormal: %g" % worst_orthonormal)

camera = vtkCamera()
check(riemann.vtkRiemannCameraPath.ApplyFrame(out, 7, camera), "ApplyFrame")
check(np.allclose(camera.GetPosition(), points[7]), "camera at frame 7")
check(np.allclose(np.array(camera.GetFocalPoint()) - points[7], forward[7]),
      "focal point one unit ahead")
check(not riemann.vtkRiemannCameraPath.ApplyFrame(out, 30, camera), "no frame 30")

keys = vtkPoints()
for key in ((-2.0, 0.0, 0.5), (0.0, 1.0, 0.0), (2.0, 0.0, -0.5)):
    keys.InsertNextPoint(key)
path.SetPathTypeToSpline()
path.SetKeyPositions(keys)
path.Update()
check(not errors, "spline: no VTK error: %s" % path.GetLastError())
spline = vtk_to_numpy(path.GetOutput().GetPoints().GetData())
check(np.allclose(spline[0], (-2.0, 0.0, 0.5), atol=1e-12), "the spline starts at its first key")
check(np.allclose(spline[-1], (2.0, 0.0, -0.5), atol=1e-6), "and ends at its last")

one = vtkPoints()
one.InsertNextPoint(0.0, 0.0, 0.0)
path.SetKeyPositions(one)
path.Update()
check(len(errors) == 1, "one key: a VTK error")
check("at least 2 key positions" in path.GetLastError(), path.GetLastError())
check(path.GetOutput().GetNumberOfPoints() == 0, "one key: empty output")

sys.exit(1 if failures else 0)
