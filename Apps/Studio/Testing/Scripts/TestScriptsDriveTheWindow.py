"""The studio module drives the window as the mouse does, and says no clearly.

- add/get/set/items/remove, and a refused property leaves the item as it was;
- a bad metric is refused with the editor's message and the metric stays;
- studio.screenshot at a chosen size writes a PNG of that size (both views);
- a film along a camera path: riemann-film-frames (the Theora decoder)
  reads back the frames asked for, and the observer and t are put back;
- riemann's and VTK's Python modules import as in scripts.
"""
import os
import struct
import subprocess
import sys
import tempfile

import studio

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message, file=sys.stderr)


def png_size(path):
    with open(path, "rb") as f:
        header = f.read(24)
    check(header[:8] == b"\x89PNG\r\n\x1a\n", path + " is a PNG")
    return struct.unpack(">II", header[16:24])


def refused(call, expected):
    try:
        call()
    except studio.StudioError as error:
        check(expected in str(error), "message %r holds %r" % (str(error), expected))
        return
    check(False, "refused: %s" % expected)


name = studio.add("exponential-map", NumberOfDirections=30)
check(studio.items() == [name], "one item: %s" % studio.items())
check(studio.get(name)["kind"] == "exponential-map", "get gives the kind")
refused(lambda: studio.set(name, NumberOfDirections=-3), "Directions")
check(studio.get(name)["NumberOfDirections"] == 30, "a refused property changes nothing")
refused(lambda: studio.add("wormhole"), 'unknown kind "wormhole"')
check(studio.items() == [name], "a refused add adds nothing")
refused(lambda: studio.get("nothing"), 'no item named "nothing"')
metric = studio.metric()
refused(lambda: studio.metric('{"type": "graph", "f": "x^2 + q"}'), "unknown symbol")
check(studio.metric() == metric, "a refused metric leaves the metric")
studio.remove(name)
check(studio.items() == [], "removed")

import riemann  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402,F401
check(hasattr(riemann, "vtkRiemannCameraPath"), "riemann's module as in scripts")

with tempfile.TemporaryDirectory() as folder:
    shot = os.path.join(folder, "both.png")
    studio.screenshot(shot, view="both", size=(320, 120))
    check(png_size(shot) == (320, 120), "screenshot at the size asked for: %s" % (png_size(shot),))

    path = studio.add("camera-path", PathType="spline",
                      KeyPositions=[[0.5, 0.5, 3.6], [0.4, 0.4, 2.5], [0.6, 0.3, 1.5]])
    studio.render()
    before = studio.observer()
    film = os.path.join(folder, "flight.ogv")
    studio.export_animation(film, frames=6, size=(96, 64), time=None, camera_path=path)
    check(studio.observer() == before, "the observer is put back")
    reader = os.environ.get("RIEMANN_FILM_FRAMES", "")
    if os.path.isfile(reader):
        out = subprocess.run([reader, film], capture_output=True, text=True).stdout.splitlines()
        check(out and out[0] == "frames 6 width 96 height 64", "the film read back: %s" % out[:1])
    else:
        print("riemann-film-frames not built: the film is not read back")
    check(os.listdir(folder) == ["both.png", "flight.ogv"] or
          sorted(os.listdir(folder)) == ["both.png", "flight.ogv"], "no partial files")

sys.exit(1 if failures else 0)
