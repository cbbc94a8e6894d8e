"""Tractography with `riemann trace` on the fibre phantom (issue 31).

Stops and selection, each against what it promises:
- --stop-mask: a tract seeded in a bundle stays in the mask's voxels, and
  ends at the first point outside them (STOPPED_BY_MASK, 11);
- --stop-fa: tracts leaving the x bundle sideways end where its FA crosses
  the threshold: the phantom's closed-form FA profile across the bundle's
  soft edge gives that radius (LOW_ANISOTROPY, 12);
- --max-angle: every kept step turns less than the limit per mm, and a cut
  tract is a prefix of the uncut one (SHARP_TURN, 13);
- --exclude / --include / --min-length: exactly the tracts of an unfiltered
  run that enter / miss the region or are shorter are dropped, and counted.
Streamline files: nibabel reads our .trk (against a reflected reference
affine) and .tck with the .vtp's points to 1e-4 mm; a tract written and read
back seeds the same geodesic; a .trk nibabel writes is read where it puts it.
"""
import json
import math
import os
import sys
import unittest

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLImageDataWriter, vtkXMLPolyDataReader

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from TestCli import DATA, TempDirTest, run  # noqa: E402

try:
    import nibabel
except ImportError:  # run.sh installs python3-nibabel; say so rather than fail obscurely
    nibabel = None

PHANTOM = os.path.join(DATA, "phantom", "fibre-phantom.json")
DIMENSIONS = (40, 40, 24)
ORIGIN = (-1.95, -1.95, -1.15)
SPACING = 0.1
CROSS_Z = -0.35
STOPPED_BY_MASK, LOW_ANISOTROPY, SHARP_TURN, OUTRAN_STEP = 11, 12, 13, 14
EXAMPLES = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))), "Examples")


def phantom():
    reader = vtkXMLImageDataReader()
    reader.SetFileName(os.path.join(DATA, "phantom", "fibre-phantom.vti"))
    reader.Update()
    image = reader.GetOutput()
    points = np.array([image.GetPoint(i) for i in range(image.GetNumberOfPoints())])
    return image, points


def voxel_index(xyz):
    """Flat index of the phantom voxel holding each point (-1 outside); as
    riemann's VoxelOnAxis, a point up to 1e-6 voxel beyond an outer face (a
    tract's end on it) is on it."""
    u = (np.asarray(xyz) - ORIGIN) / SPACING
    inside = np.all((u >= -0.5 - 1e-6) & (u <= np.asarray(DIMENSIONS) - 0.5 + 1e-6), axis=-1)
    ijk = np.clip(np.floor(u + 0.5).astype(int), 0, np.asarray(DIMENSIONS) - 1)
    flat = ijk[..., 0] + DIMENSIONS[0] * (ijk[..., 1] + DIMENSIONS[1] * ijk[..., 2])
    return np.where(inside, flat, -1)


def write_mask(path, values):
    image = vtkImageData()
    image.SetDimensions(*DIMENSIONS)
    image.SetOrigin(*ORIGIN)
    image.SetSpacing(SPACING, SPACING, SPACING)
    image.GetPointData().SetScalars(numpy_to_vtk(values.astype(np.uint8), deep=True))
    writer = vtkXMLImageDataWriter()
    writer.SetInputData(image)
    writer.SetFileName(path)
    writer.Write()
    return path


