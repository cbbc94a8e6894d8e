#!/usr/bin/python3
"""200 geodesics of the 8-Gaussian graph metric: `riemann trace` and the
library in process against SciPy's solve_ivp, at equal endpoint accuracy.

Both integrate the same geodesics with the same Dormand-Prince 5(4) tableau
(SciPy's "RK45"); the flow for SciPy is written with NumPy over the eight
bumps (x' = v, v' = -grad f (v^T H v) / (1 + |grad f|^2)). Accuracy is
matched first: the reference endpoints come from the library at tolerance
1e-13; SciPy's rtol (= atol) is the loosest of a ladder whose worst
endpoint error is not larger than the library's at its default 1e-8.

Printed (all measured in this one run, medians):
- whole process: `riemann trace` wall time (start-up included) against the
  SciPy loop's time (Python start-up not counted: in its favour);
- in process: vtkRiemannGeodesicTracer.Update() from Python against the
  SciPy loop, per geodesic.

Run: PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
       Testing/Benchmarks/trace_vs_scipy.py [--riemann build/bin/riemann]
Needs python3-scipy (Debian); it is not a test dependency.
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
METRIC = os.path.join(ROOT, "Data", "metrics", "eight-gaussians.json")
COUNT = 200
LENGTH = 10.0
TOLERANCE = 1e-8


def bumps():
    with open(METRIC) as f:
        definition = json.load(f)
    a, c, w = [], [], []
    for g in definition["gaussians"]:
        sigma = g["sigma"] if isinstance(g["sigma"], list) else [g["sigma"]] * 3
        a.append(g["amplitude"])
        c.append(g["center"])
        w.append([1.0 / (s * s) for s in sigma])
    return np.array(a), np.array(c), np.array(w)


AMPLITUDE, CENTER, INVERSE_VARIANCE = bumps()


def flow(_, y):
    x, v = y[:3], y[3:]
    d = x - CENTER
    u = INVERSE_VARIANCE * d
    f = AMPLITUDE * np.exp(-0.5 * np.sum(d * u, axis=1))
    gradient = -(f[:, None] * u).sum(axis=0)
    hessian = np.einsum("k,ki,kj->ij", f, u, u) - np.diag((f[:, None] * INVERSE_VARIANCE).sum(axis=0))
    a = -gradient * (v @ hessian @ v) / (1.0 + gradient @ gradient)
    return np.concatenate([v, a])


def metric_tensor(x):
    d = x - CENTER
    u = INVERSE_VARIANCE * d
    f = AMPLITUDE * np.exp(-0.5 * np.sum(d * u, axis=1))
    gradient = -(f[:, None] * u).sum(axis=0)
    return np.eye(3) + np.outer(gradient, gradient)


def seeds():
    """200 seeds on a sphere of radius 2.2 aimed through the bumps' region."""
    golden = math.pi * (3.0 - math.sqrt(5.0))
    points, directions = [], []
    for i in range(COUNT):
        z = 1.0 - (2.0 * i + 1.0) / COUNT
        r = math.sqrt(1.0 - z * z)
        p = 2.2 * np.array([r * math.cos(golden * i), r * math.sin(golden * i), z])
        target = 0.6 * np.array([math.sin(1.7 * i), math.cos(1.1 * i), math.sin(0.9 * i)])
        d = target - p
        d /= math.sqrt(d @ metric_tensor(p) @ d)  # unit speed in g, as the tracer does
        points.append(p)
        directions.append(d)
    return np.array(points), np.array(directions)


def scipy_endpoints(points, directions, rtol):
    from scipy.integrate import solve_ivp
    ends = []
    for p, d in zip(points, directions):
        solution = solve_ivp(flow, (0.0, LENGTH), np.concatenate([p, d]), method="RK45",
                             rtol=rtol, atol=rtol)
        ends.append(solution.y[:3, -1])
    return np.array(ends)


def write_seeds(path, points, directions):
    with open(path, "w") as f:
        f.write("x,y,z,dx,dy,dz\n")
        for p, d in zip(points, directions):
            f.write(",".join(repr(float(c)) for c in (*p, *d)) + "\n")


