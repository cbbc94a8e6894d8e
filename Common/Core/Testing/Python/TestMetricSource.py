"""vtkRiemannMetricSource and the filters' metric port (SetMetricConnection).

A metric that comes through the pipeline must give what SetMetric() gives,
bit for bit: the geodesic tracer and the curvature field on the same
definition. Parameters given through SetParameter equal the definition with
those values written in; the pipeline's time reaches the source (an animated
definition at UPDATE_TIME_STEP 1 equals SetTime(1), and differs from t = 0),
and the filters advertise the source's time steps. A bad definition or an
unknown parameter is an error of the source, and the filter downstream says
its metric input has none: both outputs empty.

Run by ctest with /usr/bin/python3 and PYTHONPATH set to the build's package
folder; exits non-zero on failure.
"""
import json
import os
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkCommonCore import vtkCommand

import riemann

BUMP = {"type": "conformal", "n": "1 + a*exp(-(x^2+y^2+z^2)/(2*s^2))", "parameters": {"a": 1.0, "s": 0.5}}
WAVY = os.path.join(os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(__file__), "../../../../Data")),
                    "metrics", "wavy-diffeo.json")


class Errors:
    """Counts the error events of VTK objects (and keeps them off the console)."""

    def __init__(self, *objects):
        self.messages = []
        for o in objects:
            o.AddObserver(vtkCommand.ErrorEvent, self.on_error)

    def on_error(self, caller, event, message=None):
        self.messages.append(str(message))

    on_error.CallDataType = "string0"


def tracer_points(tracer):
    tracer.Update()
    return vtk_to_numpy(tracer.GetOutput().GetPoints().GetData()).copy()


def new_tracer():
    tracer = riemann.vtkRiemannGeodesicTracer()
    tracer.SetStartPosition(-1.0, 0.3, 0.1)
    tracer.SetStartDirection(1.0, 0.0, 0.0)
    tracer.SetNumberOfDirections(5)
    tracer.GetIntegrationSettings().SetMaximumPropagation(2.0)
    return tracer


def curvature(field):
    field.SetDimensions(9, 9, 9)
    field.Update()
    return vtk_to_numpy(field.GetOutput().GetPointData().GetArray("ScalarCurvature")).copy()


class MetricSourceTests(unittest.TestCase):
    def test_connection_equals_set_metric(self):
        source = riemann.vtkRiemannMetricSource()
        source.SetDefinition(json.dumps(BUMP))
        through_pipeline = new_tracer()
        through_pipeline.SetMetricConnection(source.GetOutputPort())
        metric = riemann.vtkRiemannMetric()
        self.assertTrue(metric.SetDefinition(json.dumps(BUMP)), metric.GetLastError())
        direct = new_tracer()
        direct.SetMetric(metric)
        a, b = tracer_points(through_pipeline), tracer_points(direct)
        self.assertGreater(len(a), 100)
        self.assertTrue(np.array_equal(a, b), "the pipeline's metric traces other geodesics")
        self.assertEqual(through_pipeline.GetMetricPort(), 4)  # after the seeds and the three masks

        field = riemann.vtkRiemannCurvatureField()
        field.SetMetricConnection(source.GetOutputPort())
        reference = riemann.vtkRiemannCurvatureField()
        reference.SetMetric(metric)
        self.assertTrue(np.array_equal(curvature(field), curvature(reference)))

    def test_parameters_are_the_definition_with_their_values(self):
        source = riemann.vtkRiemannMetricSource()
        source.SetDefinition(json.dumps(BUMP))
        source.SetParameter("a", 0.25)
        tracer = new_tracer()
        tracer.SetMetricConnection(source.GetOutputPort())
        edited = dict(BUMP, parameters={"a": 0.25, "s": 0.5})
        metric = riemann.vtkRiemannMetric()
        self.assertTrue(metric.SetDefinition(json.dumps(edited)), metric.GetLastError())
        direct = new_tracer()
        direct.SetMetric(metric)
        self.assertTrue(np.array_equal(tracer_points(tracer), tracer_points(direct)))
        # Another value re-executes the source and the tracer (the pipeline's MTime).
        before = tracer_points(tracer)
        source.SetParameter("a", 1.0)
        self.assertFalse(np.array_equal(tracer_points(tracer), before))

    def test_pipeline_time_reaches_the_source(self):
        source = riemann.vtkRiemannMetricSource()
        source.SetDefinitionFile(WAVY)
        field = riemann.vtkRiemannCurvatureField()
        field.SetMetricConnection(source.GetOutputPort())
        field.SetDimensions(9, 9, 9)
        field.UpdateInformation()
        steps = field.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
        self.assertEqual(len(steps), 11)
        self.assertEqual((steps[0], steps[-1]), (0.0, 1.0))
        field.UpdateTimeStep(1.0)
        at_one = vtk_to_numpy(field.GetOutput().GetPointData().GetArray("ScalarCurvature")).copy()
        field.UpdateTimeStep(0.0)
        at_zero = vtk_to_numpy(field.GetOutput().GetPointData().GetArray("ScalarCurvature")).copy()
        metric = riemann.vtkRiemannMetric()
        self.assertTrue(metric.SetDefinitionFile(WAVY), metric.GetLastError())
        self.assertTrue(metric.SetTime(1.0), metric.GetLastError())
        reference = riemann.vtkRiemannCurvatureField()
        reference.SetMetric(metric)
        self.assertTrue(np.array_equal(at_one, curvature(reference)), "t = 1 through the pipeline differs")
        self.assertFalse(np.array_equal(at_zero, at_one), "the animated metric did not change with time")

    def test_bad_definition_and_unknown_parameter(self):
        for definition, parameter, expected in [
                ('{"type": "graph", "f": "x^2 + q"}', None, "q"),
                (json.dumps(BUMP), "b", 'no parameter "b"')]:
            source = riemann.vtkRiemannMetricSource()
            source.SetDefinition(definition)
            if parameter:
                source.SetParameter(parameter, 2.0)
            tracer = new_tracer()
            tracer.SetMetricConnection(source.GetOutputPort())
            errors = Errors(source, tracer, source.GetExecutive(), tracer.GetExecutive())
            tracer.Update()
            self.assertIn(expected, source.GetLastError())
            self.assertIn("carries no metric", tracer.GetLastError())
            self.assertEqual(tracer.GetOutput().GetNumberOfPoints(), 0)
            self.assertTrue(errors.messages)


if __name__ == "__main__":
    unittest.main()
