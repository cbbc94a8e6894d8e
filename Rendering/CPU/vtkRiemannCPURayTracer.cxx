#include "vtkRiemannCPURayTracer.h"

#include "vtkRiemannReportError.h"

#include "RiemannActorMesh.h"
#include "RiemannCPUTracer.h"
#include "RiemannImageIO.h"
#include "RiemannPolyDataMesh.h"
#include "RiemannScene.h"
#include "RiemannShading.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannNewArray.h"
#include "vtkRiemannObserverSettings.h"
#include "vtkRiemannParallelBatches.h"
#include "vtkRiemannScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkRiemannCPURayTracer);
vtkCxxSetObjectMacro(vtkRiemannCPURayTracer, Metric, vtkRiemannMetric);
vtkCxxSetObjectMacro(vtkRiemannCPURayTracer, Scene, vtkRiemannScene);
vtkCxxSetObjectMacro(vtkRiemannCPURayTracer, Camera, vtkCamera);

class vtkRiemannCPURayTracer::vtkInternals
{
public:
  struct AddedMesh
  {
    vtkSmartPointer<vtkPolyData> Data;
    riemann::MeshColoring Coloring;
  };
  std::vector<AddedMesh> Meshes;
  std::vector<vtkSmartPointer<vtkActor>> Actors;
  /// The image extent this update traces (the whole image, or a piece's).
  int Extent[6] = { 0, -1, 0, -1, 0, 0 };
  /// The last update's pixels (for the whole image; FillOutput writes the extent's).
  std::vector<riemann::PixelResult> Pixels;
};

vtkRiemannCPURayTracer::vtkRiemannCPURayTracer()
  : IntegrationSettings(vtkRiemannIntegrationSettings::New())
  , Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(0);
  vtkRiemannSetRayDefaults(this->IntegrationSettings);
}

vtkRiemannCPURayTracer::~vtkRiemannCPURayTracer()
{
  this->SetMetric(nullptr);
  this->SetScene(nullptr);
  this->SetCamera(nullptr);
  this->IntegrationSettings->Delete();
}

void vtkRiemannCPURayTracer::SetIntegrationSettings(vtkRiemannIntegrationSettings* settings)
{
  if (vtkRiemannIntegrationSettings::Share(this, this->IntegrationSettings, settings))
  {
    this->Modified();
  }
}

vtkMTimeType vtkRiemannCPURayTracer::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  for (vtkObject* object :
    { static_cast<vtkObject*>(this->Metric), static_cast<vtkObject*>(this->Scene),
      static_cast<vtkObject*>(this->Camera), static_cast<vtkObject*>(this->IntegrationSettings) })
  {
    if (object)
    {
      time = std::max(time, object->GetMTime());
    }
  }
  for (const auto& mesh : this->Internals->Meshes)
  {
    time = std::max(time, mesh.Data->GetMTime());
  }
  for (const auto& actor : this->Internals->Actors)
  {
    time = std::max(time, riemann::ActorMeshTime(actor));
  }
  return time;
}

void vtkRiemannCPURayTracer::AddActor(vtkActor* actor)
{
  if (!actor)
  {
    vtkRiemannReportErrorMacro(this->LastError, << "AddActor: no actor (null)");
    return;
  }
  this->Internals->Actors.emplace_back(actor);
  this->Modified();
}

void vtkRiemannCPURayTracer::RemoveAllActors()
{
  if (!this->Internals->Actors.empty())
  {
    this->Internals->Actors.clear();
    this->Modified();
  }
}

int vtkRiemannCPURayTracer::GetNumberOfAddedActors() const
{
  return static_cast<int>(this->Internals->Actors.size());
}

void vtkRiemannCPURayTracer::AddMesh(
  vtkPolyData* mesh, const char* colorArray, const char* colorMap)
{
  if (!mesh)
  {
    vtkRiemannReportErrorMacro(this->LastError, << "AddMesh: no mesh (null)");
    return;
  }
  vtkInternals::AddedMesh added;
  added.Data = vtkSmartPointer<vtkPolyData>::New();
  added.Data->ShallowCopy(mesh);
  added.Coloring.Array = colorArray ? colorArray : "";
  added.Coloring.ColorMap = colorMap ? colorMap : "cool-to-warm";
  this->Internals->Meshes.push_back(added);
  this->Modified();
}

