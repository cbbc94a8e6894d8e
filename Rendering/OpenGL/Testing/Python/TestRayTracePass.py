"""vtkRiemannRayTracePass from Python: render a small inside view.

Euclidean space and one solid sphere on a plain background: the centre pixel
is the sphere's colour and a corner the background's (colours that are exact
in 8 bits). Then the Gaussian bump of the paper with the same program
(a new amplitude is a uniform), a captured hit point read back as numbers,
the view traced with one ray per 4 x 4 pixels, both GPU paths (the same
picture) and a progressively refined still frame (the whole frame's).

Run by ctest under xvfb-run with /usr/bin/python3 and PYTHONPATH set to the
build tree's package folder (see cmake/RiemannTesting.cmake).
"""

import math
import sys

import riemann
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter

WIDTH, HEIGHT = 64, 48

SCENE = """{
  "background": [0.4, 0.2, 0.0],
  "integrator": {"method": "rk4", "step": 0.25, "max_steps": 200, "max_length": 12},
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
               "material": {"type": "solid", "color": [0.2, 0.6, 1.0]}}]
}"""

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


metric = riemann.vtkRiemannMetric()
check(metric.SetDefinition('{"type": "euclidean"}'), metric.GetLastError())
scene = riemann.vtkRiemannScene()
check(scene.SetDefinition(SCENE), scene.GetLastError())
check(scene.HasDefinition() and scene.GetNumberOfObjects() == 1, "the scene has one object")

rt = riemann.vtkRiemannRayTracePass()
rt.SetMetric(metric)
rt.SetScene(scene)
rt.CaptureHitsOn()

errors = []
rt.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(obj.GetLastError()))

renderer = vtkRenderer()
renderer.SetPass(rt)
camera = renderer.GetActiveCamera()
camera.SetPosition(0, 0, 5)
camera.SetFocalPoint(0, 0, 0)
camera.SetViewUp(0, 1, 0)
camera.SetViewAngle(30)

window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetMultiSamples(0)
window.SetSize(WIDTH, HEIGHT)
window.AddRenderer(renderer)


def render():
    """Render; the RGB pixels, row 0 at the bottom."""
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ShouldRerenderOff()
    grab.Update()
    return grab.GetOutput().GetPointData().GetScalars()


def pixel(pixels, column, row):
    i = row * WIDTH + column
    return tuple(int(pixels.GetComponent(i, c)) for c in range(3))


pixels = render()
check(not errors, "no VTK error: %s" % errors)
check(rt.GetLastError() == "", "GetLastError() is empty: %r" % rt.GetLastError())
check(pixel(pixels, 32, 24) == (51, 153, 255), "centre pixel %s is the sphere's colour" % (pixel(pixels, 32, 24),))
check(pixel(pixels, 0, 0) == (102, 51, 0), "corner pixel %s is the background" % (pixel(pixels, 0, 0),))

# The hit of the centre pixel: on the unit sphere, about 4 from the eye.
hits = rt.GetHitImage()
check(rt.GetHitImageWidth() == WIDTH and rt.GetHitImageHeight() == HEIGHT, "hit image size")
x, y, z, s = hits.GetTuple4(24 * WIDTH + 32)
check(abs(math.sqrt(x * x + y * y + z * z) - 1.0) < 1e-4, "centre hit (%g, %g, %g) on the sphere" % (x, y, z))
check(abs(s - (5.0 - z)) < 1e-3 and s > 3.9, "centre hit arc length %g" % s)
x, y, z, s = hits.GetTuple4(0)
check(s == -1.0, "corner ray has no hit (%g)" % s)

# A Gaussian bump: new structure (one compile), then a new amplitude (none).
bump = '{"type": "graph", "gaussians": [{"amplitude": %g, "center": [0, 0, 2], "sigma": 0.6}]}'
check(metric.SetDefinition(bump % 0.5), metric.GetLastError())
render()
compilations = rt.GetNumberOfShaderCompilations()
check(metric.SetDefinition(bump % 1.2), metric.GetLastError())
render()
check(rt.GetNumberOfShaderCompilations() == compilations, "a new amplitude does not recompile")
check(not errors, "no VTK error: %s" % errors)

# Fewer rays (one per 4 x 4 pixels), as while the camera moves: the centre and
# the corners keep their colours, the outline is blended.
check(metric.SetDefinition('{"type": "euclidean"}'), metric.GetLastError())
full = render()
rt.SetImageSampleDistance(4)
reduced = render()
check(rt.GetLastImageSampleDistance() == 4.0, "traced at distance %g" % rt.GetLastImageSampleDistance())
check(pixel(reduced, 32, 24) == pixel(full, 32, 24) and pixel(reduced, 0, 0) == pixel(full, 0, 0),
      "the reduced view keeps the sphere's and the background's colours")
colours = {pixel(reduced, c, r) for r in range(HEIGHT) for c in range(WIDTH)}
check(len(colours) > 4, "the reduced view is magnified (%d colours)" % len(colours))
rt.SetImageSampleDistance(1)
check(rt.GetAutoAdjustSampleDistances() and rt.GetMaximumImageSampleDistance() == 10.0,
      "interaction adjusts the distance, up to 10, by default")
check(not errors, "no VTK error: %s" % errors)

# Both GPU paths from Python: the same picture; Auto takes compute on llvmpipe.
check(rt.GetGPUPath() == riemann.vtkRiemannRayTracePass.AUTO, "GPUPath is Auto by default")
check(rt.GetLastGPUPath() == riemann.vtkRiemannRayTracePass.COMPUTE,
      "Auto took %s" % rt.GetGPUPathAsString(rt.GetLastGPUPath()))
rt.SetGPUPathToFragment()
fragment = render()
rt.SetGPUPathToCompute()
compute = render()
same = all(pixel(fragment, c, r) == pixel(compute, c, r) for r in range(HEIGHT) for c in range(WIDTH))
check(same, "the fragment and the compute path draw the same picture")
# Progressive still frames: a coarse picture first, then every ray once.
rt.ProgressiveRefinementOn()
rt.SetRefinementSeconds(0.001)
renderer.GetActiveCamera().Azimuth(0.5)
last = render()
renders = 1
while not rt.GetRefinementComplete() and renders < 500:
    last = render()
    renders += 1
check(rt.GetRefinementComplete() and renders > 1, "refined in %d renders" % renders)
rt.ProgressiveRefinementOff()
whole = render()
same = all(pixel(last, c, r) == pixel(whole, c, r) for r in range(HEIGHT) for c in range(WIDTH))
check(same, "the refined picture is the whole frame's")
check(not errors, "no VTK error: %s" % errors)

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("TestRayTracePass.py: all checks passed")
