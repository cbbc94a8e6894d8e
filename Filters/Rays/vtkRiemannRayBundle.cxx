#include "vtkRiemannRayBundle.h"

#include "ObserverCamera.h"
#include "RiemannRayBundleDeclaration.h"
#include "RiemannEmbreeMeshIntersector.h"
#include "RiemannRay.h"
#include "RiemannScene.h"
#include "RiemannShading.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannNewArray.h"
#include "vtkRiemannObserverSettings.h"
#include "vtkRiemannScene.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkRiemannRayBundle);
vtkCxxSetObjectMacro(vtkRiemannRayBundle, Scene, vtkRiemannScene);
vtkCxxSetObjectMacro(vtkRiemannRayBundle, Camera, vtkCamera);

namespace
{
/// The declared settings (a name of its own: unity batches join this file with the others').
namespace BundleDeclared = riemann::declared::vtkRiemannRayBundle;
}

vtkRiemannRayBundle::vtkRiemannRayBundle()
  : Width(static_cast<int>(BundleDeclared::Default::Width))
  , Height(static_cast<int>(BundleDeclared::Default::Height))
  , Projection(BundleDeclared::Default::Projection)
  , SubgridResolution(static_cast<int>(BundleDeclared::Default::SubgridResolution))
  , UseSceneSettings(BundleDeclared::Default::UseSceneSettings)
{
  this->SetNumberOfDataPorts(0);
  vtkRiemannSetRayDefaults(this->IntegrationSettings);
}

vtkRiemannRayBundle::~vtkRiemannRayBundle()
{
  this->SetScene(nullptr);
  this->SetCamera(nullptr);
}

int vtkRiemannRayBundle::FillDataPortInformation(int, vtkInformation*)
{
  return 1;
}

vtkMTimeType vtkRiemannRayBundle::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  for (vtkObject* o :
    { static_cast<vtkObject*>(this->Scene), static_cast<vtkObject*>(this->Camera) })
  {
    if (o)
    {
      time = std::max(time, o->GetMTime());
    }
  }
  return time;
}