void vtkRiemannCPURayTracer::RemoveAllMeshes()
{
  if (!this->Internals->Meshes.empty())
  {
    this->Internals->Meshes.clear();
    this->Modified();
  }
}

std::vector<riemann::PixelResult> vtkRiemannCPURayTracer::PixelResultsOf(vtkImageData* output)
{
  std::vector<riemann::PixelResult> pixels;
  vtkPointData* data = output ? output->GetPointData() : nullptr;
  if (!data)
  {
    return pixels;
  }
  // The arrays FillOutput writes, by type: one name for each PixelResult field.
  auto* color = vtkFloatArray::SafeDownCast(data->GetArray("Color"));
  auto* hitPosition = vtkFloatArray::SafeDownCast(data->GetArray("HitPosition"));
  auto* arcLength = vtkFloatArray::SafeDownCast(data->GetArray("ArcLength"));
  auto* steps = vtkIntArray::SafeDownCast(data->GetArray("Steps"));
  auto* reason = vtkIntArray::SafeDownCast(data->GetArray("ReasonForTermination"));
  auto* drift = vtkFloatArray::SafeDownCast(data->GetArray("SpeedDrift"));
  auto* hitError = vtkFloatArray::SafeDownCast(data->GetArray("HitError"));
  if (!color || !hitPosition || !arcLength || !steps || !reason || !drift)
  {
    return pixels;
  }
  const vtkIdType n = output->GetNumberOfPoints();
  pixels.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    riemann::PixelResult& p = pixels[static_cast<std::size_t>(i)];
    color->GetTypedTuple(i, p.Color);
    hitPosition->GetTypedTuple(i, p.HitPosition);
    p.ArcLength = arcLength->GetValue(i);
    p.Steps = steps->GetValue(i);
    p.Reason = reason->GetValue(i);
    p.SpeedDrift = drift->GetValue(i);
    p.HitError = hitError ? hitError->GetValue(i) : std::numeric_limits<float>::quiet_NaN();
  }
  return pixels;
}

int vtkRiemannCPURayTracer::GetNumberOfAddedMeshes() const
{
  return static_cast<int>(this->Internals->Meshes.size());
}

int vtkRiemannCPURayTracer::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  // Sides out of range are refused in RequestData; here they only must not overflow.
  const int extent[6] = { 0, std::max(this->Width, 0) - 1, 0, std::max(this->Height, 0) - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double spacing[3] = { 1, 1, 1 };
  const double origin[3] = { 0, 0, 0 };
  info->Set(vtkDataObject::SPACING(), spacing, 3);
  info->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_FLOAT, 3);
  // Any sub-extent can be traced alone (every pixel's rays are its own): the
  // executive turns a request for piece p of N into UPDATE_EXTENT.
  info->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  return 1;
}

