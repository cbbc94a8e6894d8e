"""vtkRiemannGeodesicTracer from Python, checked against exact geodesics.

For the twist metric (flat: MATH.md, Family 2) every geodesic is
gamma(s) = Phi^-1(Phi(p) + s J(p) v) with v = d / |d|_g, written out here with
numpy. Seeds are vtkPoints with a numpy "Direction" array; the output arrays
are read back with numpy.

Run by ctest with /usr/bin/python3 and PYTHONPATH set to the build's package
folder; exits non-zero on failure.
"""
import math
import sys
import unittest

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

import riemann

Tracer = riemann.vtkRiemannGeodesicTracer
Settings = riemann.vtkRiemannIntegrationSettings
TWIST = '{"type": "diffeo", "preset": "twist", "rate": 1}'

SEEDS = np.array([[1.0, 0.0, -1.0], [0.3, -0.7, 0.2], [-1.2, 0.5, 0.9], [0.0, 0.0, 0.0],
                  [0.8, 1.1, -0.4]])
DIRECTIONS = np.array([[0.3, 1.0, 0.5], [1.0, 0.0, 0.0], [0.0, 0.0, 2.0], [-0.4, 0.7, -0.2],
                       [0.5, -0.5, 0.9]])


def phi(p):
    x, y, z = p
    return np.array([math.cos(z) * x - math.sin(z) * y, math.sin(z) * x + math.cos(z) * y, z])


def phi_inverse(q):
    x, y, z = q
    return np.array([math.cos(z) * x + math.sin(z) * y, -math.sin(z) * x + math.cos(z) * y, z])


def jacobian(p):
    x, y, z = p
    c, s = math.cos(z), math.sin(z)
    return np.array([[c, -s, -s * x - c * y], [s, c, c * x - s * y], [0.0, 0.0, 1.0]])


def unit_velocity(p, d):
    return d / np.linalg.norm(jacobian(p) @ d)


def exact(p, d, s):
    """The twist geodesic from p with direction d, at arc length s."""
    return phi_inverse(phi(p) + s * jacobian(p) @ unit_velocity(p, d))


def make_metric(definition):
    m = riemann.vtkRiemannMetric()
    assert m.SetDefinition(definition), m.GetLastError()
    return m


def make_seeds(points, directions):
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=np.float64), deep=1))
    d = numpy_to_vtk(np.ascontiguousarray(directions, dtype=np.float64), deep=1)
    d.SetName('Direction')
    seeds = vtkPolyData()
    seeds.SetPoints(pts)
    seeds.GetPointData().AddArray(d)
    return seeds


def lines_of(output):
    """[(first point id, point count)] of the output's polylines, in order."""
    cells = output.GetLines()
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    connectivity = vtk_to_numpy(cells.GetConnectivityArray())
    result = []
    for c in range(cells.GetNumberOfCells()):
        ids = connectivity[offsets[c]:offsets[c + 1]]
        # The tracer writes each line's points contiguously.
        np.testing.assert_array_equal(ids, np.arange(ids[0], ids[0] + len(ids)))
        result.append((int(ids[0]), len(ids)))
    return result


def arrays_of(output):
    pd, cd = output.GetPointData(), output.GetCellData()
    return {
        'points': vtk_to_numpy(output.GetPoints().GetData()),
        'ArcLength': vtk_to_numpy(pd.GetArray('ArcLength')),
        'Velocity': vtk_to_numpy(pd.GetArray('Velocity')),
        'SpeedDrift': vtk_to_numpy(pd.GetArray('SpeedDrift')),
        'SeedIds': vtk_to_numpy(cd.GetArray('SeedIds')),
        'ReasonForTermination': vtk_to_numpy(cd.GetArray('ReasonForTermination')),
    }


def speed_squared(metric, p, v):
    g = [0.0] * 9
    assert metric.EvaluateMetricTensor(list(p), g)
    return float(v @ np.array(g).reshape(3, 3) @ v)


