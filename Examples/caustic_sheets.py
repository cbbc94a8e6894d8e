#!/usr/bin/env python3
"""The caustic of an astigmatic lens as two sheets, with their cusp edges.

    caustic_sheets.py [--metric M.json] [--directions N] [--output sheets.png]

An observer looks through the lens of Data/metrics/astigmatic-lens.json
(refractive index 1 + 0.6 exp(-(x^2 + (y/0.6)^2 + (z/0.85)^2) / 2), stronger
across y than across z). Every geodesic of the cone focuses twice: first
across y, then across z. vtkRiemannConjugateLocus counts the conjugate points
(Maslov phases: none is missed or merged) and outputs the caustic as sheets
(output port 1): sheet k holds each direction's k-th conjugate point counted
with multiplicity, so the two focal surfaces come out as two separate
surfaces (cell array `Sheet`, here blue and orange). Each sheet folds along a
cusp edge, where the conjugate distance does not change along the direction
that focuses (`Singularity` = 1, red): the two focal lines of the lens. The
observer is at (-3, 0.1, 0.05), off the picture to the left.
Printed: points, triangles and cusp triangles of each sheet.
"""
import argparse
import os
import sys

from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkFiltersCore import vtkThreshold
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import riemann

OBSERVER = (-3.0, 0.1, 0.05)
AXIS = (1.0, 0.0, 0.0)
SHEET_COLORS = {1: (0.3, 0.55, 0.95), 2: (0.98, 0.62, 0.22)}
CUSP_COLOR = (0.9, 0.1, 0.1)


def cells_where(data, array, value):
    """The cells of `data` whose cell array `array` equals `value`, as polydata."""
    threshold = vtkThreshold()
    threshold.SetInputData(data)
    threshold.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_CELLS, array)
    threshold.SetLowerThreshold(value - 0.5)
    threshold.SetUpperThreshold(value + 0.5)
    threshold.SetThresholdFunction(vtkThreshold.THRESHOLD_BETWEEN)
    surface = vtkGeometryFilter()
    surface.SetInputConnection(threshold.GetOutputPort())
    surface.Update()
    return surface.GetOutput()


def actor_for(data, color, opacity=1.0):
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(data)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    actor.GetProperty().SetOpacity(opacity)
    return actor


def main():
    data = os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "Data"))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--metric", default=os.path.join(data, "metrics", "astigmatic-lens.json"))
    parser.add_argument("--directions", type=int, default=8000)
    parser.add_argument("--cone-angle", type=float, default=14.0)
    parser.add_argument("--length", type=float, default=9.0)
    parser.add_argument("--output", default="sheets.png")
    args = parser.parse_args()

    metric = riemann.vtkRiemannMetric()
    if not metric.SetDefinitionFile(args.metric):
        sys.exit("caustic_sheets: " + metric.GetLastError())

    locus = riemann.vtkRiemannConjugateLocus()
    locus.SetMetric(metric)
    locus.SetObserver(*OBSERVER)
    locus.SetConeAxis(*AXIS)
    locus.SetConeAngle(args.cone_angle)
    locus.SetNumberOfDirections(args.directions)
    locus.SetMaximumNumberOfConjugatePoints(2)
    locus.GetIntegrationSettings().SetMaximumPropagation(args.length)
    locus.Update()
    if locus.GetLastError():
        sys.exit("caustic_sheets: " + locus.GetLastError())
    sheets = locus.GetOutput(1)

    # A sparse bundle of rays through the lens, for context.
    rays = riemann.vtkRiemannExponentialMap()
    rays.SetMetric(metric)
    rays.SetObserver(*OBSERVER)
    rays.SetConeAxis(*AXIS)
    rays.SetConeAngle(args.cone_angle)
    rays.SetNumberOfDirections(120)
    rays.GetIntegrationSettings().SetMaximumPropagation(6.8)
    rays.Update()

    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.11, 0.14)
    renderer.SetBackground2(0.3, 0.32, 0.38)
    renderer.GradientBackgroundOn()
    ray_actor = actor_for(rays.GetOutput(0), (0.8, 0.8, 0.75), 0.25)
    renderer.AddActor(ray_actor)
    for sheet, color in SHEET_COLORS.items():
        part = cells_where(sheets, "Sheet", sheet)
        cusps = cells_where(part, "Singularity", 1)
        print(f"caustic_sheets: sheet {sheet}: {part.GetNumberOfPoints()} points, "
              f"{part.GetNumberOfCells()} triangles, {cusps.GetNumberOfCells()} on a cusp edge")
        renderer.AddActor(actor_for(part, color, 0.75))
        cusp_actor = actor_for(cusps, CUSP_COLOR)
        cusp_actor.GetProperty().SetRepresentationToWireframe()
        cusp_actor.GetProperty().SetLineWidth(3.0)
        cusp_actor.GetProperty().LightingOff()
        renderer.AddActor(cusp_actor)

    labels = [("sheet 1: focus across y", SHEET_COLORS[1]), ("sheet 2: focus across z", SHEET_COLORS[2]),
              ("cusp edges", CUSP_COLOR)]
    for row, (text, color) in enumerate(labels):
        label = vtkTextActor()
        label.SetInput(text)
        label.GetTextProperty().SetFontSize(18)
        label.GetTextProperty().SetBold(True)
        label.GetTextProperty().SetColor(*color)
        label.SetPosition(16, 14 + 26 * (len(labels) - 1 - row))
        renderer.AddActor2D(label)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(1000, 640)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(1.05, 0.05, 0.0)
    camera.SetPosition(0.1, -2.9, 1.5)
    camera.SetViewUp(0.0, 0.0, 1.0)
    camera.SetViewAngle(30.0)
    renderer.ResetCameraClippingRange()
    window.Render()
    capture = vtkWindowToImageFilter()
    capture.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(capture.GetOutputPort())
    writer.Write()
    print(f"caustic_sheets: wrote {args.output}")


if __name__ == "__main__":
    main()
