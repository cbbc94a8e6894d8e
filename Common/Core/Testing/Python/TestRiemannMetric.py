"""vtkRiemannMetric from Python: definitions, errors, and point queries.

The expected values are computed here with numpy from the formulas of
MATH.md (twist: g = J^T J; graph: g = I + grad f grad f^T; conformal:
g = n^2 I), and the Christoffel symbols are checked against the general
formula with finite differences of g, which also pins the layout
gamma[9 m + 3 i + j] = Gamma^m_ij.

Run by ctest with /usr/bin/python3 and PYTHONPATH set to the build's package
folder; exits non-zero on failure.
"""
import math
import os
import sys
import tempfile
import unittest

import numpy as np

import riemann

TWIST = '{"type": "diffeo", "preset": "twist", "rate": 1}'
# f = A exp(-|x - c|^2 / (2 s^2))
GAUSS_A, GAUSS_C, GAUSS_S = 0.8, np.array([0.2, -0.1, 0.3]), 0.5
GRAPH = ('{"type": "graph", "gaussians": [{"amplitude": 0.8, "center": [0.2, -0.1, 0.3], '
         '"sigma": 0.5}]}')
# n = 1 + A exp(-|x - c|^2 / (2 s^2))
CONFORMAL = ('{"type": "conformal", "constant": 1, "gaussians": [{"amplitude": 0.8, '
             '"center": [0.2, -0.1, 0.3], "sigma": 0.5}]}')
TENSOR_G = np.array([[2.0, 0.3, 0.1], [0.3, 1.5, -0.2], [0.1, -0.2, 1.0]])
TENSOR = ('{"type": "tensor", "matrix": [[2, 0.3, 0.1], [0.3, 1.5, -0.2], '
          '[0.1, -0.2, 1]]}')
EUCLIDEAN = '{"type": "euclidean"}'

POINTS = [np.array(p) for p in
          ([0.0, 0.0, 0.0], [1.0, 2.0, 3.0], [-0.7, 0.4, 0.25], [0.3, -1.1, -0.6])]


def make(definition):
    m = riemann.vtkRiemannMetric()
    ok = m.SetDefinition(definition)
    assert ok, m.GetLastError()
    return m


def tensor(m, p):
    g = [0.0] * 9
    assert m.EvaluateMetricTensor(list(p), g)
    return np.array(g).reshape(3, 3)


def inverse_tensor(m, p):
    g = [0.0] * 9
    assert m.EvaluateInverseMetricTensor(list(p), g)
    return np.array(g).reshape(3, 3)


def christoffel(m, p):
    gamma = [0.0] * 27
    assert m.EvaluateChristoffelSymbols(list(p), gamma)
    return np.array(gamma).reshape(3, 3, 3)  # [m, i, j]


def twist_jacobian(p):
    x, y, z = p
    c, s = math.cos(z), math.sin(z)
    return np.array([[c, -s, -s * x - c * y], [s, c, c * x - s * y], [0.0, 0.0, 1.0]])


def gaussian_jet(p):
    """Value, gradient and Hessian of the Gaussian term."""
    d = p - GAUSS_C
    f = GAUSS_A * math.exp(-d.dot(d) / (2 * GAUSS_S ** 2))
    grad = -f * d / GAUSS_S ** 2
    hess = f * (np.outer(d, d) / GAUSS_S ** 4 - np.eye(3) / GAUSS_S ** 2)
    return f, grad, hess


def christoffel_by_differences(m, p, h=1e-5):
    """Gamma^m_ij = 1/2 g^mk (d_i g_jk + d_j g_ik - d_k g_ij), d g by central differences."""
    dg = np.zeros((3, 3, 3))  # dg[k] = d_k g
    for k in range(3):
        e = np.zeros(3)
        e[k] = h
        dg[k] = (tensor(m, p + e) - tensor(m, p - e)) / (2 * h)
    ginv = np.linalg.inv(tensor(m, p))
    # First kind: first[i, j, k] = 1/2 (d_i g_jk + d_j g_ik - d_k g_ij).
    first = np.zeros((3, 3, 3))
    for i in range(3):
        for j in range(3):
            for k in range(3):
                first[i, j, k] = 0.5 * (dg[i, j, k] + dg[j, i, k] - dg[k, i, j])
    return np.einsum('mk,ijk->mij', ginv, first)


