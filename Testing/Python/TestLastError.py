"""Every filter and renderer of the toolkit says its last error the same way
(Documentation/ErrorConventions.md): a failed update raises vtkErrorMacro,
leaves an empty output and keeps the message for GetLastError(); a good
update clears it.

Checked on one filter of each module with its own error path: the geodesic
filters (through their base vtkRiemannGeodesicAlgorithm), the field filters
(vtkRiemannFieldAlgorithm), the direction grid, the ray bundle and the CPU
ray tracer. The only algorithm without GetLastError() is
vtkRiemannSceneSource, which has no error to report (no scene: the default
scene's geometry).
"""
import inspect
import unittest

import riemann
from vtkmodules.vtkCommonCore import vtkObject
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm

EUCLIDEAN = '{"type": "euclidean"}'


def metric():
    m = riemann.vtkRiemannMetric()
    assert m.SetDefinition(EUCLIDEAN), m.GetLastError()
    return m


class LastErrorTests(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        vtkObject.GlobalWarningDisplayOff()  # the errors below are expected

    def check(self, algorithm, make_it_fail, make_it_work, expected):
        make_it_fail(algorithm)
        algorithm.Update()
        error = algorithm.GetLastError()
        self.assertIn(expected, error, type(algorithm).__name__)
        self.assertEqual(algorithm.GetOutputDataObject(0).GetNumberOfPoints(), 0)
        make_it_work(algorithm)
        algorithm.Update()
        self.assertEqual(algorithm.GetLastError(), "", type(algorithm).__name__)
        self.assertGreater(algorithm.GetOutputDataObject(0).GetNumberOfPoints(), 0)

    def test_geodesic_filters(self):
        tracer = riemann.vtkRiemannGeodesicTracer()
        tracer.SetStartPosition(0, 0, 0)
        tracer.SetStartDirection(1, 0, 0)
        self.check(tracer, lambda a: None, lambda a: a.SetMetric(metric()), "metric")

    def test_field_filters(self):
        field = riemann.vtkRiemannCurvatureField()
        field.SetDimensions(4, 4, 4)
        self.check(field, lambda a: None, lambda a: a.SetMetric(metric()), "metric")

    def test_direction_grid(self):
        grid = riemann.vtkRiemannDirectionGrid()
        self.check(grid, lambda a: a.SetNumberOfDirections(2**31 - 1),
                   lambda a: a.SetNumberOfDirections(50), "NumberOfDirections")

    def test_ray_bundle(self):
        bundle = riemann.vtkRiemannRayBundle()
        bundle.SetWidth(16)
        bundle.SetHeight(12)
        bundle.SetSubgridResolution(3)
        self.check(bundle, lambda a: None, lambda a: a.SetMetric(metric()), "metric")

    def test_cpu_ray_tracer(self):
        tracer = riemann.vtkRiemannCPURayTracer()
        tracer.SetWidth(16)
        tracer.SetHeight(12)
        self.check(tracer, lambda a: None, lambda a: a.SetMetric(metric()), "metric")

    def test_every_algorithm_but_the_scene_source_has_it(self):
        algorithms = [name for name, cls in inspect.getmembers(riemann, inspect.isclass)
                      if name.startswith("vtkRiemann") and issubclass(cls, vtkAlgorithm)]
        self.assertGreaterEqual(len(algorithms), 10, algorithms)
        without = [name for name in algorithms if not hasattr(getattr(riemann, name), "GetLastError")]
        self.assertEqual(without, ["vtkRiemannSceneSource"])


if __name__ == "__main__":
    unittest.main()
