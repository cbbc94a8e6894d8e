"""A picture of the real ParaView window with the plugin, for Documentation/ParaView.md.

    Xvfb :77 -screen 0 1600x1000x24 &
    DISPLAY=:77 RIEMANN_PARAVIEW=/usr/bin/paraview \
      RIEMANN_PARAVIEW_PLUGIN_DIR=build/paraview/lib/paraview-5.11/plugins/RiemannVTK \
      /usr/bin/python3 ParaView/Testing/Python/paraview_screenshot.py Data/metrics/gaussian-lens.json out.png

ParaView plays the steps (a Riemann Metric from the file; a Curvature Field
shown as a slice coloured by the scalar curvature), then waits while the whole
screen is grabbed.
"""

import os
import subprocess
import sys
import tempfile
import time

from PIL import ImageGrab

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paraview_gui  # noqa: E402


def main(metric, picture):
    work = tempfile.mkdtemp(prefix="ParaViewScreenshot-")
    steps = paraview_gui.Steps()
    steps.apply_source("RiemannMetricSource", DefinitionFile=os.path.abspath(metric))
    steps.apply_filter("RiemannCurvatureField")
    steps.event("pqClientMainWindow/representationToolbar/displayRepresentation/comboBox", "activated", "Slice")
    steps.event("pqClientMainWindow/variableToolbar/displayColor/Variables", "activated", "ScalarCurvature")
    steps.event("pqClientMainWindow", "pause", "8000")
    script = os.path.join(work, "screenshot.xml")
    with open(script, "w", encoding="utf-8") as f:
        f.write(steps.xml())
    env = dict(os.environ, HOME=work)
    paraview = subprocess.Popen([os.environ["RIEMANN_PARAVIEW"], "--dr",
                                 "--plugin-search-paths=" + os.environ["RIEMANN_PARAVIEW_PLUGIN_DIR"],
                                 "--plugins=RiemannVTK", "--test-script=" + script, "--exit"], env=env)
    time.sleep(float(os.environ.get("RIEMANN_SCREENSHOT_WAIT", "14")))
    ImageGrab.grab(xdisplay=os.environ["DISPLAY"]).save(picture)
    paraview.wait(timeout=120)
    print(picture)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
