"""vtkRiemannConjugateLocus from Python: the round 3-sphere and two close
simple conjugate points.

n = 2 / (1 + |x|^2) is the unit 3-sphere in stereographic coordinates: every
geodesic from p has its first conjugate point at arc length pi, the antipode
-p / |p|^2, of multiplicity 2 (on caustic sheets 1 and 2, which meet there).
g = diag((cos y cos kz)^2, 1, 1): along +x from the origin the Jacobi fields
are sin(s) and sin(ks)/k: two simple conjugate points, at pi/k and pi, with
kernel directions e_z and e_y. Output arrays are read back with numpy.

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


class ConjugateLocusTests(unittest.TestCase):
    def test_sphere_antipode(self):
        metric = riemann.vtkRiemannMetric()
        self.assertTrue(metric.SetDefinition(SPHERE), metric.GetLastError())
        locus = riemann.vtkRiemannConjugateLocus()
        locus.SetMetric(metric)
        locus.SetObserver(*OBSERVER)
        locus.SetNumberOfDirections(20)
        locus.GetIntegrationSettings().SetMaximumPropagation(4.0)
        locus.GetIntegrationSettings().SetInitialIntegrationStep(0.01)
        locus.Update()
        output = locus.GetOutput()
        self.assertEqual(output.GetNumberOfPoints(), 20)
        pd = output.GetPointData()
        arc = vtk_to_numpy(pd.GetArray("ArcLength"))
        np.testing.assert_allclose(arc, math.pi, atol=1e-6)
        np.testing.assert_array_equal(vtk_to_numpy(pd.GetArray("Multiplicity")), 2)
        np.testing.assert_array_equal(vtk_to_numpy(pd.GetArray("ConjugateIndex")), 1)
        np.testing.assert_array_equal(vtk_to_numpy(pd.GetArray("DirectionId")), np.arange(20))
        points = vtk_to_numpy(output.GetPoints().GetData())
        antipode = -OBSERVER / OBSERVER.dot(OBSERVER)
        np.testing.assert_allclose(points, np.tile(antipode, (20, 1)), atol=1e-5)
        np.testing.assert_array_equal(vtk_to_numpy(pd.GetArray("Sheet")), 1)
        sheets = locus.GetOutput(1)
        self.assertEqual(sheets.GetNumberOfPoints(), 40)
        cell_sheet = vtk_to_numpy(sheets.GetCellData().GetArray("Sheet"))
        self.assertEqual(set(cell_sheet.tolist()), {1, 2})
        np.testing.assert_array_equal(vtk_to_numpy(sheets.GetCellData().GetArray("Singularity")), 2)

    def test_close_simple_points(self):
        k = 1.005
        metric = riemann.vtkRiemannMetric()
        definition = ('{"type":"tensor","parameters":{"k":%r},"g":[["(cos(y)*cos(k*z))^2","0","0"],'
                      '["0","1","0"],["0","0","1"]]}' % k)
        self.assertTrue(metric.SetDefinition(definition), metric.GetLastError())
        locus = riemann.vtkRiemannConjugateLocus()
        locus.SetMetric(metric)
        locus.SetNumberOfDirections(1)
        locus.SetConeAxis(1.0, 0.0, 0.0)
        locus.SetConeAngle(0.0)
        locus.SetMaximumNumberOfConjugatePoints(3)
        locus.GetIntegrationSettings().SetMaximumPropagation(4.0)
        locus.Update()
        pd = locus.GetOutput().GetPointData()
        np.testing.assert_allclose(vtk_to_numpy(pd.GetArray("ArcLength")), [math.pi / k, math.pi], atol=1e-8)
        np.testing.assert_array_equal(vtk_to_numpy(pd.GetArray("Multiplicity")), [1, 1])
        np.testing.assert_array_equal(vtk_to_numpy(pd.GetArray("Sheet")), [1, 2])
        kernel = np.abs(vtk_to_numpy(pd.GetArray("KernelDirection")))
        np.testing.assert_allclose(kernel, [[0, 0, 1], [0, 1, 0]], atol=1e-9)


if __name__ == "__main__":
    unittest.main()
