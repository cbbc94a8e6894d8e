#include "vtkRiemannScene.h"

#include "vtkRiemannPictureSettings.h"

#include "RiemannPolyDataMesh.h"
#include "RiemannSceneParser.h"
#include "RiemannScene.h"

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <fstream>
#include <sstream>

vtkStandardNewMacro(vtkRiemannScene);

namespace
{
const riemann::Scene& DefaultSceneInstance()
{
  static const riemann::Scene scene = riemann::DefaultScene();
  return scene;
}
}

vtkRiemannScene::vtkRiemannScene() = default;
vtkRiemannScene::~vtkRiemannScene() = default;

bool vtkRiemannScene::Install(std::shared_ptr<const riemann::Scene> scene,
  const std::string& definition, const std::string& file)
{
  std::atomic_store(&this->Scene, std::move(scene));
  this->Definition = definition;
  this->DefinitionFile = file;
  this->LastError.clear();
  this->LastErrorPlace = riemann::JsonErrorPlace();
  this->Modified();
  return true;
}

void vtkRiemannScene::ShallowCopy(vtkRiemannScene* other)
{
  if (!other || other == this)
  {
    return;
  }
  // Without a definition the other scene is the default one: so is this.
  std::atomic_store(&this->Scene, std::atomic_load(&other->Scene));
  this->Definition = other->Definition;
  this->DefinitionFile = other->DefinitionFile;
  this->LastError.clear();
  this->LastErrorPlace = riemann::JsonErrorPlace();
  this->Modified();
}

bool vtkRiemannScene::SetDefinition(const char* json)
{
  if (!json)
  {
    this->LastError = "no definition given (null)";
    this->LastErrorPlace = riemann::JsonErrorPlace();
    return false;
  }
  try
  {
    riemann::Scene parsed = riemann::ParseScene(json, ".");
    riemann::LoadSceneMeshes(parsed); // VTK's readers: the core stays VTK-free
    auto scene = std::make_shared<const riemann::Scene>(std::move(parsed));
    return this->Install(std::move(scene), json, std::string());
  }
  catch (const riemann::JsonInputError& e)
  {
    this->LastError = e.what();
    this->LastErrorPlace = e.Place;
    return false;
  }
  catch (const std::exception& e)
  {
    this->LastError = e.what();
    this->LastErrorPlace = riemann::JsonErrorPlace();
    return false;
  }
}

bool vtkRiemannScene::SetDefinitionFile(const char* path)
{
  if (!path || !*path)
  {
    this->LastError = "no file name given";
    this->LastErrorPlace = riemann::JsonErrorPlace();
    return false;
  }
  try
  {
    riemann::Scene parsed = riemann::LoadSceneFile(path);
    riemann::LoadSceneMeshes(parsed);
    auto scene = std::make_shared<const riemann::Scene>(std::move(parsed));
    // Keep the text for GetDefinition() (LoadSceneFile has read and checked it).
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return this->Install(std::move(scene), text.str(), path);
  }
  catch (const riemann::JsonInputError& e)
  {
    this->LastError = e.what();
    this->LastErrorPlace = e.Place;
    return false;
  }
  catch (const std::exception& e)
  {
    this->LastError = e.what();
    this->LastErrorPlace = riemann::JsonErrorPlace();
    return false;
  }
}

std::shared_ptr<const riemann::Scene> vtkRiemannScene::GetSceneSnapshot() const
{
  auto scene = std::atomic_load(&this->Scene);
  if (!scene)
  {
    // Aliasing constructor: shares nothing, points at the static default.
    scene = std::shared_ptr<const riemann::Scene>(
      std::shared_ptr<const riemann::Scene>(), &DefaultSceneInstance());
  }
  return scene;
}

const riemann::Scene& vtkRiemannScene::GetScene() const
{
  const auto scene = std::atomic_load(&this->Scene);
  return scene ? *scene : DefaultSceneInstance();
}

bool vtkRiemannScene::HasDefinition() const
{
  return std::atomic_load(&this->Scene) != nullptr;
}

int vtkRiemannScene::GetNumberOfObjects() const
{
  return static_cast<int>(this->GetScene().Objects.size());
}

bool vtkRiemannScene::HasMetricDefinition() const
{
  return !this->GetScene().MetricDefinition.empty();
}

std::string vtkRiemannScene::GetMetricDefinition() const
{
  return this->GetScene().MetricDefinition;
}

bool vtkRiemannScene::HasCamera() const
{
  return this->GetScene().HasCamera;
}

namespace
{
void CopyCamera(const riemann::CameraSettings& c, vtkCamera* camera)
{
  camera->SetPosition(c.Position.x(), c.Position.y(), c.Position.z());
  camera->SetFocalPoint(c.LookAt.x(), c.LookAt.y(), c.LookAt.z());
  camera->SetViewUp(c.ViewUp.x(), c.ViewUp.y(), c.ViewUp.z());
  camera->SetUseHorizontalViewAngle(false);
  camera->SetViewAngle(c.ViewAngle);
}
} // namespace

bool vtkRiemannScene::ApplyCamera(vtkCamera* camera) const
{
  const riemann::Scene& scene = this->GetScene();
  if (!camera || !scene.HasCamera)
  {
    return false;
  }
  CopyCamera(scene.Camera, camera);
  return true;
}

void vtkRiemannScene::ApplyDefaultCamera(vtkCamera* camera)
{
  if (camera)
  {
    vtkNew<vtkRiemannPictureSettings>()->ApplyTo(camera);
  }
}

void vtkRiemannScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const riemann::Scene& scene = this->GetScene();
  os << indent << "Definition: " << (this->HasDefinition() ? "(set)" : "(none: default scene)")
     << "\n";
  os << indent << "DefinitionFile: " << this->DefinitionFile << "\n";
  os << indent << "NumberOfObjects: " << scene.Objects.size() << "\n";
  os << indent << "Background: " << scene.Background.transpose() << "\n";
  os << indent << "EnvironmentImage: " << scene.EnvironmentImage << "\n";
  os << indent << "Fog: " << scene.FogColor.transpose() << " density " << scene.FogDensity << "\n";
  os << indent << "ObserverLight: " << (scene.ObserverLight ? "on" : "off") << "\n";
  os << indent << "HasCamera: " << (scene.HasCamera ? "yes" : "no") << "\n";
  os << indent << "HasMetricDefinition: " << (scene.MetricDefinition.empty() ? "no" : "yes")
     << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
}