class MetricDefinitionTest(unittest.TestCase):
    def test_empty_metric(self):
        m = riemann.vtkRiemannMetric()
        self.assertFalse(m.HasDefinition())
        self.assertEqual(m.GetFamilyName(), '')
        self.assertEqual(m.GetDefinition(), '')
        g = [0.0] * 9
        self.assertFalse(m.EvaluateMetricTensor([0, 0, 0], g))
        self.assertFalse(m.EvaluateInverseMetricTensor([0, 0, 0], g))
        self.assertFalse(m.EvaluateChristoffelSymbols([0, 0, 0], [0.0] * 27))
        self.assertTrue(math.isnan(m.EvaluateVolumeForm([0, 0, 0])))

    def test_shallow_copy_keeps_its_metric_when_the_original_changes(self):
        original = make(GRAPH)
        self.assertTrue(original.SetTime(0.25))
        copy = riemann.vtkRiemannMetric()
        copy.ShallowCopy(original)
        self.assertEqual(copy.GetDefinition(), original.GetDefinition())
        self.assertEqual(copy.GetTime(), 0.25)
        p = [0.3, -0.2, 0.1]
        g_graph = [0.0] * 9
        self.assertTrue(copy.EvaluateMetricTensor(p, g_graph))
        # Redefine the original: the copy still answers for the graph.
        self.assertTrue(original.SetDefinition(EUCLIDEAN))
        g_copy = [0.0] * 9
        self.assertTrue(copy.EvaluateMetricTensor(p, g_copy))
        self.assertEqual(g_copy, g_graph)
        self.assertNotAlmostEqual(g_copy[0], 1.0, places=6)

    def test_families(self):
        for definition, family in ((TWIST, 'diffeo'), (GRAPH, 'graph'), (CONFORMAL, 'conformal'),
                                   (TENSOR, 'tensor'), (EUCLIDEAN, 'euclidean')):
            m = make(definition)
            self.assertTrue(m.HasDefinition())
            self.assertEqual(m.GetFamilyName(), family)
            self.assertEqual(m.GetDefinition(), definition)
            self.assertEqual(m.GetLastError(), '')

    def test_unknown_key_is_refused_and_named(self):
        m = riemann.vtkRiemannMetric()
        self.assertFalse(m.SetDefinition(
            '{"type": "graph", "gaussian": [{"amplitude": 1, "center": [0,0,0], "sigma": 1}]}'))
        error = m.GetLastError()
        self.assertIn('unknown key', error)
        self.assertIn('"gaussian"', error)
        self.assertIn('"gaussians"', error)  # what was expected
        self.assertFalse(m.HasDefinition())

    def test_error_places_are_data(self):
        # Line, column (characters), byte offset and JSON pointer of what is
        # wrong: an editor underlines from these, not from the message.
        m = riemann.vtkRiemannMetric()
        text = '{\n  "type": "diffeo",\n  "phi": ["x", "y + w", "z"]\n}'
        self.assertFalse(m.SetDefinition(text))
        self.assertEqual(m.GetLastErrorPointer(), '/phi/1')
        self.assertEqual((m.GetLastErrorLine(), m.GetLastErrorColumn()), (3, 21))
        self.assertEqual(text[m.GetLastErrorOffset()], 'w')
        self.assertFalse(m.SetDefinition('{"type": "graph",\n "f": x}'))
        self.assertEqual((m.GetLastErrorLine(), m.GetLastErrorColumn()), (2, 7))
        # About the whole metric: no place.
        self.assertFalse(m.SetDefinition('{"type": "conformal", "constant": -1}'))
        self.assertEqual((m.GetLastErrorLine(), m.GetLastErrorColumn(),
                          m.GetLastErrorOffset()), (0, 0, -1))
        self.assertTrue(m.SetDefinition('{"type": "euclidean"}'))
        self.assertEqual((m.GetLastErrorLine(), m.GetLastErrorPointer()), (0, ''))
        scene = riemann.vtkRiemannScene()
        self.assertFalse(scene.SetDefinition('{"camera": {"fov": 60,\n "positon": [0, 0, 5]}}'))
        self.assertEqual((scene.GetLastErrorLine(), scene.GetLastErrorColumn()), (2, 2))
        self.assertEqual(scene.GetLastErrorPointer(), '/camera')

    def test_bad_definitions_name_the_problem(self):
        m = riemann.vtkRiemannMetric()
        cases = [
            ('{"type": "graph", "gaussians": [', 'invalid JSON'),
            ('', 'invalid JSON'),
            ('[1, 2]', 'expected a JSON object'),
            ('{"type": "twist"}', 'unknown metric type "twist"'),
            ('{"preset": "twist"}', 'missing required key "type"'),
            ('{"type": "diffeo", "preset": "twist", "rate": "fast"}', 'metric.rate'),
            ('{"type": "graph", "gaussians": [{"amplitude": 1, "center": [0, 0], "sigma": 1}]}',
             'metric.gaussians[0].center'),
            ('{"type": "graph", "gaussians": [{"amplitude": 1, "center": [0, 0, 0], "sigma": 0}]}',
             'metric.gaussians[0].sigma'),
            ('{"type": "tensor", "matrix": [[1, 2, 0], [0, 1, 0], [0, 0, 1]]}', 'symmetric'),
            ('{"type": "tensor", "matrix": [[1, 0, 0], [0, 1, 0], [0, 0, -1]]}',
             'not positive definite'),
            # n = 1 - 2 exp(...) is negative near the centre: not a metric.
            ('{"type": "conformal", "gaussians": [{"amplitude": -2, "center": [0, 0, 0], '
             '"sigma": 0.5}]}', 'must be positive'),
            # det J = 1 + grad f . v < 0 somewhere: not a diffeomorphism.
            ('{"type": "diffeo", "preset": "bump", "gaussian": {"amplitude": 3, '
             '"center": [0, 0, 0], "sigma": 0.5}, "direction": [1, 0, 0]}',
             'not a diffeomorphism'),
            ('{"type": "diffeo", "compose": [{"preset": "twist"}, {"preset": "swirl"}]}',
             'metric.compose[1].preset'),
        ]
        for text, expected in cases:
            with self.subTest(definition=text):
                self.assertFalse(m.SetDefinition(text))
                self.assertIn(expected, m.GetLastError())
                self.assertFalse(m.HasDefinition())
        self.assertFalse(m.SetDefinition(None))
        self.assertNotEqual(m.GetLastError(), '')

    def test_failure_keeps_previous_definition(self):
        m = make(TWIST)
        p = POINTS[1]
        before = tensor(m, p)
        mtime = m.GetMTime()
        self.assertFalse(m.SetDefinition('{"type": "diffeo", "preset": "twist", "rate": 1, "x": 2}'))
        self.assertIn('"x"', m.GetLastError())
        self.assertTrue(m.HasDefinition())
        self.assertEqual(m.GetFamilyName(), 'diffeo')
        self.assertEqual(m.GetDefinition(), TWIST)
        self.assertEqual(m.GetMTime(), mtime)  # nothing changed, nothing re-executes
        np.testing.assert_array_equal(tensor(m, p), before)
        # A success clears the error and bumps the modification time.
        self.assertTrue(m.SetDefinition(EUCLIDEAN))
        self.assertEqual(m.GetLastError(), '')
        self.assertGreater(m.GetMTime(), mtime)
        np.testing.assert_allclose(tensor(m, p), np.eye(3), atol=0)

    def test_definition_file(self):
        m = riemann.vtkRiemannMetric()
        with tempfile.TemporaryDirectory() as folder:
            good = os.path.join(folder, 'twist.json')
            with open(good, 'w') as f:
                f.write(TWIST)
            self.assertTrue(m.SetDefinitionFile(good), m.GetLastError())
            self.assertEqual(m.GetFamilyName(), 'diffeo')
            bad = os.path.join(folder, 'bad.json')
            with open(bad, 'w') as f:
                f.write('{"type": "graph", "gausians": []}')
            self.assertFalse(m.SetDefinitionFile(bad))
            self.assertIn(bad, m.GetLastError())
            self.assertIn('"gausians"', m.GetLastError())
            missing = os.path.join(folder, 'missing.json')
            self.assertFalse(m.SetDefinitionFile(missing))
            self.assertIn(missing, m.GetLastError())
            self.assertEqual(m.GetFamilyName(), 'diffeo')  # still the twist
        # The shipped definitions, where the data folder has them.
        data = os.environ.get('RIEMANN_DATA_DIR')
        shipped = os.path.join(data, 'metrics') if data else None
        if shipped and os.path.isdir(shipped):
            for name in sorted(os.listdir(shipped)):
                if name.endswith('.json'):
                    with self.subTest(file=name):
                        path = os.path.join(shipped, name)
                        self.assertTrue(m.SetDefinitionFile(path), m.GetLastError())


