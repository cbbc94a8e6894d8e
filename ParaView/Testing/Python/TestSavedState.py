"""A saved ParaView state (.pvsm) that uses the plugin reloads and re-runs.

ParaView run 1: a Riemann Metric reading the animated example
(wavy-diffeo.json), a Curvature Field, the animation toolbar's Last Frame
(t = 1), File > Save State. Run 2: a fresh ParaView loads that state
(--state), the Curvature Field is selected in the Pipeline Browser and saved
(File > Save Data): it must equal the toolkit's own curvature at t = 1 (Python,
vtkRiemannMetric.SetTime(1)) bit for bit: the state kept the metric, the
filter and the time, and the filter ran again.
"""

import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_outputs  # noqa: E402
from compare_outputs import check  # noqa: E402
import paraview_gui  # noqa: E402

import riemann  # noqa: E402

DATA = os.environ["RIEMANN_DATA_DIR"]
WAVY = os.path.join(DATA, "metrics", "wavy-diffeo.json")


def main():
    work = tempfile.mkdtemp(prefix="ParaViewState-")
    state = os.path.join(work, "wavy.pvsm")
    steps = (paraview_gui.Steps()
             .apply_source("RiemannMetricSource", DefinitionFile=WAVY)
             .apply_filter("RiemannCurvatureField")
             .last_time()
             .save_state(state))
    run = paraview_gui.run(steps, work, name="save-state")
    check(run.returncode == 0 and not run.errors(), f"saving: ParaView failed or reported errors: {run.errors()[:5]}")
    check(os.path.isfile(state), "saving: no state written")
    if not os.path.isfile(state):
        return 1
    with open(state, encoding="utf-8") as f:
        text = f.read()
    check('type="RiemannMetricSource"' in text and 'type="RiemannCurvatureField"' in text,
          "the state does not hold the plugin's proxies")

    output = os.path.join(work, "reloaded.vti")
    steps = paraview_gui.Steps()
    # builtin: -> Metric1 -> CurvatureField1
    steps.event("pqClientMainWindow/pipelineBrowserDock/pipelineBrowser", "currentChanged", "/0/0/0|0")
    steps.save_data(output)
    run = paraview_gui.run(steps, work, name="load-state", extra_args=["--state=" + state])
    check(run.returncode == 0 and not run.errors(), f"loading: ParaView failed or reported errors: {run.errors()[:5]}")
    check(os.path.isfile(output), "loading: the reloaded filter's output was not saved")
    if os.path.isfile(output):
        reference = os.path.join(work, "wavy-at-1.reference.vti")
        compare_outputs.toolkit_curvature_at(riemann, WAVY, 1.0, reference)
        problems = compare_outputs.compare(output, reference, ["ScalarCurvature", "Ricci", "Points"])
        for problem in problems:
            check(False, f"reloaded: {problem}")
        if not problems:
            print("the reloaded state's curvature field is the metric's at t = 1")
    return compare_outputs.exit_status()


if __name__ == "__main__":
    sys.exit(main())
