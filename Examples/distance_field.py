#!/usr/bin/env python3
"""The distance from a point in the two-bump metric: wavefronts, cut locus,
minimal geodesics.

    distance_field.py [--metric M.json] [--dims N] [--output distance.png]

vtkRiemannDistanceField solves the eikonal equation |grad u|_{g^-1} = 1 from
the seed (-1.5, 0, 0) on an N^3 grid of [-2, 2]^3 (Data/metrics/two-bumps.json:
the graph of two Gaussian bumps, at (-0.8, 0, 0) and (0.9, 0.3, 0)). The
slice z = 0 is coloured by the distance, with its level sets (the true
wavefronts: they fold behind each bump). vtkRiemannCutLocus finds where the
minimal geodesics from the seed stop being unique (white): behind the first
bump, around its axis, and behind the second, in the plane z = 0.
vtkRiemannMinimalGeodesics walks back from a few points to the seed along
the field and refines each path into a geodesic (yellow); those ending at
the cut locus leave the seed on either side of the bump.
Printed: the field's range and timing, the cut locus's squares, each
geodesic's length against the field's distance.
"""
import argparse
import os
import time

from vtkmodules.vtkCommonDataModel import vtkPlane
from vtkmodules.vtkFiltersCore import vtkContourFilter, vtkCutter, vtkTubeFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow, vtkTextActor,
                                         vtkWindowToImageFilter)
from vtkmodules.util.numpy_support import vtk_to_numpy
import vtkmodules.vtkRenderingFreeType  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import riemann

HERE = os.path.dirname(os.path.abspath(__file__))
SEED = (-1.5, 0.0, 0.0)
TARGETS = [(1.6, 0.0, 0.0), (1.5, 0.3, 0.0), (0.2, 0.05, 0.0), (1.2, -1.2, 0.0), (0.0, 1.4, 0.0),
           (-0.2, -0.9, 0.0)]


def solid_actor(port, colour):
    """An actor drawing the output at `port` in one colour."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(port)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*colour)
    return actor


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--metric", default=os.path.join(HERE, "..", "Data", "metrics", "two-bumps.json"))
    parser.add_argument("--dims", type=int, default=97)
    parser.add_argument("--output", default="distance.png")
    args = parser.parse_args()

    metric = riemann.vtkRiemannMetric()
    with open(args.metric) as f:
        assert metric.SetDefinition(f.read()), metric.GetLastError()

    field = riemann.vtkRiemannDistanceField()
    field.SetMetric(metric)
    field.SetBounds(-2, 2, -2, 2, -2, 2)
    field.SetDimensions(args.dims, args.dims, args.dims)
    field.AddSeed(*SEED)
    start = time.perf_counter()
    field.Update()
    distance = vtk_to_numpy(field.GetOutput().GetPointData().GetArray("Distance"))
    print("distance field %d^3: from %.3f to %.3f in %.2f s (%d rounds)"
          % (args.dims, distance.min(), distance.max(), time.perf_counter() - start,
             field.GetNumberOfRounds()))

    cut = riemann.vtkRiemannCutLocus()
    cut.SetMetric(metric)
    cut.SetInputConnection(field.GetOutputPort())
    cut.Update()
    print("cut locus: %d squares" % cut.GetOutput().GetNumberOfPolys())

    minimal = riemann.vtkRiemannMinimalGeodesics()
    minimal.SetMetric(metric)
    minimal.SetInputConnection(field.GetOutputPort())
    for target in TARGETS:
        minimal.AddTarget(*target)
    minimal.Update()
    cd = minimal.GetOutput().GetCellData()
    for i in range(minimal.GetOutput().GetNumberOfLines()):
        print("geodesic to %s: length %.5f, the field's distance %.5f, refined %d"
              % (TARGETS[int(cd.GetArray("TargetIds").GetValue(i))], cd.GetArray("Length").GetValue(i),
                 cd.GetArray("Distance").GetValue(i), cd.GetArray("Refined").GetValue(i)))

    # The slice z = 0, coloured by distance, and its level sets.
    plane = vtkPlane()
    plane.SetOrigin(0, 0, 0)
    plane.SetNormal(0, 0, 1)
    slice_ = vtkCutter()
    slice_.SetCutFunction(plane)
    slice_.SetInputConnection(field.GetOutputPort())
    colours = vtkColorTransferFunction()
    colours.AddRGBPoint(0.0, 0.07, 0.10, 0.35)
    colours.AddRGBPoint(2.3, 0.20, 0.55, 0.65)
    colours.AddRGBPoint(4.7, 0.85, 0.90, 0.75)
    slice_mapper = vtkPolyDataMapper()
    slice_mapper.SetInputConnection(slice_.GetOutputPort())
    slice_mapper.SetLookupTable(colours)
    slice_mapper.SetScalarModeToUsePointFieldData()
    slice_mapper.SelectColorArray("Distance")
    slice_mapper.SetScalarRange(0, 4.7)
    slice_actor = vtkActor()
    slice_actor.SetMapper(slice_mapper)
    fronts = vtkContourFilter()
    fronts.SetInputConnection(slice_.GetOutputPort())
    fronts.GenerateValues(23, 0.2, 4.6)
    fronts_actor = solid_actor(fronts.GetOutputPort(), (0.05, 0.05, 0.05))
    fronts_actor.GetProperty().SetLineWidth(1.5)
    fronts_actor.SetPosition(0, 0, 0.01)

    cut_actor = solid_actor(cut.GetOutputPort(), (1, 1, 1))
    cut_actor.GetProperty().SetOpacity(0.55)

    tubes = vtkTubeFilter()
    tubes.SetInputConnection(minimal.GetOutputPort())
    tubes.SetRadius(0.025)
    tubes.SetNumberOfSides(12)
    tubes_actor = solid_actor(tubes.GetOutputPort(), (1.0, 0.82, 0.15))

    seed = vtkSphereSource()
    seed.SetCenter(*SEED)
    seed.SetRadius(0.07)
    seed_actor = solid_actor(seed.GetOutputPort(), (0.95, 0.3, 0.2))

    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.1, 0.12)
    for actor in (slice_actor, fronts_actor, cut_actor, tubes_actor, seed_actor):
        renderer.AddActor(actor)
    label = vtkTextActor()
    label.SetInput("two bumps: distance from the seed (z = 0), wavefronts, cut locus (white), "
                   "minimal geodesics (yellow)")
    label.GetTextProperty().SetFontSize(16)
    label.SetPosition(10, 10)
    renderer.AddActor2D(label)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.3, -3.2, 7.5)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewUp(0, 1, 0)
    renderer.ResetCamera()
    camera.Zoom(1.35)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(1000, 800)
    window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print("->", args.output)


if __name__ == "__main__":
    main()