class PointQueryTest(unittest.TestCase):
    def check_consistency(self, m, p):
        """Inverse, volume form and Christoffel symbols agree with g."""
        g = tensor(m, p)
        np.testing.assert_allclose(g, g.T, atol=1e-13)
        np.testing.assert_allclose(inverse_tensor(m, p) @ g, np.eye(3), atol=1e-12)
        self.assertAlmostEqual(m.EvaluateVolumeForm(list(p)), math.sqrt(np.linalg.det(g)),
                               delta=1e-12 * max(1.0, math.sqrt(np.linalg.det(g))))
        gamma = christoffel(m, p)
        np.testing.assert_allclose(gamma, gamma.transpose(0, 2, 1), atol=1e-13)
        np.testing.assert_allclose(gamma, christoffel_by_differences(m, p), atol=2e-7)

    def test_twist(self):
        m = make(TWIST)
        for p in POINTS:
            with self.subTest(p=p):
                j = twist_jacobian(p)
                np.testing.assert_allclose(tensor(m, p), j.T @ j, atol=1e-13)
                # A rotation in each plane z = const: det J = 1.
                self.assertAlmostEqual(m.EvaluateVolumeForm(list(p)), 1.0, delta=1e-13)
                self.check_consistency(m, p)
        # The value quoted in the docs: g at (1, 2, 3).
        np.testing.assert_allclose(tensor(m, POINTS[1]),
                                   [[1, 0, -2], [0, 1, 1], [-2, 1, 6]], atol=1e-13)

    def test_graph(self):
        m = make(GRAPH)
        for p in POINTS + [GAUSS_C + np.array([0.3, 0.2, -0.1])]:
            with self.subTest(p=p):
                _, grad, hess = gaussian_jet(p)
                w = 1.0 + grad.dot(grad)
                np.testing.assert_allclose(tensor(m, p), np.eye(3) + np.outer(grad, grad),
                                           atol=1e-13)
                np.testing.assert_allclose(inverse_tensor(m, p),
                                           np.eye(3) - np.outer(grad, grad) / w, atol=1e-13)
                self.assertAlmostEqual(m.EvaluateVolumeForm(list(p)), math.sqrt(w), delta=1e-13)
                # Gamma^m_ij = f_m f_ij / (1 + |grad f|^2)
                np.testing.assert_allclose(christoffel(m, p),
                                           np.einsum('m,ij->mij', grad, hess) / w, atol=1e-13)
                self.check_consistency(m, p)

    def test_conformal(self):
        m = make(CONFORMAL)
        for p in POINTS:
            with self.subTest(p=p):
                f, grad, _ = gaussian_jet(p)
                n = 1.0 + f
                np.testing.assert_allclose(tensor(m, p), n * n * np.eye(3), atol=1e-13)
                self.assertAlmostEqual(m.EvaluateVolumeForm(list(p)), n ** 3, delta=1e-13)
                # Gamma^m_ij = delta_mi d_j ln n + delta_mj d_i ln n - delta_ij d_m ln n
                dl = grad / n
                e = np.eye(3)
                expected = (np.einsum('mi,j->mij', e, dl) + np.einsum('mj,i->mij', e, dl)
                            - np.einsum('ij,m->mij', e, dl))
                np.testing.assert_allclose(christoffel(m, p), expected, atol=1e-13)
                self.check_consistency(m, p)

    def test_constant_tensor_and_euclidean(self):
        m = make(TENSOR)
        e = make(EUCLIDEAN)
        for p in POINTS:
            with self.subTest(p=p):
                np.testing.assert_allclose(tensor(m, p), TENSOR_G, atol=0)
                np.testing.assert_allclose(inverse_tensor(m, p), np.linalg.inv(TENSOR_G),
                                           atol=1e-13)
                self.assertAlmostEqual(m.EvaluateVolumeForm(list(p)),
                                       math.sqrt(np.linalg.det(TENSOR_G)), delta=1e-13)
                np.testing.assert_array_equal(christoffel(m, p), np.zeros((3, 3, 3)))
                np.testing.assert_array_equal(tensor(e, p), np.eye(3))
                np.testing.assert_array_equal(inverse_tensor(e, p), np.eye(3))
                np.testing.assert_array_equal(christoffel(e, p), np.zeros((3, 3, 3)))
                self.assertEqual(e.EvaluateVolumeForm(list(p)), 1.0)


if __name__ == '__main__':
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
