#!/usr/bin/python3
"""Between two points, against SciPy, in one run (issue 30's figures).

1. Distance fields. The library's eikonal solver (vtkRiemannDistanceField)
   on a 128^3 grid of [-2, 2]^3 for the two-bump graph metric
   (Data/metrics/two-bumps.json) from one seed, against SciPy's nearest
   tool: Dijkstra (scipy.sparse.csgraph.dijkstra) on the grid's 26-neighbour
   graph, each edge weighted by its length in g at its midpoint. Accuracy is
   measured where the distance is known exactly: the twist (a flat metric,
   u = |Phi(x) - Phi(p)|) on [-1, 1]^3 at 33^3 and 65^3 points, both methods.
   Dijkstra's graph distance does not converge to the geodesic distance
   (its paths are restricted to the 26 edge directions).

2. Connecting geodesics. 100 pairs (p, q) of points in [-1.5, 1.5]^3 (fixed
   seed) of the two-bump metric: the library (vtkRiemannGeodesicConnector,
   every geodesic up to arc length 1.5 |q - p| + 1 from 2000 shooting
   directions, each to |end - q| <= 1e-9) against SciPy shooting: solve_ivp
   (DOP853, rtol 1e-11, atol 1e-12) inside scipy.optimize.root (hybr, its
   own finite-difference Jacobian) on (two direction angles, length) from
   the straight line's direction and length, which finds at most one
   geodesic per pair. Printed: total and per-pair times, SciPy's failures,
   and how often the library found more than one geodesic or a shorter one
   than SciPy's.

Run: PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
       Testing/Benchmarks/between_points_vs_scipy.py [--dims 128] [--pairs 100]
Needs python3-scipy (Debian); it is not a test dependency.
"""
import argparse
import math
import os
import time

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import root
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import dijkstra
from vtkmodules.util.numpy_support import vtk_to_numpy

import riemann

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "Data")
TWIST = '{"type": "diffeo", "preset": "twist"}'

# The two-bump graph metric of Data/metrics/two-bumps.json, for NumPy.
BUMPS = [(1.0, np.array([-0.8, 0.0, 0.0]), np.array([0.5, 0.5, 0.5])),
         (0.8, np.array([0.9, 0.3, 0.0]), np.array([0.4, 0.6, 0.5]))]


def metric(text):
    m = riemann.vtkRiemannMetric()
    assert m.SetDefinition(text), m.GetLastError()
    return m


def graph_tensor(points):
    """g = I + grad f grad f^T at each point (N x 3 x 3)."""
    grad = np.zeros_like(points)
    for a, c, s in BUMPS:
        e = a * np.exp(-np.sum((points - c) ** 2 / (2 * s ** 2), axis=1))
        grad += (-(points - c) / s ** 2) * e[:, None]
    return np.eye(3)[None] + grad[:, :, None] * grad[:, None, :]


def twist_tensor(points):
    """g = J^T J of Phi(x, y, z) = (cos z x - sin z y, sin z x + cos z y, z)."""
    x, y, z = points.T
    c, s = np.cos(z), np.sin(z)
    J = np.zeros((len(points), 3, 3))
    J[:, 0, 0], J[:, 0, 1], J[:, 0, 2] = c, -s, -s * x - c * y
    J[:, 1, 0], J[:, 1, 1], J[:, 1, 2] = s, c, c * x - s * y
    J[:, 2, 2] = 1.0
    return np.einsum("nki,nkj->nij", J, J)


def twist(points):
    x, y, z = points[..., 0], points[..., 1], points[..., 2]
    return np.stack([np.cos(z) * x - np.sin(z) * y, np.sin(z) * x + np.cos(z) * y, z], -1)


def grid_points(n, half):
    axis = np.linspace(-half, half, n)
    z, y, x = np.meshgrid(axis, axis, axis, indexing="ij")  # x fastest, as VTK
    return np.stack([x.ravel(), y.ravel(), z.ravel()], 1)


