// The inside view's rays (vtkRiemannRayBundle), following the observer.
#include "PipelineItems.h"

#include "ColorMaps.h"
#include "DeclaredProperties.h"
#include "InsideViewRays.h"
#include "SettingValues.h"
#include "vtkRiemannRayBundleSettingAccess.h"

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
namespace
{
namespace bundle = riemann::declared::vtkRiemannRayBundle;

/// The bundle's settings the inside view gives (its size, projection and
/// whether the scene's settings apply), not the item.
const std::vector<std::string>& InsideViewSettings()
{
  static const std::vector<std::string> names{ "Width", "Height", "Projection", "UseSceneSettings" };
  return names;
}

/// A new item: the declared sub-grid, coloured by where each ray ends, as the inside view shows it.
nlohmann::json RayBundleDefaults()
{
  vtkNew<vtkRiemannRayBundle> filter;
  nlohmann::json values =
    DeclaredDefaults(riemann::settings::SettingValues(filter), InsideViewSettings());
  values["ColorArray"] = "EndColor";
  return values;
}
}

RayBundleItem::RayBundleItem(const QString& name)
  : PipelineItem(name, RayBundleDefaults())
{
  vtkNew<vtkPolyDataMapper> mapper;
  this->Rays->SetMapper(mapper);
  this->Rays->GetProperty()->SetLineWidth(1.5);
  this->Assembly->AddPart(this->Rays);
  this->UpdateDisplay();
}

std::vector<PropertySpec> RayBundleItem::Properties() const
{
  std::vector<PropertySpec> specs = DeclaredPropertySpecs(bundle::Settings, InsideViewSettings());
  for (const PropertySpec& spec : this->DisplayProperties())
  {
    specs.push_back(spec);
  }
  return specs;
}

vtkSmartPointer<vtkAlgorithm> RayBundleItem::MakeJob(const JobInputs& inputs) const
{
  auto job = vtkSmartPointer<vtkRiemannRayBundle>::New();
  SetUpInsideViewRays(job.Get(), inputs, inputs.Width, inputs.Height, true);
  riemann::settings::ApplySettings(job, this->Settings());
  return job;
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
  // The inside view's size, scene, camera and ray settings, then the item's own.
  std::vector<std::string> lines{
    var + " = riemann.vtkRiemannRayBundle()",
    var + ".SetMetric(metric)",
    var + ".SetScene(scene)",
    var + ".SetCamera(camera)",
    var + ".SetWidth(width)",
    var + ".SetHeight(height)",
    var + ".SetUseSceneSettings(use_scene_settings)",
    var + ".GetIntegrationSettings().DeepCopy(ray_settings)",
  };
  for (const std::string& line : riemann::SettingPythonLines(bundle::Settings, var, this->Settings()))
  {
    lines.push_back(line);
  }
  return lines;
}
}
}