int vtkRiemannCPURayTracer::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  output->Initialize();
  this->LastError.clear();
  this->NumberOfRays = 0;
  this->NumberOfIntegrationSteps = 0;
  this->TraceTime = 0.0;
  this->NumberOfTriangles = 0;
  this->HitErrorComputed = false;
  this->Internals->Pixels.clear();

  const std::shared_ptr<const riemann::Metric> metric =
    this->Metric ? this->Metric->GetMetric() : nullptr;
  if (!metric)
  {
    vtkRiemannReportErrorMacro(this->LastError, << (this->Metric ? "the metric has no definition: call SetDefinition() on it"
                                   : "no metric: call SetMetric() with a vtkRiemannMetric"));
    return 1;
  }
  const std::shared_ptr<riemann::Scene> scene = this->MakeScene();
  if (!scene || !this->CheckImageSize())
  {
    return 1;
  }
  std::unique_ptr<riemann::CPUTracer> tracer = this->MakeCoreTracer(metric, scene);
  if (!tracer)
  {
    return 1;
  }
  // The requested part of the image (all of it without a piece request).
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6] = { 0, this->Width - 1, 0, this->Height - 1, 0, 0 }; // sides checked above
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    int requested[6];
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), requested);
    for (int axis = 0; axis < 2; ++axis)
    {
      extent[2 * axis] = std::max(extent[2 * axis], requested[2 * axis]);
      extent[2 * axis + 1] = std::min(extent[2 * axis + 1], requested[2 * axis + 1]);
    }
  }
  if (extent[0] > extent[1] || extent[2] > extent[3])
  {
    return 1; // an empty piece
  }
  std::copy(extent, extent + 6, this->Internals->Extent);
  this->TraceTiles(*tracer);
  this->HitErrorComputed = this->ComputeHitError && tracer->HasExactReference();
  if (this->ComputeHitError && !this->HitErrorComputed)
  {
    vtkWarningMacro(<< "ComputeHitError: the metric (" << metric->FamilyName()
                    << ") has no exact reference; only diffeomorphism metrics have one");
  }
  this->FillOutput(output);
  return 1;
}

//------------------------------------------------------------------------------
std::shared_ptr<riemann::Scene> vtkRiemannCPURayTracer::MakeScene()
{
  // The vtkRiemannScene's (or the default), plus the added meshes.
  auto scene = std::make_shared<riemann::Scene>(
    this->Scene ? *this->Scene->GetSceneSnapshot() : riemann::DefaultScene());
  try
  {
    for (const auto& added : this->Internals->Meshes)
    {
      riemann::Material material; // position pseudo-colour over the mesh's bounds
      riemann::AddMesh(*scene, riemann::MeshFromPolyData(added.Data, added.Coloring), material);
    }
  }
  catch (const std::exception& e)
  {
    vtkRiemannReportErrorMacro(this->LastError, << "AddMesh: " << e.what());
    return nullptr;
  }
  // The added actors as the GPU pass draws a renderer's (UseRendererProps):
  // one mesh, coloured per vertex; actors that draw nothing are skipped.
  std::vector<std::shared_ptr<const riemann::TriangleMesh>> actorMeshes;
  try
  {
    for (const auto& actor : this->Internals->Actors)
    {
      if (riemann::ActorMeshTime(actor) > 0)
      {
        actorMeshes.push_back(riemann::MeshFromActor(actor));
      }
    }
  }
  catch (const std::exception& e)
  {
    vtkRiemannReportErrorMacro(this->LastError, << "AddActor: " << e.what());
    return nullptr;
  }
  if (!actorMeshes.empty())
  {
    riemann::AddMesh(*scene, riemann::AppendMeshes(actorMeshes), riemann::Material());
  }
  return scene;
}