namespace
{
using Pixel = std::pair<int, int>;

/// Step 2 of RequestData: every ray of the bundle traced from the eye through
/// its pixel in parallel, stopping at the scene's objects and, through
/// Embree, its meshes (`meshes` null when it has none).
std::vector<riemann::RayPath> TraceRays(const riemann::Metric& metric, const riemann::Scene& scene,
  const riemann::ObserverCamera& camera, const riemann::Vec3& eye, const riemann::RaySettings& rays,
  const std::vector<Pixel>& pixels, int width, int height,
  const riemann::EmbreeMeshIntersector* meshes)
{
  std::vector<riemann::RayPath> paths(pixels.size());
  // Ranges of at least 64 pixels, traced PacketWidth rays at a time (TBB's
  // automatic partitioner would hand out single pixels).
  vtkSMPTools::For(0, static_cast<vtkIdType>(pixels.size()), 8 * riemann::PacketWidth,
    [&](vtkIdType first, vtkIdType last)
    {
      std::vector<riemann::Vec3> velocities;
      for (vtkIdType k = first; k < last; ++k)
      {
        velocities.push_back(
          camera.PixelDirection(pixels[k].first, pixels[k].second, width, height));
      }
      riemann::TraceRays(metric, scene, eye, velocities.data(), static_cast<int>(last - first),
        rays, paths.data() + first, true, meshes);
    });
  return paths;
}

/// Step 3: one polyline per ray with ArcLength per point, and per line
/// PixelIndex, Hit, HitPosition (NaN for a miss), EndColor (the surface's
/// colour, or the background), Length and ReasonForTermination.
void BuildOutput(const std::vector<riemann::RayPath>& paths, const std::vector<Pixel>& pixels,
  const riemann::Scene& scene, vtkPolyData* output)
{
  vtkIdType pointCount = 0;
  for (const riemann::RayPath& path : paths)
  {
    pointCount += static_cast<vtkIdType>(path.Points.size());
  }
  const vtkIdType lineCount = static_cast<vtkIdType>(paths.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(pointCount);
  vtkNew<vtkCellArray> lines;
  lines->AllocateExact(lineCount, pointCount);
  auto arcLength = vtkRiemannNewArray<vtkDoubleArray>("ArcLength", 1, pointCount);
  auto pixelIndex = vtkRiemannNewArray<vtkIntArray>("PixelIndex", 2, lineCount);
  auto hit = vtkRiemannNewArray<vtkIntArray>("Hit", 1, lineCount);
  auto hitPosition = vtkRiemannNewArray<vtkDoubleArray>("HitPosition", 3, lineCount);
  auto endColor = vtkRiemannNewArray<vtkUnsignedCharArray>("EndColor", 3, lineCount);
  auto length = vtkRiemannNewArray<vtkDoubleArray>("Length", 1, lineCount);
  auto reason = vtkRiemannNewArray<vtkIntArray>("ReasonForTermination", 1, lineCount);

  vtkIdType next = 0;
  std::vector<vtkIdType> ids;
  for (vtkIdType k = 0; k < lineCount; ++k)
  {
    const riemann::RayPath& path = paths[k];
    ids.resize(path.Points.size());
    for (size_t i = 0; i < path.Points.size(); ++i, ++next)
    {
      ids[i] = next;
      points->SetPoint(next, path.Points[i].data());
      arcLength->SetValue(next, path.ArcLength[i]);
    }
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    pixelIndex->SetTypedComponent(k, 0, pixels[k].first);
    pixelIndex->SetTypedComponent(k, 1, pixels[k].second);
    hit->SetValue(k, path.Hit ? 1 : 0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const riemann::Vec3 position = path.Hit ? path.HitInfo.Position : riemann::Vec3(nan, nan, nan);
    hitPosition->SetTypedTuple(k, position.data());
    const riemann::Vec3 color =
      path.Hit ? riemann::SurfaceColor(scene, path.HitInfo) : scene.Background;
    for (int c = 0; c < 3; ++c)
    {
      endColor->SetTypedComponent(
        k, c, static_cast<unsigned char>(std::lround(255.0 * std::clamp(color[c], 0.0, 1.0))));
    }
    length->SetValue(k, path.Length);
    reason->SetValue(k, path.Reason);
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetPointData()->AddArray(arcLength);
  for (vtkDataArray* array :
    std::initializer_list<vtkDataArray*>{ pixelIndex, hit, hitPosition, endColor, length, reason })
  {
    output->GetCellData()->AddArray(array);
  }
  output->GetCellData()->SetScalars(endColor);
}
} // namespace

int vtkRiemannRayBundle::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Any piece can be traced alone: a share of the pixels.
  outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

// RequestData as named steps: the scene, camera and meshes -> SelectPixels
// and PieceShare -> TraceRays -> BuildOutput.
int vtkRiemannRayBundle::RequestData(
  vtkInformation* request, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  const std::shared_ptr<const riemann::Metric> metric = this->CheckMetricAndSettings();
  if (!metric)
  {
    return 1;
  }
  const std::shared_ptr<const riemann::Scene> scene = this->Scene
    ? this->Scene->GetSceneSnapshot()
    : std::make_shared<const riemann::Scene>(riemann::DefaultScene());

  // Step 1: the camera, projection and integration follow the pass's rules;
  // mesh objects (the CPU tracer's) stop the rays here too, through Embree.
  const riemann::CameraSettings settings =
    vtkRiemannCameraSettings(this->Camera, static_cast<double>(this->Width) / this->Height,
      scene->HasCamera ? scene->Camera : riemann::DefaultScene().Camera,
      vtkRiemannResolveProjection(this->UseSceneSettings, *scene, this->Projection));
  std::unique_ptr<riemann::ObserverCamera> camera;
  try
  {
    camera = std::make_unique<riemann::ObserverCamera>(*metric, settings);
  }
  catch (const std::runtime_error& e)
  {
    this->ReportError(std::string("Bad camera: ") + e.what());
    return 1;
  }
  const riemann::RaySettings rays =
    vtkRiemannResolveRaySettings(this->UseSceneSettings, *scene, this->IntegrationSettings);
  std::unique_ptr<riemann::EmbreeMeshIntersector> meshes;
  if (scene->HasMeshes())
  {
    try
    {
      meshes = std::make_unique<riemann::EmbreeMeshIntersector>(*scene);
    }
    catch (const std::runtime_error& e)
    {
      this->ReportError(std::string("The scene's meshes: ") + e.what());
      return 1;
    }
  }

  if (!this->CheckSizes(rays))
  {
    return 1;
  }
  std::vector<Pixel> pixels;
  this->SelectPixels(pixels);
  // This piece's share of the pixels (all of them without a piece request).
  vtkIdType first = 0;
  vtkIdType last = 0;
  PieceShare(request, outputVector, static_cast<vtkIdType>(pixels.size()), first, last);
  pixels.erase(pixels.begin() + last, pixels.end());
  pixels.erase(pixels.begin(), pixels.begin() + first);
  const std::vector<riemann::RayPath> paths = TraceRays(*metric, *scene, *camera, settings.Position,
    rays, pixels, this->Width, this->Height, meshes.get());
  this->UpdateProgress(1.0);
  BuildOutput(paths, pixels, *scene, output);
  return 1;
}

bool vtkRiemannRayBundle::CheckSizes(const riemann::RaySettings& rays)
{
  for (const auto& [name, value, most] :
    { std::tuple<const char*, int, int>{ "Width", this->Width,
        static_cast<int>(BundleDeclared::Maximum::Width) },
      { "Height", this->Height, static_cast<int>(BundleDeclared::Maximum::Height) },
      { "SubgridResolution", this->SubgridResolution,
        static_cast<int>(BundleDeclared::Maximum::SubgridResolution) },
      { "PixelStride", this->PixelStride, 1 << 16 } })
  {
    if (value < 1 || value > most)
    {
      this->ReportError(std::string(name) + " " + std::to_string(value) + ": must be 1 to " +
        std::to_string(most) + ".");
      return false;
    }
  }
  // The rays before SelectPixels makes them: a 4096^2 sub-grid of 1000-step
  // rays once took 11.8 GB and aborted.
  double numberOfRays = static_cast<double>(this->SubgridResolution) * this->SubgridResolution;
  if (this->UsePixelRegion)
  {
    const auto across = [this](int a, int b, int side)
    {
      const int low = std::max(0, std::min(a, b));
      const int high = std::min(side - 1, std::max(a, b));
      return high < low ? 0.0 : std::floor((high - low) / double(this->PixelStride)) + 1.0;
    };
    numberOfRays = across(this->PixelRegion[0], this->PixelRegion[1], this->Width) *
      across(this->PixelRegion[2], this->PixelRegion[3], this->Height);
  }
  const double points = numberOfRays * (static_cast<double>(rays.MaximumSteps) + 1.0);
  if (points > MaximumNumberOfPoints)
  {
    std::ostringstream message;
    message << numberOfRays << " rays of up to " << rays.MaximumSteps << " steps: up to "
            << points << " points, more than the " << MaximumNumberOfPoints
            << " a bundle holds; trace fewer rays (SubgridResolution, PixelStride) or steps.";
    this->ReportError(message.str());
    return false;
  }
  return true;
}

void vtkRiemannRayBundle::SelectPixels(std::vector<std::pair<int, int>>& pixels) const
{
  if (this->UsePixelRegion)
  {
    const int c0 = std::max(0, std::min(this->PixelRegion[0], this->PixelRegion[1]));
    const int c1 = std::min(this->Width - 1, std::max(this->PixelRegion[0], this->PixelRegion[1]));
    const int r0 = std::max(0, std::min(this->PixelRegion[2], this->PixelRegion[3]));
    const int r1 = std::min(this->Height - 1, std::max(this->PixelRegion[2], this->PixelRegion[3]));
    for (int r = r0; r <= r1; r += this->PixelStride)
    {
      for (int c = c0; c <= c1; c += this->PixelStride)
      {
        pixels.emplace_back(c, r);
      }
    }
  }
  else
  {
    const int n = this->SubgridResolution;
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        pixels.emplace_back(
          std::min(this->Width - 1, static_cast<int>((i + 0.5) * this->Width / n)),
          std::min(this->Height - 1, static_cast<int>((j + 0.5) * this->Height / n)));
      }
    }
  }
}

void vtkRiemannRayBundle::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scene: " << this->Scene << "\n";
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "Width x Height: " << this->Width << " x " << this->Height << "\n";
  os << indent << "Projection: " << this->Projection << "\n";
  os << indent << "SubgridResolution: " << this->SubgridResolution << "\n";
  os << indent << "UsePixelRegion: " << this->UsePixelRegion << " (" << this->PixelRegion[0] << ".."
     << this->PixelRegion[1] << ", " << this->PixelRegion[2] << ".." << this->PixelRegion[3]
     << ", stride " << this->PixelStride << ")\n";
  os << indent << "UseSceneSettings: " << this->UseSceneSettings << "\n";
}
