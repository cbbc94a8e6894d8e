"""The geodesic filters and the distance field in the real ParaView give what the
riemann commands give, bitwise.

For the shipped lens (gaussian-lens.json), each run opens ParaView with the
plugin, adds a Riemann Metric reading it, applies one filter with its
defaults (the declared ones) and saves the output (File > Save Data). The
command on the same file with the same defaults is the reference (the
connector's required end points are passed as their declared defaults):
every array, the points and the cells must be equal bit for bit, as both
run the same code. The ParaView log must hold no error.
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

DATA = os.environ["RIEMANN_DATA_DIR"]
SOURCE = os.path.join(DATA, "..")
RIEMANN = os.path.join(os.environ["RIEMANN_BIN_DIR"], "riemann")
METRIC = os.path.join(DATA, "metrics", "gaussian-lens.json")


def declared_default(path, name):
    with open(os.path.join(SOURCE, path), encoding="utf-8") as f:
        setting = next(s for s in json.load(f)["settings"] if s.get("name") == name)
    return ",".join(repr(float(x)) for x in setting["default"])


def cases():
    connector = "Filters/Geodesics/vtkRiemannGeodesicConnector.settings.json"
    return [
        ("RiemannExponentialMap", ["expmap"], ".vtp"),
        ("RiemannConjugateLocus", ["conjugate"], ".vtp"),
        ("RiemannGeodesicConnector", ["connect", "--start-position", declared_default(connector, "StartPosition"),
                                      "--end-position", declared_default(connector, "EndPosition")], ".vtp"),
    ]


def main():
    work = tempfile.mkdtemp(prefix="ParaViewGeodesicFilters-")
    for proxy, command, extension in cases():
        reference = os.path.join(work, proxy + ".reference" + extension)
        done = subprocess.run([RIEMANN, *command, "--metric", METRIC, "--compress", "none", "-o", reference],
                              capture_output=True, text=True)
        check(done.returncode == 0, f"{proxy}: riemann {command[0]} failed: {done.stderr}")
        output = os.path.join(work, proxy + extension)
        steps = (paraview_gui.Steps()
                 .apply_source("RiemannMetricSource", DefinitionFile=METRIC)
                 .apply_filter(proxy)
                 .save_data(output))
        run = paraview_gui.run(steps, work, name=proxy)
        check(run.returncode == 0, f"{proxy}: ParaView's script failed ({run.returncode}):\n{run.log[-3000:]}")
        check(not run.errors(), f"{proxy}: ParaView reported errors: {run.errors()[:5]}")
        check(os.path.isfile(output), f"{proxy}: ParaView wrote no {output}")
        compared(proxy, output, reference, f"riemann {command[0]}'s")
    tracer(work)
    return compare_outputs.exit_status()


def tracer(work):
    """The tracer's two inputs: ParaView's Point Source (one point at the origin) as the
    seeds, the metric as Metric; `riemann trace` from the same seed, along the tracer's
    declared start direction (the seeds carry none)."""
    tracer_file = "Filters/Geodesics/vtkRiemannGeodesicTracer.settings.json"
    seeds = os.path.join(work, "seeds.csv")
    with open(seeds, "w", encoding="utf-8") as f:
        f.write("x,y,z,dx,dy,dz\n0,0,0," + declared_default(tracer_file, "StartDirection") + "\n")
    reference = os.path.join(work, "tracer.reference.vtp")
    done = subprocess.run([RIEMANN, "trace", "--metric", METRIC, "--seeds", seeds, "--compress", "none",
                           "-o", reference], capture_output=True, text=True)
    check(done.returncode == 0, f"tracer: riemann trace failed: {done.stderr}")
    output = os.path.join(work, "tracer.vtp")
    steps = (paraview_gui.Steps()
             .apply_source("RiemannMetricSource", DefinitionFile=METRIC)
             .apply_vtk_source("PointSource")
             .apply_filter_with_inputs("RiemannGeodesicTracer", {"Metric": 0})
             .save_data(output))
    run = paraview_gui.run(steps, work, name="tracer")
    check(run.returncode == 0 and not run.errors(), f"tracer: ParaView failed or reported errors: {run.errors()[:5]}")
    check(os.path.isfile(output), "tracer: ParaView wrote no output")
    compared("RiemannGeodesicTracer", output, reference, "riemann trace's")


if __name__ == "__main__":
    sys.exit(main())
