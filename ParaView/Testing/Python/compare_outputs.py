"""Read VTK files with the toolkit's VTK (9.1) and compare their arrays; the
checks the plugin's tests share.

ParaView (VTK 9.2 inside) and the riemann commands write the same XML
formats; these read both and say where two outputs differ.
"""

import os

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLDataObjectWriter, vtkXMLGenericDataObjectReader

# What failed so far in this test (check); a test exits 1 when it is not empty.
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL: " + message)


def exit_status():
    return 1 if failures else 0


def write(algorithm, path):
    """The algorithm's output, brought up to date, as a VTK XML file (the toolkit's answer)."""
    algorithm.Update()
    writer = vtkXMLDataObjectWriter()
    writer.SetInputData(algorithm.GetOutputDataObject(0))
    writer.SetFileName(path)
    if not writer.Write():
        raise AssertionError(f"{path}: not written")


def toolkit_curvature_at(riemann, metric_file, t, path):
    """The toolkit's own curvature field (declared grid) of a metric file at time t, written to path."""
    metric = riemann.vtkRiemannMetric()
    check(metric.SetDefinitionFile(metric_file) and metric.SetTime(t), metric.GetLastError())
    field = riemann.vtkRiemannCurvatureField()
    field.SetMetric(metric)
    write(field, path)


def compared(what, output, reference, against="the toolkit's", names=None):
    """check() that `output` equals `reference` (compare: every array, or `names`, bitwise);
    says which arrays were equal. Nothing when either file is missing (the caller said why)."""
    if not (os.path.isfile(output) and os.path.isfile(reference)):
        return
    problems = compare(output, reference, names)
    for problem in problems:
        check(False, f"{what}: {problem}")
    if not problems:
        print(f"{what}: equal to {against}: " + ", ".join(sorted(arrays(read(output)))))


def rgb(path):
    """A PNG picture's red, green and blue as a rows x columns x 3 array of doubles (row 0 at the bottom)."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)
    return pixels[:, :, :3].astype(np.float64)


def read(path):
    reader = vtkXMLGenericDataObjectReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if data is None:
        raise AssertionError(f"{path}: not readable as VTK XML")
    return data


def arrays(data):
    """name -> numpy array: the point data by name, the cell data as "cell:<name>"; the
    points as "Points" (an image's: its origin, spacing and extent); a polydata's cells
    as "Lines", "Polys", "Verts" (offsets, then connectivity)."""
    out = {}
    for prefix, attributes in (("", data.GetPointData()), ("cell:", data.GetCellData())):
        for i in range(attributes.GetNumberOfArrays()):
            array = attributes.GetArray(i)
            if array is not None:
                out[prefix + array.GetName()] = vtk_to_numpy(array).astype(np.float64)
    if data.IsA("vtkPolyData"):
        for name, cells in (("Lines", data.GetLines()), ("Polys", data.GetPolys()), ("Verts", data.GetVerts())):
            if cells.GetNumberOfCells() > 0:
                out[name] = np.concatenate([vtk_to_numpy(cells.GetOffsetsArray()),
                                            vtk_to_numpy(cells.GetConnectivityArray())]).astype(np.float64)
    if data.IsA("vtkImageData"):
        out["Points"] = np.array(list(data.GetOrigin()) + list(data.GetSpacing()) + list(data.GetExtent()),
                                 dtype=np.float64)
    elif hasattr(data, "GetPoints") and data.GetPoints() is not None:
        out["Points"] = vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
    return out


# What ParaView's writers add of their own (not the filter's output).
WRITER_ARRAYS = {"vtkOriginalPointIds", "vtkOriginalCellIds"}


def compare(got_path, want_path, names=None, tolerance=0.0):
    """Each named array of `got` (None: all it has, which must include Points) equals
    `want`'s to `tolerance` (0: bitwise); messages for the rest."""
    got, want = arrays(read(got_path)), arrays(read(want_path))
    problems = []
    if names is None:
        names = sorted(set(got) - WRITER_ARRAYS)
        if "Points" not in names:
            problems.append(f"{got_path}: no points")
    for name in names:
        if name not in got:
            problems.append(f"{got_path}: no array {name} (has {sorted(got)})")
            continue
        if name not in want:
            problems.append(f"{want_path}: no array {name} (has {sorted(want)})")
            continue
        a, b = got[name], want[name]
        if a.shape != b.shape:
            problems.append(f"{name}: shape {a.shape} against {b.shape}")
            continue
        both_nan = np.isnan(a) & np.isnan(b)
        difference = np.where(both_nan, 0.0, np.abs(a - b))
        worst = float(np.nanmax(difference)) if difference.size else 0.0
        if not worst <= tolerance or np.any(np.isnan(a) != np.isnan(b)):
            problems.append(f"{name}: differs by up to {worst:.3g} (allowed {tolerance:g})")
    return problems
