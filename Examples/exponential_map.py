#!/usr/bin/env python3
"""The exponential map of an astigmatic lens: rays, a wavefront and the caustic.

    exponential_map.py [--metric M.json] [--directions N] [--output caustic.png]

An observer looks through the lens of Data/metrics/astigmatic-lens.json
(refractive index 1 + 0.6 exp(-(x^2 + (y/0.6)^2 + (z/0.85)^2) / 2), stronger
across y than across z). vtkRiemannConjugateLocus finds, along geodesics over a
cone of directions, the first and second conjugate points: the two sheets of
the caustic, as surfaces over the direction grid. (A round lens would not do:
its symmetry axis through the observer collapses one sheet to a segment.)
vtkRiemannExponentialMap gives the rays and the geodesic sphere (wavefront)
at one radius between the sheets, coloured by the sign of the transverse
Jacobian of exp: positive (blue) where the wavefront has not yet met a caustic
sheet, negative (red) where it has folded through one.
"""
import argparse
import os
import sys

from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import riemann

OBSERVER = (-3.0, 0.1, 0.05)
AXIS = (1.0, 0.0, 0.0)


def mapper_for(data, array, value_range, table=None):
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(data)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(array)
    mapper.SetScalarRange(*value_range)
    if table is not None:
        mapper.SetLookupTable(table)
    return mapper


def main():
    data = os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "Data"))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--metric", default=os.path.join(data, "metrics", "astigmatic-lens.json"))
    parser.add_argument("--directions", type=int, default=6000)
    parser.add_argument("--cone-angle", type=float, default=20.0)
    parser.add_argument("--length", type=float, default=9.0)
    parser.add_argument("--radius", type=float, default=6.0, help="radius of the wavefront")
    parser.add_argument("--output", default="caustic.png")
    args = parser.parse_args()

    metric = riemann.vtkRiemannMetric()
    if not metric.SetDefinitionFile(args.metric):
        sys.exit("exponential_map: " + metric.GetLastError())

    locus = riemann.vtkRiemannConjugateLocus()
    locus.SetMetric(metric)
    locus.SetObserver(*OBSERVER)
    locus.SetConeAxis(*AXIS)
    locus.SetConeAngle(args.cone_angle)
    locus.SetNumberOfDirections(args.directions)
    locus.GetIntegrationSettings().SetMaximumPropagation(args.length)
    locus.SetMaximumNumberOfConjugatePoints(2)
    locus.Update()
    caustic = locus.GetOutput(1)

    expmap = riemann.vtkRiemannExponentialMap()
    expmap.SetMetric(metric)
    expmap.SetObserver(*OBSERVER)
    expmap.SetConeAxis(*AXIS)
    expmap.SetConeAngle(args.cone_angle)
    expmap.SetNumberOfDirections(args.directions)
    expmap.GetIntegrationSettings().SetMaximumPropagation(args.length)
    expmap.AddRadius(args.radius)
    expmap.Update()
    wavefronts = expmap.GetOutput(1)

    # A sparse bundle of rays for context.
    rays = riemann.vtkRiemannExponentialMap()
    rays.SetMetric(metric)
    rays.SetObserver(*OBSERVER)
    rays.SetConeAxis(*AXIS)
    rays.SetConeAngle(args.cone_angle)
    rays.SetNumberOfDirections(150)
    rays.GetIntegrationSettings().SetMaximumPropagation(7.5)
    rays.Update()

    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.11, 0.14)
    renderer.SetBackground2(0.3, 0.32, 0.38)
    renderer.GradientBackgroundOn()

    ray_mapper = vtkPolyDataMapper()
    ray_mapper.SetInputData(rays.GetOutput(0))
    ray_mapper.ScalarVisibilityOff()
    ray_actor = vtkActor()
    ray_actor.SetMapper(ray_mapper)
    ray_actor.GetProperty().SetColor(0.75, 0.75, 0.7)
    ray_actor.GetProperty().SetOpacity(0.35)
    renderer.AddActor(ray_actor)

    # Sign of the transverse Jacobian: blue before the fold, red after.
    sign = vtkLookupTable()
    sign.SetNumberOfTableValues(2)
    sign.SetTableValue(0, 0.85, 0.25, 0.2, 1.0)
    sign.SetTableValue(1, 0.25, 0.5, 0.9, 1.0)
    sign.SetTableRange(-1e-12, 1e-12)
    sign.Build()
    front_actor = vtkActor()
    front_actor.SetMapper(mapper_for(wavefronts, "TransverseJacobian", (-1e-12, 1e-12), sign))
    front_actor.GetProperty().SetOpacity(0.8)
    renderer.AddActor(front_actor)

    caustic_mapper = mapper_for(caustic, "ArcLength", (4.5, 7.5))
    caustic_actor = vtkActor()
    caustic_actor.SetMapper(caustic_mapper)
    caustic_actor.GetProperty().SetOpacity(0.5)
    renderer.AddActor(caustic_actor)

    eye = vtkSphereSource()
    eye.SetCenter(OBSERVER)
    eye.SetRadius(0.06)
    eye_mapper = vtkPolyDataMapper()
    eye_mapper.SetInputConnection(eye.GetOutputPort())
    eye_actor = vtkActor()
    eye_actor.SetMapper(eye_mapper)
    eye_actor.GetProperty().SetColor(1.0, 1.0, 1.0)
    renderer.AddActor(eye_actor)

    bar = vtkScalarBarActor()
    bar.SetLookupTable(caustic_mapper.GetLookupTable())
    bar.SetTitle("Caustic: arc length")
    bar.SetNumberOfLabels(4)
    bar.SetWidth(0.08)
    bar.SetPosition(0.9, 0.15)
    renderer.AddActor2D(bar)

    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(1.4, -0.1, 0.0)
    camera.SetPosition(-0.6, -3.6, 2.2)
    camera.SetViewUp(0, 0, 1)
    camera.SetViewAngle(40)
    renderer.ResetCameraClippingRange()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(1000, 640)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print(f"exponential_map: {caustic.GetNumberOfPoints()} caustic points "
          f"({caustic.GetNumberOfPolys()} triangles), {wavefronts.GetNumberOfPolys()} wavefront triangles "
          f"-> {args.output}")


if __name__ == "__main__":
    main()