def read_lines(path):
    """[(points, velocities, seed id, reason, arc length)] of a trace's .vtp."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    xyz = vtk_to_numpy(data.GetPoints().GetData())
    velocity = vtk_to_numpy(data.GetPointData().GetArray("Velocity"))
    arc = vtk_to_numpy(data.GetPointData().GetArray("ArcLength"))
    seeds = vtk_to_numpy(data.GetCellData().GetArray("SeedIds"))
    reasons = vtk_to_numpy(data.GetCellData().GetArray("ReasonForTermination"))
    ids = vtkIdList()
    lines = []
    for cell in range(data.GetNumberOfCells()):
        data.GetCellPoints(cell, ids)
        index = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
        lines.append((xyz[index], velocity[index], int(seeds[cell]), int(reasons[cell]), arc[index]))
    return lines


def tracts_of(lines):
    """Each seed's lines joined: the backward half reversed, then the forward one."""
    halves = {}
    for xyz, _, seed, _, arc in lines:
        halves.setdefault(seed, {})["b" if arc[-1] < 0 else "f"] = xyz
    joined = {}
    for seed, h in halves.items():
        if "b" in h and "f" in h:
            joined[seed] = np.vstack([h["b"][::-1], h["f"][1:]])
        else:
            joined[seed] = h["b"][::-1] if "b" in h else h["f"]
    return joined


def x_bundle_fa(distance):
    """The phantom's FA at `distance` from the x bundle's axis (make_fibre_phantom.py)."""
    s = min(max((0.4 - distance) / 0.2, 0.0), 1.0)
    w = s * s * (3.0 - 2.0 * s)
    eigen = np.array([0.8 + 0.9 * w, 0.8 - 0.5 * w, 0.8 - 0.5 * w])
    return math.sqrt(1.5 * ((eigen - eigen.mean()) ** 2).sum() / (eigen ** 2).sum())


