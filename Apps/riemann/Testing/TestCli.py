"""Tests of the `riemann` command-line tool.

Each test runs the real binary. Answers are checked against exact geometry
(the twist's geodesics are Phi^-1 of straight lines); bad inputs must exit
non-zero with a message naming the problem and leave no output file.
Run with --table to print the bad-input table used in the issue notes.
"""
import csv
import math
import os
import subprocess
import sys
import signal
import tempfile
import time
import unittest

EXE = os.environ.get("RIEMANN_EXECUTABLE", "riemann")
DATA = os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(__file__), "../../../Data"))
METRICS = os.path.join(DATA, "metrics")


def run(*args, env=None):
    """Run riemann; return (exit status, stdout, stderr). `env`: variables added to ours."""
    environment = dict(os.environ, **env) if env else None
    result = subprocess.run([EXE, *args], capture_output=True, text=True, timeout=60, env=environment)
    return result.returncode, result.stdout, result.stderr


def twist_exact(p, d, s):
    """Exact geodesic of the twist metric: Phi^-1(Phi(p) + s J(p) v), v unit speed."""
    x, y, z = p
    c, sn = math.cos(z), math.sin(z)
    phi = (c * x - sn * y, sn * x + c * y, z)
    # J columns: d/dx, d/dy, d/dz of Phi.
    jac = [[c, -sn, -sn * x - c * y], [sn, c, c * x - sn * y], [0.0, 0.0, 1.0]]
    jd = [sum(jac[r][k] * d[k] for k in range(3)) for r in range(3)]
    speed = math.sqrt(sum(t * t for t in jd))  # |J d| = sqrt(g(d, d))
    q = [phi[r] + s * jd[r] / speed for r in range(3)]
    cz, sz = math.cos(-q[2]), math.sin(-q[2])
    return (cz * q[0] - sz * q[1], sz * q[0] + cz * q[1], q[2])


