"""Tract files, tractography from a mask and the ray bundle in the real ParaView.

1. A .tck and a .trk written by `riemann trace` on the fibre phantom, each
   opened as data (paraview --data=FILE: the Riemann Tract File reader) and
   saved: equal bit for bit to the toolkit's vtkRiemannTractReader (Python)
   on the same file (which TestTractReader checks against nibabel).
2. Tractography from masks: a seed mask and a stop mask (.vti, opened with
   File > Open: ParaView's own reader) as the Geodesic Tracer's Input and
   StopMask, the phantom's metric as its Metric, with the tracer's declared
   defaults (Integrate: forward): equal bit for bit to `riemann trace
   --seed-mask --stop-mask --propagation forward` (the command's own
   default for masks is both ways).
3. Filters > Riemann > Ray Bundle of the lens with its declared defaults:
   equal bit for bit to vtkRiemannRayBundle (Python) with the same defaults.
The ParaView log must hold no error.
"""

import os
import subprocess
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLImageDataWriter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_outputs  # noqa: E402
from compare_outputs import check, compared  # noqa: E402
import paraview_gui  # noqa: E402

import riemann  # noqa: E402

DATA = os.environ["RIEMANN_DATA_DIR"]
RIEMANN = os.path.join(os.environ["RIEMANN_BIN_DIR"], "riemann")
PHANTOM = os.path.join(DATA, "phantom", "fibre-phantom.json")
LENS = os.path.join(DATA, "metrics", "gaussian-lens.json")


def write_mask(path, select):
    """The phantom's grid, 1 in the voxels where select(Bundle array, point coordinates)."""
    reader = vtkXMLImageDataReader()
    reader.SetFileName(os.path.join(DATA, "phantom", "fibre-phantom.vti"))
    reader.Update()
    phantom = reader.GetOutput()
    bundle = vtk_to_numpy(phantom.GetPointData().GetArray("Bundle"))
    xyz = np.array([phantom.GetPoint(i) for i in range(phantom.GetNumberOfPoints())])
    mask = vtkImageData()
    mask.CopyStructure(phantom)
    values = numpy_to_vtk(select(bundle, xyz).astype(np.uint8), deep=True)
    values.SetName("Mask")
    mask.GetPointData().SetScalars(values)
    writer = vtkXMLImageDataWriter()
    writer.SetInputData(mask)
    writer.SetFileName(path)
    check(writer.Write() == 1, f"{path}: not written")
    return path


def tract_files(work):
    seeds = os.path.join(work, "seeds.csv")
    with open(seeds, "w", encoding="utf-8") as f:
        f.write("x,y,z,dx,dy,dz\n-1.0,0.05,-0.3,1,0.1,0\n0.05,-1.0,-0.4,0.1,1,0.05\n1.5,0.0,0.45,0,1,0\n")
    for name in ("tracts.tck", "tracts.trk"):
        path = os.path.join(work, name)
        done = subprocess.run([RIEMANN, "trace", "-m", PHANTOM, "--seeds", seeds, "--step", "0.01",
                               "--length", "1.5", "-o", path], capture_output=True, text=True)
        check(done.returncode == 0, f"riemann trace -o {name} failed: {done.stderr}")
        output = os.path.join(work, name + ".vtp")
        if paraview_gui.played(paraview_gui.Steps().apply().save_data(output), work, name, output,
                  extra_args=["--data=" + path]):
            reader = riemann.vtkRiemannTractReader()
            reader.SetFileName(path)
            reference = os.path.join(work, name + ".reference.vtp")
            compare_outputs.write(reader, reference)
            compared(f"Riemann Tract File ({name})", output, reference, "vtkRiemannTractReader's")


def tractography_from_a_mask(work):
    # Seeds: the third bundle above z = 0.4; stops: where |y| reaches 1.
    seeds = write_mask(os.path.join(work, "seeds.vti"), lambda bundle, xyz: (bundle == 3) & (xyz[:, 2] > 0.4))
    stops = write_mask(os.path.join(work, "stops.vti"), lambda bundle, xyz: np.abs(xyz[:, 1]) < 1.0)
    reference = os.path.join(work, "mask-tracts.reference.vtp")
    done = subprocess.run([RIEMANN, "trace", "-m", PHANTOM, "--seed-mask", seeds, "--stop-mask", stops,
                           "--propagation", "forward", "--compress", "none", "-o", reference],
                          capture_output=True, text=True)
    check(done.returncode == 0, f"riemann trace --seed-mask --stop-mask failed: {done.stderr}")
    reasons = compare_outputs.arrays(compare_outputs.read(reference)).get("cell:ReasonForTermination")
    check(reasons is not None and np.sum(reasons == 11) > 0, "the stop mask stops no tract: a weak test")
    output = os.path.join(work, "mask-tracts.vtp")
    # Rows of the Select Input dialog: the masks 0 and 1 (opened first), the Metric 2.
    steps = (paraview_gui.Steps().open_file(seeds).open_file(stops)
             .apply_source("RiemannMetricSource", DefinitionFile=PHANTOM)
             .apply_filter_with_inputs("RiemannGeodesicTracer", {"Input": 0, "StopMask": 1, "Metric": 2})
             .save_data(output))
    if paraview_gui.played(steps, work, "mask-tracts", output):
        compared("Geodesic Tracer from a seed mask, with a stop mask", output, reference,
                 "riemann trace --seed-mask --stop-mask's")


def ray_bundle(work):
    output = os.path.join(work, "bundle.vtp")
    steps = (paraview_gui.Steps()
             .apply_source("RiemannMetricSource", DefinitionFile=LENS)
             .apply_filter("RiemannRayBundle")
             .save_data(output))
    if paraview_gui.played(steps, work, "bundle", output):
        metric = riemann.vtkRiemannMetric()
        check(metric.SetDefinitionFile(LENS), metric.GetLastError())
        bundle = riemann.vtkRiemannRayBundle()
        bundle.SetMetric(metric)
        reference = os.path.join(work, "bundle.reference.vtp")
        compare_outputs.write(bundle, reference)
        compared("Ray Bundle", output, reference, "vtkRiemannRayBundle's")


def main():
    work = tempfile.mkdtemp(prefix="ParaViewTractsAndRays-")
    tract_files(work)
    tractography_from_a_mask(work)
    ray_bundle(work)
    return compare_outputs.exit_status()


if __name__ == "__main__":
    sys.exit(main())
