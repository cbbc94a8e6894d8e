"""The distance field, its cut locus and the minimal geodesics in the real
ParaView give what `riemann distance` gives, bitwise.

The metric is the shipped two-bumps.json (a seed at the origin has a cut
locus behind the bumps). Seeds and targets are the points of ParaView's own
sources with their defaults: a Point Source (one point, the origin) seeds
the Distance Field, a Line's seven points (from (-0.5, 0, 0) to (0.5, 0, 0))
are the Minimal Geodesics' targets. Two ParaView sessions, each saving what it
made (File > Save Data):
1. Metric, Point Source -> Distance Field (Metric chosen in ParaView's Select
   Input dialog) -> saved; -> Cut Locus (Metric again) -> saved.
2. Metric, Line, Point Source -> Distance Field -> Minimal Geodesics
   (Input: the field; Targets: the Line; Metric) -> saved.
`riemann distance --seed 0,0,0 --cut-locus --to X --to ... --geodesics`
(the Line's points as vtkLineSource makes them, printed exactly) with the
same declared defaults is the reference: every array,
the points and the cells equal bit for bit. The ParaView log must hold no error.
"""

import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_outputs  # noqa: E402
from compare_outputs import check, compared  # noqa: E402
import paraview_gui  # noqa: E402

DATA = os.environ["RIEMANN_DATA_DIR"]
RIEMANN = os.path.join(os.environ["RIEMANN_BIN_DIR"], "riemann")
METRIC = os.path.join(DATA, "metrics", "two-bumps.json")


def line_points():
    """The points of ParaView's Line source with its defaults, as `--to` options (exact)."""
    from vtkmodules.vtkFiltersSources import vtkLineSource
    line = vtkLineSource()
    line.SetPoint1(-0.5, 0, 0)
    line.SetPoint2(0.5, 0, 0)
    line.SetResolution(6)  # ParaView's default (VTK's is 1)
    line.Update()
    points = line.GetOutput().GetPoints()
    options = []
    for i in range(points.GetNumberOfPoints()):
        options += ["--to", ",".join(repr(x) for x in points.GetPoint(i))]
    return options


def main():
    work = tempfile.mkdtemp(prefix="ParaViewDistanceFilters-")
    reference = {name: os.path.join(work, name + ".reference" + ext)
                 for name, ext in (("field", ".vti"), ("cut", ".vtp"), ("geodesics", ".vtp"))}
    done = subprocess.run([RIEMANN, "distance", "--metric", METRIC, "--seed", "0,0,0",
                           "--cut-locus", reference["cut"], *line_points(),
                           "--geodesics", reference["geodesics"], "--compress", "none",
                           "-o", reference["field"]], capture_output=True, text=True)
    check(done.returncode == 0, f"riemann distance failed: {done.stderr}")

    # 1. The field and its cut locus. Rows of the Select Input dialog: the
    # Metric is the first source made (0); Input is the selected source.
    field, cut = os.path.join(work, "field.vti"), os.path.join(work, "cut.vtp")
    steps = (paraview_gui.Steps()
             .apply_source("RiemannMetricSource", DefinitionFile=METRIC)
             .apply_vtk_source("PointSource")
             .apply_filter_with_inputs("RiemannDistanceField", {"Metric": 0})
             .save_data(field)
             .apply_filter_with_inputs("RiemannCutLocus", {"Metric": 0})
             .save_data(cut))
    paraview_gui.played(steps, work, "field-and-cut", [field, cut])
    compared("RiemannDistanceField", field, reference["field"], "riemann distance's")
    compared("RiemannCutLocus", cut, reference["cut"], "riemann distance's")

    # 2. The minimal geodesics to the Line's points (the Line is row 1).
    geodesics = os.path.join(work, "geodesics.vtp")
    steps = (paraview_gui.Steps()
             .apply_source("RiemannMetricSource", DefinitionFile=METRIC)
             .apply_vtk_source("LineSource")
             .apply_vtk_source("PointSource")
             .apply_filter_with_inputs("RiemannDistanceField", {"Metric": 0})
             .apply_filter_with_inputs("RiemannMinimalGeodesics", {"Targets": 1, "Metric": 0})
             .save_data(geodesics))
    paraview_gui.played(steps, work, "minimal-geodesics", [geodesics])
    compared("RiemannMinimalGeodesics", geodesics, reference["geodesics"], "riemann distance's")
    return compare_outputs.exit_status()


if __name__ == "__main__":
    sys.exit(main())
