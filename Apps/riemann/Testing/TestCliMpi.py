"""Tests of `mpirun -np N riemann ...`: every command on N = 2 and 3 ranks
against the same command in one process.

- fields: the .pvti pieces read back by VTK's parallel reader hold bitwise the
  one-process arrays; --gather writes byte for byte the one-process .vti;
- trace, expmap (rays), conjugate (points): --gather writes byte for byte the
  one-process .vtp and .csv; the .pvtp pieces read back in order are the
  one-process lines and points, bitwise, with the same ids;
- expmap's wavefronts and conjugate's caustic sheets: pieces hold ghost copies
  of their neighbours' corners; gathered, every point is there once, and the
  points (by DirectionId and Radius or Sheet) and triangles are the
  one-process output's, bitwise;
- render --backend cpu: the gathered PNG is byte for byte the one-process
  PNG, the EXR's colour and AOV channels are identical (idiff, no tolerance);
- a rank that fails stops the job: one message, non-zero exit, no output
  file, no hang (each run has a timeout); usage errors are printed once.
"""
import filecmp
import os
import shutil
import subprocess
import tempfile
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import (vtkXMLImageDataReader, vtkXMLPImageDataReader, vtkXMLPolyDataReader,
                                 vtkXMLPPolyDataReader)

EXE = os.environ.get("RIEMANN_EXECUTABLE", "riemann")
DATA = os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(__file__), "../../../Data"))
METRICS = os.path.join(DATA, "metrics")
MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe"]
# The astigmatic lens seen along its axis: two caustic sheets with cusp edges.
CONJUGATE = ["-m", os.path.join(METRICS, "astigmatic-lens.json"), "--seed", "-3,0,0",
             "--cone-axis", "1,0,0", "--cone-angle", "14", "-n", "300", "-k", "3", "-l", "9"]


def run(*args, ranks=None, env=None):
    """riemann alone, or under mpirun with `ranks` processes: (status, stderr)."""
    env = env or {}
    command = [EXE, *args]
    if ranks is not None:
        forwarded = [flag for name in env for flag in ("-x", name)]
        command = [*MPIRUN, "-np", str(ranks), *forwarded, *command]
    result = subprocess.run(command, capture_output=True, text=True, timeout=120,
                            env={**os.environ, **env})
    return result.returncode, result.stderr


def read(path):
    reader = {".vti": vtkXMLImageDataReader, ".pvti": vtkXMLPImageDataReader,
              ".vtp": vtkXMLPolyDataReader, ".pvtp": vtkXMLPPolyDataReader}[os.path.splitext(path)[1]]()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def arrays(attributes):
    """{name: numpy array} of a vtkPointData or vtkCellData, ghost marks left out."""
    return {attributes.GetArrayName(i): vtk_to_numpy(attributes.GetArray(i))
            for i in range(attributes.GetNumberOfArrays())
            if attributes.GetArrayName(i) != "vtkGhostType"}


def owned_points(data, keys):
    """{key tuple: (coordinates, point arrays)} of the points not marked ghost."""
    points = vtk_to_numpy(data.GetPoints().GetData())
    pd = data.GetPointData()
    ghost = pd.GetArray("vtkGhostType")
    values = arrays(pd)
    owned = {}
    for i in range(data.GetNumberOfPoints()):
        if ghost is not None and ghost.GetValue(i) != 0:
            continue
        key = tuple(float(values[k][i]) for k in keys)
        assert key not in owned, f"point {key} twice"
        owned[key] = (points[i].tobytes(), tuple(v[i].tobytes() for _, v in sorted(values.items())))
    return owned


def triangles(data, keys):
    """Sorted triangles by their corners' keys and their cell data."""
    values = arrays(data.GetPointData())
    cells = arrays(data.GetCellData())
    polys = vtk_to_numpy(data.GetPolys().GetConnectivityArray())
    result = []
    for t in range(data.GetNumberOfPolys()):
        corners = tuple(tuple(float(values[k][c]) for k in keys) for c in polys[3 * t:3 * t + 3])
        result.append((corners, tuple(float(v[t]) for _, v in sorted(cells.items()))))
    return sorted(result)


