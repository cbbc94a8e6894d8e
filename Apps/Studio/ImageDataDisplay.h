/**
 * @file ImageDataDisplay.h
 * @brief The outside view's display of a vtkImageData (a field or distance
 * sampled on a grid): a slice, an isosurface or ellipsoid glyphs of a
 * tensor array, and level lines of the colouring on the slice.
 */
#ifndef RiemannStudio_ImageDataDisplay_h
#define RiemannStudio_ImageDataDisplay_h

#include "OutputDisplay.h"

#include "vtkActor.h"
#include "vtkNew.h"

class vtkImageData;
class vtkPolyData;

namespace riemann
{
namespace studio
{
class ImageDataDisplay : public OutputDisplay
{
public:
  explicit ImageDataDisplay(vtkAssembly* parts);
  /// Representation, SliceNormal, SliceOffset, ContourValue, NumberOfContours.
  static std::vector<PropertySpec> Properties();
  void Show(vtkDataObject* data, const OutputLook& look, const nlohmann::json& settings,
    ColorScale coloring, vtkScalarBarActor* bar) override;

private:
  vtkNew<vtkActor> Surface;
  vtkNew<vtkActor> LevelLines;
};
}
}

#endif
