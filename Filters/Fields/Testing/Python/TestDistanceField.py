"""vtkRiemannDistanceField and vtkRiemannCutLocus from Python, checked
against exact distances and against vtkRiemannGeodesicConnector.

- The twist (a flat metric pulled back by Phi): the distance from p is
  |Phi(x) - Phi(p)|; the field's error is first order (up to the point
  source's logarithm): under 0.03 on a 33^3 grid of [-1, 1]^3.
- Two bumps (a graph metric): the wavefronts from a seed before the first
  bump fold behind it; the cut locus is there. At sampled points of it,
  `connect` finds two distinct geodesics from the seed whose lengths agree
  within the field's error: two minimal geodesics meet there.

Run by ctest with /usr/bin/python3 and PYTHONPATH set to the build's package
folder; exits non-zero on failure.
"""
import math
import os
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import riemann

TWIST = '{"type": "diffeo", "preset": "twist"}'
DATA = os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(__file__), "../../../../Data"))


def metric(text):
    m = riemann.vtkRiemannMetric()
    assert m.SetDefinition(text), m.GetLastError()
    return m


def twist(x):
    c, s = np.cos(x[..., 2]), np.sin(x[..., 2])
    return np.stack([c * x[..., 0] - s * x[..., 1], s * x[..., 0] + c * x[..., 1], x[..., 2]], -1)


