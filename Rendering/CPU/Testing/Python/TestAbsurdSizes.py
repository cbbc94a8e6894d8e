"""Absurd sizes from Python are clear errors, not aborts or silent clamps.

Before: SetNumberOfDirections(2**31 - 1) on the conjugate locus or the
direction grid aborted the interpreter (an uncaught bad_alloc);
vtkRiemannRayBundle.SetSubgridResolution(2**31 - 1) took 11.8 GB, then
aborted; the CPU tracer turned a width of 2**31 - 1 into 65536 and 0 into 1
without a word. Now each filter keeps the value, reports an error through
VTK's error mechanism when it runs, and gives an empty output.

Run by ctest with /usr/bin/python3 and PYTHONPATH set to the build's package
folder; exits non-zero on failure.
"""
import unittest

import vtk

import riemann

BIG = 2**31 - 1
TWIST = '{"type": "diffeo", "preset": "twist"}'


class Errors:
    """The ErrorEvents of one VTK object (they would otherwise print)."""

    def __init__(self, obj):
        self.messages = []
        obj.AddObserver(vtk.vtkCommand.ErrorEvent, self.keep)

    def keep(self, _obj, _event, message=None):
        self.messages.append(str(message))

    keep.CallDataType = vtk.VTK_STRING

    def text(self):
        return "\n".join(self.messages)


def metric():
    m = riemann.vtkRiemannMetric()
    assert m.SetDefinition(TWIST), m.GetLastError()
    return m


class AbsurdSizeTests(unittest.TestCase):
    def test_directions(self):
        for make in (riemann.vtkRiemannConjugateLocus, riemann.vtkRiemannExponentialMap):
            with self.subTest(make.__name__):
                f = make()
                f.SetMetric(metric())
                f.SetNumberOfDirections(BIG)
                self.assertEqual(f.GetNumberOfDirections(), BIG, "kept, not clamped")
                errors = Errors(f)
                f.Update()
                # The exponential map's own sample budget speaks first there. The
                # cap is the declared maximum of NumberOfDirections (one for the
                # grid, the filters and the CLI: vtkRiemannDirectionGrid.settings.json).
                self.assertRegex(errors.text(), "NumberOfDirections: 2147483647 directions; at most 1000000 "
                                 "|Too many samples: 2147483647 directions")
                self.assertEqual(f.GetOutput().GetNumberOfPoints(), 0)
        grid = riemann.vtkRiemannDirectionGrid()
        grid.SetNumberOfDirections(BIG)
        errors = Errors(grid)
        grid.Update()
        self.assertIn("at most 1000000 ", errors.text())
        self.assertEqual(grid.GetOutput().GetNumberOfPoints(), 0)

    def test_ray_bundle(self):
        for setting, value, reason in (
            ("SetSubgridResolution", BIG, "SubgridResolution 2147483647: must be 1 to 4096"),
            ("SetWidth", 0, "Width 0: must be 1 to 65536"),
            ("SetHeight", BIG, "Height 2147483647: must be 1 to 65536"),
            # in range, but 4096^2 rays of 1000 steps: 1.7e10 points
            ("SetSubgridResolution", 4096, "more than the 1e+08 a bundle holds"),
        ):
            with self.subTest(setting=setting, value=value):
                bundle = riemann.vtkRiemannRayBundle()
                bundle.SetMetric(metric())
                getattr(bundle, setting)(value)
                errors = Errors(bundle)
                bundle.Update()
                self.assertIn(reason, errors.text())
                self.assertEqual(bundle.GetOutput().GetNumberOfPoints(), 0)

    def test_cpu_tracer_sides(self):
        for width, height in ((BIG, 480), (0, 480), (640, -5)):
            with self.subTest(width=width, height=height):
                tracer = riemann.vtkRiemannCPURayTracer()
                tracer.SetMetric(metric())
                tracer.SetWidth(width)
                tracer.SetHeight(height)
                self.assertEqual((tracer.GetWidth(), tracer.GetHeight()), (width, height))
                errors = Errors(tracer)
                tracer.Update()
                self.assertIn("each side must be 1 to 65536", errors.text())
                self.assertEqual(tracer.GetOutput().GetNumberOfPoints(), 0)


if __name__ == "__main__":
    unittest.main()