class TempDirTest(unittest.TestCase):
    """A test case with a fresh folder, self.dir, removed after each test."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()


class TraceTests(TempDirTest):
    def read_csv(self, path):
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        return rows

    def test_trace_twist_csv_matches_exact_geodesic(self):
        out = os.path.join(self.dir, "twist.csv")
        status, _, err = run("trace", "--metric", os.path.join(METRICS, "twist.json"),
                             "--seed", "1,0,-1", "--direction", "0.3,1,0.5", "--length", "5",
                             "--integrator", "rk4", "--step", "0.01", "-o", out)
        self.assertEqual(status, 0, err)
        with open(out) as f:
            self.assertEqual(f.readline().strip(), "seed_id,step,t,x,y,z,vx,vy,vz")
        rows = self.read_csv(out)
        self.assertEqual(len(rows), 501)
        last = rows[-1]
        self.assertAlmostEqual(float(last["t"]), 5.0, places=9)
        exact = twist_exact((1, 0, -1), (0.3, 1, 0.5), 5.0)
        error = math.dist([float(last[k]) for k in "xyz"], exact)
        self.assertLess(error, 1e-7)  # RK4 at h = 0.01: measured ~1e-9
        self.assertEqual([int(r["step"]) for r in rows[:3]], [0, 1, 2])

    def test_trace_dp45_both_directions_vtp(self):
        out = os.path.join(self.dir, "both.vtp")
        status, _, err = run("trace", "-m", os.path.join(METRICS, "twist.json"), "--seed", "0.5,0.2,0",
                             "--direction", "1,0,0", "--length", "2", "--integrator", "dp45",
                             "--tolerance", "1e-10", "--propagation", "both", "-o", out)
        self.assertEqual(status, 0, err)
        self.assertIn("2 geodesic(s)", err)
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
        from vtkmodules.util.numpy_support import vtk_to_numpy
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(out)
        reader.Update()
        lines = reader.GetOutput()
        self.assertEqual(lines.GetNumberOfLines(), 2)
        for name in ("ArcLength", "Velocity", "SpeedDrift"):
            self.assertIsNotNone(lines.GetPointData().GetArray(name), name)
        for name in ("SeedIds", "ReasonForTermination"):
            self.assertIsNotNone(lines.GetCellData().GetArray(name), name)
        arc = vtk_to_numpy(lines.GetPointData().GetArray("ArcLength"))
        self.assertAlmostEqual(arc.min(), -2.0, places=9)
        self.assertAlmostEqual(arc.max(), 2.0, places=9)
        # The end of the backward line is the exact point at s = -2.
        points = vtk_to_numpy(lines.GetPoints().GetData())
        end = points[arc.argmin()]
        self.assertLess(math.dist(end, twist_exact((0.5, 0.2, 0), (1, 0, 0), -2.0)), 1e-7)

    def test_trace_transverse_jacobian_csv(self):
        # Unit 3-sphere: det = sin^2 s and both singular values |sin s|.
        metric = os.path.join(self.dir, "sphere.json")
        with open(metric, "w") as f:
            f.write(SPHERE_JSON)
        out = os.path.join(self.dir, "jacobian.csv")
        status, _, err = run("trace", "-m", metric, "--seed", "0.2,0.1,-0.3", "--direction", "0.3,1,0.2",
                             "--length", "3", "--transverse-jacobian", "-o", out)
        self.assertEqual(status, 0, err)
        with open(out, newline="") as f:
            rows = list(csv.reader(f))
        self.assertEqual(rows[0], ["seed_id", "step", "t", "x", "y", "z", "vx", "vy", "vz",
                                   "TransverseJacobian", "SingularValue0", "SingularValue1"])
        self.assertGreater(len(rows), 300)
        for row in rows[1:]:
            s = float(row[2])
            self.assertAlmostEqual(float(row[9]), math.sin(s) ** 2, delta=1e-7)
            self.assertAlmostEqual(float(row[10]), abs(math.sin(s)), delta=1e-7)
            self.assertAlmostEqual(float(row[11]), abs(math.sin(s)), delta=1e-7)

    def test_trace_seeds_file(self):
        seeds = os.path.join(self.dir, "seeds.csv")
        with open(seeds, "w") as f:
            f.write("x,y,z,dx,dy,dz\n-2,0.1,0,1,0,0\n-2,0.3,0,1,0,0\n\n-2,-0.2,0.1,1,0.1,0\n")
        out = os.path.join(self.dir, "bundle.csv")
        status, _, err = run("trace", "-m", os.path.join(METRICS, "gaussian-bump.json"),
                             "--seeds", seeds, "--length", "4", "-o", out)
        self.assertEqual(status, 0, err)
        rows = self.read_csv(out)
        self.assertEqual(sorted({int(r["seed_id"]) for r in rows}), [0, 1, 2])
        # Unit speed in g at every sample: g = I + grad f grad f^T for the bump.
        for r in rows[::50]:
            x, y, z = (float(r[k]) for k in "xyz")
            v = [float(r[k]) for k in ("vx", "vy", "vz")]
            f = math.exp(-(x * x + y * y + z * z) / 0.5)
            grad = [-4.0 * c * f for c in (x, y, z)]
            gvv = sum(c * c for c in v) + sum(a * b for a, b in zip(grad, v)) ** 2
            self.assertAlmostEqual(gvv, 1.0, places=7)

    def test_info_prints_metric_at_point(self):
        status, out, err = run("info", "-m", os.path.join(METRICS, "gaussian-bump.json"), "-p", "0,0,0")
        self.assertEqual(status, 0, err)
        self.assertIn("family:  graph", out)
        self.assertIn("volume form sqrt(det g): 1", out)
        status, out, _ = run("info", "-m", os.path.join(METRICS, "paraboloid.json"), "-p", "1,0,0")
        self.assertEqual(status, 0)
        # grad f = (2,0,0): g_xx = 5, volume form sqrt(5).
        self.assertIn("volume form sqrt(det g): 2.236067977", out)
        # The paper's paraboloid at the origin: every sectional curvature 4, scalar 24.
        status, out, _ = run("info", "-m", os.path.join(METRICS, "paraboloid.json"))
        self.assertEqual(status, 0)
        self.assertIn("scalar curvature: 24\n", out)
        self.assertIn("sectional curvature over all planes: min 4, max 4", out)
        # The round 3-sphere: sectional curvature +1 everywhere.
        status, out, _ = run("info", "-m", os.path.join(METRICS, "round-sphere.json"), "-p", "0.3,0.2,-0.5")
        self.assertEqual(status, 0)
        self.assertIn("scalar curvature: 6\n", out)
        self.assertIn("min 1, max 1", out)


def png_size_and_pixels(path):
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    return width, height, vtk_to_numpy(image.GetPointData().GetScalars()).copy()


class StartupTests(unittest.TestCase):
    """`riemann` links only what its light subcommands need; render runs
    riemann-render, found next to riemann (riemann.cxx)."""

    def loaded_libraries(self, *args):
        env = dict(os.environ, LD_DEBUG="libs")
        result = subprocess.run([EXE, *args], capture_output=True, text=True, timeout=60, env=env)
        self.assertEqual(result.returncode, 0, result.stderr[-2000:])
        return [line for line in result.stderr.splitlines() if "calling init:" in line]

    def test_info_loads_no_rendering_library(self):
        libraries = self.loaded_libraries("info", "-m", os.path.join(METRICS, "gaussian-bump.json"))
        names = "\n".join(libraries)
        for heavy in ("libOpenImageIO", "libvtkRenderingOpenGL2", "libembree", "libRiemannRendering"):
            self.assertNotIn(heavy, names)
        # 35 in the GCC build, 84 in the Clang sanitizer build (no --as-needed
        # by default), 310 when render was linked in: a margin, not a timing.
        self.assertLess(len(libraries), 150, names)

    def test_render_help_comes_from_riemann_render(self):
        status, out, err = run("render", "--help")
        self.assertEqual(status, 0, err)
        self.assertIn("--backend", out)
        status, out, _ = run("--help")
        self.assertEqual(status, 0)
        self.assertIn("render", out)

    def test_render_without_riemann_render_is_a_clear_error(self):
        with tempfile.TemporaryDirectory() as folder:
            alone = os.path.join(folder, "riemann")
            import shutil
            shutil.copy2(EXE, alone)
            result = subprocess.run([alone, "render", "-o", os.path.join(folder, "x.png")],
                                    capture_output=True, text=True, timeout=60)
            self.assertEqual(result.returncode, 1)
            self.assertIn("cannot run", result.stderr)
            self.assertIn("riemann-render", result.stderr)
            self.assertFalse(os.path.exists(os.path.join(folder, "x.png")))


class RenderTests(TempDirTest):
    """riemann render: needs an X display (ctest runs under xvfb-run)."""

    def test_bundle_side_by_side(self):
        out = os.path.join(self.dir, "bundle.png")
        status, _, err = run("render", "--width", "80", "--height", "60", "--bundle", "4", "-o", out)
        self.assertEqual(status, 0, err)
        width, height, pixels = png_size_and_pixels(out)
        self.assertEqual((width, height), (160, 60))
        # Both halves hold a picture (not a flat colour).
        left = pixels.reshape(60, 160, -1)[:, :80]
        right = pixels.reshape(60, 160, -1)[:, 80:]
        self.assertGreater(left.std(), 10)
        self.assertGreater(right.std(), 5)

    def test_one_integrator_vocabulary(self):
        # render spells the adaptive integrator dp45, as trace, expmap and
        # conjugate do; "adaptive", its old word, still gives the same picture.
        pictures = {}
        for name in ("dp45", "adaptive", "euler"):
            out = os.path.join(self.dir, name + ".png")
            status, _, err = run("render", "--width", "64", "--height", "48",
                                 "--integrator", name, "-o", out)
            self.assertEqual(status, 0, err)
            pictures[name] = png_size_and_pixels(out)[2].astype(int)
        self.assertEqual(abs(pictures["dp45"] - pictures["adaptive"]).max(), 0)
        self.assertGreater(abs(pictures["dp45"] - pictures["euler"]).max(), 0)  # the option is used

    def test_gpu_without_a_display_is_a_clear_error(self):
        out = os.path.join(self.dir, "nodisplay.png")
        env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
        proc = subprocess.run([EXE, "render", "--width", "32", "--height", "24", "-o", out],
                              capture_output=True, text=True, env=env)
        self.assertEqual(proc.returncode, 1, proc.stderr)
        self.assertIn("needs an X display", proc.stderr)
        self.assertFalse(os.path.exists(out))

    def test_frames_follow_the_animated_metric(self):
        metric = os.path.join(self.dir, "growing.json")
        with open(metric, "w") as f:
            f.write('{"type": "graph", "gaussians": [{"amplitude": {"from": 0, "to": 1.5}, '
                    '"center": [0,0,0], "sigma": 0.5}]}')
        out = os.path.join(self.dir, "frame.png")
        status, _, err = run("render", "-m", metric, "--width", "64", "--height", "48",
                             "--frames", "3", "-o", out)
        self.assertEqual(status, 0, err)
        self.assertEqual(err.count("riemann render: frame"), 3)
        frames = [png_size_and_pixels(os.path.join(self.dir, f"frame_{k:04d}.png"))[2] for k in range(3)]
        self.assertFalse(os.path.exists(out), "a sequence writes numbered files only")
        # t = 0 is flat space: different from the bumped frames, which differ from each other.
        self.assertGreater(abs(frames[0].astype(int) - frames[2].astype(int)).mean(), 1.0)
        self.assertGreater(abs(frames[1].astype(int) - frames[2].astype(int)).mean(), 0.5)

    def test_reference_mismatch_fails(self):
        baseline = os.path.join(os.path.dirname(__file__), "../../../Rendering/OpenGL/Testing/Data/Baseline")
        out = os.path.join(self.dir, "x.png")
        status, _, err = run("render", "--scene", os.path.join(DATA, "scenes", "paper-grid.json"),
                             "--width", "160", "--height", "120",
                             "--reference", os.path.join(baseline, "paper-one-bump.png"), "-o", out)
        self.assertEqual(status, 3, err)
        self.assertIn("differs from the reference", err)
        status, _, err = run("render", "--scene", os.path.join(DATA, "scenes", "paper-grid.json"),
                             "--width", "160", "--height", "120",
                             "--reference", os.path.join(baseline, "paper-grid.png"), "-o", out)
        self.assertEqual(status, 0, err)

    def test_both_gpu_paths_draw_the_same_picture(self):
        # --gpu-path compute against --gpu-path fragment: the same GLSL, so
        # the same picture (mean difference at most 0.05 of 255: a pixel on
        # a grid edge may round the other way).
        scene = os.path.join(DATA, "scenes", "paper-two-bumps.json")
        fragment = os.path.join(self.dir, "fragment.png")
        status, _, err = run("render", "--gpu-path", "fragment", "--scene", scene,
                             "--width", "80", "--height", "60", "-o", fragment)
        self.assertEqual(status, 0, err)
        status, _, err = run("render", "--gpu-path", "compute", "--scene", scene,
                             "--width", "80", "--height", "60", "--threshold", "0.05",
                             "--reference", fragment, "-o", os.path.join(self.dir, "compute.png"))
        self.assertEqual(status, 0, err)


class HostileInputTests(TempDirTest):
    """Files that crashed or hung riemann: meshes (Rendering/Scene/Testing/Data/hostile-meshes)
    and tensor volumes (Common/Core/Testing/Data/hostile-tensors)."""

    def test_each_is_a_clear_error_with_no_output(self):
        folder = os.path.join(os.path.dirname(__file__), "../../../Rendering/Scene/Testing/Data/hostile-meshes")
        reasons = {"badindex.obj": "refers to point 999999998", "badconn.vtp": "refers to point 999999999",
                   "badindex.ply": "refers to vertex 99999999",
                   "trunc05_ok.ply": "the file ends in element face",
                   "trunc001_ok_ascii.ply": "the file ends in element vertex"}
        for name, reason in reasons.items():
            scene = os.path.join(self.dir, name + ".json")
            with open(scene, "w") as f:
                f.write('{"metric": {"type": "euclidean"}, "camera": {"position": [0, 0.4, 4.2], '
                        '"look_at": [0, 0, 0]}, "objects": [{"type": "mesh", "file": "%s"}]}'
                        % os.path.abspath(os.path.join(folder, name)))
            for backend in ("cpu", "gpu"):
                with self.subTest(name=name, backend=backend):
                    out = os.path.join(self.dir, "out.png")
                    status, _, err = run("render", "--backend", backend, "-s", scene,
                                         "--width", "32", "--height", "24", "-o", out)
                    self.assertEqual(status, 1, err)
                    self.assertIn("riemann: error:", err)
                    self.assertIn(reason, err)
                    self.assertFalse(os.path.exists(out), "no output is written")

    def test_messages_are_short_and_plain(self):
        # A 2 MB key was quoted whole; scene syntax errors carried nlohmann's
        # "[json.exception.parse_error.101]"; a VTK reader's error its source
        # path and the reader's address.
        key = os.path.join(self.dir, "key.json")
        with open(key, "w") as f:
            f.write('{"type": "euclidean", "%s": 1}' % ("k" * 2000000))
        status, _, err = run("info", "-m", key)
        self.assertEqual(status, 1)
        self.assertLess(len(err), 400, err[:400])
        self.assertIn('..." (2000000 characters)', err)
        scene = os.path.join(self.dir, "scene.json")
        with open(scene, "w") as f:
            f.write('{"metric": {"type": "euclidean"}, "objects": [}')
        status, _, err = run("render", "--backend", "cpu", "-s", scene, "-o", os.path.join(self.dir, "o.png"))
        self.assertEqual(status, 1, err)
        self.assertIn("scene: invalid JSON: parse error at line 1, column 47", err)
        self.assertNotIn("json.exception", err)
        vtp = os.path.join(self.dir, "garbage.vtp")
        with open(vtp, "w") as f:
            f.write('<?xml version="1.0"?>\n<VTKFile type="PolyData"><PolyData><Piece')
        with open(scene, "w") as f:
            f.write('{"metric": {"type": "euclidean"}, "objects": [{"type": "mesh", "file": "garbage.vtp"}]}')
        status, _, err = run("render", "--backend", "cpu", "-s", scene, "-o", os.path.join(self.dir, "o.png"))
        self.assertEqual(status, 1, err)
        self.assertIn("cannot read the mesh: vtkXMLPolyDataReader: ", err)
        self.assertNotIn("ERROR: In", err)
        self.assertNotIn("(0x", err)

    def test_exact_arithmetic_is_bounded(self):
        # A 310-digit exponent kept GiNaC's exact arithmetic busy forever.
        metric = os.path.join(self.dir, "power.json")
        with open(metric, "w") as f:
            f.write('{"type": "graph", "f": "0.5^1%s*x"}' % ("0" * 309))
        started = time.time()
        status, _, err = run("info", "-m", metric)
        self.assertLess(time.time() - started, 20)
        self.assertEqual(status, 1, err)
        self.assertIn('column 5: number "1000000000000000000000000000000000000000..." (310 characters) too large', err)
        self.assertLess(len(err), 400, "the 310 digits are not all quoted")

    def test_tensor_files_are_clear_errors(self):
        folder = os.path.join(os.path.dirname(__file__), "../../../Common/Core/Testing/Data/hostile-tensors")
        reasons = {"bad_datatype.nii": "unknown NIfTI datatype code 12345",
                   "dim99.nrrd": '"dimension: 99"',
                   "gzbomb.nii.gz": "tensor volumes are read up to 2 GiB",
                   "detached_list.nhdr": '"data file: LIST"',
                   "huge_extent2.vti": "its WholeExtent (0 2147483646 0 2147483646 0 2147483646) "
                                       "declares more than 2 GiB of tensors",
                   "nan_spacing.vti": 'its Spacing "nan 0.5 0.5" is not 3 finite numbers'}
        for name, reason in reasons.items():
            with self.subTest(name=name):
                metric = os.path.join(self.dir, name + ".json")
                with open(metric, "w") as f:
                    f.write('{"type": "sampled", "file": "%s"}' % os.path.abspath(os.path.join(folder, name)))
                status, _, err = run("info", "-m", metric, "--point", "0.1,0.2,0.3")
                self.assertEqual(status, 1, err)
                self.assertIn("riemann: error:", err)
                self.assertIn(reason, err)


class FilePathTests(unittest.TestCase):
    """Inputs must be regular files (a device read without end, a FIFO blocked
    forever); an output may not replace an input or another output, nor be a
    device or FIFO (outputs are renamed into place). All before any work."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.twist = os.path.join(METRICS, "twist.json")

    def tearDown(self):
        self.tmp.cleanup()

    def test_an_output_that_is_an_input_is_refused_and_the_input_kept(self):
        seeds = os.path.join(self.dir, "S.csv")
        with open(seeds, "w") as f:
            f.write("x,y,z,dx,dy,dz\n0,0,0,1,0,0\n")
        status, _, err = run("trace", "-m", self.twist, "--seeds", seeds, "-o", seeds)
        self.assertEqual(status, 2, err)
        self.assertIn("-o %s: is also the input --seeds" % seeds, err)
        with open(seeds) as f:
            self.assertEqual(f.read(), "x,y,z,dx,dy,dz\n0,0,0,1,0,0\n")
        # the same file by another name
        status, _, err = run("trace", "-m", self.twist, "--seeds", seeds,
                             "-o", os.path.join(self.dir, ".", "S.csv"))
        self.assertEqual(status, 2, err)

    def test_two_outputs_with_one_name_are_refused(self):
        out = os.path.join(self.dir, "a.vtp")
        for args in (["conjugate", "-m", self.twist, "-o", out, "--surface", out],
                     ["expmap", "-m", self.twist, "-o", out, "--wavefronts", out]):
            with self.subTest(args[0]):
                status, _, err = run(*args)
                self.assertEqual(status, 2, err)
                self.assertIn("is also -o; one would replace the other", err)
                self.assertFalse(os.path.exists(out))

    def test_devices_fifos_and_folders_are_no_files(self):
        fifo = os.path.join(self.dir, "pipe")
        os.mkfifo(fifo)
        seeds = os.path.join(self.dir, "S.csv")
        with open(seeds, "w") as f:
            f.write("x,y,z,dx,dy,dz\n0,0,0,1,0,0\n")
        sampled = os.path.join(self.dir, "sampled.json")
        with open(sampled, "w") as f:
            f.write('{"type": "sampled", "file": "pipe"}')
        cases = [
            (["info", "-m", "/dev/zero"], 1, "/dev/zero: the metric file is not a regular file"),
            (["info", "-m", fifo], 1, "the metric file is not a regular file"),
            (["info", "-m", sampled, "--point", "0,0,0"], 1, "pipe: the tensor file is not a regular file"),
            (["trace", "-m", self.twist, "--seeds", fifo, "-o", os.path.join(self.dir, "o.csv")], 1,
             "the seeds file is not a regular file"),
            (["trace", "-m", self.twist, "-o", "/dev/null"], 2, "-o /dev/null: is not a regular file"),
            (["trace", "-m", self.twist, "-o", fifo], 2, "is not a regular file"),
            (["fields", "-m", self.twist, "-o", self.dir + "/"], 2, "is a folder; outputs are written whole"),
        ]
        for args, expected, reason in cases:
            with self.subTest(args=args):
                started = time.time()
                status, _, err = run(*args)
                self.assertLess(time.time() - started, 20, "answers without opening the FIFO")
                self.assertEqual(status, expected, err)
                self.assertIn(reason, err)
        self.assertTrue(os.path.exists("/dev/null") and not os.path.isfile("/dev/null"))

    def test_an_unreadable_reference_is_an_error_before_the_picture(self):
        reference = os.path.join(self.dir, "cut.png")
        with open(os.path.join(os.path.dirname(__file__),
                               "../../../Rendering/OpenGL/Testing/Data/Baseline/paper-twist.png"), "rb") as f:
            data = f.read()
        with open(reference, "wb") as f:
            f.write(data[: len(data) // 3])
        out = os.path.join(self.dir, "out.png")
        # Under the sanitizer build: OpenImageIO leaks its error text when
        # libpng longjmps (lsan.supp); full stacks let the suppression see it.
        lsan = os.environ.get("LSAN_OPTIONS")
        status, _, err = run("render", "--backend", "cpu", "--scene", os.path.join(DATA, "scenes", "paper-twist.json"),
                             "--width", "16", "--height", "12", "--reference", reference, "-o", out,
                             env={"LSAN_OPTIONS": lsan + ":fast_unwind_on_malloc=0"} if lsan else None)
        self.assertEqual(status, 2, err)
        self.assertIn("--reference: cannot read image %s: " % reference, err)
        self.assertTrue(err.startswith("riemann: error:"), "libpng's own line is not printed: " + err)
        self.assertEqual(len(err.strip().splitlines()), 2, err)  # the error and the --help hint
        self.assertFalse(os.path.exists(out))

    def test_a_truncated_binary_stl_is_refused(self):
        stl = os.path.join(self.dir, "cut.stl")
        with open(stl, "wb") as f:
            f.write(b"binary".ljust(80, b" ") + (448).to_bytes(4, "little") + bytes(50 * 99))
        scene = os.path.join(self.dir, "scene.json")
        with open(scene, "w") as f:
            f.write('{"metric": {"type": "euclidean"}, "objects": [{"type": "mesh", "file": "cut.stl"}]}')
        out = os.path.join(self.dir, "out.png")
        status, _, err = run("render", "--backend", "cpu", "-s", scene, "--width", "8", "--height", "8", "-o", out)
        self.assertEqual(status, 1, err)
        self.assertIn("a binary STL of 448 triangles takes 22484 bytes, the file has 5034 (cut short?)", err)
        self.assertFalse(os.path.exists(out))


class InterruptTests(TempDirTest):
    """SIGINT and SIGTERM stop a command: exit 130 / 143, one line, this run's
    partial files removed, earlier outputs and other processes' files kept."""

    def interrupt(self, sig, name, status):
        out = os.path.join(self.dir, "c.vtp")
        with open(out, "w") as f:
            f.write("earlier output")
        # 200,000 directions take minutes: the signal comes mid-computation.
        proc = subprocess.Popen([EXE, "conjugate", "-m", os.path.join(METRICS, "round-sphere.json"),
                                 "--directions", "200000", "--length", "30", "-o", out],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        # A partial file of this run, as WriteAtomically names it, and one of
        # another process whose id starts with this one's.
        partial = out + ".partial-%d" % proc.pid
        other = out + ".partial-%d7" % proc.pid
        for path in (partial, other):
            with open(path, "w") as f:
                f.write("x")
        time.sleep(1.0)
        self.assertIsNone(proc.poll(), "the command should still be computing")
        proc.send_signal(sig)
        _, err = proc.communicate(timeout=60)
        self.assertEqual(proc.returncode, status, err)
        self.assertEqual(err.strip(), "riemann: interrupted by %s; stopped, removed 1 partial file "
                                      "(earlier outputs are kept)" % name)
        self.assertFalse(os.path.exists(partial))
        self.assertTrue(os.path.exists(other))
        with open(out) as f:
            self.assertEqual(f.read(), "earlier output")

    def test_sigint_exits_130(self):
        self.interrupt(signal.SIGINT, "SIGINT", 130)

    def test_sigterm_exits_143(self):
        self.interrupt(signal.SIGTERM, "SIGTERM", 143)


class ConcurrentWriteTests(TempDirTest):
    """Several runs writing one .pvti name: whatever order they finish in,
    the summary names pieces that exist and are of the same run (before,
    12 of 20 rounds of four runs left a summary with no pieces or another
    run's pieces)."""

    def test_one_name_many_runs(self):
        import re
        out = os.path.join(self.dir, "same.pvti")
        for round_ in range(4):
            # Each run its own grid size, so that a summary and a piece of
            # different runs disagree on the extent.
            procs = [subprocess.Popen([EXE, "fields", "-m", os.path.join(METRICS, "twist.json"),
                                       "--dims", "%d,%d,%d" % (n, n, n), "-o", out],
                                      stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
                     for n in (5, 6, 7, 8)]
            for proc in procs:
                _, err = proc.communicate(timeout=120)
                self.assertEqual(proc.returncode, 0, err)
            with open(out) as f:
                summary = f.read()
            whole = re.search(r'WholeExtent="([^"]*)"', summary).group(1)
            sources = re.findall(r'Source="([^"]*)"', summary)
            self.assertEqual(len(sources), 1, summary)
            piece = os.path.join(self.dir, sources[0])
            self.assertTrue(os.path.exists(piece), "round %d: %s is missing" % (round_, piece))
            with open(piece, "rb") as f:
                head = f.read(2000).decode("latin-1")
            self.assertIn('WholeExtent="%s"' % whole, head, "round %d: the piece is another run's" % round_)
            self.assertEqual([n for n in os.listdir(self.dir) if "partial" in n], [])


class IntegrationOptionTests(unittest.TestCase):
    """One name, one range, one wording: every command that integrates lists
    the declared integration options in its --help (IntegrationOptions.h,
    vtkRiemannIntegrationSettings.settings.json): the property's name, then
    the old spellings that still work. Python.TestSettingSurfaces checks
    their defaults and ranges against the declaration."""

    OPTIONS = {
        "--integrator-type": ("--integrator", "euler|rk4|dp45"),
        "--initial-integration-step": ("--step", "FLOAT"),
        "--maximum-propagation": ("--length", "FLOAT"),
        "--maximum-error": ("--tolerance", "FLOAT"),
        "--maximum-number-of-steps": ("--max-steps", "INT"),
    }
    # Where --tolerance is the filter's own (the conjugate points' accuracy,
    # what |end - q| reaches), MaximumError is not an option.
    OWN_TOLERANCE = ("conjugate", "connect")

    def test_every_integrating_command_lists_them(self):
        import re
        for command in ("trace", "expmap", "conjugate", "connect", "render"):
            with self.subTest(command=command):
                status, out, err = run(command, "--help")
                self.assertEqual(status, 0, err)
                for option, (old, kind) in self.OPTIONS.items():
                    if option == "--maximum-error" and command in self.OWN_TOLERANCE:
                        self.assertNotIn(option, out)
                        continue
                    line = re.search(r"^\s+(?:-\w,)?%s((?:,[-\w]+)*) (\S+)" % re.escape(option),
                                     out, re.MULTILINE)
                    self.assertIsNotNone(line, "%s --help lacks %s:\n%s" % (command, option, out))
                    self.assertIn(old, line.group(1).split(","), (command, option, line.group(0)))
                    self.assertEqual(line.group(2), kind, (command, option, line.group(0)))

    def test_render_takes_every_one(self):
        out = os.path.join(tempfile.mkdtemp(), "o.png")
        status, _, err = run("render", "--backend", "cpu", "--width", "16", "--height", "12",
                             "--integrator", "dp45", "--step", "0.05", "--length", "12",
                             "--tolerance", "1e-5", "--max-steps", "400", "-o", out)
        self.assertEqual(status, 0, err)
        self.assertTrue(os.path.exists(out))


class ConnectTests(TempDirTest):
    """riemann connect: every geodesic from p to q, against the round sphere's
    great circles and the twist's straight lines."""

    SPHERE = os.path.join(METRICS, "round-sphere.json")

    @staticmethod
    def on_sphere(x):
        r2 = sum(c * c for c in x)
        return [2 * c / (1 + r2) for c in x] + [(1 - r2) / (1 + r2)]

    def connect(self, *args):
        out = os.path.join(self.dir, "c.csv")
        status, stdout, err = run("connect", *args, "-o", out)
        self.assertEqual(status, 0, err)
        table = list(csv.DictReader(stdout.splitlines()))
        with open(out) as f:
            rows = list(csv.DictReader(f))
        return table, rows

    def test_both_arcs_of_the_great_circle(self):
        p, q = (0.4, 0.1, -0.2), (-0.3, 0.5, 0.6)
        d = math.acos(sum(a * b for a, b in zip(self.on_sphere(p), self.on_sphere(q))))
        table, rows = self.connect("-m", self.SPHERE, "--from", "0.4,0.1,-0.2",
                                   "--to", "-0.3,0.5,0.6", "--length", "7")
        self.assertEqual(len(table), 2)
        self.assertAlmostEqual(float(table[0]["length"]), d, delta=1e-8)
        self.assertAlmostEqual(float(table[1]["length"]), 2 * math.pi - d, delta=1e-8)
        self.assertEqual([t["morse_index"] for t in table], ["0", "2"])
        self.assertEqual([t["shortest"] for t in table], ["1", "0"])
        self.assertLessEqual(max(float(t["miss"]) for t in table), 1e-9)
        # The CSV is trace's: one seed_id per geodesic, from p to q.
        self.assertEqual(sorted({r["seed_id"] for r in rows}), ["0", "1"])
        for seed in ("0", "1"):
            line = [r for r in rows if r["seed_id"] == seed]
            self.assertEqual(tuple(float(line[0][k]) for k in "xyz"), p)
            for k, v in zip("xyz", q):
                self.assertAlmostEqual(float(line[-1][k]), v, delta=1e-8)

    def test_the_antipode_is_conjugate_along_every_geodesic(self):
        # (0.5, 0, 0) and (-2, 0, 0) are antipodes on the sphere.
        table, _ = self.connect("-m", self.SPHERE, "--from", "0.5,0,0", "--to", "-2,0,0",
                                "--length", "4", "-n", "60")
        self.assertGreaterEqual(len(table), 57)
        for t in table:
            self.assertAlmostEqual(float(t["length"]), math.pi, delta=1e-8)
            self.assertEqual(t["conjugate_multiplicity"], "2")

    def test_the_twist_has_one_geodesic(self):
        p, q = (0.2, -0.4, 0.3), (1.0, 0.7, 1.6)
        table, _ = self.connect("-m", os.path.join(METRICS, "twist.json"), "--from", "0.2,-0.4,0.3",
                                "--to", "1.0,0.7,1.6", "-n", "300")
        phi = lambda x: (math.cos(x[2]) * x[0] - math.sin(x[2]) * x[1],
                         math.sin(x[2]) * x[0] + math.cos(x[2]) * x[1], x[2])
        self.assertEqual(len(table), 1)
        self.assertAlmostEqual(float(table[0]["length"]), math.dist(phi(p), phi(q)), delta=1e-8)

    def test_bad_input_is_refused_before_any_work(self):
        out = os.path.join(self.dir, "c.csv")
        for args, words in ((["--to", "0.5,0,0"], "the same point"),
                            (["--to", "1,1,1", "--tolerance", "0.5"], '--tolerance: expected a number from 1e-13 to 0.01, got "0.5"'),
                            (["--to", "1,1,1", "-o", os.path.join(self.dir, "c.png")], "must end in .vtp or .csv")):
            with self.subTest(args=args):
                line = ["connect", "-m", self.SPHERE, "--from", "0.5,0,0", *args]
                if "-o" not in args:
                    line += ["-o", out]
                status, _, err = run(*line)
                self.assertEqual(status, 2, err)
                self.assertIn(words, err)
                self.assertEqual(os.listdir(self.dir), [])


class DistanceTests(TempDirTest):
    """riemann distance: the twist's exact distance |Phi(x) - Phi(p)|, seeds'
    Voronoi regions, the cut locus file, and bad input refused before work."""

    @staticmethod
    def read(path):
        from vtkmodules.vtkIOXML import vtkXMLImageDataReader
        from vtkmodules.util.numpy_support import vtk_to_numpy
        import numpy as np
        reader = vtkXMLImageDataReader()
        reader.SetFileName(path)
        reader.Update()
        image = reader.GetOutput()
        points = np.array([image.GetPoint(i) for i in range(image.GetNumberOfPoints())])
        pd = image.GetPointData()
        return points, vtk_to_numpy(pd.GetArray("Distance")), vtk_to_numpy(pd.GetArray("SeedId"))

    def test_the_twist_and_two_seeds(self):
        import numpy as np
        out = os.path.join(self.dir, "d.vti")
        cut = os.path.join(self.dir, "cut.vtp")
        seeds = os.path.join(self.dir, "seeds.csv")
        with open(seeds, "w") as f:
            f.write("x,y,z\n0.5,0.1,0.2\n")
        lines = os.path.join(self.dir, "g.csv")
        status, _, err = run("distance", "-m", os.path.join(METRICS, "twist.json"), "--seed", "-0.5,0,-0.1",
                             "--seeds", seeds, "--bounds", "-1,1,-1,1,-1,1", "--dims", "25,25,25",
                             "-o", out, "--cut-locus", cut, "--to", "0.9,0.8,0.7", "--to", "-0.9,0.2,-0.3",
                             "--geodesics", lines)
        self.assertEqual(status, 0, err)
        self.assertIn("2 seed(s)", err)
        points, distance, seed_id = self.read(out)
        phi = lambda x: np.stack([np.cos(x[:, 2]) * x[:, 0] - np.sin(x[:, 2]) * x[:, 1],
                                  np.sin(x[:, 2]) * x[:, 0] + np.cos(x[:, 2]) * x[:, 1], x[:, 2]], 1)
        exact = np.stack([np.linalg.norm(phi(points) - phi(np.array([s])), axis=1)
                          for s in ([-0.5, 0, -0.1], [0.5, 0.1, 0.2])])
        # First order at h = 1/12 (measured 0.051 at most).
        self.assertLess(np.abs(distance - exact.min(axis=0)).max(), 0.06)
        clear = np.abs(exact[0] - exact[1]) > 0.2
        self.assertTrue((seed_id[clear] == exact.argmin(axis=0)[clear]).all())
        self.assertTrue(os.path.getsize(cut) > 0)
        # The minimal geodesics: one per --to point, from its closer seed to it.
        with open(lines) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(sorted({r["seed_id"] for r in rows}), ["0", "1"])
        for seed_id, target, seed in (("0", (0.9, 0.8, 0.7), (0.5, 0.1, 0.2)),
                                      ("1", (-0.9, 0.2, -0.3), (-0.5, 0, -0.1))):
            line = [r for r in rows if r["seed_id"] == seed_id]
            self.assertEqual(tuple(float(line[0][k]) for k in "xyz"), seed)
            for k, v in zip("xyz", target):
                self.assertAlmostEqual(float(line[-1][k]), v, delta=1e-8)
            exact = float(np.linalg.norm(phi(np.array([target])) - phi(np.array([seed]))))
            self.assertAlmostEqual(float(line[-1]["t"]), exact, delta=1e-8)

    def test_bad_input_is_refused_before_any_work(self):
        out = os.path.join(self.dir, "d.vti")
        twist = os.path.join(METRICS, "twist.json")
        for args, words in (([], "no seed"),
                            (["--seed", "3,0,0"], "outside --bounds"),
                            (["--seed", "0,0,0", "--dims", "2,2,1"], "--dimensions: expected three whole numbers, each from 2 to 512"),
                            (["--seed", "0,0,0", "--seed-radius", "50"], "--seed-radius"),
                            (["--seed", "0,0,0", "--cut-locus", os.path.join(self.dir, "c.vti")], "must be a .vtp"),
                            (["--seed", "0,0,0", "--to", "1,1,1"], "--to and --geodesics go together")):
            with self.subTest(args=args):
                status, _, err = run("distance", "-m", twist, *args, "-o", out)
                self.assertEqual(status, 2, err)
                self.assertIn(words, err)
                self.assertEqual(os.listdir(self.dir), [])


class TractographyTests(TempDirTest):
    """Tracing a sampled tensor volume as a tractography user does: seeds on
    the volume's faces are inside it (up to the rounding of its affine map),
    and every seed that makes no geodesic is counted, with why."""

    PHANTOM = os.path.join(DATA, "phantom", "fibre-phantom.json")

    def test_face_seeds_are_inside_and_untraced_seeds_are_counted(self):
        # The phantom's voxel centres on its x faces, 1e-13 beyond them (as a
        # NIfTI affine's rounding puts them), pointing inwards; one seed
        # well outside.
        origin, spacing = -1.9500000000000002, 0.1
        seeds = os.path.join(self.dir, "seeds.csv")
        rows = ["x,y,z,dx,dy,dz"]
        for j in (0, 13, 26, 39):
            for k in (0, 11, 23):
                y, z = origin + j * spacing, -1.1500000000000001 + k * spacing
                rows.append("%r,%r,%r,-1,0,0" % (origin + 39 * spacing + 1e-13, y, z))
                rows.append("%r,%r,%r,1,0,0" % (origin - 1e-13, y, z))
        rows.append("5,0,0,1,0,0")
        with open(seeds, "w") as f:
            f.write("\n".join(rows) + "\n")
        out = os.path.join(self.dir, "t.csv")
        status, _, err = run("trace", "-m", self.PHANTOM, "--seeds", seeds, "--length", "1", "-o", out)
        self.assertEqual(status, 0, err)
        self.assertIn("riemann trace: 24 geodesic(s)", err)
        self.assertIn("1 seed(s) made no geodesic: 1 left the sampled data at the seed", err)
        # No seed at all: the failure says why.
        with open(seeds, "w") as f:
            f.write("x,y,z,dx,dy,dz\n5,0,0,1,0,0\n-5,0,0,1,0,0\n")
        status, _, err = run("trace", "-m", self.PHANTOM, "--seeds", seeds, "-o", out)
        self.assertEqual(status, 1, err)
        self.assertIn("no geodesic could be traced from the given seeds: 2 seed(s) made no geodesic: "
                      "2 left the sampled data at the seed", err)


    def test_mean_diffusivity_scale(self):
        # The phantom's volume holds diffusion tensors of mean diffusivity
        # about 0.8 in its isotropic background; "scale": "mean-diffusivity"
        # divides them by the median (the background's), so g is I there
        # (to the background's own anisotropy, below 1%), whatever the units.
        volume = os.path.abspath(os.path.join(DATA, "phantom", "fibre-phantom.vti"))
        plain = self.diagonal('')
        scaled = self.diagonal(', "scale": "mean-diffusivity"')
        for value in scaled:
            self.assertAlmostEqual(value, 1.0, delta=0.01)
        self.assertTrue(all(abs(p - 0.8) < 0.01 for p in plain), plain)
        metric = os.path.join(self.dir, "bad.json")
        with open(metric, "w") as f:
            f.write('{"type": "sampled", "file": "%s", "array": "Tensors", "scale": "mm"}' % volume)
        status, _, err = run("info", "-m", metric, "--point", "0,0,0")
        self.assertEqual(status, 1, err)
        self.assertIn('expected a positive number or "mean-diffusivity"', err)

    def test_distance_and_connect_keep_to_the_volume(self):
        # With "outside": "stop", geodesics end at the volume's faces: the
        # distance is not defined beyond them, and no point there is joined.
        out = os.path.join(self.dir, "d.vti")
        status, _, err = run("distance", "-m", self.PHANTOM, "--seed", "0,0,0", "--bounds",
                             "-3,3,-3,3,-2,2", "--dims", "31,31,21", "-o", out)
        self.assertEqual(status, 0, err)
        # The volume reaches its outer voxels' faces (x, y in [-2, 2], z in
        # [-1.2, 1.2]): 21 x 21 x 13 of the grid's points, the other 14448
        # unreached.
        self.assertIn("14448 points unreached: outside the metric's data", err)
        status, _, err = run("distance", "-m", self.PHANTOM, "--seed", "2.5,0,0", "--bounds",
                             "-3,3,-3,3,-2,2", "--dims", "31,31,21", "-o", out)
        self.assertEqual(status, 1, err)
        self.assertIn("seed 0 is outside the metric's data", err)
        status, _, err = run("connect", "-m", self.PHANTOM, "--from", "3,0,0", "--to", "0,0,0",
                             "-o", os.path.join(self.dir, "c.csv"))
        self.assertEqual(status, 1, err)
        self.assertIn("StartPosition is outside the metric's data", err)

    def test_seeds_from_a_nifti_mask_stay_in_their_bundle(self):
        # A NIfTI mask written with the phantom's placement (s-form: spacing
        # 0.1, origin (-1.95, -1.95, -1.15)) over the x bundle's voxels with
        # -1.2 <= x <= -0.8: seeded along e1 both ways, every tract runs
        # along the bundle (within its radius 0.4 of the axis y = 0,
        # z = -0.35) up to the crossing, and each seed is a voxel centre of
        # the phantom.
        import numpy as np
        from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
        from vtkmodules.vtkCommonMath import vtkMatrix4x4
        from vtkmodules.vtkCommonDataModel import vtkImageData
        from vtkmodules.vtkIOImage import vtkNIFTIImageWriter
        from vtkmodules.vtkIOXML import vtkXMLImageDataReader
        reader = vtkXMLImageDataReader()
        reader.SetFileName(os.path.join(DATA, "phantom", "fibre-phantom.vti"))
        reader.Update()
        phantom = reader.GetOutput()
        bundle = vtk_to_numpy(phantom.GetPointData().GetArray("Bundle"))
        points = np.array([phantom.GetPoint(i) for i in range(phantom.GetNumberOfPoints())])
        chosen = (bundle == 1) & (points[:, 0] >= -1.2) & (points[:, 0] <= -0.8) & \
            (np.hypot(points[:, 1], points[:, 2] + 0.35) < 0.2)
        self.assertGreater(chosen.sum(), 5)
        mask = vtkImageData()
        mask.SetDimensions(40, 40, 24)
        mask.GetPointData().SetScalars(numpy_to_vtk(chosen.astype(np.uint8), deep=True))
        placement = vtkMatrix4x4()
        for r, (step, origin) in enumerate(((0.1, -1.95), (0.1, -1.95), (0.1, -1.15))):
            placement.SetElement(r, r, 1.0)
            placement.SetElement(r, 3, origin)
        mask.SetSpacing(0.1, 0.1, 0.1)
        path = os.path.join(self.dir, "mask.nii.gz")
        writer = vtkNIFTIImageWriter()
        writer.SetInputData(mask)
        writer.SetQFormMatrix(placement)
        writer.SetFileName(path)
        writer.Write()
        out = os.path.join(self.dir, "tracts.csv")
        status, _, err = run("trace", "-m", self.PHANTOM, "--seed-mask", path, "--length", "1.2",
                             "--step", "0.02", "-o", out)
        self.assertEqual(status, 0, err)
        self.assertIn("riemann trace: %d geodesic(s)" % (2 * chosen.sum()), err)
        with open(out) as f:
            rows = list(csv.DictReader(f))
        xyz = np.array([[float(r[k]) for k in "xyz"] for r in rows])
        starts = xyz[[r["step"] == "0" for r in rows]]
        # Each seed is a chosen voxel's centre (to 1e-6: NIfTI stores the
        # q-form's offsets as 32-bit floats; measured 5.6e-8).
        centres = points[chosen]
        self.assertLess(max(np.min(np.linalg.norm(centres - s, axis=1)) for s in starts), 1e-6)
        # Before the crossing with the y bundle (x around 0, where the
        # tensors are oblate and a tract may turn into the other bundle).
        before = xyz[:, 0] <= -0.4
        off_axis = np.hypot(xyz[before, 1], xyz[before, 2] + 0.35)
        self.assertGreater(before.sum(), 100)
        self.assertLess(off_axis.max(), 0.4)

    def test_seed_mask_errors(self):
        out = os.path.join(self.dir, "t.csv")
        empty = os.path.join(self.dir, "empty.vti")
        from vtkmodules.vtkCommonDataModel import vtkImageData
        from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
        from vtkmodules.util.numpy_support import numpy_to_vtk
        import numpy as np
        image = vtkImageData()
        image.SetDimensions(3, 3, 3)
        image.GetPointData().SetScalars(numpy_to_vtk(np.zeros(27, np.uint8), deep=True))
        writer = vtkXMLImageDataWriter()
        writer.SetInputData(image)
        writer.SetFileName(empty)
        writer.Write()
        for args, status_, words in (([ "--seed-mask", empty], 1, "no voxel of the mask is set"),
                                     (["--seed-mask", self.PHANTOM], 1, "unknown image format"),
                                     (["--seed-mask", empty, "--seed", "0,0,0"], 2, "excludes")):
            with self.subTest(args=args):
                status, _, err = run("trace", "-m", self.PHANTOM, *args, "-o", out)
                self.assertEqual(status, status_, err)
                self.assertIn(words, err)
                self.assertFalse(os.path.exists(out))

    def diagonal(self, scale):
        """The diagonal of g at a background point of the phantom, as info prints
        it, read by the spline, which averages 64 voxels: at this point the
        default trilinear reading of 8 is off 1 by 1.2%, the spline by 0.3%."""
        import re
        volume = os.path.abspath(os.path.join(DATA, "phantom", "fibre-phantom.vti"))
        metric = os.path.join(self.dir, "m.json")
        with open(metric, "w") as f:
            f.write('{"type": "sampled", "file": "%s", "array": "Tensors", "christoffel": "spline"%s}'
                    % (volume, scale))
        status, out, err = run("info", "-m", metric, "--point", "0.3,-0.2,0.1")
        self.assertEqual(status, 0, err)
        rows = re.findall(r"\[([^\]]*)\]", out.split("g^ij")[0].split("g_ij")[1])
        return [float(rows[i].split(",")[i]) for i in range(3)]


class PictureOptionTests(TempDirTest):
    """The camera and picture options of render are vtkRiemannPictureSettings's
    declared settings: the same names, defaults, ranges and words as a
    scene's "camera" block (Python.TestSettingSurfaces checks the defaults
    and ranges of every one against the declaration)."""

    # option: (old spellings that still work, what --help says to type)
    OPTIONS = {
        "--width": ((), "INT"),
        "--height": ((), "INT"),
        "--samples-per-pixel": (("--samples",), "INT"),
        "--backend": ((), "gpu|cpu"),
        "--gpu-path": ((), "auto|fragment|compute"),
        "--position": (("--camera-position",), "X,Y,Z"),
        "--look-at": ((), "X,Y,Z"),
        "--view-up": ((), "X,Y,Z"),
        "--view-angle": (("--fov",), "FLOAT"),
        "--projection": ((), "perspective|equirectangular"),
    }

    def scene(self, camera):
        import json
        path = os.path.join(self.dir, "scene-%d.json" % len(os.listdir(self.dir)))
        scene = {"objects": [{"type": "grid", "extent": [-3, 3, -3, 3, -3, 3], "spacing": 1,
                              "thickness": 0.05, "material": {"type": "position"}}]}
        if camera is not None:
            scene["camera"] = camera
        with open(path, "w") as f:
            json.dump(scene, f)
        return path

    def test_help_lists_them_with_their_old_spellings(self):
        import re
        status, out, err = run("render", "--help")
        self.assertEqual(status, 0, err)
        for option, (old, kind) in self.OPTIONS.items():
            line = re.search(r"^\s+%s((?:,[-\w]+)*) (\S+)" % re.escape(option), out, re.MULTILINE)
            self.assertIsNotNone(line, "render --help lacks %s:\n%s" % (option, out))
            self.assertEqual(tuple(a for a in line.group(1).split(",") if a), old, line.group(0))
            self.assertEqual(line.group(2), kind, (option, line.group(0)))

    def test_the_option_and_the_scene_refuse_alike(self):
        # One range, one sentence: 179.5 degrees is refused by --view-angle
        # (exit 2, before any work) and by a scene's camera.fov (exit 1, bad scene).
        words = "expected a number above 0 and at most 179 (degrees)"
        out = os.path.join(self.dir, "o.png")
        status, _, err = run("render", "--view-angle", "179.5", "-o", out)
        self.assertEqual(status, 2, err)
        self.assertIn(words, err)
        status, _, err = run("render", "-s", self.scene({"fov": 179.5}), "-o", out)
        self.assertEqual(status, 1, err)
        self.assertIn("scene.camera.fov: " + words, err)
        status, _, err = run("render", "--projection", "fisheye", "-o", out)
        self.assertEqual(status, 2, err)
        self.assertIn("expected one of perspective, equirectangular", err)
        status, _, err = run("render", "-s", self.scene({"projection": "fisheye"}), "-o", out)
        self.assertEqual(status, 1, err)
        self.assertIn("expected one of perspective, equirectangular", err)
        status, _, err = run("render", "--projection", "perspective", "--equirectangular", "-o", out)
        self.assertEqual(status, 2, err)
        self.assertIn("two projections", err)
        self.assertFalse(os.path.exists(out))

    def test_a_scene_without_camera_takes_the_declared_one(self):
        # Not vtkCamera's own defaults (from 0,0,1 with 30 degrees): the
        # picture of the declared camera given as options, pixel for pixel.
        bare = self.scene(None)
        common = ["--backend", "cpu", "--width", "48", "--height", "36", "-s", bare]
        implicit = os.path.join(self.dir, "implicit.png")
        explicit = os.path.join(self.dir, "explicit.png")
        vtk_default = os.path.join(self.dir, "vtk.png")
        self.assertEqual(run("render", *common, "-o", implicit)[0], 0)
        self.assertEqual(run("render", *common, "--position", "0,0,5", "--look-at", "0,0,0",
                             "--view-up", "0,1,0", "--view-angle", "60", "-o", explicit)[0], 0)
        self.assertEqual(run("render", *common, "--camera-position", "0,0,1", "--fov", "30",
                             "-o", vtk_default)[0], 0)
        a, b, c = (png_size_and_pixels(p)[2] for p in (implicit, explicit, vtk_default))
        self.assertEqual(abs(a.astype(int) - b.astype(int)).max(), 0)
        self.assertGreater(abs(a.astype(float) - c.astype(float)).mean(), 5)

    def test_projection_is_the_long_form_of_equirectangular(self):
        pictures = []
        for flags in (["--projection", "equirectangular"], ["--equirectangular"]):
            out = os.path.join(self.dir, "e%d.png" % len(pictures))
            status, _, err = run("render", "--backend", "cpu", "--width", "48", "--height", "24",
                                 *flags, "-o", out)
            self.assertEqual(status, 0, err)
            pictures.append(png_size_and_pixels(out)[2])
        self.assertEqual(abs(pictures[0].astype(int) - pictures[1].astype(int)).max(), 0)
        # and a scene's equirectangular camera is overridden by --projection perspective
        scene = self.scene({"position": [0, 0, 5], "projection": "equirectangular"})
        perspective = os.path.join(self.dir, "p.png")
        equirect = os.path.join(self.dir, "q.png")
        base = ["--backend", "cpu", "--width", "48", "--height", "24", "-s", scene]
        self.assertEqual(run("render", *base, "--projection", "perspective", "-o", perspective)[0], 0)
        self.assertEqual(run("render", *base, "-o", equirect)[0], 0)
        p, q = (png_size_and_pixels(x)[2] for x in (perspective, equirect))
        self.assertGreater(abs(p.astype(float) - q.astype(float)).mean(), 5)


class CpuRenderTests(TempDirTest):
    """riemann render --backend cpu (the Embree tracer)."""

    def test_cpu_matches_the_gpu_baselines(self):
        # The GPU's committed pictures of the paper's figures are the CPU's
        # references too: mean difference at most 0.5 of 255.
        baseline = os.path.join(os.path.dirname(__file__), "../../../Rendering/OpenGL/Testing/Data/Baseline")
        for name in ("paper-one-bump", "paper-twist"):
            with self.subTest(name):
                out = os.path.join(self.dir, name + ".png")
                status, _, err = run("render", "--backend", "cpu",
                                     "--scene", os.path.join(DATA, "scenes", name + ".json"),
                                     "--width", "160", "--height", "120", "--threshold", "0.5",
                                     "--reference", os.path.join(baseline, name + ".png"), "-o", out)
                self.assertEqual(status, 0, err)
                self.assertNotIn("[", err, "no progress bar when stderr is not a terminal")

    def test_mesh_scene_on_both_backends(self):
        # The GPU pass draws mesh objects; the CPU's picture of the same scene
        # is within 0.5 of 255 of it on average.
        scene = os.path.join(DATA, "scenes", "mesh-two-bumps.json")
        gpu = os.path.join(self.dir, "gpu.png")
        status, _, err = run("render", "--scene", scene, "--width", "80", "--height", "60", "-o", gpu)
        self.assertEqual(status, 0, err)
        status, _, err = run("render", "--backend", "cpu", "--scene", scene, "--width", "80",
                             "--height", "60", "--threshold", "0.5", "--reference", gpu, "-o",
                             os.path.join(self.dir, "cpu.png"))
        self.assertEqual(status, 0, err)

    def test_exr_channels_and_hit_error(self):
        out = os.path.join(self.dir, "twist.exr")
        picture = os.path.join(self.dir, "error.png")
        status, _, err = run("render", "--backend", "cpu", "--samples", "4",
                             "--scene", os.path.join(DATA, "scenes", "paper-twist.json"),
                             "--width", "40", "--height", "30", "--hit-error",
                             "--hit-error-image", picture, "-o", out)
        self.assertEqual(status, 0, err)
        info = subprocess.run(["oiiotool", "--info", "-v", out], capture_output=True, text=True).stdout
        for channel in ("R, G, B", "HitPosition.X", "HitPosition.Y", "HitPosition.Z", "ArcLength",
                        "Steps", "ReasonForTermination", "SpeedDrift", "HitError"):
            self.assertIn(channel, info)
        # RK4 at step 0.02 (the scene's) against the exact geodesics: median below 1e-4.
        line = [l for l in err.splitlines() if "hit error against the exact geodesic" in l][0]
        median = float(line.split("median ")[1].split(",")[0])
        maximum = float(line.split("max ")[1].split(",")[0])
        self.assertLess(median, 1e-4, line)
        self.assertGreaterEqual(maximum, median, line)
        width, height, _ = png_size_and_pixels(picture)
        self.assertEqual((width, height), (40, 30))


class GlslTests(unittest.TestCase):
    def test_every_example_metric_emits_valid_glsl(self):
        """`riemann info --glsl` for each Data/metrics file compiles as GLSL 3.30 (glslangValidator)."""
        import shutil
        validator = shutil.which("glslangValidator")
        if validator is None:
            self.skipTest("glslangValidator (glslang-tools) is not installed")
        for name in sorted(os.listdir(METRICS)):
            with self.subTest(name):
                status, source, err = run("info", "--glsl", "-m", os.path.join(METRICS, name))
                self.assertEqual(status, 0, err)
                self.assertIn("bool rt_metric_acceleration(vec3 p, vec3 v, out vec3 a)", source)
                with tempfile.TemporaryDirectory() as d:
                    path = os.path.join(d, "metric.frag")
                    with open(path, "w") as f:
                        f.write("#version 330 core\nout vec4 color;\n" + source +
                                "\nvoid main() { mat3 g; vec3 a; bool ok = rt_metric_tensor(vec3(0.1), g)"
                                " && rt_metric_acceleration(vec3(0.2), vec3(1.0), a);"
                                " color = vec4(a + g[0], ok ? 1.0 : 0.0); }\n")
                    result = subprocess.run([validator, path], capture_output=True, text=True)
                    self.assertEqual(result.returncode, 0, result.stdout + result.stderr)


# (description, arguments, metric text or None, expected substring of stderr)
SPHERE_JSON = '{"type": "conformal", "n": "2/(1+x^2+y^2+z^2)"}'


class FieldsTests(unittest.TestCase):
    """riemann fields: the round 3-sphere (ScalarCurvature 6) as CSV and .vti."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.metric = os.path.join(self.dir, "sphere.json")
        with open(self.metric, "w") as f:
            f.write(SPHERE_JSON)

    def tearDown(self):
        self.tmp.cleanup()

    def test_csv_header_and_sphere_values(self):
        out = os.path.join(self.dir, "fields.csv")
        status, _, err = run("fields", "--metric", self.metric, "--bounds", "-1,1,-1,1,-0.5,0.5",
                             "--dims", "3,4,2", "-o", out)
        self.assertEqual(status, 0, err)
        with open(out, newline="") as f:
            rows = list(csv.reader(f))
        header = rows[0]
        self.assertEqual(header[:4], ["x", "y", "z", "ScalarCurvature"])
        for name in ("Ricci_0", "Ricci_5", "SectionalMin", "SectionalMax", "RiemannNorm",
                     "VolumeForm", "MetricTensor_0", "InverseMetricTensor_5",
                     "MetricEigenvalues_2"):
            self.assertIn(name, header)
        self.assertEqual(len(rows) - 1, 3 * 4 * 2)
        col = {name: k for k, name in enumerate(header)}
        for row in rows[1:]:
            x, y, z = (float(row[k]) for k in range(3))
            n = 2.0 / (1.0 + x * x + y * y + z * z)
            self.assertAlmostEqual(float(row[col["ScalarCurvature"]]), 6.0, places=9)
            self.assertAlmostEqual(float(row[col["Ricci_0"]]), 2 * n * n, places=9)
            self.assertAlmostEqual(float(row[col["VolumeForm"]]), n ** 3, places=12)
            self.assertAlmostEqual(float(row[col["MetricTensor_1"]]), n * n, places=12)
        self.assertEqual(sorted(os.listdir(self.dir)), ["fields.csv", "sphere.json"])

    def test_vti_readable_with_arrays(self):
        from vtkmodules.vtkIOXML import vtkXMLImageDataReader
        out = os.path.join(self.dir, "fields.vti")
        status, _, err = run("fields", "--metric", self.metric, "--dims", "5,5,5", "-o", out)
        self.assertEqual(status, 0, err)
        reader = vtkXMLImageDataReader()
        reader.SetFileName(out)
        reader.Update()
        image = reader.GetOutput()
        self.assertEqual(image.GetDimensions(), (5, 5, 5))
        self.assertEqual(image.GetBounds(), (-2.0, 2.0, -2.0, 2.0, -2.0, 2.0))
        pd = image.GetPointData()
        for name, components in (("ScalarCurvature", 1), ("Ricci", 6), ("VolumeForm", 1),
                                 ("MetricTensor", 6), ("InverseMetricTensor", 6),
                                 ("MetricEigenvalues", 3), ("SectionalYZ", 1)):
            array = pd.GetArray(name)
            self.assertIsNotNone(array, name)
            self.assertEqual(array.GetNumberOfComponents(), components, name)
        lo, hi = pd.GetArray("ScalarCurvature").GetRange()
        self.assertAlmostEqual(lo, 6.0, places=9)
        self.assertAlmostEqual(hi, 6.0, places=9)
        self.assertIsNotNone(image.GetFieldData().GetArray("VolumeIntegral"))

    def test_compressors_write_the_same_values(self):
        # --compress lz4 (the default), zlib and none: the header names the
        # compressor, and the values read back are identical.
        from vtkmodules.vtkIOXML import vtkXMLImageDataReader
        from vtkmodules.util.numpy_support import vtk_to_numpy
        values = {}
        for compress, header in (("lz4", 'compressor="vtkLZ4DataCompressor"'),
                                 ("zlib", 'compressor="vtkZLibDataCompressor"'), ("none", None)):
            with self.subTest(compress=compress):
                out = os.path.join(self.dir, "fields-%s.vti" % compress)
                args = ["fields", "--metric", self.metric, "--dims", "6,5,4", "-o", out]
                if compress != "lz4":
                    args[1:1] = ["--compress", compress]
                status, _, err = run(*args)
                self.assertEqual(status, 0, err)
                with open(out, "rb") as f:
                    start = f.read(400).decode("latin-1")
                if header:
                    self.assertIn(header, start)
                else:
                    self.assertNotIn("compressor=", start)
                reader = vtkXMLImageDataReader()
                reader.SetFileName(out)
                reader.Update()
                values[compress] = vtk_to_numpy(reader.GetOutput().GetPointData().GetArray("Ricci"))
        self.assertTrue((values["lz4"] == values["zlib"]).all())
        self.assertTrue((values["lz4"] == values["none"]).all())
        status, _, err = run("fields", "--metric", self.metric, "--compress", "lz5", "-o",
                             os.path.join(self.dir, "bad.vti"))
        self.assertEqual(status, 2, err)
        self.assertIn("--compress", err)
        self.assertFalse(os.path.exists(os.path.join(self.dir, "bad.vti")))

    def test_bad_bounds_and_dims(self):
        cases = [
            # The grid's declared settings (--dims is Dimensions' old spelling).
            (["--bounds", "-1,1,-1,1"], '--bounds: expected six finite comma-separated numbers X0,X1,Y0,Y1,Z0,Z1, got "-1,1,-1,1"'),
            (["--bounds", "-1,1,-1,1,-1,inf"], "--bounds: expected six finite"),
            (["--bounds", "-1,abc,-1,1,-1,1"], "--bounds: expected six finite"),
            (["--bounds", "1,-1,-1,1,-1,1"], '--bounds: "1,-1,-1,1,-1,1": the x range needs x0 < x1, got 1 >= -1'),
            (["--bounds", "-1,1,-1,1,2,2"], "the z range needs z0 < z1"),
            (["--dims", "3,3"], "--dimensions: expected three comma-separated whole numbers NX,NY,NZ"),
            (["--dims", "0,3,3"], "--dimensions: expected three whole numbers, each from 1 to 512 (points)"),
            (["--dims", "3,513,3"], "each from 1 to 512"),
            (["--dims", "300,300,300"], "at most 20000000"),
            (["--dims", "3.5,3,3"], "whole numbers"),
        ]
        for args, expected in cases:
            with self.subTest(args=args):
                out = os.path.join(self.dir, "bad.csv")
                status, _, err = run("fields", "--metric", self.metric, *args, "-o", out)
                self.assertEqual(status, 2, err)
                self.assertIn(expected, err)
                self.assertEqual(sorted(os.listdir(self.dir)), ["sphere.json"])


class ConjugateTests(unittest.TestCase):
    """riemann conjugate: the round 3-sphere's first conjugate points (the antipode)."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.metric = os.path.join(self.dir, "sphere.json")
        with open(self.metric, "w") as f:
            f.write(SPHERE_JSON)

    def tearDown(self):
        self.tmp.cleanup()

    def test_sphere_csv(self):
        out = os.path.join(self.dir, "conjugate.csv")
        status, _, err = run("conjugate", "--metric", self.metric, "--seed", "0.2,0.1,-0.3",
                             "--directions", "20", "--length", "4", "--step", "0.01", "-o", out)
        self.assertEqual(status, 0, err)
        self.assertIn("20 direction(s), 20 conjugate point(s)", err)
        with open(out, newline="") as f:
            rows = list(csv.reader(f))
        self.assertEqual(rows[0], ["direction_id", "x", "y", "z", "ArcLength", "Multiplicity",
                                   "ConjugateIndex", "Sheet"])
        self.assertEqual(len(rows) - 1, 20)
        p = (0.2, 0.1, -0.3)
        r2 = sum(t * t for t in p)
        for k, row in enumerate(rows[1:]):
            self.assertEqual(int(row[0]), k)
            for c in range(3):
                self.assertAlmostEqual(float(row[1 + c]), -p[c] / r2, delta=1e-5)
            self.assertAlmostEqual(float(row[4]), math.pi, delta=1e-6)
            self.assertEqual(int(row[5]), 2)
            self.assertEqual(int(row[6]), 1)
            self.assertEqual(int(row[7]), 1)
        self.assertEqual(sorted(os.listdir(self.dir)), ["conjugate.csv", "sphere.json"])

    def test_close_simple_points_are_both_found(self):
        # g = diag((cos y cos kz)^2, 1, 1): along +x the Jacobi fields are
        # sin(s) and sin(ks)/k, two simple conjugate points at pi/k and pi that
        # the old search merged with its defaults (the reproducer).
        for k in (1.002, 1.005, 1.01, 1.05):
            with self.subTest(k=k):
                metric = os.path.join(self.dir, "two-speeds.json")
                with open(metric, "w") as f:
                    f.write('{"type":"tensor","parameters":{"k":%r},'
                            '"g":[["(cos(y)*cos(k*z))^2","0","0"],["0","1","0"],["0","0","1"]]}' % k)
                out = os.path.join(self.dir, "pair.csv")
                status, _, err = run("conjugate", "--metric", metric, "--cone-axis", "1,0,0",
                                     "--cone-angle", "0", "-n", "1", "-l", "4", "-k", "3", "-o", out)
                self.assertEqual(status, 0, err)
                with open(out, newline="") as f:
                    rows = list(csv.DictReader(f))
                self.assertEqual(len(rows), 2)
                for row, expected, index in ((rows[0], math.pi / k, 1), (rows[1], math.pi, 2)):
                    self.assertAlmostEqual(float(row["ArcLength"]), expected, delta=1e-8)
                    self.assertEqual(int(row["Multiplicity"]), 1)
                    self.assertEqual(int(row["ConjugateIndex"]), index)
                    self.assertEqual(int(row["Sheet"]), index)

    def test_sphere_vtp(self):
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
        out = os.path.join(self.dir, "conjugate.vtp")
        status, _, err = run("conjugate", "--metric", self.metric, "--seed", "0.2,0.1,-0.3",
                             "--directions", "5", "--length", "7", "--count", "2", "-o", out)
        self.assertEqual(status, 0, err)
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(out)
        reader.Update()
        data = reader.GetOutput()
        self.assertEqual(data.GetNumberOfPoints(), 10)
        self.assertEqual(data.GetNumberOfVerts(), 10)
        pd = data.GetPointData()
        for name in ("ArcLength", "Multiplicity", "ConjugateIndex", "DirectionId", "Sheet",
                     "KernelDirection"):
            self.assertIsNotNone(pd.GetArray(name), name)
        self.assertEqual(pd.GetArray("ConjugateIndex").GetRange(), (1.0, 2.0))
        # Double points: the second one lies on sheets 3 and 4.
        self.assertEqual(pd.GetArray("Sheet").GetRange(), (1.0, 3.0))

    def test_bad_arguments(self):
        cases = [
            (["--directions", "0"], "--number-of-directions"),
            (["--directions", "-3"], "--number-of-directions"),
            (["--length", "0"], "--maximum-propagation"),
            (["--step", "0"], "--initial-integration-step"),
            (["--count", "0"], "--maximum-number-of-conjugate-points"),
            (["--seed", "1,2"], "--observer: expected three finite"),
            (["--max-step", "0"], "--maximum-integration-step"),
            (["--max-step", "0.001"], "--max-step 0.001: must be at least --step 0.01"),
        ]
        for args, expected in cases:
            with self.subTest(args=args):
                out = os.path.join(self.dir, "bad.csv")
                status, _, err = run("conjugate", "--metric", self.metric, *args, "-o", out)
                self.assertEqual(status, 2, err)
                self.assertIn(expected, err)
                self.assertEqual(sorted(os.listdir(self.dir)), ["sphere.json"])

    def test_locus_surface_and_integrator(self):
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
        out = os.path.join(self.dir, "conjugate.vtp")
        surface = os.path.join(self.dir, "caustic.vtp")
        status, _, err = run("conjugate", "--metric", self.metric, "--seed", "0.2,0.1,-0.3",
                             "--directions", "30", "--length", "4", "--integrator", "dp45",
                             "--cone-axis", "1,0,0", "--cone-angle", "60", "-o", out, "--surface", surface)
        self.assertEqual(status, 0, err)
        self.assertIn("caustic 2 sheet(s)", err)
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(surface)
        reader.Update()
        data = reader.GetOutput()
        # Every direction has a first conjugate point, double: one per grid
        # point on each of sheets 1 and 2, the grid's triangles (a disc: more
        # than N - 2) on each, all at the antipode, where the two sheets meet.
        self.assertEqual(data.GetNumberOfPoints(), 60)
        self.assertGreater(data.GetNumberOfPolys(), 40)
        cells = data.GetCellData()
        self.assertEqual(cells.GetArray("Sheet").GetRange(), (1.0, 2.0))
        self.assertEqual(cells.GetArray("Singularity").GetRange(), (2.0, 2.0))
        p = (0.2, 0.1, -0.3)
        r2 = sum(t * t for t in p)
        for i in range(data.GetNumberOfPoints()):
            x = data.GetPoint(i)
            self.assertLess(max(abs(x[c] + p[c] / r2) for c in range(3)), 1e-5)
        bad = os.path.join(self.dir, "bad.csv")
        for args, expected in [(["--integrator", "rk5"], "--integrator"),
                               (["--surface", os.path.join(self.dir, "s.csv")], "--surface"),
                               (["--cone-axis", "1,2"], "--cone-axis")]:
            with self.subTest(args=args):
                status, _, err = run("conjugate", "--metric", self.metric, *args, "-o", bad)
                self.assertEqual(status, 2, err)
                self.assertIn(expected, err)
        self.assertEqual(sorted(os.listdir(self.dir)), ["caustic.vtp", "conjugate.vtp", "sphere.json"])


class ExpmapTests(unittest.TestCase):
    """riemann expmap: the round 3-sphere's geodesic spheres."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.metric = os.path.join(self.dir, "sphere.json")
        with open(self.metric, "w") as f:
            f.write(SPHERE_JSON)

    def tearDown(self):
        self.tmp.cleanup()

    def test_every_vtp_output_takes_compress(self):
        # trace, expmap (bundle and wavefronts) and conjugate (points and
        # surface) write LZ4 by default, as fields; --compress zlib|none
        # change it, and the values read back are the same.
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
        from vtkmodules.util.numpy_support import vtk_to_numpy

        def header(path):
            with open(path, "rb") as f:
                return f.read(600).decode("latin-1")

        commands = {
            "trace": (["trace", "--seed", "0.2,0.1,-0.3", "--direction", "1,0.2,0", "--length", "2"],
                      None),
            "expmap": (["expmap", "--seed", "0.2,0.1,-0.3", "--directions", "12", "--length", "2",
                        "--radii", "1"], "--wavefronts"),
            "conjugate": (["conjugate", "--seed", "0.2,0.1,-0.3", "--directions", "12",
                           "--length", "4"], "--surface"),
        }
        for name, (args, second) in commands.items():
            points = {}
            for compress, expected in (("lz4", 'compressor="vtkLZ4DataCompressor"'),
                                       ("zlib", 'compressor="vtkZLibDataCompressor"'),
                                       ("none", None)):
                with self.subTest(command=name, compress=compress):
                    out = os.path.join(self.dir, "%s-%s.vtp" % (name, compress))
                    extra = os.path.join(self.dir, "%s-%s-2.vtp" % (name, compress))
                    call = args + ["--metric", self.metric, "-o", out]
                    if second:
                        call += [second, extra]
                    if compress != "lz4":
                        call += ["--compress", compress]
                    status, _, err = run(*call)
                    self.assertEqual(status, 0, err)
                    for path in [out] + ([extra] if second else []):
                        if expected:
                            self.assertIn(expected, header(path), path)
                        else:
                            self.assertNotIn("compressor=", header(path), path)
                    reader = vtkXMLPolyDataReader()
                    reader.SetFileName(out)
                    reader.Update()
                    points[compress] = vtk_to_numpy(reader.GetOutput().GetPoints().GetData())
                    self.assertGreater(len(points[compress]), 0)
            self.assertTrue((points["lz4"] == points["zlib"]).all(), name)
            self.assertTrue((points["lz4"] == points["none"]).all(), name)

    def test_bundle_and_wavefronts(self):
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
        rays = os.path.join(self.dir, "rays.vtp")
        fronts = os.path.join(self.dir, "fronts.vtp")
        status, _, err = run("expmap", "--metric", self.metric, "--seed", "0.2,0.1,-0.3",
                             "--directions", "40", "--length", "3.5", "--radii", "1,3.14159265358979",
                             "-o", rays, "--wavefronts", fronts)
        self.assertEqual(status, 0, err)
        self.assertIn("40 geodesic(s)", err)
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(fronts)
        reader.Update()
        data = reader.GetOutput()
        self.assertEqual(data.GetNumberOfPoints(), 80)
        self.assertEqual(data.GetNumberOfPolys(), 2 * (2 * 40 - 4))
        radius = data.GetPointData().GetArray("Radius")
        det = data.GetPointData().GetArray("TransverseJacobian")
        p = (0.2, 0.1, -0.3)
        r2 = sum(t * t for t in p)
        for i in range(80):
            r = radius.GetValue(i)
            self.assertAlmostEqual(det.GetValue(i), math.sin(r) ** 2, delta=1e-6)
            if r > 3:  # the sphere of radius pi is the antipode
                x = data.GetPoint(i)
                self.assertLess(max(abs(x[c] + p[c] / r2) for c in range(3)), 1e-5)
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(rays)
        reader.Update()
        self.assertEqual(reader.GetOutput().GetNumberOfLines(), 40)
        self.assertIsNotNone(reader.GetOutput().GetPointData().GetArray("TransverseJacobian"))

    def test_bad_arguments(self):
        cases = [
            (["--radii", "1,x"], '--radii: expected numbers, each above 0'),
            (["--radii", "-1"], "--radii"),
            # The filter's own length, 5, is the command's default.
            (["--radii", "11"], "--radii: 11 is beyond --length 5"),
            (["--wavefronts", "W.vtp"], "--wavefronts needs --radii"),
            (["--radii", "1", "--wavefronts", "W.csv"], "--wavefronts"),
            (["--directions", "0"], "--number-of-directions"),
            (["--integrator", "rk5"], "--integrator-type"),
            (["--cone-angle", "200"], "--cone-angle"),
        ]
        for args, expected in cases:
            with self.subTest(args=args):
                args = [a.replace("W.", os.path.join(self.dir, "w.")) for a in args]
                out = os.path.join(self.dir, "rays.vtp")
                status, _, err = run("expmap", "--metric", self.metric, *args, "-o", out)
                self.assertNotEqual(status, 0, err)
                self.assertIn(expected, err)
                self.assertEqual(sorted(os.listdir(self.dir)), ["sphere.json"])


BAD_INPUTS = [
    ("missing metric file", ["trace", "-m", "/nonexistent.json", "-o", "OUT.csv"], None, "File does not exist"),
    ("malformed JSON", ["trace", "-m", "METRIC", "-o", "OUT.csv"], '{"type": "graph",\n "gaussians": [}',
     "invalid JSON: parse error at line 2, column 16"),
    ("unknown key", ["trace", "-m", "METRIC", "-o", "OUT.csv"], '{"type": "graph", "gausians": []}',
     'unknown key "gausians"'),
    ("not a diffeomorphism", ["trace", "-m", "METRIC", "-o", "OUT.csv"],
     '{"type": "diffeo", "preset": "bump", "gaussian": {"amplitude": 2, "center": [0,0,0], "sigma": 0.5}, "direction": [1,0,0]}',
     "is not a diffeomorphism"),
    ("expression with an unknown symbol", ["trace", "-m", "METRIC", "-o", "OUT.csv"],
     '{"type": "graph", "f": "x^2 + w"}', 'metric.f: column 7: unknown symbol "w"'),
    ("expression with a syntax error", ["info", "-m", "METRIC"], '{"type": "conformal", "n": "1 + (x"}',
     "metric.n: column"),
    ("info where the metric degenerates", ["info", "-m", "METRIC", "-p", "2,0,0"],
     '{"type": "conformal", "n": "2/(1 - x^2 - y^2 - z^2)"}', "geodesics and rays stop here"),
    ("seed with two numbers", ["trace", "-m", "METRIC", "--seed", "1,2", "-o", "OUT.csv"], '{"type": "euclidean"}',
     "--start-position: expected three finite comma-separated numbers"),
    ("NaN in seed", ["trace", "-m", "METRIC", "--seed", "nan,0,0", "-o", "OUT.csv"], '{"type": "euclidean"}',
     "--start-position: expected three finite"),
    ("zero direction", ["trace", "-m", "METRIC", "--direction", "0,0,0", "-o", "OUT.csv"], '{"type": "euclidean"}',
     "must not be zero"),
    ("unknown integrator", ["trace", "-m", "METRIC", "--integrator", "rk5", "-o", "OUT.csv"], '{"type": "euclidean"}',
     '--integrator-type: expected one of euler, rk4, dp45, got "rk5"'),
    ("negative length", ["trace", "-m", "METRIC", "--length", "-1", "-o", "OUT.csv"], '{"type": "euclidean"}',
     "--maximum-propagation"),
    ("absurd step count", ["trace", "-m", "METRIC", "--max-steps", "99999999999", "-o", "OUT.csv"],
     '{"type": "euclidean"}', "--maximum-number-of-steps"),
    ("wrong output extension", ["trace", "-m", "METRIC", "-o", "OUT.txt"], '{"type": "euclidean"}',
     "must end in .vtp, .pvtp, .csv, .tck or .trk"),
    ("missing output folder", ["trace", "-m", "METRIC", "-o", "/nonexistent-dir/out.csv"], '{"type": "euclidean"}',
     "the folder /nonexistent-dir does not exist"),
    ("bad number in seeds file", ["trace", "-m", "METRIC", "--seeds", "SEEDS", "-o", "OUT.csv"], '{"type": "euclidean"}',
     'line 3: "abc" is not a finite number'),
    ("info at a bad point", ["info", "-m", "METRIC", "-p", "1,2,inf"], '{"type": "euclidean"}',
     "--point: expected three finite"),
    ("no subcommand", [], None, "A subcommand is required"),
    ("render: samples on the GPU", ["render", "--samples", "4", "-o", "OUT.png"], None,
     "need --backend cpu"),
    ("render: unknown GPU path", ["render", "--gpu-path", "vulkan", "-o", "OUT.png"], None,
     "--gpu-path"),
    ("render: GPU path on the CPU", ["render", "--backend", "cpu", "--gpu-path", "compute",
     "-o", "OUT.png"], None, "needs --backend gpu"),
    ("render: hit error without a diffeomorphism", ["render", "--backend", "cpu", "--hit-error",
     "-m", "METRIC", "-o", "OUT.png"], '{"type": "euclidean"}', "no exact reference"),
    ("render: mesh scene on the GPU", ["render", "--scene", "METRIC", "-o", "OUT.png"],
     '{"objects": [{"type": "mesh", "file": "nowhere.ply"}]}', "not found"),
    ("render: wrong extension", ["render", "-o", "OUT.txt"], None, "must end in .png, .exr or .ogv"),
    ("render: bad scene", ["render", "--scene", "METRIC", "-o", "OUT.png"], '{"objects": [{"type": "sphere"}]}',
     "bad scene"),
    ("render: reference with frames", ["render", "--frames", "2", "--reference", "METRIC", "-o", "OUT.png"],
     '{"type": "euclidean"}', "cannot be used with --frames"),
]


class BadInputTests(unittest.TestCase):
    def run_bad(self, args, metric_text):
        with tempfile.TemporaryDirectory() as d:
            metric = os.path.join(d, "metric.json")
            if metric_text is not None:
                with open(metric, "w") as f:
                    f.write(metric_text)
            seeds = os.path.join(d, "seeds.csv")
            with open(seeds, "w") as f:
                f.write("x,y,z,dx,dy,dz\n0,0,0,1,0,0\n1,abc,0,1,0,0\n")
            out = os.path.join(d, "out.csv")
            resolved = [a.replace("METRIC", metric).replace("OUT.csv", out).replace("OUT.txt", out[:-3] + "txt")
                        .replace("OUT.png", out[:-3] + "png")
                        .replace("SEEDS", seeds) for a in args]
            status, _, err = run(*resolved)
            leftovers = [n for n in os.listdir(d) if n not in ("metric.json", "seeds.csv")]
            return status, err, leftovers

    def test_bad_inputs(self):
        for what, args, metric_text, expected in BAD_INPUTS:
            with self.subTest(what):
                status, err, leftovers = self.run_bad(args, metric_text)
                self.assertNotEqual(status, 0, what)
                self.assertIn(expected, err, what)
                self.assertEqual(leftovers, [], f"{what}: output files left behind")


# Every numeric option of every command, refused by name before any work:
# (command, arguments, expected substring of stderr). Each run gets a valid
# metric (and -o) unless its arguments say otherwise; exit status 2, no file.
NUMERIC_OPTIONS = [
    ("trace", ["--step", "nan"], '--initial-integration-step: expected a number from 1e-09 to 1e+06 (arc length), got "nan"'),
    ("trace", ["--step", "inf"], '--initial-integration-step: expected a number from 1e-09 to 1e+06 (arc length), got "inf"'),
    ("trace", ["--step", "0"], '--initial-integration-step: expected a number from 1e-09 to 1e+06 (arc length), got "0"'),
    ("trace", ["--tolerance", "nan"], '--maximum-error: expected a number from 1e-15 to 1, got "nan"'),
    ("trace", ["--tolerance", "-inf"], '--maximum-error: expected a number from 1e-15 to 1, got "-inf"'),
    ("trace", ["--length", "nan"], '--maximum-propagation: expected a number above 0 and at most 1e+09 (arc length), got "nan"'),
    ("trace", ["--length", "0"], '--maximum-propagation: expected a number above 0 and at most 1e+09 (arc length), got "0"'),
    ("trace", ["--length", "1e999"], '--maximum-propagation: expected a number above 0 and at most 1e+09 (arc length), got "1e999"'),
    ("trace", ["--max-steps", "nan"], '--maximum-number-of-steps: expected a whole number from 1 to 1e+09 (steps), got "nan"'),
    ("trace", ["--max-steps", "2.5"], '--maximum-number-of-steps: expected a whole number from 1 to 1e+09 (steps), got "2.5"'),
    # The seed and direction are the tracer's StartPosition and StartDirection (old spellings --seed, --direction).
    ("trace", ["--seed", "inf,0,0"], '--start-position: expected three finite comma-separated numbers X,Y,Z, got "inf,0,0"'),
    ("trace", ["--direction", "nan,1,0"], '--start-direction: expected three finite comma-separated numbers'),
    ("trace", ["--direction", "0,0,0"], '--start-direction: "0,0,0" is the zero vector: a direction must not be zero'),
    ("trace", ["--direction", "1e-200,0,0"], '--start-direction: "1e-200,0,0" is too short to normalise (scale it)'),
    ("info", ["--point", "nan,0,0"], '--point: expected three finite comma-separated numbers X,Y,Z, got "nan,0,0"'),
    ("info", ["--precision", "nan"], '--precision: expected a whole number from 1 to 17, got "nan"'),
    ("info", ["--precision", "0"], '--precision: expected a whole number from 1 to 17, got "0"'),
    ("render", ["--step", "nan"], '--initial-integration-step: expected a number from 1e-09 to 1e+06 (arc length), got "nan"'),
    ("render", ["--fov", "nan"], '--view-angle: expected a number above 0 and at most 179 (degrees), got "nan"'),
    ("render", ["--view-angle", "180"], '--view-angle: expected a number above 0 and at most 179 (degrees), got "180"'),
    ("render", ["--fov", "0"], '--view-angle: expected a number above 0 and at most 179 (degrees), got "0"'),
    ("render", ["--max-length", "nan"], '--maximum-propagation: expected a number above 0 and at most 1e+09 (arc length), got "nan"'),
    ("render", ["--length", "inf"], '--maximum-propagation: expected a number above 0 and at most 1e+09 (arc length), got "inf"'),
    ("render", ["--tolerance", "0"], '--maximum-error: expected a number from 1e-15 to 1, got "0"'),
    ("expmap", ["--max-steps", "0"], '--maximum-number-of-steps: expected a whole number from 1 to 1e+09 (steps), got "0"'),
    ("conjugate", ["--max-steps", "1e10"], '--maximum-number-of-steps: expected a whole number from 1 to 1e+09 (steps)'),
    ("render", ["--max-steps", "nan"], '--maximum-number-of-steps: expected a whole number from 1 to 1e+09 (steps), got "nan"'),
    ("render", ["--width", "nan"], '--width: expected a whole number from 1 to 16384 (pixels), got "nan"'),
    ("render", ["--height", "0"], '--height: expected a whole number from 1 to 16384 (pixels), got "0"'),
    ("render", ["--samples", "inf"], '--samples-per-pixel: expected a whole number from 1 to 4096, got "inf"'),
    ("render", ["--frames", "nan"], '--frames: expected a whole number from 1 to 100000, got "nan"'),
    ("render", ["--bundle", "0"], '--bundle: expected a whole number from 1 to 256, got "0"'),
    ("render", ["--threshold", "nan"], '--threshold: expected a finite non-negative number at most 255, got "nan"'),
    ("render", ["--view-up", "0,0,0"], '--view-up: "0,0,0" is the zero vector: a direction must not be zero'),
    ("render", ["--view-up", "nan,1,0"], '--view-up: expected three finite comma-separated numbers'),
    ("render", ["--camera-position", "0,0,nan"], '--position: expected three finite comma-separated numbers'),
    ("render", ["--look-at", "inf,0,0"], '--look-at: expected three finite comma-separated numbers'),
    ("render", ["--position", "0,0,5", "--look-at", "0,0,0", "--view-up", "0,0,-2"],
     "--view-up 0,0,-2 is parallel to the view direction (from --position 0,0,5 to --look-at 0,0,0)"),
    ("render", ["--camera-position", "1,2,3", "--look-at", "1,2,3"],
     "--position 1,2,3 and --look-at 1,2,3: the camera is at the point it looks at"),
    # Declared settings (Documentation/Settings.md): the message names the
    # property's option, whichever old spelling was typed.
    ("conjugate", ["--step", "nan"], '--initial-integration-step: expected a number from 1e-09 to 1e+06 (arc length), got "nan"'),
    ("conjugate", ["--length", "inf"], '--maximum-propagation: expected a number above 0 and at most 1e+09 (arc length), got "inf"'),
    ("conjugate", ["--max-step", "nan"], '--maximum-integration-step: expected a number above 0 and at most 1e+06 (arc length), got "nan"'),
    ("conjugate", ["--tolerance", "nan"], '--tolerance: expected a number from 1e-15 to 1 (arc length), got "nan"'),
    ("conjugate", ["--cone-angle", "nan"], '--cone-angle: expected a number from 0 to 180 (degrees), got "nan"'),
    ("conjugate", ["--cone-axis", "0,0,0"], '--cone-axis: "0,0,0" is the zero vector: a direction must not be zero'),
    ("conjugate", ["--directions", "nan"], '--number-of-directions: expected a whole number from 1 to 1e+06, got "nan"'),
    ("conjugate", ["--count", "inf"], '--maximum-number-of-conjugate-points: expected a whole number from 1 to 1e+06, got "inf"'),
    ("conjugate", ["--seed", "nan,0,0"], '--observer: expected three finite comma-separated numbers X,Y,Z, got "nan,0,0"'),
    ("conjugate", ["--length", "1", "--step", "2"], "--step 2: must be at most --length 1"),
    ("expmap", ["--step", "nan"], '--initial-integration-step: expected a number from 1e-09 to 1e+06 (arc length), got "nan"'),
    ("expmap", ["--length", "nan"], '--maximum-propagation: expected a number above 0 and at most 1e+09 (arc length), got "nan"'),
    ("expmap", ["--tolerance", "inf"], '--maximum-error: expected a number from 1e-15 to 1, got "inf"'),
    ("expmap", ["--cone-angle", "inf"], '--cone-angle: expected a number from 0 to 180 (degrees), got "inf"'),
    ("expmap", ["--cone-axis", "0,0,0"], '--cone-axis: "0,0,0" is the zero vector: a direction must not be zero'),
    ("expmap", ["--directions", "1.5"], '--number-of-directions: expected a whole number from 1 to 1e+06, got "1.5"'),
    ("expmap", ["--radii", "nan"], '--radii: expected numbers, each above 0 and at most 1e+09 (arc length), got "nan"'),
    ("expmap", ["--radii", "1,inf"], '--radii: expected numbers, each above 0 and at most 1e+09 (arc length), got "1,inf"'),
    ("expmap", ["--seed", "0,nan,0"], '--observer: expected three finite comma-separated numbers X,Y,Z, got "0,nan,0"'),
    ("fields", ["--bounds", "-1,1,-1,1,nan,1"], '--bounds: expected six finite comma-separated numbers X0,X1,Y0,Y1,Z0,Z1, got "-1,1,-1,1,nan,1"'),
    ("fields", ["--dims", "nan,3,3"], '--dimensions: expected three comma-separated whole numbers NX,NY,NZ, got "nan,3,3"'),
    ("fields", ["--dims", "3,inf,3"], '--dimensions: expected three comma-separated whole numbers'),
]

OUTPUT_EXTENSION = {"trace": "csv", "render": "png", "conjugate": "csv", "expmap": "vtp", "fields": "csv"}


class NumericOptionTests(unittest.TestCase):
    """NaN, infinities, out-of-range numbers and degenerate vectors: refused by name, status 2."""

    @staticmethod
    def run_case(command, args):
        """Run one case in a fresh folder; return (status, stdout, stderr, files left there)."""
        with tempfile.TemporaryDirectory() as d:
            metric = os.path.join(d, "metric.json")
            with open(metric, "w") as f:
                f.write(SPHERE_JSON)
            line = [command, "-m", metric, *args]
            if command in OUTPUT_EXTENSION:
                line += ["-o", os.path.join(d, "out." + OUTPUT_EXTENSION[command])]
            status, out, err = run(*line)
            return status, out, err, sorted(os.listdir(d))

    def test_every_numeric_option_is_checked(self):
        # Some 60 runs, a few at a time (each is a process start and a refusal).
        from concurrent.futures import ThreadPoolExecutor
        with ThreadPoolExecutor(max_workers=4) as pool:
            results = list(pool.map(lambda case: self.run_case(case[0], case[1]), NUMERIC_OPTIONS))
        for (command, args, expected), (status, out, err, files) in zip(NUMERIC_OPTIONS, results):
            with self.subTest(command=command, args=args):
                self.assertEqual(status, 2, err)
                self.assertIn(expected, err)
                self.assertTrue(err.startswith("riemann: error: "), err)
                self.assertEqual(out, "", "no work done")
                self.assertEqual(files, ["metric.json"], "no output file written")

    def test_bad_direction_in_seeds_file(self):
        with tempfile.TemporaryDirectory() as d:
            seeds = os.path.join(d, "seeds.csv")
            with open(seeds, "w") as f:
                f.write("x,y,z,dx,dy,dz\n0,0,0,1,0,0\n1,0,0,0,0,0\n")
            out = os.path.join(d, "out.csv")
            status, _, err = run("trace", "-m", os.path.join(METRICS, "twist.json"), "--seeds", seeds, "-o", out)
            self.assertNotEqual(status, 0, err)
            self.assertIn('line 3: dx,dy,dz "0,0,0" is the zero vector', err)
            self.assertFalse(os.path.exists(out))


class VtkMessageTests(unittest.TestCase):
    """VTK's own messages: kept by default (one clear line from the tool), printed plainly with --verbose."""

    def trace_to(self, output, before=(), after=()):
        return run(*before, "trace", "-m", os.path.join(METRICS, "twist.json"), "--length", "1",
                   "-o", output, *after)

    def test_unwritable_output_is_one_clear_line(self):
        status, out, err = self.trace_to("/proc/x.vtp")
        self.assertNotEqual(status, 0, err)
        self.assertEqual(err.splitlines(), ["riemann: error: could not write /proc/x.vtp "
                                            "(check that its folder exists and is writable)"], err)
        self.assertNotIn("\x1b", err)
        self.assertNotIn("vtkXMLPolyDataWriter", err)

    def test_verbose_prints_vtk_detail_plainly(self):
        # --verbose belongs to `riemann` itself and may also follow the command.
        for before, after in ((["--verbose"], []), ([], ["--verbose"])):
            with self.subTest(before=before, after=after):
                status, _, err = self.trace_to("/proc/x.vtp", before, after)
                self.assertNotEqual(status, 0, err)
                self.assertIn("riemann: VTK error (", err)
                self.assertIn("vtkXMLPolyDataWriter", err)
                self.assertNotIn("\x1b", err)
                self.assertEqual(err.splitlines()[-1], "riemann: error: could not write /proc/x.vtp "
                                 "(check that its folder exists and is writable)")

    def test_vtk_warnings_are_noted_in_one_line(self):
        # The Poincare ball's metric is undefined at the seed: the tracer warns, the tool fails.
        with tempfile.TemporaryDirectory() as d:
            metric = os.path.join(d, "ball.json")
            with open(metric, "w") as f:
                f.write('{"type": "conformal", "n": "2/(1 - x^2 - y^2 - z^2)"}')
            line = ["trace", "-m", metric, "--seed", "2,0,0", "-o", os.path.join(d, "out.csv")]
            status, _, err = run(*line)
            self.assertEqual(status, 1, err)
            self.assertEqual(err.splitlines(), ["riemann: error: no geodesic could be traced from the given seeds: "
                                                "1 seed(s) made no geodesic: 1 degenerate metric at the seed",
                                                "riemann: note: VTK also reported 1 warning; --verbose prints it"])
            status, _, err = run(*line, "--verbose")
            self.assertEqual(status, 1, err)
            self.assertIn("riemann: VTK warning (vtkRiemannGeodesicTracer.cxx:", err)
            self.assertIn("1 of 1 geodesics made no line: degenerate metric at the seed", err)
            self.assertNotIn("\x1b", err)
            self.assertEqual(sorted(os.listdir(d)), ["ball.json"])

    def test_successful_run_prints_no_vtk_lines(self):
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "twist.vtp")
            status, _, err = self.trace_to(out)
            self.assertEqual(status, 0, err)
            self.assertEqual(len(err.splitlines()), 1, err)
            self.assertTrue(err.startswith("riemann trace: 1 geodesic(s)"), err)


def print_table():
    print("| bad input | exit | message |\n|---|---|---|")
    for what, args, metric_text, _ in BAD_INPUTS:
        status, err, _ = BadInputTests().run_bad(args, metric_text)
        message = " ".join(err.strip().splitlines()[:2]).replace("|", "\\|")
        print(f"| {what} | {status} | {message} |")


if __name__ == "__main__":
    if "--table" in sys.argv:
        print_table()
    else:
        unittest.main()
