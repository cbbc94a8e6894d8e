#!/usr/bin/env python3
"""RiemannVTK demo: the paper's Gaussian bump, from inside and from outside.

An observer at (-2.5, 0, 0) looks along +x through the graph metric of
f = exp(-|p|^2 / (2 * 0.5^2)) (Novello, da Silva, Velho, "Design and
visualization of Riemannian metrics"). Rays leave the observer on a grid of
directions, unit speed in g, and are traced with RK4; the bump deflects the
rays that pass near it. The demo writes

  <output-dir>/inside.png   the inside view of the built-in default scene (the
                            paper's grid of bars warped by the bump), ray traced
                            per pixel on the GPU by vtkRiemannRayTracePass
  <output-dir>/bundle.vtp   the geodesics (ArcLength, Velocity, SpeedDrift, ...)
  <output-dir>/bundle.png   an offscreen VTK picture of the bundle

Run it with ./run.sh (which builds first and sets PYTHONPATH).
"""
import argparse
import math
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkTubeFilter
from vtkmodules.vtkFiltersSources import vtkLineSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL backend)
import vtkmodules.vtkRenderingFreeType  # noqa: F401
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor

import riemann
from perceptual_colours import viridis

OBSERVER = (-2.5, 0.0, 0.0)


def ray_bundle(count, half_angle_degrees):
    """Seeds at the observer with directions on a count x count grid in a cone around +x."""
    tangent = math.tan(math.radians(half_angle_degrees))
    offsets = np.linspace(-tangent, tangent, count)
    directions = np.array([(1.0, u, w) for w in offsets for u in offsets])
    points = vtkPoints()
    points.SetDataTypeToDouble()
    for _ in directions:
        points.InsertNextPoint(OBSERVER)
    seeds = vtkPolyData()
    seeds.SetPoints(points)
    array = numpy_to_vtk(directions, deep=True)
    array.SetName("Direction")
    seeds.GetPointData().AddArray(array)
    return seeds


def add_deflection(lines):
    """Cell data `Deflection`: the angle (degrees) between each ray's first and last velocity."""
    velocity = vtk_to_numpy(lines.GetPointData().GetArray("Velocity"))
    angles = []
    ids = lines.GetLines()
    ids.InitTraversal()
    from vtkmodules.vtkCommonCore import vtkIdList
    cell = vtkIdList()
    while ids.GetNextCell(cell):
        first = velocity[cell.GetId(0)]
        last = velocity[cell.GetId(cell.GetNumberOfIds() - 1)]
        cosine = np.dot(first, last) / (np.linalg.norm(first) * np.linalg.norm(last))
        angles.append(math.degrees(math.acos(max(-1.0, min(1.0, cosine)))))
    array = numpy_to_vtk(np.array(angles), deep=True)
    array.SetName("Deflection")
    lines.GetCellData().AddArray(array)
    return max(angles)


def write_atomically(path, write):
    temporary = path + ".partial"
    write(temporary)
    os.replace(temporary, path)