def library_field(text, n, half, seed):
    field = riemann.vtkRiemannDistanceField()
    field.SetMetric(metric(text))
    field.SetBounds(-half, half, -half, half, -half, half)
    field.SetDimensions(n, n, n)
    field.AddSeed(*seed)
    start = time.perf_counter()
    field.Update()
    seconds = time.perf_counter() - start
    assert field.GetLastError() == "", field.GetLastError()
    return vtk_to_numpy(field.GetOutput().GetPointData().GetArray("Distance")).copy(), seconds


def dijkstra_field(tensor, n, half, seed):
    """Graph distance on the 26-neighbour grid; the seed's nearest point is the source."""
    start = time.perf_counter()
    points = grid_points(n, half)
    h = 2.0 * half / (n - 1)
    index = np.arange(n ** 3).reshape(n, n, n)  # [k, j, i]
    rows, cols, weights = [], [], []
    for dk in (0, 1):
        for dj in (-1, 0, 1):
            for di in (-1, 0, 1):
                if (dk, dj, di) <= (0, 0, 0):
                    continue  # each undirected edge once
                # a runs over the points whose neighbour b = a + offset exists.
                span = [slice(max(0, -d), n - max(0, d)) for d in (dk, dj, di)]
                moved = [slice(r.start + d, r.stop + d) for r, d in zip(span, (dk, dj, di))]
                a, b = index[tuple(span)].ravel(), index[tuple(moved)].ravel()
                d = np.array([di, dj, dk], float) * h
                middle = 0.5 * (points[a] + points[b])
                g = tensor(middle)
                w = np.sqrt(np.einsum("i,nij,j->n", d, g, d))
                rows.append(a)
                cols.append(b)
                weights.append(w)
    rows, cols, weights = np.concatenate(rows), np.concatenate(cols), np.concatenate(weights)
    graph = coo_matrix((weights, (rows, cols)), shape=(n ** 3, n ** 3)).tocsr()
    source = int(np.argmin(np.linalg.norm(points - np.asarray(seed), axis=1)))
    distance = dijkstra(graph, directed=False, indices=source)
    # From the source point to the seed itself, in g at the source: as the
    # library's local distance near the seed.
    offset = np.sqrt((points[source] - seed) @ tensor(points[source][None])[0] @ (points[source] - seed))
    return distance + offset, time.perf_counter() - start


def distance_fields(dims):
    print("== Distance fields ==")
    seed = np.array([-1.5, 0.0, 0.0])
    with open(os.path.join(DATA, "metrics", "two-bumps.json")) as f:
        bumps = f.read()
    ours, ours_time = library_field(bumps, dims, 2.0, seed)
    theirs, their_time = dijkstra_field(graph_tensor, dims, 2.0, seed)
    print("two bumps, %d^3 grid of [-2, 2]^3, seed (-1.5, 0, 0), %d cores:" % (dims, os.cpu_count()))
    print("  library eikonal solver   %7.2f s" % ours_time)
    print("  SciPy Dijkstra (graph)   %7.2f s   (ratio %.1f)" % (their_time, their_time / ours_time))
    print("  mean |difference| %.4f, max %.4f (Dijkstra is longer: %.0f%% of points)"
          % (np.mean(np.abs(ours - theirs)), np.max(np.abs(ours - theirs)), 100 * np.mean(theirs > ours)))
    seed = np.array([0.1, -0.15, 0.05])
    print("twist on [-1, 1]^3 (exact u = |Phi(x) - Phi(p)|), mean / max error:")
    for n in (33, 65):
        exact = np.linalg.norm(twist(grid_points(n, 1.0)) - twist(seed), axis=1)
        ours, _ = library_field(TWIST, n, 1.0, seed)
        theirs, _ = dijkstra_field(twist_tensor, n, 1.0, seed)
        print("  %3d^3  library %.4f / %.4f   Dijkstra %.4f / %.4f"
              % (n, np.mean(np.abs(ours - exact)), np.max(np.abs(ours - exact)),
                 np.mean(np.abs(theirs - exact)), np.max(np.abs(theirs - exact))))


