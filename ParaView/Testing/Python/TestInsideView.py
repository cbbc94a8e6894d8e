"""The inside view in ParaView draws what `riemann render` draws of the same scene.

ParaView: the first view split, the new half a Riemann Inside View; a Riemann
Metric reading the lens (gaussian-lens.json) and ParaView's Sphere source
shown in it; the sphere's geometry saved (File > Save Data), the state saved
(for the view's camera and background), and a 400 x 300 screenshot of the
inside view (File > Save Screenshot).

The reference: `riemann render` of the scene made of the same parts (the
metric file; ParaView's camera and background; the observer's light; the
saved sphere as a mesh, white as ParaView colours it) at the same size. The
two pictures' mean difference must stay under 1/255 per channel, and the
sphere must be in the picture (pixels that are not the background).

Twice: ParaView alone, and connected to a pvserver (--server-url), where
the server renders the view through the pass and sends the picture.
"""

import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_outputs  # noqa: E402
import paraview_gui  # noqa: E402
from compare_outputs import check  # noqa: E402

DATA = os.environ["RIEMANN_DATA_DIR"]
RIEMANN = os.path.join(os.environ["RIEMANN_BIN_DIR"], "riemann")
LENS = os.path.join(DATA, "metrics", "gaussian-lens.json")
WIDTH, HEIGHT = 400, 300


def view_properties(state):
    """The inside view's camera and background, as the saved state holds them (the
    background: the colour palette's when the view follows it, as it does by default)."""
    root = ET.parse(state).getroot()

    def proxy(group, kind):
        return next(p for p in root.iter("Proxy") if p.get("group") == group and p.get("type") == kind)

    def values(of, name):
        prop = next(p for p in of.iter("Property") if p.get("name") == name)
        return [float(e.get("value")) for e in prop.iter("Element")]

    view = proxy("views", "RiemannInsideView")
    properties = {name: values(view, name) for name in
                  ("CameraPosition", "CameraFocalPoint", "CameraViewUp", "CameraViewAngle", "Background")}
    if values(view, "UseColorPaletteForBackground") == [1.0]:
        properties["Background"] = values(proxy("settings", "ColorPalette"), "BackgroundColor")
    return properties


def main():
    work = tempfile.mkdtemp(prefix="ParaViewInsideView-")
    inside_view(os.path.join(work, "builtin"))
    server_work = os.path.join(work, "pvserver")
    os.makedirs(server_work)
    server = paraview_gui.Server(server_work)
    inside_view(os.path.join(work, "pvserver"), server)
    return compare_outputs.exit_status()


def inside_view(work, server=None):
    """The picture ParaView draws (alone, or through `server`) against riemann render's."""
    os.makedirs(work, exist_ok=True)
    mode = "pvserver" if server else "builtin"
    sphere = os.path.join(work, "sphere.vtp")
    state = os.path.join(work, "inside.pvsm")
    picture = os.path.join(work, "paraview.png")
    steps = (paraview_gui.Steps()
             .open_inside_view()
             .apply_source("RiemannMetricSource", DefinitionFile=LENS)
             .apply_vtk_source("SphereSource")
             .save_data(sphere)
             .save_state(state)
             .save_screenshot(picture, WIDTH, HEIGHT))
    extra = ["--server-url=" + server.url()] if server else []
    run = paraview_gui.run(steps, work, name="inside-view", extra_args=extra, timeout=600)
    server_log = server.stop() if server else ""
    check(run.returncode == 0, f"{mode}: ParaView's script failed ({run.returncode}):\n{run.log[-3000:]}")
    check(not run.errors(), f"{mode}: ParaView reported errors: {run.errors()[:5]}")
    check(not paraview_gui.Run(0, server_log).errors(), f"{mode}: the server reported errors: {server_log[-2000:]}")
    for path in (sphere, state, picture):
        check(os.path.isfile(path), f"{mode}: ParaView wrote no {path}")
    if compare_outputs.failures:
        return

    view = view_properties(state)
    scene = {
        "metric": LENS,
        "camera": {"position": view["CameraPosition"], "look_at": view["CameraFocalPoint"],
                   "view_up": view["CameraViewUp"], "fov": view["CameraViewAngle"][0]},
        "background": view["Background"],
        "lighting": "observer",
        "objects": [{"type": "mesh", "file": sphere, "material": {"type": "solid", "color": [1, 1, 1]}}],
    }
    scene_path = os.path.join(work, "scene.json")
    with open(scene_path, "w", encoding="utf-8") as f:
        json.dump(scene, f, indent=2)
    reference = os.path.join(work, "riemann-render.png")
    done = subprocess.run([RIEMANN, "render", "--scene", scene_path, "--width", str(WIDTH), "--height", str(HEIGHT),
                           "-o", reference], capture_output=True, text=True)
    check(done.returncode == 0, f"riemann render failed: {done.stderr}")
    if compare_outputs.failures:
        return
    got, want = compare_outputs.rgb(picture), compare_outputs.rgb(reference)
    check(got.shape == want.shape, f"{mode}: ParaView's picture is {got.shape}, riemann render's {want.shape}")
    if got.shape == want.shape:
        mean = float(np.mean(np.abs(got - want))) / 255.0
        background = np.round(np.array(view["Background"]) * 255.0)
        drawn = int(np.count_nonzero(np.any(np.abs(want - background) > 2, axis=2)))
        print(f"{mode}: mean difference {mean * 255:.4f}/255 over {WIDTH}x{HEIGHT}; "
              f"the sphere covers {drawn} pixels")
        check(mean < 1.0 / 255.0, f"{mode}: the pictures differ by {mean * 255:.3f}/255 on average (allowed 1/255): "
              f"{picture} against {reference}")
        check(drawn > 100, f"{mode}: the sphere covers only {drawn} pixels of the reference")


if __name__ == "__main__":
    sys.exit(main())