class DistanceFieldTests(unittest.TestCase):
    def test_twist_is_the_mapped_distance(self):
        field = riemann.vtkRiemannDistanceField()
        field.SetMetric(metric(TWIST))
        field.SetBounds(-1, 1, -1, 1, -1, 1)
        field.SetDimensions(33, 33, 33)
        seed = np.array([0.2, -0.1, 0.3])
        field.AddSeed(*seed)
        field.Update()
        self.assertEqual(field.GetLastError(), "")
        image = field.GetOutput()
        points = np.array([image.GetPoint(i) for i in range(image.GetNumberOfPoints())])
        exact = np.linalg.norm(twist(points) - twist(seed), axis=1)
        distance = vtk_to_numpy(image.GetPointData().GetArray("Distance"))
        self.assertLess(np.abs(distance - exact).max(), 0.04)  # measured 0.035
        self.assertTrue((vtk_to_numpy(image.GetPointData().GetArray("SeedId")) == 0).all())

    def test_cut_locus_points_have_two_minimal_geodesics(self):
        with open(os.path.join(DATA, "metrics", "two-bumps.json")) as f:
            bumps = metric(f.read())
        seed = (-1.5, 0.0, 0.0)
        field = riemann.vtkRiemannDistanceField()
        field.SetMetric(bumps)
        field.SetBounds(-2, 2, -2, 2, -2, 2)
        field.SetDimensions(49, 49, 49)
        field.AddSeed(*seed)
        cut = riemann.vtkRiemannCutLocus()
        cut.SetMetric(bumps)
        cut.SetInputConnection(field.GetOutputPort())
        cut.Update()
        self.assertEqual(cut.GetLastError(), "")
        squares = cut.GetOutput()
        kinds = vtk_to_numpy(squares.GetCellData().GetArray("Kind"))
        self.assertGreater(squares.GetNumberOfPolys(), 20)
        self.assertTrue((kinds == 1).all())  # one seed: only direction jumps
        # The squares of the largest jumps (the discrete field smears a jump
        # over a cell or two beside it), checked by connect.
        distances = vtk_to_numpy(squares.GetCellData().GetArray("Distance"))
        angles = vtk_to_numpy(squares.GetCellData().GetArray("Angle"))
        cut_points = vtk_to_numpy(squares.GetCellData().GetArray("CutPoint"))
        checked = 0
        for s in np.argsort(-angles)[:6]:
            centre = cut_points[s]
            connector = riemann.vtkRiemannGeodesicConnector()
            connector.SetMetric(bumps)
            connector.SetStartPosition(*seed)
            connector.SetEndPosition(*centre)
            connector.SetNumberOfDirections(3000)
            connector.GetIntegrationSettings().SetMaximumPropagation(1.3 * distances[s] + 0.2)
            connector.Update()
            cd = connector.GetOutput().GetCellData()
            lengths = vtk_to_numpy(cd.GetArray("Length"))  # sorted by length
            leaving = vtk_to_numpy(cd.GetArray("InitialDirection"))
            with self.subTest(square=s, centre=centre):
                self.assertGreaterEqual(len(lengths), 2, lengths)
                # Two different geodesics: they leave the seed apart.
                cosine = leaving[0] @ leaving[1] / np.linalg.norm(leaving[0]) / np.linalg.norm(leaving[1])
                self.assertLess(cosine, math.cos(math.radians(5)), (lengths, leaving[:2]))
                print("cut point %s: u %.4f, geodesics %.4f and %.4f, %.1f degrees apart"
                      % (np.round(centre, 3), distances[s], lengths[0], lengths[1],
                         math.degrees(math.acos(min(1, cosine)))))
                # The two shortest agree within the field's error (h = 1/12),
                # and the field's distance is theirs within it too.
                self.assertLess(lengths[1] - lengths[0], 0.05, lengths)
                self.assertLess(abs(lengths[0] - distances[s]), 0.08, (lengths, distances[s]))
            checked += 1
        self.assertGreaterEqual(checked, 5)

    def test_minimal_geodesics_are_the_twists_straight_lines(self):
        # Two seeds; each target's geodesic comes from its closer seed (in
        # the twist's flat geometry) and, refined by Newton, has exactly the
        # mapped length; the field's distance there is within its error.
        seeds = np.array([[-0.6, 0.1, -0.2], [0.6, -0.1, 0.3]])
        targets = np.array([[-0.2, 0.7, 0.5], [0.9, 0.8, -0.7], [0.1, -0.9, 0.8], [-0.9, -0.8, -0.9]])
        field = riemann.vtkRiemannDistanceField()
        twist_metric = metric(TWIST)
        field.SetMetric(twist_metric)
        field.SetBounds(-1, 1, -1, 1, -1, 1)
        field.SetDimensions(33, 33, 33)
        for seed in seeds:
            field.AddSeed(*seed)
        minimal = riemann.vtkRiemannMinimalGeodesics()
        minimal.SetMetric(twist_metric)
        minimal.SetInputConnection(field.GetOutputPort())
        for target in targets:
            minimal.AddTarget(*target)
        minimal.Update()
        self.assertEqual(minimal.GetLastError(), "")
        lines = minimal.GetOutput()
        self.assertEqual(lines.GetNumberOfLines(), len(targets))
        cd = lines.GetCellData()
        exact = np.linalg.norm(twist(targets)[:, None] - twist(seeds)[None], axis=2)
        self.assertEqual(list(vtk_to_numpy(cd.GetArray("SeedId"))), list(exact.argmin(axis=1)))
        self.assertTrue((vtk_to_numpy(cd.GetArray("Refined")) == 1).all())
        np.testing.assert_allclose(vtk_to_numpy(cd.GetArray("Length")), exact.min(axis=1), atol=1e-8)
        np.testing.assert_allclose(vtk_to_numpy(cd.GetArray("Distance")), exact.min(axis=1), atol=0.04)
        # Each line runs from its seed to its target.
        ids = vtk_to_numpy(lines.GetLines().GetConnectivityArray())
        offsets = vtk_to_numpy(lines.GetLines().GetOffsetsArray())
        points = vtk_to_numpy(lines.GetPoints().GetData())
        for line, target in enumerate(targets):
            first, last = ids[offsets[line]], ids[offsets[line + 1] - 1]
            np.testing.assert_allclose(points[first], seeds[exact[line].argmin()], atol=1e-15)
            np.testing.assert_allclose(points[last], target, atol=1e-8)

    def test_seeds_targets_and_metric_from_the_pipeline_are_the_setters(self):
        # ParaView's way: the seeds and the targets as the points of datasets,
        # the metric from a vtkRiemannMetricSource. Every array, bit for bit,
        # as with AddSeed, AddTarget and SetMetric.
        seeds = [(-0.6, 0.1, -0.2), (0.6, -0.1, 0.3)]
        targets = [(-0.2, 0.7, 0.5), (0.9, 0.8, -0.7)]

        def points(coordinates):
            from vtkmodules.vtkCommonCore import vtkPoints
            from vtkmodules.vtkCommonDataModel import vtkPolyData
            data, pts = vtkPolyData(), vtkPoints()
            pts.SetDataTypeToDouble()
            for p in coordinates:
                pts.InsertNextPoint(p)
            data.SetPoints(pts)
            return data

        def grid(field):
            field.SetBounds(-1, 1, -1, 1, -1, 1)
            field.SetDimensions(17, 17, 17)
            return field

        twist_metric = metric(TWIST)
        by_setters = grid(riemann.vtkRiemannDistanceField())
        by_setters.SetMetric(twist_metric)
        for p in seeds:
            by_setters.AddSeed(*p)
        cut_by_setters = riemann.vtkRiemannCutLocus()
        cut_by_setters.SetMetric(twist_metric)
        cut_by_setters.SetInputConnection(by_setters.GetOutputPort())
        minimal_by_setters = riemann.vtkRiemannMinimalGeodesics()
        minimal_by_setters.SetMetric(twist_metric)
        minimal_by_setters.SetInputConnection(by_setters.GetOutputPort())
        for p in targets:
            minimal_by_setters.AddTarget(*p)

        source = riemann.vtkRiemannMetricSource()
        source.SetDefinition(TWIST)
        by_pipeline = grid(riemann.vtkRiemannDistanceField())
        self.assertEqual(by_pipeline.GetMetricPort(), 1)
        by_pipeline.SetInputData(points(seeds))
        by_pipeline.SetMetricConnection(source.GetOutputPort())
        cut_by_pipeline = riemann.vtkRiemannCutLocus()
        cut_by_pipeline.SetInputConnection(by_pipeline.GetOutputPort())
        cut_by_pipeline.SetMetricConnection(source.GetOutputPort())
        minimal_by_pipeline = riemann.vtkRiemannMinimalGeodesics()
        self.assertEqual(minimal_by_pipeline.GetMetricPort(), 2)
        minimal_by_pipeline.SetInputConnection(by_pipeline.GetOutputPort())
        minimal_by_pipeline.SetInputData(1, points(targets))
        minimal_by_pipeline.SetMetricConnection(source.GetOutputPort())

        for a, b in ((by_setters, by_pipeline), (cut_by_setters, cut_by_pipeline),
                     (minimal_by_setters, minimal_by_pipeline)):
            with self.subTest(filter=a.GetClassName()):
                a.Update()
                b.Update()
                self.assertEqual(b.GetLastError(), "")
                out_a, out_b = a.GetOutput(), b.GetOutput()
                self.assertGreater(out_a.GetNumberOfPoints(), 0)
                self.assertEqual(out_a.GetNumberOfPoints(), out_b.GetNumberOfPoints())
                for attributes in ("GetPointData", "GetCellData", "GetFieldData"):
                    da, db = getattr(out_a, attributes)(), getattr(out_b, attributes)()
                    names = sorted(da.GetArrayName(i) for i in range(da.GetNumberOfArrays()))
                    self.assertEqual(names, sorted(db.GetArrayName(i) for i in range(db.GetNumberOfArrays())))
                    for name in names:
                        np.testing.assert_array_equal(vtk_to_numpy(da.GetArray(name)),
                                                      vtk_to_numpy(db.GetArray(name)), err_msg=name)
        self.assertEqual(cut_by_pipeline.GetOutput().GetCellData().GetArray("Kind").GetRange()[1], 2)
        self.assertEqual(minimal_by_pipeline.GetOutput().GetNumberOfLines(), 2)

    def test_errors_leave_an_empty_output(self):
        field = riemann.vtkRiemannDistanceField()
        field.SetMetric(metric(TWIST))
        field.Update()
        self.assertIn("no seed", field.GetLastError())
        field.AddSeed(5, 0, 0)
        field.Update()
        self.assertIn("not inside the grid", field.GetLastError())
        self.assertEqual(field.GetOutput().GetNumberOfPoints(), 0)
        cut = riemann.vtkRiemannCutLocus()
        from vtkmodules.vtkCommonDataModel import vtkImageData
        empty = vtkImageData()
        empty.SetDimensions(3, 3, 3)
        cut.SetInputData(empty)
        cut.Update()
        self.assertIn("must be a distance field", cut.GetLastError())
        minimal = riemann.vtkRiemannMinimalGeodesics()
        minimal.SetMetric(metric(TWIST))
        minimal.SetInputData(empty)
        minimal.AddTarget(0, 0, 0)
        minimal.Update()
        self.assertIn("must be a distance field", minimal.GetLastError())


if __name__ == "__main__":
    from vtkmodules.vtkCommonCore import vtkObject
    vtkObject.GlobalWarningDisplayOff()  # the errors of the last test are expected
    unittest.main()