class TractStopTests(TempDirTest):
    def setUp(self):
        super().setUp()
        self.image, self.points = phantom()
        self.bundle = vtk_to_numpy(self.image.GetPointData().GetArray("Bundle"))
        x, y, z = self.points.T
        # Seeds: x-bundle voxels with -1.2 <= x <= -0.8, within 0.2 of its axis.
        chosen = (self.bundle == 1) & (x >= -1.2) & (x <= -0.8) & (np.hypot(y, z - CROSS_Z) < 0.2)
        self.seeds = write_mask(os.path.join(self.dir, "seeds.vti"), chosen)
        self.seed_count = int(chosen.sum())

    def trace(self, *args, output="t.vtp", metric=PHANTOM):
        out = os.path.join(self.dir, output)
        status, _, err = run("trace", "-m", metric, "--seed-mask", self.seeds, "--step", "0.01",
                             "--length", "4", *args, "-o", out)
        self.assertEqual(status, 0, err)
        return out, err

    def test_stop_mask_keeps_tracts_in_their_bundle(self):
        mask = write_mask(os.path.join(self.dir, "bundle.vti"), self.bundle == 1)
        out, err = self.trace("--seed-direction", "random", "--propagation", "both",
                              "--stop-mask", mask)
        lines = read_lines(out)
        self.assertEqual(len(lines), 2 * self.seed_count)
        stopped = 0
        for xyz, _, _, reason, _ in lines:
            inside = self.bundle[voxel_index(xyz)] == 1
            self.assertTrue(inside[:-1].all())
            if reason == STOPPED_BY_MASK:
                stopped += 1
                self.assertFalse(inside[-1])
        self.assertGreater(stopped, self.seed_count)  # random directions mostly leave sideways
        self.assertIn("left the stop mask", err)

    def test_stop_fa_ends_tracts_at_the_bundles_edge(self):
        # The radius where the x bundle's FA crosses 0.3, by bisection of its profile.
        low, high = 0.2, 0.4
        for _ in range(60):
            middle = 0.5 * (low + high)
            low, high = (middle, high) if x_bundle_fa(middle) > 0.3 else (low, middle)
        edge = 0.5 * (low + high)
        # The FA is that of the metric's g: the default reading's trilinear g
        # ("christoffel": "voxels", measured mean |r - edge| 0.028, max 0.046
        # of the 0.1 voxel) or the B-spline's smoother one ("spline": 0.013,
        # 0.036). Both within half a voxel of the edge.
        with open(PHANTOM) as f:
            spline = dict(json.load(f), christoffel="spline",
                          file=os.path.join(os.path.dirname(PHANTOM), "fibre-phantom.vti"))
        spline_json = os.path.join(self.dir, "spline.json")
        with open(spline_json, "w") as f:
            json.dump(spline, f)
        for metric, mean in ((PHANTOM, 0.035), (spline_json, 0.025)):
            with self.subTest(metric=os.path.basename(metric)):
                out, err = self.trace("--seed-direction", "random", "--propagation", "both",
                                      "--stop-fa", "0.3", metric=metric)
                ends = [xyz[-1] for xyz, _, _, reason, _ in read_lines(out) if reason == LOW_ANISOTROPY]
                self.assertGreater(len(ends), self.seed_count)
                radii = np.array([math.hypot(p[1], p[2] - CROSS_Z) for p in ends if p[0] < -0.5])
                self.assertGreater(len(radii), self.seed_count // 2)
                print("FA stop, %s: mean |r - edge| %.4f, max %.4f"
                      % (os.path.basename(metric), np.abs(radii - edge).mean(), np.abs(radii - edge).max()))
                self.assertLess(np.abs(radii - edge).max(), 0.05, (edge, radii.min(), radii.max()))
                self.assertLess(np.abs(radii - edge).mean(), mean)
                self.assertIn("fell below the anisotropy threshold", err)

    def test_max_angle_cuts_prefixes_at_sharp_turns(self):
        plain, _ = self.trace("--seed-direction", "random", output="plain.vtp")
        cut, err = self.trace("--seed-direction", "random", "--max-angle", "60", output="cut.vtp")
        plain_lines = {(seed, arc[-1] < 0): xyz for xyz, _, seed, _, arc in read_lines(plain)}
        sharp = 0
        for xyz, velocity, seed, reason, arc in read_lines(cut):
            whole = plain_lines[(seed, arc[-1] < 0)]
            self.assertTrue(np.array_equal(whole[:len(xyz)], xyz))
            u = velocity / np.linalg.norm(velocity, axis=1)[:, None]
            angles = np.degrees(np.arccos(np.clip((u[1:] * u[:-1]).sum(1), -1, 1)))
            chords = np.linalg.norm(np.diff(xyz, axis=0), axis=1)
            self.assertTrue((angles <= 60 * chords * (1 + 1e-9) + 1e-9).all())
            if reason == SHARP_TURN:
                sharp += 1
                self.assertLess(len(xyz), len(whole))
        self.assertGreater(sharp, 0)
        self.assertIn("turned too sharply", err)

    def test_exclude_include_and_min_length_drop_exactly_those_tracts(self):
        plain, _ = self.trace("--propagation", "both", output="plain.vtp")
        tracts = tracts_of(read_lines(plain))
        self.assertEqual(len(tracts), self.seed_count)
        x, _, _ = self.points.T
        slab = (x > 0.85) & (x < 0.95)
        slab_file = write_mask(os.path.join(self.dir, "slab.vti"), slab)
        entering = {s for s, t in tracts.items() if slab[voxel_index(t)[voxel_index(t) >= 0]].any()}
        self.assertGreater(len(entering), 0)
        self.assertLess(len(entering), len(tracts))
        out, err = self.trace("--propagation", "both", "--exclude", slab_file, output="ex.vtp")
        self.assertEqual(set(tracts_of(read_lines(out))), set(tracts) - entering)
        self.assertIn("%d tract(s) dropped: %d entered the exclude region" % (len(entering), len(entering)), err)
        out, err = self.trace("--propagation", "both", "--include", slab_file, output="in.vtp")
        self.assertEqual(set(tracts_of(read_lines(out))), entering)
        lengths = {s: np.linalg.norm(np.diff(t, axis=0), axis=1).sum() for s, t in tracts.items()}
        threshold = float(np.median(list(lengths.values())))
        out, err = self.trace("--propagation", "both", "--min-length", repr(threshold), output="len.vtp")
        self.assertEqual(set(tracts_of(read_lines(out))), {s for s, l in lengths.items() if l >= threshold})
        self.assertIn("shorter than the minimum length", err)

    def test_bad_stop_options_are_refused(self):
        out = os.path.join(self.dir, "t.vtp")
        # Refusals name the option by the property's name (--stop-fa is its old spelling).
        for args, words in ((["--stop-fa", "1.5"], "--stop-fractional-anisotropy: expected a number from 0 to 1"),
                            (["--exclude", PHANTOM], "--exclude: "),
                            (["--max-angle", "-1"], "--maximum-angle: expected a number from 0 to 1e+06")):
            with self.subTest(args=args):
                status, _, err = run("trace", "-m", PHANTOM, "--seed-mask", self.seeds, *args, "-o", out)
                self.assertNotEqual(status, 0, err)
                self.assertIn(words, err)
                self.assertFalse(os.path.exists(out))


class ConnectivityTests(TempDirTest):
    def write_labels(self, name, labels, origin=(0.0, 0.0, 0.0), spacing=0.1):
        image = vtkImageData()
        image.SetDimensions(*labels.shape[::-1])
        image.SetOrigin(*origin)
        image.SetSpacing(spacing, spacing, spacing)
        image.GetPointData().SetScalars(numpy_to_vtk(labels.ravel().astype(np.int16), deep=True))
        writer = vtkXMLImageDataWriter()
        writer.SetInputData(image)
        writer.SetFileName(os.path.join(self.dir, name))
        writer.Write()
        return os.path.join(self.dir, name)

    def read_matrix(self, path):
        with open(path) as f:
            first = f.readline()
        return first, np.loadtxt(path, delimiter=",")

    def test_flat_space_distances_are_the_closest_voxels(self):
        # Three regions in a 21 x 11 x 11 grid of spacing 0.1 (z, y, x order
        # here); in flat space the distance between two regions is the
        # smallest distance between their voxel centres.
        labels = np.zeros((11, 11, 21), int)
        labels[4:7, 4:7, 0:2] = 3
        labels[4:7, 4:7, 18:21] = 7
        labels[0:2, 9:11, 9:12] = 5
        path = self.write_labels("atlas.vti", labels)
        out = os.path.join(self.dir, "m.csv")
        status, _, err = run("connectivity", "-m", os.path.join(DATA, "metrics", "euclidean.json"),
                             "--labels", path, "-o", out)
        self.assertEqual(status, 0, err)
        header, matrix = self.read_matrix(out)
        self.assertIn("labels: 3 5 7", header)
        centres = {v: 0.1 * np.argwhere(labels == v)[:, ::-1] for v in (3, 5, 7)}
        for a, va in enumerate((3, 5, 7)):
            for b, vb in enumerate((3, 5, 7)):
                exact = min(np.linalg.norm(centres[va][:, None] - centres[vb][None], axis=2).min(), 1e9)
                # The first-order scheme's error across the diagonal, a
                # spacing and a half from the seeds: measured 2.3% (3 to 5),
                # 0 along the axis (3 to 7).
                self.assertAlmostEqual(matrix[a, b], exact, delta=0.03 * exact + 1e-12, msg=(va, vb))
        self.assertTrue(np.array_equal(matrix, matrix.T))

    def test_tract_counts_are_the_traces_tracts_between_regions(self):
        image, points = phantom()
        bundle = vtk_to_numpy(image.GetPointData().GetArray("Bundle"))
        x, y, z = points.T
        labels = np.zeros(len(points), int)
        labels[(bundle == 1) & (x < -1.3)] = 1
        labels[(bundle == 1) & (x > 1.3)] = 2
        labels[(bundle == 2) & (y < -1.3)] = 3
        atlas = self.write_labels("atlas.vti", labels.reshape(DIMENSIONS[::-1]), ORIGIN, SPACING)
        options = ["--stop-fa", "0.2", "--length", "6", "--step", "0.02"]
        matrix, counts = os.path.join(self.dir, "m.csv"), os.path.join(self.dir, "c.csv")
        status, _, err = run("connectivity", "-m", PHANTOM, "--labels", atlas, "-o", matrix,
                             "--tract-counts", counts, *options)
        self.assertEqual(status, 0, err)
        _, count = self.read_matrix(counts)
        # The same tracts from `trace`, their ends' regions counted here.
        vtp = os.path.join(self.dir, "t.vtp")
        status, _, err = run("trace", "-m", PHANTOM, "--seed-mask", atlas, *options, "-o", vtp)
        self.assertEqual(status, 0, err)
        expected = np.zeros((3, 3), int)
        for tract in tracts_of(read_lines(vtp)).values():
            ends = [labels[i] if i >= 0 else 0 for i in voxel_index(tract[[0, -1]])]
            if ends[0] and ends[1] and ends[0] != ends[1]:
                expected[ends[0] - 1, ends[1] - 1] += 1
                expected[ends[1] - 1, ends[0] - 1] += 1
        self.assertTrue(np.array_equal(count, expected), (count, expected))
        self.assertGreater(count[0, 1], 20)  # the x bundle joins its two ends
        _, distance = self.read_matrix(matrix)
        self.assertLess(distance[0, 1], 2.6)  # cheaper than flat space along the fibres

    def test_bad_label_images_are_refused(self):
        one = self.write_labels("one.vti", np.ones((3, 3, 3), int))
        out = os.path.join(self.dir, "m.csv")
        status, _, err = run("connectivity", "-m", PHANTOM, "--labels", one, "-o", out)
        self.assertEqual(status, 1, err)
        self.assertIn("1 region(s)", err)
        self.assertFalse(os.path.exists(out))


@unittest.skipIf(nibabel is None, "nibabel is not installed (run.sh installs python3-nibabel)")
class StreamlineFileTests(TempDirTest):
    def reflected_reference(self):
        """A NIfTI image of the phantom's grid, its x axis reversed (an 'LAS' affine)."""
        affine = np.diag([-SPACING, SPACING, SPACING, 1.0])
        affine[:3, 3] = (-ORIGIN[0], ORIGIN[1], ORIGIN[2])
        path = os.path.join(self.dir, "reference.nii.gz")
        nibabel.save(nibabel.Nifti1Image(np.zeros(DIMENSIONS, np.uint8), affine), path)
        return path

    def test_nibabel_reads_our_trk_and_tck_where_the_vtp_has_them(self):
        image, points = phantom()
        bundle = vtk_to_numpy(image.GetPointData().GetArray("Bundle"))
        seeds = write_mask(os.path.join(self.dir, "seeds.vti"), (bundle == 3) & (points[:, 2] > 0.4))
        common = ["trace", "-m", PHANTOM, "--seed-mask", seeds, "--step", "0.02", "--length", "3",
                  "--stop-fa", "0.3"]
        vtp = os.path.join(self.dir, "t.vtp")
        self.assertEqual(run(*common, "-o", vtp)[0], 0)
        expected = tracts_of(read_lines(vtp))
        for name, extra in (("t.tck", []), ("t.trk", ["--reference", self.reflected_reference()]),
                            ("grid.trk", [])):
            with self.subTest(file=name):
                path = os.path.join(self.dir, name)
                status, _, err = run(*common, *extra, "-o", path)
                self.assertEqual(status, 0, err)
                loaded = nibabel.streamlines.load(path)
                streamlines = list(loaded.streamlines)
                self.assertEqual(len(streamlines), len(expected))
                worst = max(np.abs(a - b).max() for a, b in zip(streamlines, expected.values()))
                self.assertLess(worst, 1e-4)  # float32 storage: measured 1.3e-7
                if name.endswith(".trk"):
                    # Why each end stopped: the halves' codes, as the .vtp has them.
                    stops = loaded.tractogram.data_per_streamline
                    reasons = {}
                    for _, _, seed, reason, arc in read_lines(vtp):
                        reasons.setdefault(seed, [0, 0])[1 if arc[-1] > 0 else 0] = reason
                    self.assertEqual([[int(a), int(b)] for a, b in zip(stops["stop_at_start"][:, 0],
                                                                       stops["stop_at_end"][:, 0])],
                                     list(reasons.values()))
                    self.assertEqual([int(i) for i in stops["seed_id"][:, 0]], list(reasons))
                if name == "t.trk":
                    # The reference's own voxel order, as DIPY compares it.
                    self.assertEqual(loaded.header["voxel_order"], b"LAS")
                    affine = nibabel.load(extra[1]).affine
                    self.assertLess(np.abs(loaded.header["voxel_to_rasmm"] - affine).max(), 1e-6)

    def test_a_tract_read_back_seeds_the_same_geodesic(self):
        common = ["trace", "-m", PHANTOM, "--step", "0.01", "--length", "1.5"]
        seeds = os.path.join(self.dir, "seeds.csv")
        with open(seeds, "w") as f:
            f.write("x,y,z,dx,dy,dz\n-1.0,0.05,-0.3,1,0.1,0\n0.05,-1.0,-0.4,0.1,1,0.05\n"
                    "1.5,0.0,0.45,0,1,0\n")
        first = os.path.join(self.dir, "first.vtp")
        self.assertEqual(run(*common, "--seeds", seeds, "-o", first)[0], 0)
        original = [xyz for xyz, *_ in read_lines(first)]
        for name in ("first.tck", "first.trk", "first.vtp"):
            with self.subTest(file=name):
                path = os.path.join(self.dir, name)
                if name != "first.vtp":
                    status, _, err = run(*common, "--seeds", seeds, "--reference",
                                         self.reflected_reference(), "-o", path)
                    self.assertEqual(status, 0, err)
                again = os.path.join(self.dir, "again.vtp")
                status, _, err = run(*common, "--seeds", path, "-o", again)
                self.assertEqual(status, 0, err)
                retraced = [xyz for xyz, *_ in read_lines(again)]
                self.assertEqual(len(retraced), len(original))
                for a, b in zip(original, retraced):
                    n = min(len(a), len(b))
                    self.assertGreater(n, 100)
                    # The .vtp's velocity is exact; a file's tangent comes from
                    # its float32 points (measured deviation 2e-5 over 1.5).
                    self.assertLess(np.abs(a[:n] - b[:n]).max(), 1e-9 if name == "first.vtp" else 1e-4)

    def test_a_trk_nibabel_writes_is_read_where_nibabel_puts_it(self):
        affine = np.array([[0.0, -2.0, 0.0, 30.0], [2.5, 0.0, 0.0, -20.0], [0.0, 0.0, -1.5, 10.0],
                           [0.0, 0.0, 0.0, 1.0]])
        header = {nibabel.streamlines.Field.VOXEL_TO_RASMM: affine,
                  nibabel.streamlines.Field.VOXEL_SIZES: np.array([2.5, 2.0, 1.5]),
                  nibabel.streamlines.Field.DIMENSIONS: np.array([20, 30, 40]),
                  nibabel.streamlines.Field.VOXEL_ORDER: "PRI"}
        lines = [np.array([[1.0, 2.0, 3.0], [1.5, 2.0, 3.0], [2.0, 2.1, 3.0]]),
                 np.array([[-4.0, 0.0, 1.0], [-4.0, 0.5, 1.0], [-4.0, 1.0, 1.2]])]
        tractogram = nibabel.streamlines.Tractogram(lines, affine_to_rasmm=np.eye(4))
        path = os.path.join(self.dir, "nib.trk")
        nibabel.streamlines.save(tractogram, path, header=header)
        metric = os.path.join(DATA, "metrics", "euclidean.json")
        out = os.path.join(self.dir, "t.csv")
        status, _, err = run("trace", "-m", metric, "--seeds", path, "--length", "0.1", "-o", out)
        self.assertEqual(status, 0, err)
        with open(out) as f:
            import csv
            rows = [r for r in csv.DictReader(f) if r["step"] == "0"]
        starts = np.array([[float(r[k]) for k in "xyz"] for r in rows])
        self.assertLess(np.abs(starts - np.array([l[0] for l in lines])).max(), 1e-5)

    def test_seeds_on_the_faces_of_an_oblique_s_form_are_inside(self):
        # As DIPY writes small_64D's tensors: an s-form only (float32) with
        # its oblique, permuted axes, and qfac -1 (pixdim[0]), so VTK's reader
        # reverses the slices. Every voxel of the outer layer seeds a tract;
        # before the fix 180 of its 488 seeds were "outside" (by about 1e-7 voxel).
        affine = np.array([[0.0, -2.0, 0.0, 20.0], [-1.939744, 0.0, -0.4872305, 25.170544],
                           [-0.48723, 0.0, 1.9397439, 12.320495], [0.0, 0.0, 0.0, 1.0]])
        shape = (10, 10, 10)
        tensor = np.array([1.7e-3, 0.1e-3, 0.3e-3, 0.0, 0.0, 0.3e-3], np.float32)  # XX XY YY XZ YZ ZZ
        files = {}
        for name, values in (("tensors.nii.gz", np.broadcast_to(tensor, shape + (1, 6)).copy()),
                             ("layer.nii.gz", np.pad(np.zeros((8, 8, 8), np.uint8), 1, constant_values=1))):
            image = nibabel.Nifti1Image(values, None)
            image.set_sform(affine, code=2)
            image.set_qform(None, code=0)
            image.header["pixdim"][0] = -1.0
            if name.startswith("tensors"):
                image.header.set_intent("symmetric matrix")
            files[name] = os.path.join(self.dir, name)
            nibabel.save(image, files[name])
        metric = os.path.join(self.dir, "dti.json")
        with open(metric, "w") as f:
            f.write('{"type": "sampled", "file": "tensors.nii.gz", "inverse": true, "outside": "stop", '
                    '"scale": "mean-diffusivity"}')
        out = os.path.join(self.dir, "t.vtp")
        status, _, err = run("trace", "-m", metric, "--seed-mask", files["layer.nii.gz"],
                             "--length", "3", "--step", "0.5", "-o", out)
        self.assertEqual(status, 0, err)
        self.assertNotIn("made no geodesic", err)
        self.assertEqual(len(tracts_of(read_lines(out))), 10 ** 3 - 8 ** 3)

    def test_bad_streamline_files_are_refused(self):
        out = os.path.join(self.dir, "t.vtp")
        truncated = os.path.join(self.dir, "cut.tck")
        with open(truncated, "wb") as f:
            f.write(b"mrtrix tracks\ndatatype: Float32LE\nfile: . 64\nEND\n".ljust(64, b"\0"))
            f.write(np.array([0, 0, 0, 1, 0, 0], np.float32).tobytes())
        fake = os.path.join(self.dir, "fake.trk")
        with open(fake, "wb") as f:
            f.write(b"not a track file")
        # A valid header (nibabel's) whose one streamline claims 2^31 - 1 points.
        huge = os.path.join(self.dir, "huge.trk")
        nibabel.streamlines.save(nibabel.streamlines.Tractogram([np.zeros((3, 3))], affine_to_rasmm=np.eye(4)), huge)
        with open(huge, "r+b") as f:
            f.seek(1000)
            f.write(np.array([2 ** 31 - 1], np.int32).tobytes())
        for path, words in ((truncated, "truncated .tck"), (fake, "not a TrackVis .trk file"),
                            (huge, "runs past the end of the file")):
            with self.subTest(path=path):
                status, _, err = run("trace", "-m", PHANTOM, "--seeds", path, "-o", out)
                self.assertEqual(status, 1, err)
                self.assertIn(words, err)
                self.assertFalse(os.path.exists(out))
        status, _, err = run("trace", "-m", os.path.join(DATA, "metrics", "euclidean.json"),
                             "-o", os.path.join(self.dir, "t.trk"))
        self.assertEqual(status, 2, err)
        self.assertIn("reference image", err)


class ScanTests(TempDirTest):
    """A real scan, as a diffusion-MRI user traces it: DIPY's small_64D,
    its tensors fitted by DIPY and written as dipy_fit_dti writes them
    (Examples/tractography_dipy.py), seeds where FA > 0.3, stop at FA 0.2,
    step 0.5 mm. Every tensor metric, on the spline's symbols and on the
    voxels', keeps every point of every tract in the scan's box (its outer
    voxels' faces), and no step is longer than twice its nominal length.
    Before the steps were checked, a sharpened metric's step went 31 m (one
    point 28 m from this 20 mm scan) and tracts stopped at the outer voxel
    centres, half a voxel inside the faces."""

    def setUp(self):
        super().setUp()
        try:
            import dipy  # noqa: F401
        except ImportError:
            self.skipTest("needs DIPY (run.sh installs python3-dipy)")
        sys.path.insert(0, EXAMPLES)
        import tractography_dipy
        self.example = tractography_dipy

    def test_no_point_leaves_the_scan_and_no_step_jumps(self):
        example = self.example
        data, affine, gtab, _ = example.load_scan()
        fit = example.TensorModel(gtab).fit(data)
        paths = example.write_inputs(self.dir, fit, example.fractional_anisotropy(fit), affine)
        to_voxels = np.linalg.inv(affine)
        faces = np.asarray(data.shape[:3]) - 0.5
        refused = {}
        for tensor_metric in example.TENSOR_METRICS:
            for christoffel in ("spline", "voxels"):
                with self.subTest(tensor_metric=tensor_metric, christoffel=christoffel):
                    metric = example.write_metric(os.path.join(self.dir, "m.json"), tensor_metric)
                    with open(metric) as f:
                        definition = json.load(f)
                    definition["christoffel"] = christoffel
                    with open(metric, "w") as f:
                        json.dump(definition, f)
                    for output in ("t.trk", "t.vtp"):
                        command = example.riemann_trace_command(
                            "riemann", metric, os.path.join(self.dir, output),
                            seed_mask=paths["mask.nii.gz"], step=0.5, length=40.0)
                        status, _, err = run(*command[1:])
                        self.assertEqual(status, 0, err)
                    # The .trk as nibabel reads it (float32, RAS+ mm): in the
                    # box to float32's rounding (1e-5 voxel here).
                    tracts = nibabel.streamlines.load(os.path.join(self.dir, "t.trk")).streamlines
                    self.assertGreater(len(tracts), 500)
                    points = np.vstack([np.asarray(t, float) for t in tracts])
                    ijk = points @ to_voxels[:3, :3].T + to_voxels[:3, 3]
                    beyond = np.maximum(-0.5 - ijk, ijk - faces).max()
                    self.assertLess(beyond, 1e-5)
                    # Tracts reach the faces (before, they ended half a voxel inside).
                    self.assertGreater(beyond, -1e-5)
                    # Every step of the .vtp (float64): chord <= 2 |dx/ds| ds.
                    lines = read_lines(os.path.join(self.dir, "t.vtp"))
                    for xyz, velocity, _, _, arc in lines:
                        chord = np.linalg.norm(np.diff(xyz, axis=0), axis=1)
                        nominal = np.linalg.norm(velocity[:-1], axis=1) * np.abs(np.diff(arc))
                        self.assertTrue(np.all(chord <= 2.0 * nominal * (1 + 1e-9)))
                    refused[tensor_metric, christoffel] = sum(r == OUTRAN_STEP for *_, r, _ in lines)
        # The sharpened metric of this scan has steps to refuse (17 and 22
        # of 1,180 geodesics, measured); D^-1's hardly any.
        self.assertGreater(refused["sharpened", "spline"], 0)
        self.assertGreater(refused["sharpened", "voxels"], 0)
        print("geodesics that refused a step:", refused)


if __name__ == "__main__":
    unittest.main()
