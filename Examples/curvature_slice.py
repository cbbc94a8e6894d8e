#!/usr/bin/env python3
"""Scalar curvature of a metric on a slice, as a picture.

    curvature_slice.py [--metric M.json] [--z 0] [--output curvature.png]

Computes vtkRiemannCurvatureField on a grid around the origin and shows the
slice z = const of ScalarCurvature with a diverging colour map (blue
negative, red positive) and contour lines. Default metric: the paper's two
bumps (Data/metrics/two-bumps.json). Run with ./run.sh's environment
(PYTHONPATH=build/lib/python3/dist-packages, under an X server).
"""
import argparse
import os
import sys

from vtkmodules.vtkFiltersCore import vtkContourFilter
from vtkmodules.vtkFiltersGeometry import vtkImageDataGeometryFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import riemann


def main():
    data = os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "Data"))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--metric", default=os.path.join(data, "metrics", "two-bumps.json"))
    parser.add_argument("--z", type=float, default=0.0, help="height of the slice (default 0)")
    parser.add_argument("--output", default="curvature.png")
    args = parser.parse_args()

    metric = riemann.vtkRiemannMetric()
    if not metric.SetDefinitionFile(args.metric):
        sys.exit("curvature_slice: " + metric.GetLastError())
    n = 201
    field = riemann.vtkRiemannCurvatureField()
    field.SetMetric(metric)
    field.SetBounds(-2.2, 2.2, -1.6, 1.6, args.z, args.z)
    field.SetDimensions(n, int(n * 3.2 / 4.4), 1)
    field.Update()
    image = field.GetOutput()
    values = image.GetPointData().GetArray("ScalarCurvature")
    low, high = values.GetRange()
    image.GetPointData().SetActiveScalars("ScalarCurvature")

    surface = vtkImageDataGeometryFilter()
    surface.SetInputData(image)
    # Diverging blue-white-red, white at zero; the negative side is scaled to
    # its own extreme so weak negative curvature (the rings around bumps) shows.
    lut = vtkColorTransferFunction()
    lut.SetColorSpaceToDiverging()
    lut.AddRGBPoint(min(low, -1e-9), 0.23, 0.30, 0.75)
    lut.AddRGBPoint(0.0, 0.97, 0.97, 0.97)
    lut.AddRGBPoint(max(high, 1e-9), 0.71, 0.02, 0.15)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    mapper.SetLookupTable(lut)
    mapper.SetScalarRange(min(low, -1e-9), max(high, 1e-9))
    actor = vtkActor()
    actor.SetMapper(mapper)

    contours = vtkContourFilter()
    contours.SetInputConnection(surface.GetOutputPort())
    contours.GenerateValues(12, low, high)
    contour_mapper = vtkPolyDataMapper()
    contour_mapper.SetInputConnection(contours.GetOutputPort())
    contour_mapper.ScalarVisibilityOff()
    contour_actor = vtkActor()
    contour_actor.SetMapper(contour_mapper)
    contour_actor.GetProperty().SetColor(0.1, 0.1, 0.1)

    bar = vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle("Scalar curvature")
    bar.SetNumberOfLabels(5)
    bar.SetPosition(0.88, 0.1)
    bar.SetWidth(0.1)
    bar.SetHeight(0.8)
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)

    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(actor)
    renderer.AddActor(contour_actor)
    legend = vtkRenderer()
    legend.SetBackground(1, 1, 1)
    legend.SetViewport(0.86, 0.0, 1.0, 1.0)
    bar.SetPosition(0.1, 0.1)
    bar.SetWidth(0.6)
    legend.AddActor2D(bar)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Zoom(1.15)
    renderer.SetViewport(0.0, 0.0, 0.86, 1.0)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.AddRenderer(legend)
    window.SetSize(900, 600)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print(f"curvature_slice: scalar curvature on z = {args.z} in [{low:.3g}, {high:.3g}] -> {args.output}")


if __name__ == "__main__":
    main()
