/**
 * @file ItemDisplay.h
 * @brief What the outside view draws for one pipeline item: one display per
 * output the item shows (OutputDisplay.h, chosen by the output's data
 * type), in one assembly, and the item's scalar bar. The view owns it; the
 * item only holds settings and results.
 */
#ifndef RiemannStudio_ItemDisplay_h
#define RiemannStudio_ItemDisplay_h

#include "OutputDisplay.h"

#include "vtkAssembly.h"
#include "vtkNew.h"
#include "vtkScalarBarActor.h"

#include <memory>
#include <vector>

namespace riemann
{
namespace studio
{
class PipelineItem;

class ItemDisplay
{
public:
  /// The displays of `item`'s outputs (its Looks()), nothing shown yet.
  explicit ItemDisplay(const PipelineItem& item);
  ~ItemDisplay();
  /// Draw `item` as it is now: its shown outputs, display settings, colouring and visibility.
  void Show(const PipelineItem& item);
  /// Every actor of the item (for the renderer, picking and tests).
  vtkAssembly* Prop() const { return this->Parts; }
  /// The item's legend: shown when its ScalarBar setting is on and an array colours it.
  vtkScalarBarActor* ScalarBar() const { return this->Bar; }

  ItemDisplay(const ItemDisplay&) = delete;
  ItemDisplay& operator=(const ItemDisplay&) = delete;

private:
  vtkNew<vtkAssembly> Parts;
  vtkNew<vtkScalarBarActor> Bar;
  /// One per look of the item; null for a data type no display shows.
  std::vector<std::unique_ptr<OutputDisplay>> Outputs;
};
}
}

#endif
