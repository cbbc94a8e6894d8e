"""The field filters in the real ParaView give what `riemann fields` gives, bitwise.

For a shipped metric file, each run opens ParaView with the plugin, adds a
Riemann Metric (its File set to the example), applies one field filter
(Curvature Field, Volume Form, Metric Tensor Field on the bump; Curvature
Field on the twist) with its defaults, and saves the output (File > Save
Data). `riemann fields` on the same file and
the same (declared) grid is the reference: every array the filter makes
must be equal to the command's bit for bit, as both run the same code on the
same grid. The ParaView log must hold no error.
"""

import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_outputs  # noqa: E402
from compare_outputs import check  # noqa: E402
import paraview_gui  # noqa: E402

DATA = os.environ["RIEMANN_DATA_DIR"]
RIEMANN = os.path.join(os.environ["RIEMANN_BIN_DIR"], "riemann")
# Each filter's arrays: the same names as the command's.
FILTERS = {
    "RiemannCurvatureField": ["ScalarCurvature", "Ricci", "RiemannNorm", "SectionalMin", "SectionalMax",
                              "SectionalXY", "SectionalXZ", "SectionalYZ", "Points"],
    "RiemannVolumeForm": ["VolumeForm", "Points"],
    "RiemannMetricTensorField": ["MetricTensor", "InverseMetricTensor", "MetricEigenvalues", "Points"],
}
# Every filter on the bump; the curvature (the most code) on the twist too.
METRICS = {"gaussian-bump.json": list(FILTERS), "twist.json": ["RiemannCurvatureField"]}


def main():
    work = tempfile.mkdtemp(prefix="ParaViewFieldFilters-")
    for metric_name, proxies in METRICS.items():
        metric = os.path.join(DATA, "metrics", metric_name)
        reference = os.path.join(work, metric_name + ".reference.vti")
        subprocess.run([RIEMANN, "fields", "--metric", metric, "--compress", "none", "-o", reference],
                       check=True, capture_output=True)
        for proxy in proxies:
            names = FILTERS[proxy]
            output = os.path.join(work, f"{metric_name}.{proxy}.vti")
            steps = (paraview_gui.Steps()
                     .apply_source("RiemannMetricSource", DefinitionFile=metric)
                     .apply_filter(proxy)
                     .save_data(output))
            run = paraview_gui.run(steps, work, name=f"{metric_name}.{proxy}")
            where = f"{metric_name}, {proxy}"
            check(run.returncode == 0, f"{where}: ParaView's script failed ({run.returncode}):\n{run.log[-3000:]}")
            check(not run.errors(), f"{where}: ParaView reported errors: {run.errors()[:5]}")
            check(os.path.isfile(output), f"{where}: ParaView wrote no {output}")
            if os.path.isfile(output):
                for problem in compare_outputs.compare(output, reference, names):
                    check(False, f"{where}: {problem}")
                print(f"{where}: {len(names)} arrays equal to riemann fields'")
    return compare_outputs.exit_status()


if __name__ == "__main__":
    sys.exit(main())
