#!/usr/bin/env python3
"""Geodesic tractography through the synthetic fibre phantom (issue 17).

    tractography.py [--output tracts.png] [--tracts tracts.vtp]

The metric is the inverse of the phantom's diffusion tensors
(Data/phantom/fibre-phantom.json: {"type": "sampled", "inverse": true,
"outside": "stop"}): moving along a fibre is cheap, so a geodesic started
along a bundle stays in it. Seeds: a small disc of points across each
bundle half way along it, tracked both ways along the bundle's direction. The
tracts (vtkRiemannGeodesicTracer) are drawn as tubes coloured by bundle over
the fractional-anisotropy slice through the crossing, and each tract's angle
to the fibre direction is measured where it is inside its own bundle:
the mean per bundle is printed. Run with ./run.sh's environment
(PYTHONPATH=build/lib/python3/dist-packages, under an X server for the picture).
"""
import argparse
import math
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdList, vtkLookupTable, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkProbeFilter, vtkTubeFilter
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataWriter

import riemann

DATA = os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data"))
PHANTOM = os.path.join(DATA, "phantom")
# Bundle number (the phantom's "Bundle" array) -> seed centre, direction there, name.
ARC_RADIUS, ARC_Z, CROSS_Z = 1.5, 0.45, -0.35
# Seeds half way along each bundle (the straight ones between their end and
# the crossing, the arc at its apex), tracked both ways.
BUNDLES = {
    1: ((-0.9, 0.0, CROSS_Z), (1.0, 0.0, 0.0), "x bundle"),
    2: ((0.0, -0.9, CROSS_Z), (0.0, 1.0, 0.0), "y bundle"),
    3: ((0.0, ARC_RADIUS, ARC_Z), (-1.0, 0.0, 0.0), "arc bundle"),
}


def seeds(radius=0.08, rings=2, per_ring=6):
    """A disc of seed points across each bundle (centre plus rings), with the
    bundle's direction; point data "Direction" and "SeedBundle"."""
    points, directions, labels = [], [], []
    for bundle, (centre, direction, _) in BUNDLES.items():
        t = np.array(direction)
        u = np.cross(t, (0.0, 0.0, 1.0)) if abs(t[2]) < 0.9 else np.array((1.0, 0.0, 0.0))
        u /= np.linalg.norm(u)
        w = np.cross(t, u)
        offsets = [np.zeros(3)]
        for ring in range(1, rings + 1):
            for k in range(per_ring):
                angle = 2.0 * math.pi * (k + 0.5 * ring) / per_ring
                offsets.append(radius * ring / rings * (math.cos(angle) * u + math.sin(angle) * w))
        for offset in offsets:
            points.append(np.array(centre) + offset)
            directions.append(t)
            labels.append(bundle)
    polydata = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetDataTypeToDouble()
    for p in points:
        vtk_points.InsertNextPoint(*p)
    polydata.SetPoints(vtk_points)
    for name, values in (("Direction", np.array(directions)), ("SeedBundle", np.array(labels, dtype=np.int32))):
        array = numpy_to_vtk(values, deep=1)
        array.SetName(name)
        polydata.GetPointData().AddArray(array)
    return polydata


def trace_tracts(length=6.0, step=0.01, tensor_metric="inverse", christoffel="spline"):
    """The tracts: geodesics of the phantom's metric from seeds().
    `tensor_metric`: which metric of the tensors (MetricFormat.md): "inverse"
    (the shipped definition's D^-1), "adjugate" or "sharpened";
    `christoffel`: "spline" (exact) or "voxels" (tractography's fast path)."""
    import json
    with open(os.path.join(PHANTOM, "fibre-phantom.json")) as f:
        definition = json.load(f)
    definition.pop("inverse", None)
    definition["tensor_metric"] = tensor_metric
    definition["christoffel"] = christoffel
    metric = riemann.vtkRiemannMetric()
    if not metric.SetDefinition(json.dumps(definition), PHANTOM):
        raise RuntimeError(metric.GetLastError())
    tracer = riemann.vtkRiemannGeodesicTracer()
    tracer.SetMetric(metric)
    tracer.SetInputData(seeds())
    tracer.SetIntegrationDirection(tracer.BOTH)
    settings = tracer.GetIntegrationSettings()
    settings.SetIntegratorTypeToRungeKutta4()
    settings.SetInitialIntegrationStep(step)
    settings.SetMaximumPropagation(length)
    tracer.Update()
    return tracer.GetOutput()


def read_phantom():
    reader = vtkXMLImageDataReader()
    reader.SetFileName(os.path.join(PHANTOM, "fibre-phantom.vti"))
    reader.Update()
    return reader.GetOutput()