def save_png(window, png_path):
    """The window's picture as a PNG, written whole or not at all."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()

    def write_png(path):
        writer = vtkPNGWriter()
        writer.SetFileName(path)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
    write_atomically(png_path, write_png)


def render(lines, max_deflection, png_path, size):
    renderer = vtkRenderer()
    renderer.SetBackground(0.08, 0.09, 0.12)
    renderer.SetBackground2(0.22, 0.24, 0.30)
    renderer.GradientBackgroundOn()

    tubes = vtkTubeFilter()
    tubes.SetInputData(lines)
    tubes.SetRadius(0.006)
    tubes.SetNumberOfSides(8)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(tubes.GetOutputPort())
    mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectColorArray("Deflection")
    mapper.SetScalarRange(0.0, max_deflection)
    # viridis (perceptual, colour-blind safe), as riemann-studio's default map.
    colours = viridis(0.0, max_deflection)
    mapper.SetLookupTable(colours)
    mapper.UseLookupTableScalarRangeOff()
    rays = vtkActor()
    rays.SetMapper(mapper)
    renderer.AddActor(rays)

    # The bump: a translucent sphere of radius sigma at its centre.
    sphere = vtkSphereSource()
    sphere.SetRadius(0.5)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(32)
    sphere_mapper = vtkPolyDataMapper()
    sphere_mapper.SetInputConnection(sphere.GetOutputPort())
    bump = vtkActor()
    bump.SetMapper(sphere_mapper)
    bump.GetProperty().SetColor(1.0, 0.85, 0.4)
    bump.GetProperty().SetOpacity(0.35)
    renderer.AddActor(bump)

    # The observer, and the x axis it looks along.
    eye = vtkSphereSource()
    eye.SetCenter(OBSERVER)
    eye.SetRadius(0.06)
    eye_mapper = vtkPolyDataMapper()
    eye_mapper.SetInputConnection(eye.GetOutputPort())
    eye_actor = vtkActor()
    eye_actor.SetMapper(eye_mapper)
    eye_actor.GetProperty().SetColor(1, 1, 1)
    renderer.AddActor(eye_actor)
    axis = vtkLineSource()
    axis.SetPoint1(OBSERVER)
    axis.SetPoint2(3.0, 0, 0)
    axis_mapper = vtkPolyDataMapper()
    axis_mapper.SetInputConnection(axis.GetOutputPort())
    axis_actor = vtkActor()
    axis_actor.SetMapper(axis_mapper)
    axis_actor.GetProperty().SetColor(0.6, 0.6, 0.6)
    renderer.AddActor(axis_actor)

    bar = vtkScalarBarActor()
    bar.SetLookupTable(colours)
    bar.SetTitle("Deflection (deg)")
    bar.SetNumberOfLabels(4)
    bar.SetWidth(0.08)
    bar.SetHeight(0.5)
    bar.SetPosition(0.9, 0.25)
    renderer.AddActor2D(bar)

    # Look from the side and above: the observer on the left, the rays
    # fanning out to the right, bent where they cross the bump.
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0.4, 0.0, 0.0)
    camera.SetPosition(0.4, -7.5, 4.0)
    camera.SetViewUp(0, 0, 1)
    camera.SetViewAngle(35)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(8)
    window.AddRenderer(renderer)
    window.SetSize(*size)
    window.Render()
    save_png(window, png_path)


def render_inside_view(metric, png_path, size):
    """The default scene (the paper's grid) seen through the metric, on the GPU."""
    scene = riemann.vtkRiemannScene()          # no definition: the built-in default scene
    trace = riemann.vtkRiemannRayTracePass()
    trace.SetMetric(metric)
    trace.SetScene(scene)
    renderer = vtkRenderer()
    renderer.SetPass(trace)
    scene.ApplyCamera(renderer.GetActiveCamera())
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(*size)
    window.Render()
    if trace.GetLastError():
        sys.exit("demo: " + trace.GetLastError())
    save_png(window, png_path)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--output-dir", default="demo-output")
    parser.add_argument("--rays", type=int, default=15, help="rays per side of the bundle (default 15)")
    parser.add_argument("--size", default="1200x800", help="picture size WxH (default 1200x800)")
    args = parser.parse_args()
    if not 2 <= args.rays <= 200:
        parser.error("--rays must be between 2 and 200")
    size = tuple(int(v) for v in args.size.lower().split("x"))

    data_dir = os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "Data"))
    metric = riemann.vtkRiemannMetric()
    if not metric.SetDefinitionFile(os.path.join(data_dir, "metrics", "gaussian-bump.json")):
        sys.exit("demo: " + metric.GetLastError())

    tracer = riemann.vtkRiemannGeodesicTracer()
    tracer.SetMetric(metric)
    tracer.SetInputData(ray_bundle(args.rays, 7.0))
    tracer.GetIntegrationSettings().SetIntegratorTypeToRungeKutta4()
    tracer.GetIntegrationSettings().SetInitialIntegrationStep(0.01)
    tracer.GetIntegrationSettings().SetMaximumPropagation(5.0)
    tracer.Update()
    lines = tracer.GetOutput()
    max_deflection = add_deflection(lines)
    drift = np.abs(vtk_to_numpy(lines.GetPointData().GetArray("SpeedDrift"))).max()

    os.makedirs(args.output_dir, exist_ok=True)
    vtp = os.path.join(args.output_dir, "bundle.vtp")
    png = os.path.join(args.output_dir, "bundle.png")

    def write_vtp(path):
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(path)
        writer.SetInputData(lines)
        if not writer.Write():
            raise RuntimeError("could not write " + path)
    write_atomically(vtp, write_vtp)
    render(lines, max_deflection, png, size)
    inside = os.path.join(args.output_dir, "inside.png")
    render_inside_view(metric, inside, size)
    print(f"demo: {lines.GetNumberOfLines()} geodesics of the Gaussian-bump graph metric, "
          f"{lines.GetNumberOfPoints()} points, max deflection {max_deflection:.1f} deg, "
          f"max |g(v,v)-1| {drift:.1e}")
    print(f"demo: wrote {inside}, {vtp} and {png}")


if __name__ == "__main__":
    main()
