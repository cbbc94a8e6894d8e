/**
 * @file ShownOutput.h
 * @brief What an item says about each thing it shows: its data type (which
 * picks the outside view's display, OutputDisplay.h) and its look when no
 * array colours it. The item says what is shown; the view decides how.
 */
#ifndef RiemannStudio_ShownOutput_h
#define RiemannStudio_ShownOutput_h

#include "vtkSmartPointer.h"

#include <array>
#include <string>

class vtkDataSet;
class vtkPolyData;

namespace riemann
{
namespace studio
{
struct OutputLook
{
  /// The output's data type ("vtkPolyData", "vtkImageData"): the display that shows it.
  std::string DataType = "vtkPolyData";
  /// Its colour when no array colours it.
  std::array<double, 3> Solid{ { 0.9, 0.9, 0.9 } };
  /// A factor on the item's Opacity (faint rays next to wavefronts).
  double OpacityScale = 1.0;
  /// Coloured by the item's ColorArray (markers keep their solid colour).
  bool FollowsColoring = true;
  /// The item's scalar bar shows this output's colouring.
  bool Legend = false;
  /// Lines' width in pixels.
  double LineWidth = 1.0;
  /// Vertices drawn as spheres of this size in pixels (0: VTK's points).
  double PointSize = 0.0;
  /// Lines drawn as tubes of this radius, a fraction of the data's size (0: lines).
  double TubeRadius = 0.0;
  /// A point vector array drawn as cones along it ("Forward": where an observer looks).
  std::string HeadingArray;
};

/// Look helpers: one output of `dataType` in `solid`, with the legend or without.
OutputLook LookOf(const std::string& dataType, const std::array<double, 3>& solid, bool legend);

/// The largest side of `data`'s bounds, at least 1: what tubes, cones and markers are sized by.
double LargestSide(vtkDataSet* data);

/// A sphere at `center` (a marker: the distance field's seed, a connection's end).
vtkSmartPointer<vtkPolyData> SphereMarker(const double center[3], double radius);
}
}

#endif
