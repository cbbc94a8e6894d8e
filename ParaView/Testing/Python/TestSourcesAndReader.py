"""The direction grid, the camera path and the metric file reader in the real ParaView.

1. Sources > Riemann > Direction Grid with its defaults, saved: equal bit for
   bit to the toolkit's vtkRiemannDirectionGrid (Python) with the same
   declared defaults.
2. A Riemann Metric reading the lens, then a Camera Path with its defaults:
   equal to vtkRiemannCameraPath on the same file (Python).
3. A metric file opened as data (paraview --data=FILE.json: the Riemann
   Metric File reader), then a Curvature Field: equal to `riemann fields`.
4. A typed Metric (a bump of height a = 1) whose Parameters table gives a
   the value 0.25, then a Curvature Field: equal to `riemann fields` of the
   definition written with a = 0.25, unlike the one with a = 1.
"""

import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_outputs  # noqa: E402
from compare_outputs import check, compared  # noqa: E402
import paraview_gui  # noqa: E402

import riemann  # noqa: E402

DATA = os.environ["RIEMANN_DATA_DIR"]
RIEMANN = os.path.join(os.environ["RIEMANN_BIN_DIR"], "riemann")
LENS = os.path.join(DATA, "metrics", "gaussian-lens.json")


def main():
    work = tempfile.mkdtemp(prefix="ParaViewSources-")

    output = os.path.join(work, "directions.vtp")
    if paraview_gui.played(paraview_gui.Steps().apply_source("RiemannDirectionGrid").save_data(output), work, "direction-grid", output):
        reference = os.path.join(work, "directions.reference.vtp")
        compare_outputs.write(riemann.vtkRiemannDirectionGrid(), reference)
        compared("direction grid", output, reference)

    output = os.path.join(work, "camera-path.vtp")
    steps = (paraview_gui.Steps()
             .apply_source("RiemannMetricSource", DefinitionFile=LENS)
             .apply_filter("RiemannCameraPath")
             .save_data(output))
    if paraview_gui.played(steps, work, "camera-path", output):
        metric = riemann.vtkRiemannMetric()
        check(metric.SetDefinitionFile(LENS), metric.GetLastError())
        path = riemann.vtkRiemannCameraPath()
        path.SetMetric(metric)
        reference = os.path.join(work, "camera-path.reference.vtp")
        compare_outputs.write(path, reference)
        compared("camera path", output, reference)

    output = os.path.join(work, "from-reader.vti")
    steps = paraview_gui.Steps().apply().apply_filter("RiemannCurvatureField").save_data(output)
    if paraview_gui.played(steps, work, "reader", output, extra_args=["--data=" + LENS]):
        reference = os.path.join(work, "from-reader.reference.vti")
        subprocess.run([RIEMANN, "fields", "--metric", LENS, "--compress", "none", "-o", reference],
                       check=True, capture_output=True)
        compared("metric file reader", output, reference, names=["ScalarCurvature", "Ricci", "Points"])
    parameters_in_the_panel(work)
    return compare_outputs.exit_status()


def parameters_in_the_panel(work):
    def bump(a):
        return json.dumps({"type": "graph", "f": "a*exp(-(x^2+y^2)/(2*s^2))", "parameters": {"a": a, "s": 0.5}})

    output = os.path.join(work, "parameters.vti")
    steps = paraview_gui.Steps().menu("menuSources", "Riemann", "RiemannMetricSource")
    steps.set_text("Definition", bump(1)).set_parameter(0, "a", 0.25).apply()
    steps.apply_filter("RiemannCurvatureField").save_data(output)
    if not paraview_gui.played(steps, work, "parameters", output):
        return
    references = {}
    for a in (0.25, 1):
        definition = os.path.join(work, f"bump-{a}.json")
        with open(definition, "w", encoding="utf-8") as f:
            f.write(bump(a))
        references[a] = os.path.join(work, f"bump-{a}.reference.vti")
        subprocess.run([RIEMANN, "fields", "--metric", definition, "--compress", "none", "-o", references[a]],
                       check=True, capture_output=True)
    compared("parameters (a = 0.25 in the table)", output, references[0.25], names=["ScalarCurvature", "Ricci", "Points"])
    check(compare_outputs.compare(output, references[1], ["ScalarCurvature"]) != [],
          "parameters: the table's value changed nothing (the output equals a = 1's)")


if __name__ == "__main__":
    sys.exit(main())
