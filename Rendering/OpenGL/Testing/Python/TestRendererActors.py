"""VTK actors in the inside view, from Python: Examples/actors_through_metric.py.

The example adds a vtkParametricFunctionSource torus and a transformed
vtkSphereSource to a renderer drawn by vtkRiemannRayTracePass with
UseRendererProps on, with a text overlay, in the two-bump metric; with --cpu
it renders the same actors with vtkRiemannCPURayTracer.AddActor. Checks: the
example runs, the pass drew both actors and the text, and the GPU picture
equals the CPU one (mean difference under 0.1 of 255 outside the text, at
most 0.5 % of those pixels apart by more than 24).

Run by ctest under xvfb-run with /usr/bin/python3 and PYTHONPATH set to the
build tree's package folder (see cmake/RiemannTesting.cmake).
"""

import os
import subprocess
import sys
import tempfile

from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "..", "..", "..", "Examples", "actors_through_metric.py")
WIDTH, HEIGHT = 160, 120
TEXT_ROWS = 36  # the overlay's band at the bottom of the GPU picture

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def rows(path):
    """RGB rows of a PNG, bottom row first (as VTK reads it)."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
    return pixels.reshape(HEIGHT, WIDTH, -1)[:, :, :3].astype(int)


with tempfile.TemporaryDirectory() as tmp:
    gpu_png = os.path.join(tmp, "gpu.png")
    cpu_png = os.path.join(tmp, "cpu.png")
    run = subprocess.run([sys.executable, EXAMPLE, "--size", f"{WIDTH}x{HEIGHT}", "--output", gpu_png,
                          "--cpu", cpu_png], capture_output=True, text=True)
    print(run.stdout, run.stderr)
    check(run.returncode == 0, f"the example exits 0 (got {run.returncode})")
    check("3 props drawn" in run.stdout, "the torus, the sphere and the text are drawn")
    if run.returncode == 0:
        gpu = rows(gpu_png)
        cpu = rows(cpu_png)
        difference = abs(gpu - cpu).max(axis=2)[TEXT_ROWS:]
        mean = difference.mean()
        above = (difference > 24).mean()
        print(f"actors, GPU vs CPU outside the text: mean {mean:.4f}, above 24: {100 * above:.3f}%")
        check(mean < 0.1, f"mean difference {mean}")
        check(above < 0.005, f"pixels apart by more than 24: {100 * above}%")
        text = abs(gpu - cpu).max(axis=2)[:TEXT_ROWS]
        check((text > 100).sum() > 30, "the text is on the GPU picture only")

if failures:
    sys.exit(1)
print("OK")
