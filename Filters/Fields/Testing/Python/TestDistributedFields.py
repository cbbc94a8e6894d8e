"""Examples/distributed_fields.py under mpirun with 2 and 3 ranks.

Each rank computes its piece of a curvature volume and its share of a fan of
geodesics and writes it with VTK's parallel XML writers; rank 0 writes the
.pvti/.pvtp summaries. Checks: the job exits 0, one piece file per rank, and
what VTK's parallel readers read back equals, bitwise, the same pipeline run
in this one process (every array of the volume at every point; the
geodesics' points and SeedIds in order).

Run by ctest with /usr/bin/python3 and PYTHONPATH set to the build tree's
package folder (see cmake/RiemannTesting.cmake). Needs openmpi-bin and
python3-mpi4py (run.sh installs them); as root mpirun needs
--allow-run-as-root, and 3 ranks on 2 cores --oversubscribe.
"""

import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPImageDataReader, vtkXMLPPolyDataReader

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "..", "..", "..", "Examples", "distributed_fields.py")
sys.path.insert(0, os.path.dirname(EXAMPLE))
import distributed_fields  # noqa: E402  (its seeds(), for the one-process reference)

import riemann  # noqa: E402

DATA = os.environ.get("RIEMANN_DATA_DIR", os.path.join(HERE, "..", "..", "..", "..", "Data"))
N, GEODESICS = 20, 17

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def reference():
    """The same pipeline in this process, whole."""
    metric = riemann.vtkRiemannMetric()
    assert metric.SetDefinitionFile(os.path.join(DATA, "metrics", "two-bumps.json"))
    field = riemann.vtkRiemannCurvatureField()
    field.SetMetric(metric)
    field.SetBounds(-2, 2, -2, 2, -2, 2)
    field.SetDimensions(N, N, N)
    field.Update()
    tracer = riemann.vtkRiemannGeodesicTracer()
    tracer.SetMetric(metric)
    tracer.SetInputData(distributed_fields.seeds(GEODESICS))
    tracer.GetIntegrationSettings().SetMaximumPropagation(6.0)
    tracer.Update()
    return field.GetOutput(), tracer.GetOutput()


def same_bits(a, b):
    return a.shape == b.shape and a.tobytes() == b.tobytes()


whole_field, whole_lines = reference()
mpirun = shutil.which("mpirun")
check(mpirun is not None, "mpirun is installed (openmpi-bin)")
for ranks in (2, 3):
    if mpirun is None:
        break
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks),
                              sys.executable, EXAMPLE, "--dimensions", str(N), "--geodesics", str(GEODESICS),
                              "--output-dir", out], capture_output=True, text=True, timeout=300)
        print(run.stdout, run.stderr[-2000:])
        check(run.returncode == 0, f"{ranks} ranks: the job exits 0 (got {run.returncode})")
        if run.returncode != 0:
            continue
        for r in range(ranks):
            check(os.path.exists(os.path.join(out, f"curvature_{r}.vti")), f"{ranks} ranks: piece {r} of the volume")
            check(os.path.exists(os.path.join(out, f"geodesics_{r}.vtp")), f"{ranks} ranks: piece {r} of the geodesics")

        reader = vtkXMLPImageDataReader()
        reader.SetFileName(os.path.join(out, "curvature.pvti"))
        reader.Update()
        volume = reader.GetOutput()
        check(volume.GetDimensions() == (N, N, N), f"{ranks} ranks: the volume is {N}^3 ({volume.GetDimensions()})")
        for a in range(whole_field.GetPointData().GetNumberOfArrays()):
            name = whole_field.GetPointData().GetArrayName(a)
            got = volume.GetPointData().GetArray(name)
            check(got is not None, f"{ranks} ranks: array {name}")
            if got is not None:
                expected = vtk_to_numpy(whole_field.GetPointData().GetArray(a))
                check(same_bits(vtk_to_numpy(got), expected), f"{ranks} ranks: {name} is bitwise the one-process volume")

        lines = vtkXMLPPolyDataReader()
        lines.SetFileName(os.path.join(out, "geodesics.pvtp"))
        lines.Update()
        read = lines.GetOutput()
        check(read.GetNumberOfLines() == whole_lines.GetNumberOfLines(),
              f"{ranks} ranks: {read.GetNumberOfLines()} geodesics of {whole_lines.GetNumberOfLines()}")
        check(same_bits(vtk_to_numpy(read.GetPoints().GetData()), vtk_to_numpy(whole_lines.GetPoints().GetData())),
              f"{ranks} ranks: the geodesics' points are bitwise the one-process ones, in order")
        check(np.array_equal(vtk_to_numpy(read.GetCellData().GetArray("SeedIds")),
                             vtk_to_numpy(whole_lines.GetCellData().GetArray("SeedIds"))),
              f"{ranks} ranks: the same SeedIds in order")

if failures:
    sys.exit(1)
print("OK")
