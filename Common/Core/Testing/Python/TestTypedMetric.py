"""Typed (expression) metrics from Python: values, parameters, time and errors."""
import math
import unittest

import riemann


class TypedMetricTests(unittest.TestCase):
    def test_typed_graph_equals_closed_form(self):
        m = riemann.vtkRiemannMetric()
        ok = m.SetDefinition('{"type": "graph", "parameters": {"a": 0.5}, "f": "a*(x^2 + y^2 - z^2)"}')
        self.assertTrue(ok, m.GetLastError())
        g = [0.0] * 9
        self.assertTrue(m.EvaluateMetricTensor((1.0, 2.0, 3.0), g))
        grad = (1.0, 2.0, -3.0)  # a * (2x, 2y, -2z) with a = 0.5
        for i in range(3):
            for j in range(3):
                self.assertAlmostEqual(g[3 * i + j], (i == j) + grad[i] * grad[j], places=12)

    def test_animated_parameter_follows_time(self):
        m = riemann.vtkRiemannMetric()
        self.assertTrue(m.SetDefinition('{"type": "conformal", "parameters": {"k": {"from": 1, "to": 3}},'
                                        ' "n": "k + 0*x"}'), m.GetLastError())
        for t in (0.0, 0.5, 1.0):
            self.assertTrue(m.SetTime(t), m.GetLastError())
            self.assertAlmostEqual(m.EvaluateVolumeForm((0.1, 0.2, 0.3)), (1 + 2 * t) ** 3, places=12)

    def test_errors_name_the_place(self):
        m = riemann.vtkRiemannMetric()
        self.assertFalse(m.SetDefinition('{"type": "diffeo", "phi": ["x", "y + ", "z"]}'))
        self.assertIn("metric.phi[1]: column", m.GetLastError())
        self.assertFalse(m.SetDefinition('{"type": "graph", "f": "x^2 + w"}'))
        self.assertIn('unknown symbol "w"', m.GetLastError())

    def test_degenerate_region_is_reported_at_a_point(self):
        m = riemann.vtkRiemannMetric()
        self.assertTrue(m.SetDefinition('{"type": "conformal", "n": "2/(1 - x^2 - y^2 - z^2)"}'))
        g = [0.0] * 9
        self.assertTrue(m.EvaluateMetricTensor((0.1, 0.0, 0.0), g))
        self.assertFalse(m.EvaluateMetricTensor((1.5, 0.0, 0.0), g))
        self.assertTrue(math.isnan(m.EvaluateVolumeForm((1.5, 0.0, 0.0))))


if __name__ == "__main__":
    unittest.main()