def read_endpoints(path):
    """Last point of each SeedId from `riemann trace`'s CSV."""
    import csv
    ends = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            ends[int(row["seed_id"])] = [float(row["x"]), float(row["y"]), float(row["z"])]
    return np.array([ends[i] for i in range(COUNT)])


def run_cli(riemann, seeds_csv, output, tolerance):
    command = [riemann, "trace", "-m", METRIC, "--seeds", seeds_csv, "-l", str(LENGTH),
               "--integrator", "dp45", "--tolerance", str(tolerance), "-o", output]
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def library_in_process(points, directions, repeats):
    import riemann
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    metric = riemann.vtkRiemannMetric()
    with open(METRIC) as f:
        assert metric.SetDefinition(f.read()), metric.GetLastError()
    seeds_data = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(points.copy(), deep=True))
    seeds_data.SetPoints(vtk_points)
    direction = numpy_to_vtk(directions.copy(), deep=True)
    direction.SetName("Direction")
    seeds_data.GetPointData().AddArray(direction)
    tracer = riemann.vtkRiemannGeodesicTracer()
    tracer.SetMetric(metric)
    tracer.SetInputData(seeds_data)
    settings = tracer.GetIntegrationSettings()
    settings.SetIntegratorTypeToDormandPrince45()
    settings.SetMaximumError(TOLERANCE)
    settings.SetMaximumPropagation(LENGTH)
    times = []
    for _ in range(repeats):
        tracer.Modified()
        start = time.perf_counter()
        tracer.Update()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--riemann", default=os.path.join(ROOT, "build", "bin", "riemann"))
    parser.add_argument("--runs", type=int, default=11)
    args = parser.parse_args()
    points, directions = seeds()
    with tempfile.TemporaryDirectory() as tmp:
        seeds_csv = os.path.join(tmp, "seeds.csv")
        write_seeds(seeds_csv, points, directions)
        # 1. Accuracy: the library at 1e-13 is the reference.
        reference_csv = os.path.join(tmp, "reference.csv")
        run_cli(args.riemann, seeds_csv, reference_csv, 1e-13)
        reference = read_endpoints(reference_csv)
        ours_csv = os.path.join(tmp, "ours.csv")
        run_cli(args.riemann, seeds_csv, ours_csv, TOLERANCE)
        our_error = np.abs(read_endpoints(ours_csv) - reference).max()
        chosen = None
        for rtol in (1e-6, 3e-7, 1e-7, 3e-8, 1e-8, 3e-9, 1e-9, 3e-10, 1e-10):
            error = np.abs(scipy_endpoints(points, directions, rtol) - reference).max()
            print(f"scipy RK45 rtol=atol={rtol:g}: worst endpoint error {error:.2e}")
            if error <= our_error:
                chosen = rtol
                break
        print(f"riemann dp45 tolerance {TOLERANCE:g}: worst endpoint error {our_error:.2e}")
        if chosen is None:
            sys.exit("SciPy never reached the library's accuracy on the ladder")
        # 2. Times, medians in one run.
        cli = statistics.median(run_cli(args.riemann, seeds_csv, ours_csv, TOLERANCE)
                                for _ in range(args.runs))
        scipy_times = []
        for _ in range(3):
            start = time.perf_counter()
            scipy_endpoints(points, directions, chosen)
            scipy_times.append(time.perf_counter() - start)
        scipy = statistics.median(scipy_times)
        in_process = library_in_process(points, directions, args.runs)
    print(f"SciPy solve_ivp RK45 (rtol {chosen:g}), {COUNT} geodesics: {scipy * 1e3:.1f} ms "
          f"({scipy / COUNT * 1e6:.0f} us per geodesic)")
    print(f"riemann trace, whole process: {cli * 1e3:.1f} ms  -> {scipy / cli:.1f}x SciPy")
    print(f"vtkRiemannGeodesicTracer in process: {in_process * 1e3:.2f} ms "
          f"({in_process / COUNT * 1e6:.1f} us per geodesic) -> {scipy / in_process:.0f}x SciPy")


if __name__ == "__main__":
    main()
