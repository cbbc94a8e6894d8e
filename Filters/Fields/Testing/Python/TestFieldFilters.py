"""The field filters from Python: the round 3-sphere has ScalarCurvature 6 and
Ricci = 2 g everywhere, the twist metric has VolumeIntegral 8 over [-1,1]^3,
and VTK 9.1's vtkTensorGlyph reads our 6-component MetricTensor as the
9-component tensor it stands for (XX, YY, ZZ, XY, YZ, XZ).

Run by ctest with /usr/bin/python3 and PYTHONPATH set to the build's package
folder; exits non-zero on failure.
"""
import math
import sys
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkTensorGlyph
from vtkmodules.vtkFiltersSources import vtkSphereSource

import riemann

SPHERE = '{"type": "conformal", "n": "2/(1+x^2+y^2+z^2)"}'
TWIST = '{"type": "diffeo", "preset": "twist"}'


def make_metric(definition):
    m = riemann.vtkRiemannMetric()
    assert m.SetDefinition(definition), m.GetLastError()
    return m


def grid_filter(cls, definition, half, n):
    f = cls()
    f.SetMetric(make_metric(definition))
    f.SetBounds(-half, half, -half, half, -half, half)
    f.SetDimensions(n, n, n)
    f.Update()
    return f.GetOutput()


class FieldFilterTests(unittest.TestCase):
    def test_sphere_scalar_curvature_and_ricci(self):
        out = grid_filter(riemann.vtkRiemannCurvatureField, SPHERE, 1.5, 9)
        self.assertEqual(out.GetNumberOfPoints(), 729)
        s = vtk_to_numpy(out.GetPointData().GetArray("ScalarCurvature"))
        np.testing.assert_allclose(s, 6.0, atol=1e-9)
        x = np.array([out.GetPoint(i) for i in range(out.GetNumberOfPoints())])
        n = 2.0 / (1.0 + np.sum(x * x, axis=1))
        ricci = vtk_to_numpy(out.GetPointData().GetArray("Ricci"))
        self.assertEqual(ricci.shape, (729, 6))
        np.testing.assert_allclose(ricci[:, :3], 2 * (n * n)[:, None] * np.ones((1, 3)), atol=1e-9)
        np.testing.assert_allclose(ricci[:, 3:], 0.0, atol=1e-9)
        for name in ("SectionalMin", "SectionalMax", "SectionalXY"):
            np.testing.assert_allclose(vtk_to_numpy(out.GetPointData().GetArray(name)), 1.0,
                                       atol=1e-9)

    def test_twist_volume_integral(self):
        f = riemann.vtkRiemannVolumeForm()
        f.SetMetric(make_metric(TWIST))
        f.SetBounds(-1, 1, -1, 1, -1, 1)
        f.SetDimensions(11, 11, 11)
        f.Update()
        self.assertAlmostEqual(f.GetVolumeIntegral(), 8.0, places=9)
        field = f.GetOutput().GetFieldData().GetArray("VolumeIntegral")
        self.assertAlmostEqual(field.GetValue(0), 8.0, places=9)

    def test_metric_tensor_feeds_tensor_glyph(self):
        out = grid_filter(riemann.vtkRiemannMetricTensorField,
                          '{"type": "tensor", "matrix": [[2, 1, 0], [1, 3, 0.5], [0, 0.5, 1]]}',
                          1.0, 1)
        six = vtk_to_numpy(out.GetPointData().GetArray("MetricTensor"))[0]
        np.testing.assert_allclose(six, [2, 3, 1, 1, 0.5, 0], atol=1e-14)
        eig = vtk_to_numpy(out.GetPointData().GetArray("MetricEigenvalues"))[0]
        full = np.array([[2, 1, 0], [1, 3, 0.5], [0, 0.5, 1]])
        np.testing.assert_allclose(eig, np.linalg.eigvalsh(full), atol=1e-12)

        def glyph_bounds(components):
            points = vtkPoints()
            points.InsertNextPoint(0, 0, 0)
            data = vtkPolyData()
            data.SetPoints(points)
            tensors = vtkDoubleArray()
            tensors.SetNumberOfComponents(len(components))
            tensors.InsertNextTuple(components)
            data.GetPointData().SetTensors(tensors)
            source = vtkSphereSource()
            source.SetThetaResolution(24)
            source.SetPhiResolution(24)
            glyph = vtkTensorGlyph()
            glyph.SetInputData(data)
            glyph.SetSourceConnection(source.GetOutputPort())
            glyph.Update()
            return np.array(glyph.GetOutput().GetBounds())

        np.testing.assert_allclose(glyph_bounds(list(six)), glyph_bounds(list(full.ravel())),
                                   atol=1e-6)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
