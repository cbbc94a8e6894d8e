"""vtkRiemannGeodesicConnector from Python: the two arcs of a great circle.

n = 2 / (1 + |x|^2) is the unit 3-sphere in stereographic coordinates. Two
points p and q at spherical distance d are joined, up to arc length 7, by
exactly two geodesics: the arcs of lengths d and 2 pi - d; the longer passes
the antipode of p (a conjugate point of multiplicity 2), so its Morse index
is 2. Output arrays are read back with numpy.

Run by ctest with /usr/bin/python3 and PYTHONPATH set to the build's package
folder; exits non-zero on failure.
"""
import math
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import riemann

SPHERE = '{"type": "conformal", "n": "2/(1+x^2+y^2+z^2)"}'


def on_sphere(x):
    x = np.asarray(x, dtype=float)
    r2 = x @ x
    return np.append(2 * x / (1 + r2), (1 - r2) / (1 + r2))


class GeodesicConnectorTests(unittest.TestCase):
    def test_two_arcs(self):
        p, q = [0.4, 0.1, -0.2], [-0.3, 0.5, 0.6]
        d = math.acos(on_sphere(p) @ on_sphere(q))
        metric = riemann.vtkRiemannMetric()
        self.assertTrue(metric.SetDefinition(SPHERE), metric.GetLastError())
        connector = riemann.vtkRiemannGeodesicConnector()
        connector.SetMetric(metric)
        connector.SetStartPosition(*p)
        connector.SetEndPosition(*q)
        connector.SetNumberOfDirections(400)
        connector.GetIntegrationSettings().SetMaximumPropagation(7.0)
        connector.Update()
        self.assertEqual(connector.GetLastError(), "")
        cd = connector.GetOutput().GetCellData()
        lengths = vtk_to_numpy(cd.GetArray("Length"))
        np.testing.assert_allclose(lengths, [d, 2 * math.pi - d], atol=1e-8)
        self.assertEqual(list(vtk_to_numpy(cd.GetArray("MorseIndex"))), [0, 2])
        self.assertEqual(list(vtk_to_numpy(cd.GetArray("Shortest"))), [1, 0])
        # The arcs leave p in opposite directions.
        directions = vtk_to_numpy(cd.GetArray("InitialDirection"))
        cosine = directions[0] @ directions[1] / np.linalg.norm(directions[0]) / np.linalg.norm(directions[1])
        self.assertAlmostEqual(cosine, -1.0, delta=1e-6)


if __name__ == "__main__":
    unittest.main()
