#include "ItemDisplay.h"

#include "PipelineItem.h"

#include "vtkDataObject.h"

namespace riemann
{
namespace studio
{
ItemDisplay::ItemDisplay(const PipelineItem& item)
{
  this->Bar->SetVisibility(false);
  this->Bar->SetNumberOfLabels(5);
  this->Bar->SetPosition(0.88, 0.1);
  this->Bar->SetWidth(0.08);
  this->Bar->SetHeight(0.8);
  for (const OutputLook& look : item.Looks())
  {
    this->Outputs.push_back(MakeOutputDisplay(look.DataType, this->Parts));
  }
}

ItemDisplay::~ItemDisplay() = default;

void ItemDisplay::Show(const PipelineItem& item)
{
  const std::vector<vtkSmartPointer<vtkDataObject>> shown = item.ShownData();
  const std::vector<OutputLook>& looks = item.Looks();
  const ColorScale coloring = item.CurrentColoring();
  this->Bar->SetVisibility(false);
  for (std::size_t i = 0; i < this->Outputs.size(); ++i)
  {
    if (this->Outputs[i])
    {
      vtkDataObject* data = i < shown.size() ? shown[i].Get() : nullptr;
      this->Outputs[i]->Show(data, looks[i], item.Settings(), coloring,
        looks[i].Legend ? this->Bar.Get() : nullptr);
    }
  }
  this->Parts->SetVisibility(item.IsVisible());
  // A hidden item's legend goes with it; it comes back with the colouring.
  if (!item.IsVisible())
  {
    this->Bar->SetVisibility(false);
  }
}
}
}