def fibre_angles(tracts, phantom):
    """Per bundle: (mean angle in degrees between each tract's tangent and
    the fibre direction at its points inside its own bundle, the fraction of
    its points that are inside its own bundle, number of tracts). The fibre
    direction is the phantom's nearest sample's (probe, linear weights on
    the unit "FibreDirection" field renormalised)."""
    probe = vtkProbeFilter()
    probe.SetInputData(tracts)
    probe.SetSourceData(phantom)
    probe.Update()
    probed = probe.GetOutput()
    fibre = vtk_to_numpy(probed.GetPointData().GetArray("FibreDirection"))
    bundle = np.rint(vtk_to_numpy(probed.GetPointData().GetArray("Bundle"))).astype(int)
    velocity = vtk_to_numpy(tracts.GetPointData().GetArray("Velocity"))
    seed_ids = vtk_to_numpy(tracts.GetCellData().GetArray("SeedIds"))
    seed_bundle = vtk_to_numpy(seeds().GetPointData().GetArray("SeedBundle"))
    results = {}
    lines = tracts.GetLines()
    lines.InitTraversal()
    ids = vtkIdList()
    cell = 0
    while lines.GetNextCell(ids):
        own = seed_bundle[seed_ids[cell]]
        cell += 1
        point_ids = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
        inside = [p for p in point_ids if bundle[p] == own and np.linalg.norm(fibre[p]) > 0.5]
        angles = []
        for p in inside:
            f = fibre[p] / np.linalg.norm(fibre[p])
            v = velocity[p] / np.linalg.norm(velocity[p])
            angles.append(math.degrees(math.acos(min(1.0, abs(float(np.dot(f, v)))))))
        entry = results.setdefault(own, {"angles": [], "inside": [], "tracts": 0})
        entry["angles"].extend(angles)
        entry["inside"].append(len(inside) / len(point_ids))
        entry["tracts"] += 1
    return {b: (float(np.mean(e["angles"])), float(np.mean(e["inside"])), e["tracts"]) for b, e in results.items()}


def coloured_actor(port, array, lookup_table, cells):
    """An actor of `port`'s output coloured by its cell or point array `array`
    through `lookup_table` (over the table's range)."""
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(port)
    if cells:
        mapper.SetScalarModeToUseCellFieldData()
    else:
        mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(array)
    mapper.SetLookupTable(lookup_table)
    mapper.SetScalarRange(lookup_table.GetTableRange())
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def render(tracts, phantom, output, size):
    """Tubes coloured by bundle over the FA slice z = CROSS_Z, seen from above."""
    from vtkmodules.vtkFiltersGeometry import vtkImageDataGeometryFilter
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

    seed_bundle = vtk_to_numpy(seeds().GetPointData().GetArray("SeedBundle"))
    seed_ids = vtk_to_numpy(tracts.GetCellData().GetArray("SeedIds"))
    labels = numpy_to_vtk(seed_bundle[seed_ids].astype(np.int32), deep=1)
    labels.SetName("Bundle")
    coloured = vtkPolyData()
    coloured.ShallowCopy(tracts)
    coloured.GetCellData().AddArray(labels)
    tubes = vtkTubeFilter()
    tubes.SetInputData(coloured)
    tubes.SetRadius(0.012)
    tubes.SetNumberOfSides(8)
    bundle_colours = vtkLookupTable()
    bundle_colours.SetNumberOfTableValues(3)
    for i, rgb in enumerate(((0.95, 0.35, 0.2), (0.25, 0.6, 0.95), (0.3, 0.85, 0.35))):
        bundle_colours.SetTableValue(i, *rgb, 1.0)
    bundle_colours.SetTableRange(1, 3)
    bundle_colours.Build()
    tube_actor = coloured_actor(tubes.GetOutputPort(), "Bundle", bundle_colours, cells=True)

    k = int(round((CROSS_Z - phantom.GetOrigin()[2]) / phantom.GetSpacing()[2]))
    nx, ny, _ = phantom.GetDimensions()
    slice_filter = vtkImageDataGeometryFilter()
    slice_filter.SetInputData(phantom)
    slice_filter.SetExtent(0, nx - 1, 0, ny - 1, k, k)
    grey = vtkLookupTable()
    grey.SetSaturationRange(0, 0)
    grey.SetValueRange(0.1, 0.9)
    grey.SetTableRange(0, 0.9)
    grey.Build()
    slice_actor = coloured_actor(slice_filter.GetOutputPort(), "FractionalAnisotropy", grey, cells=False)

    renderer = vtkRenderer()
    renderer.SetBackground(0.08, 0.08, 0.1)
    renderer.AddActor(slice_actor)
    renderer.AddActor(tube_actor)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.4, -3.6, 5.6)
    camera.SetFocalPoint(0.0, 0.35, 0.0)
    camera.SetViewUp(0.0, 0.0, 1.0)
    renderer.ResetCameraClippingRange()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--output", default="tracts.png", help="the picture (default tracts.png)")
    parser.add_argument("--tracts", default="", help="also write the tracts as .vtp")
    parser.add_argument("--size", default="960x720")
    args = parser.parse_args()
    try:
        tracts = trace_tracts()
    except RuntimeError as error:
        sys.exit("tractography: " + str(error))
    phantom = read_phantom()
    for bundle, (angle, inside, count) in sorted(fibre_angles(tracts, phantom).items()):
        print(f"{BUNDLES[bundle][2]}: {count} tracts, mean angle to the fibres {angle:.2f} deg, "
              f"{100 * inside:.0f}% of their points inside the bundle")
    if args.tracts:
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(args.tracts)
        writer.SetInputData(tracts)
        writer.Write()
    render(tracts, phantom, args.output, tuple(int(v) for v in args.size.lower().split("x")))
    print("wrote", args.output)


if __name__ == "__main__":
    main()
