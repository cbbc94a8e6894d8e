// The inside view's rays (vtkRiemannRayBundle), following the observer.
#include "PipelineItems.h"

#include "DeclaredProperties.h"
#include "InsideViewRays.h"
#include "SettingValues.h"
#include "vtkRiemannRayBundleSettingAccess.h"

#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayBundle.h"
#include "vtkRiemannScene.h"

#include "vtkCamera.h"
#include "vtkPolyData.h"

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

/// Grey lines, as the inside view's rays, coloured by where they end.
OutputLook RayBundleLook()
{
  OutputLook look = LookOf("vtkPolyData", { { 0.8, 0.8, 0.8 } }, true);
  look.LineWidth = 1.5;
  return look;
}
}

RayBundleItem::RayBundleItem(const QString& name)
  : PipelineItem(name, RayBundleDefaults(), { RayBundleLook() })
{
}

std::vector<PropertySpec> RayBundleItem::ItemProperties() const
{
  return DeclaredPropertySpecs(bundle::Settings, InsideViewSettings());
}

vtkSmartPointer<vtkAlgorithm> RayBundleItem::MakeJob(const JobInputs& inputs) const
{
  auto job = vtkSmartPointer<vtkRiemannRayBundle>::New();
  SetUpInsideViewRays(job.Get(), inputs, inputs.Width, inputs.Height, true);
  riemann::settings::ApplySettings(job, this->Settings());
  return job;
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