class TracerTest(unittest.TestCase):
    def test_constants(self):
        self.assertEqual((Settings.EULER, Settings.RUNGE_KUTTA4, Settings.DORMAND_PRINCE45), (0, 1, 2))
        self.assertEqual((Tracer.FORWARD, Tracer.BACKWARD, Tracer.BOTH), (0, 1, 2))
        self.assertEqual((Tracer.OUT_OF_DOMAIN, Tracer.NOT_INITIALIZED, Tracer.UNEXPECTED_VALUE,
                          Tracer.OUT_OF_LENGTH, Tracer.OUT_OF_STEPS, Tracer.STAGNATION,
                          Tracer.DEGENERATE_METRIC, Tracer.HIT_SURFACE),
                         (1, 2, 3, 4, 5, 6, 8, 9))
        t = Tracer()
        self.assertEqual(t.GetIntegrationSettings().GetIntegratorType(), Settings.RUNGE_KUTTA4)  # the default
        t.GetIntegrationSettings().SetIntegratorTypeToDormandPrince45()
        self.assertEqual(t.GetIntegrationSettings().GetIntegratorType(), Settings.DORMAND_PRINCE45)
        t.GetIntegrationSettings().SetIntegratorTypeToEuler()
        self.assertEqual(t.GetIntegrationSettings().GetIntegratorType(), Settings.EULER)
        t.SetIntegrationDirectionToBoth()
        self.assertEqual(t.GetIntegrationDirection(), Tracer.BOTH)
        self.assertEqual(t.GetDirectionArrayName(), 'Direction')
        m = make_metric(TWIST)
        t.SetMetric(m)
        self.assertIs(t.GetMetric(), m)

    def trace(self, integrator, length=3.0, step=0.01, **settings):
        metric = make_metric(TWIST)
        t = Tracer()
        t.SetMetric(metric)
        t.SetInputData(make_seeds(SEEDS, DIRECTIONS))
        t.GetIntegrationSettings().SetIntegratorType(integrator)
        t.GetIntegrationSettings().SetInitialIntegrationStep(step)
        t.GetIntegrationSettings().SetMaximumPropagation(length)
        for name, value in settings.items():
            owner = t.GetIntegrationSettings() if hasattr(Settings, 'Set' + name) else t
            getattr(owner, 'Set' + name)(value)
        errors = []
        t.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
        t.AddObserver(vtkCommand.WarningEvent, lambda obj, event: errors.append(event))
        t.Update()
        self.assertEqual(errors, [])
        return metric, t.GetOutput()

    def test_rk4_twist_endpoints(self):
        length = 3.0
        metric, output = self.trace(Settings.RUNGE_KUTTA4, length)
        a = arrays_of(output)
        lines = lines_of(output)
        self.assertEqual(len(lines), len(SEEDS))
        np.testing.assert_array_equal(a['SeedIds'], np.arange(len(SEEDS)))
        np.testing.assert_array_equal(a['ReasonForTermination'], Tracer.OUT_OF_LENGTH)
        self.assertEqual(a['Velocity'].shape, (output.GetNumberOfPoints(), 3))
        for (first, count), p, d in zip(lines, SEEDS, DIRECTIONS):
            with self.subTest(seed=p):
                last = first + count - 1
                self.assertIn(count, (301, 302))  # 300 steps of 0.01
                np.testing.assert_array_equal(a['points'][first], p)
                self.assertEqual(a['ArcLength'][first], 0.0)
                self.assertAlmostEqual(a['ArcLength'][last], length, delta=1e-12)
                self.assertTrue(np.all(np.diff(a['ArcLength'][first:last + 1]) > 0))
                self.assertLess(np.linalg.norm(a['points'][last] - exact(p, d, length)), 1e-8)
                # Every sample is on the exact geodesic at its own arc length.
                worst = max(np.linalg.norm(a['points'][k] - exact(p, d, a['ArcLength'][k]))
                            for k in range(first, last + 1, 10))
                self.assertLess(worst, 1e-8)
                # Unit speed in g at the seed, in the direction given.
                v0 = a['Velocity'][first]
                self.assertAlmostEqual(speed_squared(metric, p, v0), 1.0, delta=1e-12)
                np.testing.assert_allclose(v0, unit_velocity(p, d), atol=1e-12)
                self.assertAlmostEqual(
                    speed_squared(metric, a['points'][last], a['Velocity'][last]), 1.0,
                    delta=1e-9)
                self.assertLess(np.abs(a['SpeedDrift'][first:last + 1]).max(), 1e-9)

    def test_dormand_prince_twist_endpoints(self):
        length = 3.0
        _, output = self.trace(Settings.DORMAND_PRINCE45, length, MaximumError=1e-9)
        a = arrays_of(output)
        lines = lines_of(output)
        self.assertEqual(len(lines), len(SEEDS))
        for (first, count), p, d in zip(lines, SEEDS, DIRECTIONS):
            with self.subTest(seed=p):
                last = first + count - 1
                self.assertAlmostEqual(a['ArcLength'][last], length, delta=1e-12)
                self.assertLess(np.linalg.norm(a['points'][last] - exact(p, d, length)), 1e-6)
                self.assertLess(count, 200)  # adaptive: fewer steps than RK4's 300
        np.testing.assert_array_equal(a['ReasonForTermination'], Tracer.OUT_OF_LENGTH)

    def test_euler_converges_at_first_order(self):
        errors = []
        for step in (0.02, 0.01):
            _, output = self.trace(Settings.EULER, 1.0, step)
            a = arrays_of(output)
            first, count = lines_of(output)[0]
            errors.append(np.linalg.norm(a['points'][first + count - 1]
                                         - exact(SEEDS[0], DIRECTIONS[0], 1.0)))
        self.assertLess(errors[1], 1e-2)
        self.assertAlmostEqual(math.log2(errors[0] / errors[1]), 1.0, delta=0.15)

    def test_both_directions(self):
        _, output = self.trace(Settings.RUNGE_KUTTA4, 2.0, IntegrationDirection=Tracer.BOTH)
        a = arrays_of(output)
        lines = lines_of(output)
        self.assertEqual(len(lines), 2 * len(SEEDS))
        np.testing.assert_array_equal(np.sort(a['SeedIds']), np.repeat(np.arange(len(SEEDS)), 2))
        ends = {}
        for (first, count), seed in zip(lines, a['SeedIds']):
            last = first + count - 1
            s = a['ArcLength'][last]
            ends[(int(seed), s > 0)] = s
            p, d = SEEDS[seed], DIRECTIONS[seed]
            np.testing.assert_array_equal(a['points'][first], p)
            self.assertAlmostEqual(abs(s), 2.0, delta=1e-12)
            self.assertLess(np.linalg.norm(a['points'][last] - exact(p, d, s)), 1e-8)
        self.assertEqual(len(ends), 2 * len(SEEDS))  # one forward, one backward each

    def test_no_metric(self):
        t = Tracer()
        t.SetInputData(make_seeds(SEEDS, DIRECTIONS))
        errors = []
        t.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
        t.Update()
        self.assertEqual(len(errors), 1)
        self.assertEqual(t.GetOutput().GetNumberOfPoints(), 0)
        self.assertEqual(t.GetOutput().GetNumberOfCells(), 0)

    def test_progress_reaches_one(self):
        rng = np.random.default_rng(1)
        points = rng.uniform(-1, 1, (600, 3))
        directions = rng.uniform(-1, 1, (600, 3)) + np.array([0.0, 0.0, 2.0])
        t = Tracer()
        t.SetMetric(make_metric(TWIST))
        t.SetInputData(make_seeds(points, directions))
        t.GetIntegrationSettings().SetMaximumPropagation(0.3)
        progress = []
        t.AddObserver(vtkCommand.ProgressEvent,
                      lambda obj, event: progress.append(obj.GetProgress()))
        t.Update()
        self.assertEqual(progress[-1], 1.0)
        self.assertEqual(progress, sorted(progress))
        self.assertEqual(t.GetOutput().GetNumberOfLines(), 600)
        # Endpoints of all 600 lines at once, vectorised.
        a = arrays_of(t.GetOutput())
        lines = lines_of(t.GetOutput())
        lasts = np.array([first + count - 1 for first, count in lines])
        worst = max(np.linalg.norm(a['points'][k] - exact(points[i], directions[i], 0.3))
                    for k, i in zip(lasts, a['SeedIds']))
        self.assertLess(worst, 1e-8)

    def test_seeds_from_a_mask_image(self):
        # A mask image as the input: seeds at its set voxels' centres, along
        # e1 (for g = diag(4, 1, 9) the cheapest direction is y); with
        # several seeds per voxel, spread in the voxel, the same RandomSeed
        # gives the same seeds and another gives others.
        from vtkmodules.vtkCommonDataModel import vtkImageData
        m = riemann.vtkRiemannMetric()
        self.assertTrue(m.SetDefinition(
            '{"type": "tensor", "g": [["4","0","0"],["0","1","0"],["0","0","9"]]}'), m.GetLastError())
        mask = vtkImageData()
        mask.SetDimensions(4, 3, 2)
        mask.SetOrigin(1.0, 2.0, 3.0)
        mask.SetSpacing(0.5, 0.5, 0.5)
        values = np.zeros(24, np.uint8)
        values[[0, 5, 17]] = 1
        mask.GetPointData().SetScalars(numpy_to_vtk(values, deep=True))

        def trace(per_voxel, seed, direction=riemann.vtkRiemannGeodesicTracer.E1):
            t = riemann.vtkRiemannGeodesicTracer()
            t.SetMetric(m)
            t.SetInputData(mask)
            t.SetSeedsPerVoxel(per_voxel)
            t.SetSeedDirection(direction)
            t.SetRandomSeed(seed)
            t.GetIntegrationSettings().SetMaximumPropagation(0.2)
            t.Update()
            self.assertEqual(t.GetLastError(), "")
            out = t.GetOutput()
            lines = lines_of(out)
            points = vtk_to_numpy(out.GetPoints().GetData())
            return points[[first for first, _ in lines]], points[[first + 1 for first, _ in lines]]

        starts, seconds = trace(1, 1)
        voxels = np.array([mask.GetPoint(i) for i in (0, 5, 17)])
        np.testing.assert_allclose(starts, voxels, atol=1e-15)
        steps = seconds - starts
        np.testing.assert_allclose(np.abs(steps / np.linalg.norm(steps, axis=1)[:, None]),
                                   [[0, 1, 0]] * 3, atol=1e-9)
        a, _ = trace(5, 7)
        b, _ = trace(5, 7)
        c, _ = trace(5, 8)
        self.assertEqual(len(a), 15)
        np.testing.assert_array_equal(a, b)
        self.assertGreater(np.abs(a - c).max(), 1e-3)
        self.assertLessEqual(np.abs(a - np.repeat(voxels, 5, axis=0)).max(), 0.25 + 1e-12)
        random, _ = trace(1, 3, riemann.vtkRiemannGeodesicTracer.RANDOM)
        np.testing.assert_allclose(random, voxels, atol=1e-15)


if __name__ == '__main__':
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
