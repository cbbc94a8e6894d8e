#!/usr/bin/env python3
"""Ordinary VTK actors seen through a metric, with the GPU render pass.

    actors_through_metric.py [--metric M.json] [--size 640x480] [--output actors.png]
                             [--cpu cpu.png]

A torus from vtkParametricFunctionSource coloured by its height through a
lookup table, and a sphere moved and scaled by a transform, are added to a
renderer as any VTK user would; vtkRiemannRayTracePass with UseRendererProps
on draws them as seen from inside the space with that metric (default: the
paper's two Gaussian bumps, Data/metrics/two-bumps.json), above a checker
floor of the scene, with a text overlay composed on top. --cpu also renders
the same actors with vtkRiemannCPURayTracer.AddActor for comparison. Run with
./run.sh's environment (PYTHONPATH=build/lib/python3/dist-packages, under an
X server).
"""
import argparse
import json
import os
import sys

from vtkmodules.vtkCommonComputationalGeometry import vtkParametricTorus
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersSources import vtkParametricFunctionSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow, vtkTextActor,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkImagingCore import vtkImageShiftScale
import vtkmodules.vtkRenderingFreeType  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import riemann
from perceptual_colours import viridis

# The scene around the actors: a checker floor, fog and the observer's light.
FLOOR_SCENE = {
    "camera": {"position": [0, 0.6, 4.5], "look_at": [0, -0.2, -1.0], "view_up": [0, 1, 0], "fov": 55},
    "integrator": {"method": "rk4", "step": 0.02, "max_steps": 1500, "max_length": 25},
    "background": [0.05, 0.05, 0.08],
    "fog": {"color": [0.05, 0.05, 0.08], "density": 0.03},
    "lighting": "observer",
    "objects": [{"type": "plane", "point": [0, -2, 0], "normal": [0, 1, 0],
                 "material": {"type": "checker", "color": [0.85, 0.85, 0.85],
                              "color2": [0.25, 0.25, 0.3], "size": 0.5}}],
}


def make_actors():
    """A torus coloured by z through the mapper's lookup table, and a transformed sphere."""
    torus = vtkParametricTorus()
    torus.SetRingRadius(1.0)
    torus.SetCrossSectionRadius(0.35)
    source = vtkParametricFunctionSource()
    source.SetParametricFunction(torus)
    source.SetUResolution(96)
    source.SetVResolution(32)
    source.SetScalarModeToZ()
    torus_mapper = vtkPolyDataMapper()
    torus_mapper.SetInputConnection(source.GetOutputPort())
    torus_mapper.SetScalarRange(-0.35, 0.35)
    torus_mapper.SetLookupTable(viridis(-0.35, 0.35))
    torus_mapper.UseLookupTableScalarRangeOff()
    torus_actor = vtkActor()
    torus_actor.SetMapper(torus_mapper)
    torus_actor.SetPosition(-0.9, -0.3, -1.5)
    torus_actor.RotateX(60)

    sphere = vtkSphereSource()
    sphere.SetThetaResolution(64)
    sphere.SetPhiResolution(32)
    sphere_mapper = vtkPolyDataMapper()
    sphere_mapper.SetInputConnection(sphere.GetOutputPort())
    transform = vtkTransform()
    transform.Translate(1.3, -0.6, -2.2)
    transform.Scale(1.2, 0.8, 1.2)
    sphere_actor = vtkActor()
    sphere_actor.SetMapper(sphere_mapper)
    sphere_actor.SetUserTransform(transform)
    sphere_actor.GetProperty().SetColor(0.95, 0.55, 0.2)
    return [torus_actor, sphere_actor]


def main():
    data = os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "Data"))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--metric", default=os.path.join(data, "metrics", "two-bumps.json"))
    parser.add_argument("--size", default="640x480")
    parser.add_argument("--output", default="actors.png")
    parser.add_argument("--cpu", help="also render the actors on the CPU into this PNG")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))

    metric = riemann.vtkRiemannMetric()
    if not metric.SetDefinitionFile(args.metric):
        sys.exit("actors_through_metric: " + metric.GetLastError())
    scene = riemann.vtkRiemannScene()
    if not scene.SetDefinition(json.dumps(FLOOR_SCENE)):
        sys.exit("actors_through_metric: " + scene.GetLastError())
    actors = make_actors()

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(width, height)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    for actor in actors:
        renderer.AddActor(actor)
    text = vtkTextActor()
    text.SetInput("VTK actors through two bumps")
    text.GetTextProperty().SetFontSize(18)
    text.SetPosition(10, 10)
    renderer.AddActor2D(text)

    rt = riemann.vtkRiemannRayTracePass()
    rt.SetMetric(metric)
    rt.SetScene(scene)
    rt.UseRendererPropsOn()
    renderer.SetPass(rt)
    scene.ApplyCamera(renderer.GetActiveCamera())
    window.Render()
    if rt.GetLastError():
        sys.exit("actors_through_metric: " + rt.GetLastError())
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print(f"{args.output}: {rt.GetNumberOfRenderedProps()} props drawn")

    if args.cpu:
        tracer = riemann.vtkRiemannCPURayTracer()
        tracer.SetMetric(metric)
        tracer.SetScene(scene)
        for actor in actors:
            tracer.AddActor(actor)
        tracer.SetCamera(renderer.GetActiveCamera())
        tracer.SetWidth(width)
        tracer.SetHeight(height)
        tracer.Update()
        to_bytes = vtkImageShiftScale()
        to_bytes.SetInputData(tracer.GetOutput())
        to_bytes.SetShift(0.5 / 255.0)  # (x + shift) * scale, truncated: rounds to the nearest byte
        to_bytes.SetScale(255.0)
        to_bytes.SetOutputScalarTypeToUnsignedChar()
        to_bytes.ClampOverflowOn()
        writer.SetInputConnection(to_bytes.GetOutputPort())
        writer.SetFileName(args.cpu)
        writer.Write()
        print(f"{args.cpu}: the CPU tracer's picture")


if __name__ == "__main__":
    main()
