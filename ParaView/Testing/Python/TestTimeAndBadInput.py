"""The metric's time is ParaView's time, and a bad metric typed in the panel is
reported where it is wrong, with the pipeline still usable.

1. A Riemann Metric reading the animated example (wavy-diffeo.json), a
   Curvature Field, then the animation toolbar's Last Frame (t = 1), then
   File > Save Data: the scalar curvature equals the toolkit's own
   (Python: vtkRiemannMetric.SetTime(1), the same grid) bit for bit, and
   differs from `riemann fields` (t = 0).
2. File > Save Animation of an Exponential Map of the same metric: one
   picture a time step, the last unlike the first and equal to a
   screenshot of the view after Last Frame.
3. A Riemann Metric whose typed Definition uses an unknown symbol: ParaView's
   log (its output window) names the symbol and the column; the same
   source, given a metric file instead, then applies, a Curvature Field
   follows and equals `riemann fields`; ParaView exits 0.
"""

import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_outputs  # noqa: E402
from compare_outputs import check  # noqa: E402
import paraview_gui  # noqa: E402

import riemann  # noqa: E402

DATA = os.environ["RIEMANN_DATA_DIR"]
RIEMANN = os.path.join(os.environ["RIEMANN_BIN_DIR"], "riemann")
CURVATURE = ["ScalarCurvature", "Ricci", "SectionalMin", "SectionalMax", "Points"]


def reference_fields(metric, path):
    subprocess.run([RIEMANN, "fields", "--metric", metric, "--compress", "none", "-o", path],
                   check=True, capture_output=True)


def time_is_paraview_time(work):
    wavy = os.path.join(DATA, "metrics", "wavy-diffeo.json")
    output = os.path.join(work, "wavy-at-1.vti")
    steps = (paraview_gui.Steps()
             .apply_source("RiemannMetricSource", DefinitionFile=wavy)
             .apply_filter("RiemannCurvatureField")
             .last_time()
             .save_data(output))
    run = paraview_gui.run(steps, work, name="time")
    check(run.returncode == 0 and not run.errors(), f"time: ParaView failed or reported errors: {run.errors()[:5]}")
    check(os.path.isfile(output), "time: no output saved")
    if not os.path.isfile(output):
        return
    # The toolkit's own answer at t = 1, on the declared grid.
    at_one = os.path.join(work, "wavy-at-1.reference.vti")
    compare_outputs.toolkit_curvature_at(riemann, wavy, 1.0, at_one)
    for problem in compare_outputs.compare(output, at_one, CURVATURE):
        check(False, f"time: {problem}")
    at_zero = os.path.join(work, "wavy-at-0.reference.vti")
    reference_fields(wavy, at_zero)
    check(compare_outputs.compare(output, at_zero, ["ScalarCurvature"]) != [],
          "time: the output at the last frame equals the one at t = 0")
    print("time: the curvature at ParaView's last frame is the metric's at t = 1")


def save_animation_steps_the_metric(work):
    """File > Save Animation of an Exponential Map of the animated metric: one
    picture a time step (11), the first unlike the last, and the last equal to
    a screenshot of the same view after Last Frame (t = 1)."""
    wavy = os.path.join(DATA, "metrics", "wavy-diffeo.json")
    frames = os.path.join(work, "frame.png")
    last = os.path.join(work, "last-frame.png")
    steps = (paraview_gui.Steps()
             .apply_source("RiemannMetricSource", DefinitionFile=wavy)
             .apply_filter("RiemannExponentialMap")
             .save_animation(frames, 400, 300)
             .last_time()
             .save_screenshot(last, 400, 300))
    run = paraview_gui.run(steps, work, name="animation")
    check(run.returncode == 0 and not run.errors(),
          f"animation: ParaView failed or reported errors: {run.errors()[:5]}")
    pictures = [os.path.join(work, f"frame.{i:04d}.png") for i in range(11)]
    missing = [p for p in pictures + [last] if not os.path.isfile(p)]
    check(not missing, f"animation: not written: {missing}")
    if missing:
        return
    first, final, screenshot = (compare_outputs.rgb(p) for p in (pictures[0], pictures[-1], last))
    changed = int(np.count_nonzero(np.abs(first - final).sum(axis=2)))
    check(changed > 1000, f"animation: the first and last frames differ in {changed} pixels only")
    check(np.array_equal(final, screenshot), "animation: the last frame is not the view at t = 1")
    print(f"animation: 11 frames; the last differs from the first in {changed} of {400 * 300} pixels "
          "and equals the view at t = 1")


def bad_metric_is_reported(work):
    good = os.path.join(DATA, "metrics", "gaussian-bump.json")
    output = os.path.join(work, "after-error.vti")
    steps = paraview_gui.Steps()
    steps.menu("menuSources", "Riemann", "RiemannMetricSource")
    steps.set_text("Definition", '{"type": "graph", "f": "x^2 + q"}').apply()
    steps.set_file("DefinitionFile", good).apply()
    steps.apply_filter("RiemannCurvatureField").save_data(output)
    run = paraview_gui.run(steps, work, name="bad-metric")
    check(run.returncode == 0, f"bad metric: ParaView's script failed ({run.returncode}):\n{run.log[-3000:]}")
    said = [line for line in run.errors() if '"q"' in line and "column" in line]
    check(said, f"bad metric: the log does not name the symbol and its column: {run.errors()[:5]}")
    reference = os.path.join(work, "after-error.reference.vti")
    reference_fields(good, reference)
    check(os.path.isfile(output), "bad metric: the pipeline did not go on after the error")
    if os.path.isfile(output):
        for problem in compare_outputs.compare(output, reference, CURVATURE):
            check(False, f"bad metric, then a good one: {problem}")
    if said:
        print("bad metric: ParaView said: " + said[0].strip())


def main():
    work = tempfile.mkdtemp(prefix="ParaViewTime-")
    time_is_paraview_time(work)
    save_animation_steps_the_metric(work)
    bad_metric_is_reported(work)
    return compare_outputs.exit_status()


if __name__ == "__main__":
    sys.exit(main())
