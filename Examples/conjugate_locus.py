#!/usr/bin/env python3
"""Conjugate loci of the paper's paraboloid metric, from a few observers.

    conjugate_locus.py [--metric M.json] [--directions N] [--output conjugate.png]

For the graph of f = x^2 + y^2 + z^2 (Data/metrics/paraboloid.json) the
exponential map is not injective (the paper's example): geodesics from an
observer meet again. vtkRiemannConjugateLocus finds, for N directions, the
first point where the transverse Jacobian of exp loses rank; this script
draws those points (coloured by arc length) for three observers.
"""
import argparse
import os
import sys

from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import riemann
from perceptual_colours import viridis

OBSERVERS = [((0.0, 0.0, 0.0), (1.0, 1.0, 1.0)), ((0.6, 0.0, 0.0), (1.0, 0.5, 0.2)),
             ((0.0, -0.5, 0.4), (0.3, 0.7, 1.0))]


def main():
    data = os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "Data"))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--metric", default=os.path.join(data, "metrics", "paraboloid.json"))
    parser.add_argument("--directions", type=int, default=4000)
    parser.add_argument("--length", type=float, default=4.0)
    parser.add_argument("--output", default="conjugate.png")
    args = parser.parse_args()

    metric = riemann.vtkRiemannMetric()
    if not metric.SetDefinitionFile(args.metric):
        sys.exit("conjugate_locus: " + metric.GetLastError())
    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.11, 0.14)
    renderer.SetBackground2(0.28, 0.3, 0.36)
    renderer.GradientBackgroundOn()
    found = []
    mapper = None
    for observer, color in OBSERVERS:
        locus = riemann.vtkRiemannConjugateLocus()
        locus.SetMetric(metric)
        locus.SetObserver(*observer)
        locus.SetNumberOfDirections(args.directions)
        locus.GetIntegrationSettings().SetMaximumPropagation(args.length)
        locus.GetIntegrationSettings().SetInitialIntegrationStep(0.01)
        locus.Update()
        points = locus.GetOutput()
        found.append(points.GetNumberOfPoints())
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(points)
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray("ArcLength")
        mapper.SetScalarRange(0.0, args.length)
        mapper.SetLookupTable(viridis(0.0, args.length))
        mapper.UseLookupTableScalarRangeOff()
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetPointSize(3)
        renderer.AddActor(actor)
        eye = vtkSphereSource()
        eye.SetCenter(observer)
        eye.SetRadius(0.03)
        eye_mapper = vtkPolyDataMapper()
        eye_mapper.SetInputConnection(eye.GetOutputPort())
        eye_actor = vtkActor()
        eye_actor.SetMapper(eye_mapper)
        eye_actor.GetProperty().SetColor(*color)
        renderer.AddActor(eye_actor)
    bar = vtkScalarBarActor()
    bar.SetLookupTable(mapper.GetLookupTable())
    bar.SetTitle("Arc length")
    bar.SetNumberOfLabels(5)
    bar.SetWidth(0.08)
    bar.SetPosition(0.9, 0.15)
    renderer.AddActor2D(bar)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(2.2, -2.6, 1.8)
    camera.SetFocalPoint(0.1, 0.0, 0.1)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(900, 700)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print(f"conjugate_locus: {found} first conjugate points for {args.directions} directions per observer "
          f"-> {args.output}")


if __name__ == "__main__":
    main()
