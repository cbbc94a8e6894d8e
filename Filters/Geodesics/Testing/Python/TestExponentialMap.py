"""vtkRiemannExponentialMap and vtkRiemannGeodesicTracer's transverse Jacobian
from Python, on the unit 3-sphere (n = 2 / (1 + |x|^2), stereographic).

The geodesic sphere of radius r around p lies at spherical distance r from p
(measured in R^4 after inverse stereographic projection, independently of the
library) and its transverse Jacobian is sin^2 r.

Run by ctest with /usr/bin/python3 and PYTHONPATH set to the build's package
folder; exits non-zero on failure.
"""
import math
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import riemann

SPHERE = '{"type": "conformal", "n": "2/(1+x^2+y^2+z^2)"}'
OBSERVER = np.array([0.2, 0.1, -0.3])


def to_s3(x):
    r2 = np.sum(x * x, axis=-1, keepdims=True)
    return np.concatenate([2 * x, 1 - r2], axis=-1) / (1 + r2)


class ExponentialMapTests(unittest.TestCase):
    def setUp(self):
        self.metric = riemann.vtkRiemannMetric()
        self.assertTrue(self.metric.SetDefinition(SPHERE), self.metric.GetLastError())

    def test_wavefronts(self):
        expmap = riemann.vtkRiemannExponentialMap()
        expmap.SetMetric(self.metric)
        expmap.SetObserver(*OBSERVER)
        expmap.SetNumberOfDirections(80)
        expmap.AddRadius(0.7)
        expmap.AddRadius(2.0)
        expmap.GetIntegrationSettings().SetMaximumPropagation(2.5)
        expmap.GetIntegrationSettings().SetIntegratorTypeToDormandPrince45()
        expmap.GetIntegrationSettings().SetMaximumError(1e-10)
        expmap.Update()
        self.assertEqual(expmap.GetNumberOfRadii(), 2)
        self.assertEqual(expmap.GetOutput(0).GetNumberOfLines(), 80)
        fronts = expmap.GetOutput(1)
        self.assertEqual(fronts.GetNumberOfPoints(), 160)
        self.assertEqual(fronts.GetNumberOfPolys(), 2 * (2 * 80 - 4))
        points = vtk_to_numpy(fronts.GetPoints().GetData())
        radius = vtk_to_numpy(fronts.GetPointData().GetArray("Radius"))
        det = vtk_to_numpy(fronts.GetPointData().GetArray("TransverseJacobian"))
        cosines = np.clip(to_s3(points) @ to_s3(OBSERVER), -1, 1)
        np.testing.assert_allclose(np.arccos(cosines), radius, atol=1e-6)
        np.testing.assert_allclose(det, np.sin(radius) ** 2, atol=1e-7)

    def test_tracer_transverse_jacobian(self):
        tracer = riemann.vtkRiemannGeodesicTracer()
        tracer.SetMetric(self.metric)
        tracer.SetStartPosition(*OBSERVER)
        tracer.SetStartDirection(0.3, 1.0, 0.2)
        tracer.GetIntegrationSettings().SetMaximumPropagation(3.0)
        tracer.ComputeTransverseJacobianOn()
        tracer.Update()
        pd = tracer.GetOutput().GetPointData()
        s = vtk_to_numpy(pd.GetArray("ArcLength"))
        np.testing.assert_allclose(vtk_to_numpy(pd.GetArray("TransverseJacobian")), np.sin(s) ** 2,
                                   atol=1e-7)
        singular = vtk_to_numpy(pd.GetArray("TransverseJacobianSingularValues"))
        self.assertEqual(singular.shape[1], 2)
        np.testing.assert_allclose(singular, np.abs(np.sin(s))[:, None].repeat(2, axis=1), atol=1e-7)
        self.assertAlmostEqual(s[-1], 3.0, places=12)


if __name__ == "__main__":
    unittest.main()
