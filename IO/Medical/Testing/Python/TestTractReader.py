"""vtkRiemannTractReader reads the tract files `riemann trace` writes where
nibabel (the reference reader of .trk and .tck) puts their streamlines.

Geodesics of the fibre phantom are written as .tck and as .trk against a
reference image whose x axis is reversed (so the .trk's voxel-to-RAS affine
and voxel order matter). .tck: the reader's points are nibabel's float32
values, exactly. .trk: nibabel applies the header's affine in float32, the
reader in double: they agree to float32's rounding (stated 1e-5 mm on
coordinates of a few mm). A truncated file and a missing one give an
error naming the file and an empty output.

Run by ctest with /usr/bin/python3 and PYTHONPATH set to the build's package
folder; exits non-zero on failure.
"""
import os
import shutil
import subprocess
import tempfile
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import riemann

try:
    import nibabel
except ImportError:  # run.sh installs python3-nibabel; say so rather than fail obscurely
    nibabel = None

DATA = os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(__file__), "../../../../Data"))
RIEMANN = os.path.join(os.environ.get("RIEMANN_BIN_DIR", ""), "riemann")
PHANTOM = os.path.join(DATA, "phantom", "fibre-phantom.json")


def read(path):
    reader = riemann.vtkRiemannTractReader()
    reader.SetFileName(path)
    reader.Update()
    return reader


def lines_of(polydata):
    points = vtk_to_numpy(polydata.GetPoints().GetData()) if polydata.GetPoints() else np.zeros((0, 3))
    offsets = vtk_to_numpy(polydata.GetLines().GetOffsetsArray())
    ids = vtk_to_numpy(polydata.GetLines().GetConnectivityArray())
    return [points[ids[offsets[i]:offsets[i + 1]]] for i in range(len(offsets) - 1)]


@unittest.skipIf(nibabel is None, "nibabel is not installed (run.sh installs python3-nibabel)")
class TractReaderTests(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="TractReader-")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def trace(self, name, *extra):
        seeds = os.path.join(self.dir, "seeds.csv")
        with open(seeds, "w") as f:
            f.write("x,y,z,dx,dy,dz\n-1.0,0.05,-0.3,1,0.1,0\n0.05,-1.0,-0.4,0.1,1,0.05\n1.5,0.0,0.45,0,1,0\n")
        path = os.path.join(self.dir, name)
        done = subprocess.run([RIEMANN, "trace", "-m", PHANTOM, "--seeds", seeds, "--step", "0.01",
                               "--length", "1.5", *extra, "-o", path], capture_output=True, text=True)
        self.assertEqual(done.returncode, 0, done.stderr)
        return path

    def reflected_reference(self):
        """A NIfTI image whose x axis is reversed (an 'LAS' affine), spacing 0.1."""
        affine = np.diag([-0.1, 0.1, 0.1, 1.0])
        affine[:3, 3] = (2.0, -2.0, -2.0)
        path = os.path.join(self.dir, "reference.nii.gz")
        nibabel.save(nibabel.Nifti1Image(np.zeros((41, 41, 41), np.uint8), affine), path)
        return path

    def test_tck_points_are_nibabels_exactly(self):
        path = self.trace("t.tck")
        reader = read(path)
        self.assertEqual(reader.GetLastError(), "")
        ours = lines_of(reader.GetOutput())
        theirs = list(nibabel.streamlines.load(path).streamlines)
        self.assertEqual(len(ours), 3)
        self.assertEqual([len(a) for a in ours], [len(b) for b in theirs])
        for a, b in zip(ours, theirs):
            np.testing.assert_array_equal(a, b.astype(np.float64))
        tract_ids = vtk_to_numpy(reader.GetOutput().GetCellData().GetArray("TractId"))
        self.assertEqual(list(tract_ids), [0, 1, 2])

    def test_trk_points_are_nibabels_to_float32(self):
        path = self.trace("t.trk", "--reference", self.reflected_reference())
        self.assertEqual(nibabel.streamlines.load(path).header["voxel_order"], b"LAS")
        reader = read(path)
        self.assertEqual(reader.GetLastError(), "")
        ours = lines_of(reader.GetOutput())
        theirs = list(nibabel.streamlines.load(path).streamlines)
        self.assertEqual([len(a) for a in ours], [len(b) for b in theirs])
        worst = max(np.abs(a - b).max() for a, b in zip(ours, theirs))
        print(f".trk: largest difference to nibabel's points {worst:.2e}")
        self.assertLess(worst, 1e-5)
        # And where the .tck of the same trace has them (one float32 rounding each).
        tck = lines_of(read(self.trace("t.tck")).GetOutput())
        self.assertLess(max(np.abs(a - b).max() for a, b in zip(ours, tck)), 1e-5)

    def test_bad_files_give_an_error_and_empty_output(self):
        path = self.trace("t.tck")
        truncated = os.path.join(self.dir, "truncated.tck")
        with open(path, "rb") as f:
            data = f.read()
        with open(truncated, "wb") as f:
            f.write(data[: len(data) - 100])
        from vtkmodules.vtkCommonCore import vtkObject
        vtkObject.GlobalWarningDisplayOff()
        for name in (truncated, os.path.join(self.dir, "missing.trk")):
            with self.subTest(file=name):
                reader = read(name)
                self.assertIn(os.path.basename(name), reader.GetLastError())
                self.assertEqual(reader.GetOutput().GetNumberOfPoints(), 0)
                self.assertEqual(reader.GetOutput().GetNumberOfLines(), 0)
        vtkObject.GlobalWarningDisplayOn()


if __name__ == "__main__":
    unittest.main()