//------------------------------------------------------------------------------
bool vtkRiemannCPURayTracer::CheckImageSize()
{
  if (this->Width < 1 || this->Width > 65536 || this->Height < 1 || this->Height > 65536)
  {
    vtkRiemannReportErrorMacro(this->LastError, << "The image is " << this->Width << " x " << this->Height
                  << " pixels; each side must be 1 to 65536.");
    return false;
  }
  // About 90 bytes per pixel are held at once (the tracer's results and the
  // output arrays): refuse what would exhaust memory rather than crash.
  const double pixels = static_cast<double>(this->Width) * this->Height;
  if (pixels > MaximumNumberOfPixels)
  {
    vtkRiemannReportErrorMacro(this->LastError, << "The image is too large: " << this->Width << " x " << this->Height << " = "
                  << pixels / 1e6 << " million pixels, more than " << MaximumNumberOfPixels / 1e6
                  << " million (about " << 90.0 * MaximumNumberOfPixels / (1 << 30)
                  << " GiB of memory); render a smaller image.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
std::unique_ptr<riemann::CPUTracer> vtkRiemannCPURayTracer::MakeCoreTracer(
  const std::shared_ptr<const riemann::Metric>& metric,
  const std::shared_ptr<riemann::Scene>& scene)
{
  // Settings, projection and camera by the rules every renderer shares.
  const std::string settingsError = this->IntegrationSettings->CheckSettings();
  if (!this->UseSceneSettings && !settingsError.empty())
  {
    vtkRiemannReportErrorMacro(this->LastError, << "Integration settings: " << settingsError << ".");
    return nullptr;
  }
  const riemann::RaySettings rays =
    vtkRiemannResolveRaySettings(this->UseSceneSettings, *scene, this->IntegrationSettings);
  const riemann::CameraSettings camera =
    vtkRiemannCameraSettings(this->Camera, static_cast<double>(this->Width) / this->Height,
      scene->Camera, vtkRiemannResolveProjection(this->UseSceneSettings, *scene, this->Projection));

  std::shared_ptr<riemann::EnvironmentMap> environment;
  if (!scene->EnvironmentImage.empty())
  {
    try
    {
      environment = std::make_shared<riemann::EnvironmentMap>(
        riemann::ReadEnvironmentMap(scene->EnvironmentImage));
    }
    catch (const riemann::ImageFileError& e)
    {
      // As the GPU pass: reported, and the background colour stands in for it.
      vtkRiemannReportErrorMacro(this->LastError, << "cannot use the environment image " << scene->EnvironmentImage << ": "
                    << e.what() << " (the background colour is shown instead)");
    }
  }

  riemann::CPUTracerSettings settings;
  settings.Width = this->Width;
  settings.Height = this->Height;
  settings.SamplesPerPixel = this->SamplesPerPixel;
  settings.Seed = this->Seed;
  settings.UseRayStreams = this->UseRayStreams;
  settings.ComputeHitError = this->ComputeHitError;
  std::unique_ptr<riemann::CPUTracer> tracer;
  try
  {
    tracer.reset(new riemann::CPUTracer(metric, scene, camera, rays, settings, environment));
  }
  catch (const std::exception& e)
  {
    vtkRiemannReportErrorMacro(this->LastError, << "cannot trace the scene: " << e.what());
    return nullptr;
  }
  this->NumberOfTriangles = static_cast<vtkIdType>(tracer->NumberOfTriangles());
  return tracer;
}

//------------------------------------------------------------------------------
void vtkRiemannCPURayTracer::TraceTiles(const riemann::CPUTracer& tracer)
{
  // Tiles, run in parallel in batches; progress and AbortExecute between batches.
  // The tiles of the whole image's tiling that meet the extent, cut to it.
  const int width = this->Width;
  const int height = this->Height;
  const int* extent = this->Internals->Extent;
  const int tile = this->TileSize;
  const int firstX = extent[0] / tile;
  const int firstY = extent[2] / tile;
  const int tilesX = extent[1] / tile - firstX + 1;
  const int tilesY = extent[3] / tile - firstY + 1;
  const vtkIdType tiles = static_cast<vtkIdType>(tilesX) * tilesY;
  std::vector<riemann::PixelResult>& pixels = this->Internals->Pixels;
  pixels.assign(static_cast<std::size_t>(width) * height, riemann::PixelResult());
  std::atomic<long long> steps(0);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  // The first batch is one tile per thread: a tile can take a second at many
  // samples per pixel, and Cancel is seen between batches (which then grow
  // to 0.1 s of work each, vtkRiemannParallelBatches.h).
  vtkRiemannForInBatches(this, tiles, std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads()),
    [&](vtkIdType begin, vtkIdType end)
    {
      long long local = 0;
      for (vtkIdType t = begin; t < end; ++t)
      {
        const int x0 = (firstX + static_cast<int>(t % tilesX)) * tile;
        const int y0 = (firstY + static_cast<int>(t / tilesX)) * tile;
        local += tracer.RenderTile(std::max(x0, extent[0]), std::max(y0, extent[2]),
          std::min({ width, x0 + tile, extent[1] + 1 }),
          std::min({ height, y0 + tile, extent[3] + 1 }), pixels.data());
      }
      steps += local;
    });
  timer->StopTimer();
  this->TraceTime = timer->GetElapsedTime();
  this->NumberOfIntegrationSteps = steps.load();
  this->NumberOfRays = static_cast<vtkIdType>(extent[1] - extent[0] + 1) *
    (extent[3] - extent[2] + 1) * (this->SamplesPerPixel > 1 ? this->SamplesPerPixel + 1 : 1);
}

//------------------------------------------------------------------------------
void vtkRiemannCPURayTracer::FillOutput(vtkImageData* output)
{
  const int* extent = this->Internals->Extent;
  const vtkIdType n =
    static_cast<vtkIdType>(extent[1] - extent[0] + 1) * (extent[3] - extent[2] + 1);
  output->SetExtent(const_cast<int*>(extent));
  output->SetSpacing(1, 1, 1);
  output->SetOrigin(0, 0, 0);
  auto color = vtkRiemannNewArray<vtkFloatArray>("Color", 3, n);
  auto hitPosition = vtkRiemannNewArray<vtkFloatArray>("HitPosition", 3, n);
  auto arcLength = vtkRiemannNewArray<vtkFloatArray>("ArcLength", 1, n);
  auto stepCount = vtkRiemannNewArray<vtkIntArray>("Steps", 1, n);
  auto reason = vtkRiemannNewArray<vtkIntArray>("ReasonForTermination", 1, n);
  auto drift = vtkRiemannNewArray<vtkFloatArray>("SpeedDrift", 1, n);
  auto hitError =
    this->HitErrorComputed ? vtkRiemannNewArray<vtkFloatArray>("HitError", 1, n) : nullptr;
  const std::vector<riemann::PixelResult>& pixels = this->Internals->Pixels;
  const int columns = extent[1] - extent[0] + 1;
  for (vtkIdType i = 0; i < n; ++i)
  {
    // Pixels are stored for the whole image, row 0 at the bottom.
    const std::size_t x = static_cast<std::size_t>(extent[0] + i % columns);
    const std::size_t y = static_cast<std::size_t>(extent[2] + i / columns);
    const riemann::PixelResult& p = pixels[y * static_cast<std::size_t>(this->Width) + x];
    color->SetTypedTuple(i, p.Color);
    hitPosition->SetTypedTuple(i, p.HitPosition);
    arcLength->SetValue(i, p.ArcLength);
    stepCount->SetValue(i, p.Steps);
    reason->SetValue(i, p.Reason);
    drift->SetValue(i, p.SpeedDrift);
    if (hitError)
    {
      hitError->SetValue(i, p.HitError);
    }
  }
  vtkPointData* pointData = output->GetPointData();
  pointData->SetScalars(color);
  for (vtkDataArray* array :
    { static_cast<vtkDataArray*>(hitPosition), static_cast<vtkDataArray*>(arcLength),
      static_cast<vtkDataArray*>(stepCount), static_cast<vtkDataArray*>(reason),
      static_cast<vtkDataArray*>(drift), static_cast<vtkDataArray*>(hitError) })
  {
    if (array)
    {
      pointData->AddArray(array);
    }
  }
}

void vtkRiemannCPURayTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Metric: " << this->Metric << "\n";
  os << indent << "Scene: " << this->Scene << "\n";
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "AddedMeshes: " << this->Internals->Meshes.size() << "\n";
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "SamplesPerPixel: " << this->SamplesPerPixel << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "TileSize: " << this->TileSize << "\n";
  os << indent << "UseRayStreams: " << (this->UseRayStreams ? "On" : "Off") << "\n";
  os << indent << "ComputeHitError: " << (this->ComputeHitError ? "On" : "Off") << "\n";
  os << indent << "UseSceneSettings: " << (this->UseSceneSettings ? "On" : "Off") << "\n";
  os << indent << "IntegrationSettings:\n";
  this->IntegrationSettings->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Projection: " << this->Projection << "\n";
  os << indent << "NumberOfRays: " << this->NumberOfRays << "\n";
  os << indent << "NumberOfIntegrationSteps: " << this->NumberOfIntegrationSteps << "\n";
  os << indent << "TraceTime: " << this->TraceTime << "\n";
}
