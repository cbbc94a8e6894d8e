"""vtkRiemannConjugateLocus from Python: the round 3-sphere.

n = 2 / (1 + |x|^2) is the unit 3-sphere in stereographic coordinates: every
geodesic from p has its first conjugate point at arc length pi, the antipode
-p / |p|^2, of multiplicity 2. Output arrays are read back with numpy.
20 directions at step 0.01: with many more, RK4's error at this step splits
the double zero of an odd direction (ArcLength off by ~1e-6, multiplicity 1;
see TestConjugateLocus.cxx).

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


if __name__ == "__main__":
    unittest.main()