def graph_flow(_, y):
    """x' = v, v' = -grad f (v^T H v) / (1 + |grad f|^2) for the two bumps."""
    x, v = y[:3], y[3:]
    grad = np.zeros(3)
    hess = np.zeros((3, 3))
    for a, c, s in BUMPS:
        d = (x - c) / s ** 2
        e = a * math.exp(-np.sum((x - c) ** 2 / (2 * s ** 2)))
        grad += -d * e
        hess += (np.outer(d, d) - np.diag(1 / s ** 2)) * e
    return np.concatenate([v, -grad * (v @ hess @ v) / (1 + grad @ grad)])


def unit_speed(x, u):
    g = graph_tensor(x[None])[0]
    return u / math.sqrt(u @ g @ u)


def scipy_connect(p, q):
    """Shooting with solve_ivp inside root; (length, converged)."""
    u0 = (q - p) / np.linalg.norm(q - p)
    e1 = np.cross(u0, [1, 0, 0] if abs(u0[0]) < 0.9 else [0, 1, 0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(u0, e1)

    def end(z):
        u = unit_speed(p, u0 + z[0] * e1 + z[1] * e2)
        s = z[2]
        if not s > 0:
            return np.full(3, 1e3)
        sol = solve_ivp(graph_flow, (0, s), np.concatenate([p, u]), method="DOP853",
                        rtol=1e-11, atol=1e-12)
        return sol.y[:3, -1] - q

    solution = root(end, [0.0, 0.0, np.linalg.norm(q - p)], method="hybr", options={"xtol": 1e-12})
    miss = np.linalg.norm(end(solution.x))
    return solution.x[2], miss <= 1e-9


def connections(pairs):
    print("== Connecting geodesics ==")
    rng = np.random.default_rng(30)
    ps = rng.uniform(-1.5, 1.5, (pairs, 3))
    qs = rng.uniform(-1.5, 1.5, (pairs, 3))
    with open(os.path.join(DATA, "metrics", "two-bumps.json")) as f:
        bumps = metric(f.read())
    ours_lengths, counts = [], []
    start = time.perf_counter()
    for p, q in zip(ps, qs):
        connector = riemann.vtkRiemannGeodesicConnector()
        connector.SetMetric(bumps)
        connector.SetStartPosition(*p)
        connector.SetEndPosition(*q)
        connector.SetNumberOfDirections(2000)
        connector.GetIntegrationSettings().SetMaximumPropagation(1.5 * np.linalg.norm(q - p) + 1)
        connector.Update()
        lengths = connector.GetOutput().GetCellData().GetArray("Length")
        counts.append(connector.GetNumberOfGeodesics())
        ours_lengths.append(lengths.GetValue(0) if counts[-1] else math.nan)
    ours_time = time.perf_counter() - start
    start = time.perf_counter()
    theirs = [scipy_connect(p, q) for p, q in zip(ps, qs)]
    their_time = time.perf_counter() - start
    failed = sum(not ok for _, ok in theirs)
    shorter = sum(ok and l < s - 1e-7 for l, (s, ok) in zip(ours_lengths, theirs))
    print("two bumps, %d pairs in [-1.5, 1.5]^3:" % pairs)
    print("  library (all geodesics up to 1.5|q-p|+1)  %7.2f s  (%.3f s a pair; %d geodesics, "
          "more than one for %d pairs, none for %d)"
          % (ours_time, ours_time / pairs, sum(counts), sum(c > 1 for c in counts),
             sum(c == 0 for c in counts)))
    print("  SciPy shooting (one geodesic)              %7.2f s  (%.3f s a pair; %d did not converge)"
          % (their_time, their_time / pairs, failed))
    print("  ratio SciPy / library: %.1f; the library's shortest is shorter than SciPy's for %d pairs"
          % (their_time / ours_time, shorter))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--dims", type=int, default=128)
    parser.add_argument("--pairs", type=int, default=100)
    args = parser.parse_args()
    distance_fields(args.dims)
    connections(args.pairs)


if __name__ == "__main__":
    main()
