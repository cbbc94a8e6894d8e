"""Writes Data/meshes/torus.vtp: a torus from VTK's parametric sources with an
"Elevation" point array, tilted 65 degrees about x, the mesh of Data/scenes/mesh-two-bumps.json.
Run with /usr/bin/python3 (Debian's VTK bindings) from the repository root."""
from vtkmodules.vtkCommonComputationalGeometry import vtkParametricTorus
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import vtkElevationFilter, vtkTriangleFilter
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import vtkParametricFunctionSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

torus = vtkParametricTorus()
torus.SetRingRadius(1.3)
torus.SetCrossSectionRadius(0.45)
source = vtkParametricFunctionSource()
source.SetParametricFunction(torus)
source.SetUResolution(160)
source.SetVResolution(48)
source.GenerateTextureCoordinatesOff()
triangles = vtkTriangleFilter()
triangles.SetInputConnection(source.GetOutputPort())
# Tilted 65 degrees about x: the ring runs through the bumps at z = 0.
tilt = vtkTransform()
tilt.RotateX(65)
tilted = vtkTransformPolyDataFilter()
tilted.SetTransform(tilt)
tilted.SetInputConnection(triangles.GetOutputPort())
elevation = vtkElevationFilter()
elevation.SetInputConnection(tilted.GetOutputPort())
elevation.SetLowPoint(0, -1.75, 0)
elevation.SetHighPoint(0, 1.75, 0)
elevation.Update()
mesh = elevation.GetOutput()
mesh.GetPointData().GetScalars().SetName("Elevation")
writer = vtkXMLPolyDataWriter()
writer.SetInputData(mesh)
writer.SetFileName("Data/meshes/torus.vtp")
writer.SetDataModeToBinary()
writer.SetCompressorTypeToZLib()
writer.Write()
print(mesh.GetNumberOfPoints(), "points,", mesh.GetNumberOfPolys(), "triangles")
