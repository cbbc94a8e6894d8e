"""How far the camera path's frames drift from g-orthonormal (issue 32): the largest
|e_i^T g e_j - delta_ij| over 200 frames of geodesic and spline flights through the
paper's Gaussian bump and the twist, through vtkRiemannCameraPath. A measurement;
the tests bound it (CommonMetric.CameraPath.*, 1e-9).

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Testing/Benchmarks/camera_path_orthonormality.py
"""
import numpy as np, riemann
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
m = riemann.vtkRiemannMetric()
m.SetDefinition('{"type": "graph", "gaussians": [{"amplitude": 1.0, "center": [0, 0, 0], "sigma": [0.5, 0.5, 0.5]}]}')
def worst(path):
    path.Update(); o = path.GetOutput()
    P = vtk_to_numpy(o.GetPoints().GetData()); d = o.GetPointData()
    F, U, R = (vtk_to_numpy(d.GetArray(n)) for n in ("Forward", "Up", "Right"))
    w = 0
    for k in range(len(P)):
        g = [0.0]*9; m.EvaluateMetricTensor(list(P[k]), g)
        E = np.column_stack((F[k], U[k], R[k])); w = max(w, np.abs(E.T @ np.array(g).reshape(3,3) @ E - np.eye(3)).max())
    return w
p = riemann.vtkRiemannCameraPath(); p.SetMetric(m); p.SetPosition(-2, -0.3, 0.1); p.SetLookAt(0, 0, 0); p.SetViewUp(0, 0, 1); p.SetLength(4); p.SetNumberOfFrames(200)
print("bump geodesic flight, 200 frames: %.2e" % worst(p))
keys = vtkPoints()
for k in ([-2.0, -1.0, 0.3], [-0.5, 0.4, 0.1], [0.6, -0.3, -0.2], [2.0, 0.5, 0.4]): keys.InsertNextPoint(k)
p.SetPathTypeToSpline(); p.SetKeyPositions(keys)
print("bump spline flight, 200 frames: %.2e" % worst(p))
m.SetDefinition('{"type": "diffeo", "preset": "twist", "rate": 1.0}')
print("twist spline flight: %.2e" % worst(p))
