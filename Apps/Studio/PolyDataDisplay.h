/**
 * @file PolyDataDisplay.h
 * @brief The outside view's display of a vtkPolyData: its vertices, lines
 * and polygons in one actor, coloured as the item says, lines as tubes and
 * a vector array as cones where the item's look asks for them.
 */
#ifndef RiemannStudio_PolyDataDisplay_h
#define RiemannStudio_PolyDataDisplay_h

#include "OutputDisplay.h"

#include "vtkActor.h"
#include "vtkGlyph3D.h"
#include "vtkMaskPoints.h"
#include "vtkNew.h"
#include "vtkTubeFilter.h"

namespace riemann
{
namespace studio
{
class PolyDataDisplay : public OutputDisplay
{
public:
  explicit PolyDataDisplay(vtkAssembly* parts);
  /// Its own settings: none (the colouring is every display's).
  static std::vector<PropertySpec> Properties() { return {}; }
  void Show(vtkDataObject* data, const OutputLook& look, const nlohmann::json& settings,
    ColorScale coloring, vtkScalarBarActor* bar) override;

private:
  vtkNew<vtkActor> Surface;
  vtkNew<vtkTubeFilter> Tubes;
  /// Every k-th point carries a cone: a few along the whole path, however many frames it has.
  vtkNew<vtkMaskPoints> HeadingPoints;
  vtkNew<vtkGlyph3D> Heading;
  vtkNew<vtkActor> Cones;
};
}
}

#endif
