"""The weak-scaling model of `mpirun -np N riemann` (issue 16), from measured
per-rank throughput, and its figure for the README.

Model: a job of W work items (grid points, conjugate directions) on N ranks
of one core each takes

    T(N) = t0 + W / (N r)

where r is one rank's throughput (items per second, its share of the output
written) and t0 the job's fixed cost (launch, MPI start-up, metric load, the
summary file). Both come from runs on this machine: r from a one-rank job of
20 s or more, t0 from a tiny job. Weak scaling keeps W / N fixed, so T stays
t0 + (W/N) / r while the file system takes the ranks' writes in parallel;
strong scaling's efficiency is (W / r) / (N T(N)).

Usage (measures, prints the table, writes the figure; needs a display for
VTK's chart: run under xvfb-run):
  xvfb-run -a /usr/bin/python3 Testing/Benchmarks/mpi_scaling_model.py build [figure.png]
"""
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build")
FIGURE = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "Documentation", "figures", "mpi-scaling.png")
RIEMANN = os.path.join(BUILD, "bin", "riemann")
METRICS = os.path.join(ROOT, "Data", "metrics")
ENV = {**os.environ, "VTK_SMP_BACKEND_IN_USE": "Sequential"}


def wall(ranks, *args):
    """Seconds of `mpirun -np ranks riemann args`, one thread per rank."""
    start = time.perf_counter()
    subprocess.run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-x", "VTK_SMP_BACKEND_IN_USE",
                    "-np", str(ranks), RIEMANN, *args], check=True, env=ENV, capture_output=True)
    return time.perf_counter() - start


def main():
    work = tempfile.mkdtemp()
    bump = os.path.join(METRICS, "two-bumps.json")
    lens = ["-m", os.path.join(METRICS, "astigmatic-lens.json"), "--seed", "-3,0,0", "--cone-axis", "1,0,0",
            "--cone-angle", "14", "-k", "3", "-l", "9"]
    jobs = {
        # name: (items of the measured job, items of the target, command of n items)
        "fields": (220 ** 3, 512 ** 3, lambda n: ["fields", "-m", bump, "--dims", ",".join([str(round(n ** (1 / 3)))] * 3),
                                                  "-o", os.path.join(work, "f.pvti")]),
        "conjugate": (70000, 10 ** 6, lambda n: ["conjugate", *lens, "-n", str(n), "-o", os.path.join(work, "c.pvtp"),
                                                 "--surface", os.path.join(work, "s.pvtp")]),
    }
    model = {}
    print("| job | one rank | throughput r | fixed cost t0 | target | T on 1 rank | ranks for 60 s | T on 64 ranks |")
    print("|---|---|---|---|---|---|---|---|")
    for name, (measured, target, command) in jobs.items():
        t0 = min(wall(1, *command(8 if name == "fields" else 10)) for _ in range(3))
        t1 = wall(1, *command(measured))
        r = measured / (t1 - t0)
        model[name] = (t0, r, target)
        one = t0 + target / r
        needed = next(n for n in range(1, 100000) if t0 + target / (n * r) <= 60.0)
        label = "512^3 points" if name == "fields" else "10^6 directions"
        print(f"| {name} | {measured} items: {t1:.1f} s | {r:,.0f} /s | {t0:.2f} s | {label} | "
              f"{one / 60:.1f} min | {needed} | {t0 + target / (64 * r):.1f} s |")
    draw(model)


def draw(model):
    from vtkmodules.vtkChartsCore import vtkAxis, vtkChart, vtkChartXY
    from vtkmodules.vtkCommonCore import vtkFloatArray
    from vtkmodules.vtkCommonDataModel import vtkTable
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingContext2D import vtkPen
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    from vtkmodules.vtkViewsContext2D import vtkContextView
    import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401 (the OpenGL context device)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

    ranks = [1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024]
    table = vtkTable()
    columns = {"ranks": ranks}
    for name, (t0, r, target) in model.items():
        unit = "512^3 points" if name == "fields" else "10^6 directions"
        columns[f"{name}, {unit} in all (strong)"] = [t0 + target / (n * r) for n in ranks]
        columns[f"{name}, 1/64 of {unit} per rank (weak)"] = [t0 + target / (64 * r) for _ in ranks]
    for title, values in columns.items():
        array = vtkFloatArray()
        array.SetName(title)
        for v in values:
            array.InsertNextValue(v)
        table.AddColumn(array)
    view = vtkContextView()
    view.GetRenderer().SetBackground(1, 1, 1)
    view.GetRenderWindow().SetSize(760, 460)
    view.GetRenderWindow().SetOffScreenRendering(1)
    chart = vtkChartXY()
    view.GetScene().AddItem(chart)
    chart.SetShowLegend(True)
    chart.SetTitle("riemann under mpirun: modelled wall time, one core per rank")
    colours = {"fields": (31, 119, 180), "conjugate": (214, 39, 40)}
    for index, title in enumerate(list(columns)[1:], start=1):
        plot = chart.AddPlot(vtkChart.LINE)
        plot.SetInputData(table, 0, index)
        plot.SetColor(*colours[title.split(",")[0]], 255)
        plot.SetWidth(3.0)
        if "(weak)" in title:
            plot.GetPen().SetLineType(vtkPen.DASH_LINE)
    bottom = chart.GetAxis(vtkAxis.BOTTOM)
    bottom.SetTitle("ranks N")
    bottom.SetLogScale(True)
    left = chart.GetAxis(vtkAxis.LEFT)
    left.SetTitle("seconds")
    left.SetLogScale(True)
    view.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(FIGURE)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print(f"figure: {FIGURE}")


if __name__ == "__main__":
    main()
