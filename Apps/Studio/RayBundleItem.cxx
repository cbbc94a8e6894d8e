// The inside view's rays (vtkRiemannRayBundle), following the observer.
#include "PipelineItems.h"

#include "ColorMaps.h"
#include "InsideViewRays.h"

#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayBundle.h"
#include "vtkRiemannScene.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkCamera.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

namespace riemann
{
namespace studio
{
RayBundleItem::RayBundleItem(const QString& name)
  // Coloured by where each ray ends, as the inside view shows it.
  : PipelineItem(name, { { "SubgridResolution", 8 }, { "ColorArray", "EndColor" } })
{
  vtkNew<vtkPolyDataMapper> mapper;
  this->Rays->SetMapper(mapper);
  this->Rays->GetProperty()->SetLineWidth(1.5);
  this->Assembly->AddPart(this->Rays);
  this->UpdateDisplay();
}

std::vector<PropertySpec> RayBundleItem::Properties() const
{
  PropertySpec grid;
  grid.Key = "SubgridResolution";
  grid.Label = "Rays per side";
  grid.Type = PropertySpec::Integer;
  grid.Minimum = 1;
  grid.Maximum = 256;
  grid.Help = "N: the rays of an N x N grid of the inside view's pixels (its camera, its "
              "integration settings)";
  std::vector<PropertySpec> specs{ grid };
  for (const PropertySpec& spec : this->DisplayProperties())
  {
    specs.push_back(spec);
  }
  return specs;
}

vtkSmartPointer<vtkAlgorithm> RayBundleItem::MakeJob(const JobInputs& inputs) const
{
  auto bundle = vtkSmartPointer<vtkRiemannRayBundle>::New();
  SetUpInsideViewRays(bundle.Get(), inputs, inputs.Width, inputs.Height, true);
  bundle->SetSubgridResolution(this->Integer("SubgridResolution"));
  return bundle;
}

void RayBundleItem::UpdateDisplay()
{
  auto* rays = vtkPolyData::SafeDownCast(this->Result(0));
  if (rays)
  {
    vtkPolyDataMapper::SafeDownCast(this->Rays->GetMapper())->SetInputData(rays);
  }
  const double grey[3] = { 0.8, 0.8, 0.8 };
  ApplyColoring(this->Rays, rays, this->Coloring(this->Text("ColorArray"), this->Number("Opacity")),
    grey, this->ScalarBar());
  this->Rays->SetVisibility(rays != nullptr);
}

std::vector<std::string> RayBundleItem::PythonLines(const std::string& var) const
{
  return {
    var + " = riemann.vtkRiemannRayBundle()",
    var + ".SetMetric(metric)",
    var + ".SetScene(scene)",
    var + ".SetCamera(camera)",
    var + ".SetWidth(width)",
    var + ".SetHeight(height)",
    var + ".SetUseSceneSettings(use_scene_settings)",
    var + ".GetIntegrationSettings().DeepCopy(ray_settings)",
    var + ".SetSubgridResolution(" + std::to_string(this->Integer("SubgridResolution")) + ")",
  };
}
}
}
