"""Films with `riemann render` (issue 32): --frames N along --camera-path, as
numbered pictures or one .ogv film.

- The film holds what was asked: riemann-film-frames (Testing/Tools) decodes
  it with the Theora decoder and finds N frames of the asked size, and they
  differ where the camera moved.
- The flight is the one promised: in flat space a geodesic flight is a
  straight line at unit speed, so its first frame is the still picture from
  the path's start and its last the still picture from start + length *
  direction (same view up), to within rendering noise (--reference).
- Bad input loses nothing: a bad path file (status 2, the key named), a
  spline with coinciding keys (status 1), odd sides for a film or a folder
  that does not exist (status 2, before any frame is drawn) leave no film
  and no partial file behind.
"""
import os
import sys
import subprocess
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from TestCli import DATA, TempDirTest, run  # noqa: E402

FILM_FRAMES = os.environ.get("RIEMANN_FILM_FRAMES", "")
SCENE = os.path.join(DATA, "scenes", "paper-grid.json")
START, LOOK_AT, UP, LENGTH = (0.5, 0.5, 3.6), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0), 2.0


def vector(v):
    return ",".join("%.17g" % c for c in v)


class FilmTests(TempDirTest):
    def write(self, name, text):
        path = os.path.join(self.dir, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def geodesic_path(self):
        return self.write("fly.json", """{"path": "geodesic", "position": [%s], "look_at": [%s],
            "view_up": [%s], "length": %g}""" % (vector(START), vector(LOOK_AT), vector(UP), LENGTH))

    def render(self, *args):
        return run("render", "--backend", "cpu", "-s", SCENE, "--width", "64", "--height", "48", *args)

    def leftovers(self):
        return sorted(name for name in os.listdir(self.dir) if not name.endswith(".json"))

    @unittest.skipUnless(os.path.isfile(FILM_FRAMES), "riemann-film-frames not built (libtheora-dev)")
    def test_a_film_holds_its_frames(self):
        film = os.path.join(self.dir, "film.ogv")
        status, _, err = self.render("--camera-path", self.geodesic_path(), "--frames", "6", "-o", film)
        self.assertEqual(status, 0, err)
        result = subprocess.run([FILM_FRAMES, film], capture_output=True, text=True, timeout=60)
        self.assertEqual(result.returncode, 0, result.stderr)
        lines = result.stdout.splitlines()
        self.assertEqual(lines[0], "frames 6 width 64 height 48")
        luma = [float(line.split()[-1]) for line in lines[1:]]
        self.assertEqual(len(luma), 6)
        self.assertGreater(max(luma) - min(luma), 1.0, "the frames differ as the camera moves")
        self.assertEqual(self.leftovers(), ["film.ogv"], "no partial file left")

    def test_a_flat_geodesic_flight_starts_and_ends_where_it_should(self):
        flat = self.write("flat.json", '{"type": "euclidean"}')
        frames = os.path.join(self.dir, "frame.png")
        status, _, err = self.render("-m", flat, "--camera-path", self.geodesic_path(),
                                     "--frames", "3", "-o", frames)
        self.assertEqual(status, 0, err)
        self.assertEqual(self.leftovers(), ["frame_0000.png", "frame_0001.png", "frame_0002.png"])
        norm = sum((b - a) ** 2 for a, b in zip(START, LOOK_AT)) ** 0.5
        end = [a + LENGTH * (b - a) / norm for a, b in zip(START, LOOK_AT)]
        ahead = [e + (b - a) / norm for e, a, b in zip(end, START, LOOK_AT)]
        for frame, (position, look_at) in ((0, (START, LOOK_AT)), (2, (end, ahead))):
            still = os.path.join(self.dir, "still%d.png" % frame)
            status, _, err = self.render(
                "-m", flat, "--camera-position", vector(position), "--look-at", vector(look_at),
                "--view-up", vector(UP), "-o", still,
                "--reference", os.path.join(self.dir, "frame_%04d.png" % frame), "--threshold", "0.5")
            self.assertEqual(status, 0, "frame %d is not the still picture from there: %s" % (frame, err))

    def test_bad_input_leaves_nothing(self):
        film = os.path.join(self.dir, "film.ogv")
        bad = self.write("bad.json", '{"path": "geodesic", "position": [0, 0, 3], "look_at": [0, 0, 0]}')
        status, _, err = self.render("--camera-path", bad, "--frames", "4", "-o", film)
        self.assertEqual(status, 2, err)
        self.assertIn('missing required key "length"', err)
        same = self.write("same.json", '{"path": "spline", "keys": [[0, 0, 3], [0, 1, 3], [0, 1, 3]]}')
        status, _, err = self.render("--camera-path", same, "--frames", "4", "-o", film)
        self.assertEqual(status, 1, err)
        self.assertIn("key positions 2 and 3 coincide", err)
        status, _, err = run("render", "--backend", "cpu", "--width", "63", "--height", "48",
                             "--frames", "2", "-o", film)
        self.assertEqual(status, 2, err)
        self.assertIn("even sides", err)
        missing = os.path.join(self.dir, "no-such-folder", "film.ogv")
        status, _, err = self.render("--frames", "2", "-o", missing)
        self.assertEqual(status, 2, err)
        self.assertIn("no-such-folder does not exist", err)
        self.assertEqual(self.leftovers(), [])


if __name__ == "__main__":
    unittest.main()
