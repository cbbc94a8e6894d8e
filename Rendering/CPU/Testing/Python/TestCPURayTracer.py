"""vtkRiemannCPURayTracer from Python: a vtkPolyData mesh in Euclidean space.

A unit sphere (vtkSphereSource, its pole vertex at (0, 0, 1)) seen from
(0, 0, 5): the centre pixel's ray runs down the axis and hits the pole at arc
length 4, with the position pseudo-colour of (0, 0, 1) over the sphere's
bounds, (0.5, 0.5, 1); a corner pixel's ray misses. Output arrays are read
back with numpy.

Run by ctest with /usr/bin/python3 and PYTHONPATH set to the build's package
folder; exits non-zero on failure.
"""
import json
import os
import tempfile
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

import riemann

SCENE = """{"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "view_up": [0, 1, 0], "fov": 40},
            "integrator": {"method": "rk4", "step": 0.05, "max_steps": 400, "max_length": 12},
            "background": [0, 0, 0], "objects": []}"""
WIDTH, HEIGHT = 65, 49


class CPURayTracerTests(unittest.TestCase):
    def test_mesh_in_euclidean_space(self):
        metric = riemann.vtkRiemannMetric()
        self.assertTrue(metric.SetDefinition('{"type": "euclidean"}'), metric.GetLastError())
        scene = riemann.vtkRiemannScene()
        self.assertTrue(scene.SetDefinition(SCENE), scene.GetLastError())
        sphere = vtkSphereSource()
        sphere.SetRadius(1.0)
        sphere.SetThetaResolution(64)
        sphere.SetPhiResolution(64)
        sphere.Update()

        tracer = riemann.vtkRiemannCPURayTracer()
        tracer.SetMetric(metric)
        tracer.SetScene(scene)
        tracer.AddMesh(sphere.GetOutput())
        tracer.SetWidth(WIDTH)
        tracer.SetHeight(HEIGHT)
        tracer.Update()
        self.assertEqual(tracer.GetNumberOfAddedMeshes(), 1)
        self.assertEqual(tracer.GetNumberOfTriangles(), sphere.GetOutput().GetNumberOfPolys())
        image = tracer.GetOutput()
        self.assertEqual(image.GetDimensions()[:2], (WIDTH, HEIGHT))
        pd = image.GetPointData()
        hit = vtk_to_numpy(pd.GetArray("HitPosition")).reshape(HEIGHT, WIDTH, 3)
        arc = vtk_to_numpy(pd.GetArray("ArcLength")).reshape(HEIGHT, WIDTH)
        reason = vtk_to_numpy(pd.GetArray("ReasonForTermination")).reshape(HEIGHT, WIDTH)
        color = vtk_to_numpy(pd.GetArray("Color")).reshape(HEIGHT, WIDTH, 3)
        steps = vtk_to_numpy(pd.GetArray("Steps")).reshape(HEIGHT, WIDTH)

        centre = (HEIGHT // 2, WIDTH // 2)
        self.assertEqual(reason[centre], 9)  # hit a surface
        np.testing.assert_allclose(hit[centre], [0.0, 0.0, 1.0], atol=1e-6)
        self.assertAlmostEqual(float(arc[centre]), 4.0, places=5)
        self.assertGreater(int(steps[centre]), 0)
        np.testing.assert_allclose(color[centre], [0.5, 0.5, 1.0], atol=2e-3)

        self.assertNotEqual(reason[0, 0], 9)
        self.assertTrue(np.all(np.isnan(hit[0, 0])))
        # Every hit lies on the tessellated sphere: within its chord error of radius 1.
        hits = hit[reason == 9]
        self.assertGreater(len(hits), 100)
        radii = np.linalg.norm(hits, axis=1)
        self.assertLess(np.max(np.abs(radii - 1.0)), 2e-3)

    def test_mesh_file_in_the_bundle_and_the_outside_view(self):
        # The same sphere as a mesh object of the scene (a .vtp file): the ray
        # bundle stops on it, and the outside view draws it.
        sphere = vtkSphereSource()
        sphere.SetRadius(1.0)
        sphere.SetThetaResolution(64)
        sphere.SetPhiResolution(64)
        with tempfile.TemporaryDirectory() as folder:
            mesh_path = os.path.join(folder, "sphere.vtp")
            writer = vtkXMLPolyDataWriter()
            writer.SetFileName(mesh_path)
            writer.SetInputConnection(sphere.GetOutputPort())
            self.assertEqual(writer.Write(), 1)
            definition = json.loads(SCENE)
            definition["objects"] = [{"type": "mesh", "file": mesh_path}]
            scene = riemann.vtkRiemannScene()
            self.assertTrue(scene.SetDefinition(json.dumps(definition)), scene.GetLastError())
        metric = riemann.vtkRiemannMetric()
        self.assertTrue(metric.SetDefinition('{"type": "euclidean"}'), metric.GetLastError())

        bundle = riemann.vtkRiemannRayBundle()
        bundle.SetMetric(metric)
        bundle.SetScene(scene)
        bundle.SetWidth(WIDTH)
        bundle.SetHeight(HEIGHT)
        bundle.SetSubgridResolution(9)
        bundle.Update()
        cd = bundle.GetOutput().GetCellData()
        hit = vtk_to_numpy(cd.GetArray("Hit")).astype(bool)
        positions = vtk_to_numpy(cd.GetArray("HitPosition"))[hit]
        # The middle of the 9 x 9 sub-grid looks at the sphere; the corners miss it.
        self.assertGreater(hit.sum(), 4)
        self.assertLess(hit.sum(), 81)
        self.assertLess(np.max(np.abs(np.linalg.norm(positions, axis=1) - 1.0)), 2e-3)

        outside = riemann.vtkRiemannSceneSource()
        outside.SetScene(scene)
        outside.Update()
        self.assertEqual(outside.GetOutput().GetNumberOfPoints(), sphere.GetOutput().GetNumberOfPoints())
        self.assertEqual(outside.GetOutput().GetNumberOfPolys(), sphere.GetOutput().GetNumberOfPolys())
        self.assertIsNotNone(outside.GetOutput().GetPointData().GetArray("Colors"))

    def test_no_metric_gives_empty_output(self):
        tracer = riemann.vtkRiemannCPURayTracer()
        tracer.SetWidth(8)
        tracer.SetHeight(8)
        tracer.GlobalWarningDisplayOff()
        tracer.Update()
        self.assertEqual(tracer.GetOutput().GetNumberOfPoints(), 0)

    def test_absurd_size_is_refused_before_allocating(self):
        metric = riemann.vtkRiemannMetric()
        self.assertTrue(metric.SetDefinition('{"type": "euclidean"}'), metric.GetLastError())
        tracer = riemann.vtkRiemannCPURayTracer()
        tracer.SetMetric(metric)
        tracer.SetWidth(65536)
        tracer.SetHeight(4096)  # 268 million pixels: about 24 GiB
        errors = []
        # An observer takes the error instead of the output window.
        tracer.AddObserver("ErrorEvent", lambda caller, event: errors.append(event))
        tracer.Update()
        self.assertEqual(len(errors), 1)
        self.assertEqual(tracer.GetOutput().GetNumberOfPoints(), 0)


if __name__ == "__main__":
    unittest.main()