class MpiTests(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.dir, name)

    def ok(self, *args, ranks=None):
        status, err = run(*args, ranks=ranks)
        self.assertEqual(status, 0, err)
        return err

    def assertSameArrays(self, a, b):
        self.assertEqual(sorted(a), sorted(b))
        for name in a:
            self.assertEqual(a[name].tobytes(), b[name].tobytes(), name)

    def test_fields_pieces_and_gathered_equal_one_process(self):
        args = ["fields", "-m", os.path.join(METRICS, "gaussian-bump.json"), "--dims", "30,26,22"]
        self.ok(*args, "-o", self.path("one.vti"))
        one = read(self.path("one.vti"))
        for ranks in (2, 3):
            with self.subTest(ranks=ranks):
                err = self.ok(*args, "-o", self.path("par.pvti"), ranks=ranks)
                self.assertEqual(err.count("riemann fields:"), 1, err)  # rank 0 speaks for the job
                self.assertEqual(sorted(os.listdir(self.path("par"))),
                                 [f"par_{r}.vti" for r in range(ranks)])
                pieces = read(self.path("par.pvti"))
                self.assertEqual(pieces.GetExtent(), one.GetExtent())
                self.assertSameArrays(arrays(pieces.GetPointData()), arrays(one.GetPointData()))
                self.ok(*args, "-o", self.path("gathered.vti"), "--gather", ranks=ranks)
                self.assertTrue(filecmp.cmp(self.path("one.vti"), self.path("gathered.vti"), shallow=False))
                self.ok(*args, "-o", self.path("gathered.csv"), "--gather", ranks=ranks)
        self.ok(*args, "-o", self.path("one.csv"))
        self.assertTrue(filecmp.cmp(self.path("one.csv"), self.path("gathered.csv"), shallow=False))
        # Dotfiles of the staging folder are gone; only the outputs remain.
        self.assertFalse([f for f in os.listdir(self.dir) if f.startswith(".")])

    def test_trace_pieces_and_gathered_equal_one_process(self):
        seeds = self.path("seeds.csv")
        rng = np.random.default_rng(1)
        with open(seeds, "w") as f:
            f.write("x,y,z,dx,dy,dz\n")
            for row in rng.uniform(-1, 1, (40, 6)):
                f.write(",".join(repr(v) for v in row) + "\n")
        args = ["trace", "-m", os.path.join(METRICS, "two-bumps.json"), "--seeds", seeds, "-l", "3"]
        self.ok(*args, "-o", self.path("one.vtp"))
        self.ok(*args, "-o", self.path("one.csv"))
        one = read(self.path("one.vtp"))
        for ranks in (2, 3):
            with self.subTest(ranks=ranks):
                for name in ("gathered.vtp", "gathered.csv"):
                    self.ok(*args, "-o", self.path(name), "--gather", ranks=ranks)
                    self.assertTrue(filecmp.cmp(self.path("one" + name[-4:]), self.path(name), shallow=False))
                self.ok(*args, "-o", self.path("par.pvtp"), ranks=ranks)
                pieces = read(self.path("par.pvtp"))
                self.assertEqual(pieces.GetNumberOfLines(), 40)
                self.assertEqual(vtk_to_numpy(pieces.GetPoints().GetData()).tobytes(),
                                 vtk_to_numpy(one.GetPoints().GetData()).tobytes())
                self.assertSameArrays(arrays(pieces.GetPointData()), arrays(one.GetPointData()))
                self.assertSameArrays(arrays(pieces.GetCellData()), arrays(one.GetCellData()))

    def test_expmap_rays_and_wavefronts(self):
        args = ["expmap", "-m", os.path.join(METRICS, "two-bumps.json"), "--directions", "300",
                "-l", "3", "--radii", "1,2.5"]
        self.ok(*args, "-o", self.path("one.vtp"), "--wavefronts", self.path("w1.vtp"))
        keys = ("DirectionId", "Radius")
        one = read(self.path("w1.vtp"))
        for ranks in (2, 3):
            with self.subTest(ranks=ranks):
                self.ok(*args, "-o", self.path("g.vtp"), "--wavefronts", self.path("wg.vtp"), "--gather",
                        ranks=ranks)
                self.assertTrue(filecmp.cmp(self.path("one.vtp"), self.path("g.vtp"), shallow=False))
                gathered = read(self.path("wg.vtp"))
                self.assertIsNone(gathered.GetPointData().GetArray("vtkGhostType"))
                self.assertEqual(gathered.GetNumberOfPoints(), one.GetNumberOfPoints())
                self.assertEqual(owned_points(gathered, keys), owned_points(one, keys))
                self.assertEqual(triangles(gathered, keys), triangles(one, keys))
                self.ok(*args, "-o", self.path("p.pvtp"), "--wavefronts", self.path("wp.pvtp"), ranks=ranks)
                pieces = read(self.path("wp.pvtp"))
                self.assertGreater(pieces.GetNumberOfPoints(), one.GetNumberOfPoints())  # ghost corners
                self.assertEqual(owned_points(pieces, keys), owned_points(one, keys))
                self.assertEqual(triangles(pieces, keys), triangles(one, keys))

    def test_conjugate_points_and_caustic(self):
        self.ok("conjugate", *CONJUGATE, "-o", self.path("one.vtp"), "--surface", self.path("s1.vtp"))
        self.ok("conjugate", *CONJUGATE, "-o", self.path("one.csv"))
        keys = ("Sheet", "DirectionId")
        one = read(self.path("s1.vtp"))
        self.assertGreater(one.GetNumberOfPolys(), 0)
        for ranks in (2, 3):
            with self.subTest(ranks=ranks):
                err = self.ok("conjugate", *CONJUGATE, "-o", self.path("g.vtp"), "--surface",
                              self.path("sg.vtp"), "--gather", ranks=ranks)
                self.assertIn("600 conjugate point(s) found on 300", err)
                self.assertTrue(filecmp.cmp(self.path("one.vtp"), self.path("g.vtp"), shallow=False))
                self.ok("conjugate", *CONJUGATE, "-o", self.path("g.csv"), "--gather", ranks=ranks)
                self.assertTrue(filecmp.cmp(self.path("one.csv"), self.path("g.csv"), shallow=False))
                gathered = read(self.path("sg.vtp"))
                self.assertEqual(owned_points(gathered, keys), owned_points(one, keys))
                self.assertEqual(triangles(gathered, keys), triangles(one, keys))

    def test_render_cpu_gathers_the_picture_and_its_channels(self):
        args = ["render", "--backend", "cpu", "-s", os.path.join(DATA, "scenes", "paper-two-bumps.json"),
                "--width", "96", "--height", "72"]
        self.ok(*args, "-o", self.path("one.png"))
        self.ok(*args, "-o", self.path("one.exr"))
        for ranks in (2, 3):
            with self.subTest(ranks=ranks):
                self.ok(*args, "-o", self.path("par.png"), ranks=ranks)
                self.assertTrue(filecmp.cmp(self.path("one.png"), self.path("par.png"), shallow=False))
                self.ok(*args, "-o", self.path("par.exr"), ranks=ranks)
                # Every channel (colour, HitPosition, ArcLength, ...), no tolerance.
                diff = subprocess.run(["idiff", "-a", "-fail", "0", "-failpercent", "0", "-warn", "0",
                                       self.path("one.exr"), self.path("par.exr")],
                                      capture_output=True, text=True, timeout=60)
                self.assertEqual(diff.returncode, 0, diff.stdout)
                self.assertIn("PASS", diff.stdout)
        status, err = run("render", "--width", "16", "--height", "12", "-o", self.path("gpu.png"), ranks=2)
        self.assertEqual(status, 2)
        self.assertEqual(err.count("needs --backend cpu"), 1, err)

    def test_a_failing_rank_stops_the_job_with_its_message(self):
        args = ["fields", "-m", os.path.join(METRICS, "gaussian-bump.json"), "--dims", "20,20,20"]
        for output in ("f.pvti", "f.vti"):
            with self.subTest(output=output):
                extra = ["--gather"] if output == "f.vti" else []
                status, err = run(*args, "-o", self.path(output), *extra, ranks=3,
                                  env={"RIEMANN_TEST_FAILING_RANK": "1"})
                self.assertNotEqual(status, 0)
                self.assertEqual(err.count("error:"), 1, err)
                self.assertIn("riemann (rank 1 of 3): error: rank 1 failed on purpose", err)
                self.assertEqual(os.listdir(self.dir), [])  # nothing written, nothing left
        # A usage error is every rank's: said once.
        status, err = run(*args, "-o", self.path("f.vti"), ranks=2)
        self.assertEqual(status, 2)
        self.assertEqual(err.count("riemann: error:"), 1, err)
        self.assertIn("write their pieces in VTK's parallel format (.pvti), or add --gather", err)
        self.assertEqual(os.listdir(self.dir), [])

    def test_pieces_replace_their_own_folder_only(self):
        args = ["fields", "-m", os.path.join(METRICS, "gaussian-bump.json"), "--dims", "12,12,12"]
        self.ok(*args, "-o", self.path("f.pvti"), ranks=3)
        self.ok(*args, "-o", self.path("f.pvti"), ranks=2)
        self.assertEqual(sorted(os.listdir(self.path("f"))), ["f_0.vti", "f_1.vti"])
        # A folder of that name with other files is the user's: refused, kept.
        os.makedirs(self.path("g"))
        with open(self.path("g/notes.txt"), "w") as f:
            f.write("mine")
        status, err = run(*args, "-o", self.path("g.pvti"), ranks=2)
        self.assertEqual(status, 1)
        self.assertIn("holds files other than pieces of g", err)
        self.assertEqual(os.listdir(self.path("g")), ["notes.txt"])
        self.assertFalse(os.path.exists(self.path("g.pvti")))


if __name__ == "__main__":
    if shutil.which("mpirun") is None:
        raise SystemExit("mpirun not found: install openmpi-bin (run.sh does)")
    unittest.main()
