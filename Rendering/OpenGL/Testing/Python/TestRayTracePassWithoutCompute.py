"""vtkRiemannRayTracePass in a context without compute shaders.

Mesa is asked for an OpenGL 3.3 context without GL_ARB_compute_shader and
GL_ARB_shader_image_load_store (MESA_GL_VERSION_OVERRIDE,
MESA_EXTENSION_OVERRIDE; the script runs itself again with them): GPUPath
Auto then takes the fragment path and draws the view, and GPUPath Compute
is an error that names the context's version, with the view red. On a
renderer that is not Mesa the overrides do nothing, and the test says so
and passes.

Run by ctest under xvfb-run with /usr/bin/python3 and PYTHONPATH set to the
build tree's package folder (see cmake/RiemannTesting.cmake).
"""

import os
import subprocess
import sys

OVERRIDES = {
    "MESA_GL_VERSION_OVERRIDE": "3.3",
    "MESA_EXTENSION_OVERRIDE": "-GL_ARB_compute_shader -GL_ARB_shader_image_load_store",
}
if any(os.environ.get(k) != v for k, v in OVERRIDES.items()):
    sys.exit(subprocess.call([sys.executable, __file__], env=dict(os.environ, **OVERRIDES)))

import riemann
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


metric = riemann.vtkRiemannMetric()
check(metric.SetDefinition('{"type": "euclidean"}'), metric.GetLastError())
scene = riemann.vtkRiemannScene()
check(scene.SetDefinition('{"background": [0.4, 0.2, 0.0], "objects": []}'), scene.GetLastError())
rt = riemann.vtkRiemannRayTracePass()
rt.SetMetric(metric)
rt.SetScene(scene)
errors = []
rt.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(obj.GetLastError()))
renderer = vtkRenderer()
renderer.SetPass(rt)
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(16, 12)
window.AddRenderer(renderer)


def centre():
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ShouldRerenderOff()
    grab.Update()
    scalars = grab.GetOutput().GetPointData().GetScalars()
    return tuple(int(scalars.GetComponent(6 * 16 + 8, c)) for c in range(3))


picture = centre()
capabilities = window.ReportCapabilities()
if "Mesa" not in capabilities:
    print("not Mesa: the overrides do not apply; nothing to check")
    sys.exit(0)
check("OpenGL version string:  3.3" in capabilities, "Mesa gave OpenGL 3.3")
check(rt.GetLastGPUPath() == riemann.vtkRiemannRayTracePass.FRAGMENT,
      "Auto took %s" % rt.GetGPUPathAsString(rt.GetLastGPUPath()))
check(picture == (102, 51, 0), "the fragment path drew the background, %s" % (picture,))
check(not errors, "no error on Auto: %s" % errors)

rt.SetGPUPathToCompute()
picture = centre()
check(len(errors) == 1, "one error for GPUPath Compute: %s" % errors)
check("needs OpenGL 4.3" in rt.GetLastError() and "3.3" in rt.GetLastError(), rt.GetLastError())
check(picture == (255, 0, 0), "the view is red, %s" % (picture,))

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("TestRayTracePassWithoutCompute.py: all checks passed")
