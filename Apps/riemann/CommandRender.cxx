// riemann render: the inside view of R^3 with a metric, ray traced per pixel
// on the GPU by vtkRiemannRayTracePass or (--backend cpu) on the CPU by
// vtkRiemannCPURayTracer (meshes, anti-aliasing, EXR channels of arbitrary
// output variables, the error against the exact reference), written through
// OpenImageIO; with
// --bundle, side by side with an outside view of the scene and the same rays;
// with --frames, an animation in the metric's time t; with --reference, an
// image regression test in one command (as F3D's CLI).
#include "CliUtilities.h"
#include "IntegrationOptions.h"
#include "Commands.h"
#include "Distributed.h"
#include "FilmFrames.h"
#include "ProgressBar.h"

#include "RiemannCPUImage.h"
#include "RiemannFilmWriter.h"
#include "RiemannImageIO.h"
#include "RiemannPictureSettingsDeclaration.h"
#include "RiemannScene.h"
#include "SettingValues.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRiemannCPURayTracer.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayBundle.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannOutsideScene.h"
#include "vtkRiemannScene.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <memory>
#include <type_traits>

namespace riemann
{
namespace cli
{
namespace
{
/// The paper's one Gaussian bump in the graph metric: the default picture.
constexpr const char* DefaultMetric =
  R"({"type": "graph", "gaussians": [{"amplitude": 1.0, "center": [0, 0, 0], "sigma": [0.5, 0.5, 0.5]}]})";

struct RenderArguments
{
  std::string Metric;
  std::string Scene;
  /// The picture's options (size, samples, renderer) and the camera's, made
  /// from vtkRiemannPictureSettings's declaration; TakePictureOptions reads
  /// them into the fields below once the command line is parsed.
  std::unique_ptr<DeclaredOptions> Picture;
  std::unique_ptr<DeclaredOptions> Camera;
  int Width = 0;
  int Height = 0;
  int Samples = 0;
  std::string Backend;
  /// vtkRiemannRayTracePass::GPUPath by name: auto, fragment or compute.
  std::string GpuPath;
  // The camera's options as typed ("" when not given: the scene's camera,
  // else the declared defaults).
  std::string CameraPosition;
  std::string LookAt;
  std::string ViewUp;
  double Fov = 0.0;
  /// perspective or equirectangular; "" for the scene's.
  std::string Projection;
  bool Equirectangular = false;
  /// The integration options; what is not given is the scene's.
  std::unique_ptr<DeclaredOptions> Integration;
  int Frames = 1;
  /// A camera path file (CameraPathFile.h): the observer's flight over the frames.
  std::string CameraPath;
  bool HitError = false;
  std::string HitErrorImage;
  bool Progress = false;
  bool Quiet = false;
  int Bundle = 0;
  std::string Reference;
  double Threshold = 1.0;
  std::string Output;
};

/// The declared picture settings of the camera; the others are the picture's own.
constexpr const char* CameraSettingNames = "Position,LookAt,ViewUp,ViewAngle,Projection";
constexpr const char* PictureOutputSettingNames = "Width,Height,SamplesPerPixel,Backend,GPUPath";

/// The option of picture setting `name` ("--position"), for messages.
std::string PictureOption(const char* name)
{
  return DeclaredOptions::OptionOf(riemann::declared::vtkRiemannPictureSettings::Settings, name);
}

/// The parsed picture and camera options into the fields RunRender reads.
void TakePictureOptions(RenderArguments& args)
{
  const DeclaredOptions& picture = *args.Picture;
  args.Width = static_cast<int>(picture.Integer("Width"));
  args.Height = static_cast<int>(picture.Integer("Height"));
  args.Samples = static_cast<int>(picture.Integer("SamplesPerPixel"));
  args.Backend = picture.Text("Backend");
  args.GpuPath = picture.Text("GPUPath");
  // The camera's: only what was given (the scene's camera fills the rest).
  const nlohmann::json given = args.Camera->Given();
  const auto text = [&given](const char* name)
  {
    const riemann::SettingDeclaration& setting =
      *riemann::declared::vtkRiemannPictureSettings::Settings.Find(name);
    return given.contains(name) ? riemann::SettingText(setting, given.at(name)) : std::string();
  };
  args.CameraPosition = text("Position");
  args.LookAt = text("LookAt");
  args.ViewUp = text("ViewUp");
  args.Fov = given.contains("ViewAngle") ? given.at("ViewAngle").get<double>() : 0.0;
  args.Projection = text("Projection");
}

/// The window's colour buffer as an image (row 0 at the top).
Image Grab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkImageData* data = grab->GetOutput();
  int dims[3];
  data->GetDimensions(dims);
  Image image;
  image.Width = dims[0];
  image.Height = dims[1];
  image.Channels = 3;
  image.ChannelNames = { "R", "G", "B" };
  image.Pixels.resize(static_cast<size_t>(dims[0]) * dims[1] * 3);
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(data->GetPointData()->GetScalars());
  for (int row = 0; row < dims[1]; ++row)
  {
    for (int column = 0; column < dims[0]; ++column)
    {
      const vtkIdType source = static_cast<vtkIdType>(row) * dims[0] + column;
      const size_t target = (static_cast<size_t>(dims[1] - 1 - row) * dims[0] + column) * 3;
      for (int c = 0; c < 3; ++c)
      {
        image.Pixels[target + c] = scalars->GetTypedComponent(source, c) / 255.0f;
      }
    }
  }
  return image;
}

/// Two pictures of the same height, side by side.
Image SideBySide(const Image& left, const Image& right)
{
  Image both;
  both.Width = left.Width + right.Width;
  both.Height = left.Height;
  both.Channels = 3;
  both.ChannelNames = { "R", "G", "B" };
  both.Pixels.resize(static_cast<size_t>(both.Width) * both.Height * 3);
  for (int row = 0; row < both.Height; ++row)
  {
    std::copy_n(&left.Pixels[static_cast<size_t>(row) * left.Width * 3], left.Width * 3,
      &both.Pixels[static_cast<size_t>(row) * both.Width * 3]);
    std::copy_n(&right.Pixels[static_cast<size_t>(row) * right.Width * 3], right.Width * 3,
      &both.Pixels[(static_cast<size_t>(row) * both.Width + left.Width) * 3]);
  }
  return both;
}

/**
 * How the rays go, for every renderer of this command (the pass or the CPU
 * tracer, and the bundle): the scene's settings unless an option overrides
 * them, one shared settings object, and the projection.
 */
struct RaySetup
{
  bool UseSceneSettings = true;
  vtkNew<vtkRiemannIntegrationSettings> Settings;
  int Projection = vtkRiemannRayTracePass::PERSPECTIVE;

  template <class Renderer>
  void ApplyTo(Renderer* renderer) const
  {
    renderer->SetUseSceneSettings(this->UseSceneSettings);
    renderer->SetIntegrationSettings(this->Settings);
    renderer->SetProjection(this->Projection);
  }
};

/// The outside view: the scene as ordinary geometry, the observer, and the
/// bundle of its curved rays coloured by where they end.
Image RenderOutside(vtkRiemannMetric* metric, vtkRiemannScene* scene, vtkCamera* inside,
  const RaySetup& raySetup, const RenderArguments& args, ErrorCollector* errors)
{
  vtkNew<vtkRiemannRayBundle> bundle;
  errors->Observe(bundle);
  bundle->SetMetric(metric);
  bundle->SetScene(scene);
  bundle->SetCamera(inside);
  bundle->SetWidth(args.Width);
  bundle->SetHeight(args.Height);
  bundle->SetSubgridResolution(args.Bundle);
  raySetup.ApplyTo(bundle.Get());
  bundle->Update();
  errors->ThrowIfAny("tracing the ray bundle failed:");

  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRiemannOutsideScene> outside;
  outside->SetScene(scene);
  outside->SetObserver(inside);
  outside->SetAspectRatio(static_cast<double>(args.Width) / args.Height);
  outside->SetRays(bundle->GetOutput());
  outside->AddToRenderer(renderer);
  outside->PlaceCamera(renderer);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(4);
  window->AddRenderer(renderer);
  window->SetSize(args.Width, args.Height);
  errors->Observe(window);
  window->Render();
  errors->ThrowIfAny("rendering the outside view failed:");
  return Grab(window);
}

/// Refuses a camera that does not define a view: its position at its focal
/// point, or its view-up along its view direction (VTK would render NaNs, or
/// the picture of a camera it silently changed). Names the options at fault.
void CheckCamera(vtkCamera* camera, const RenderArguments& args)
{
  const double* position = camera->GetPosition();
  const double* focal = camera->GetFocalPoint();
  const double* up = camera->GetViewUp();
  const auto text = [](const double* v)
  { return FormatNumber(v[0]) + "," + FormatNumber(v[1]) + "," + FormatNumber(v[2]); };
  // The options as typed; the scene's values as the camera holds them.
  const std::string from = args.CameraPosition.empty()
    ? "the scene's camera position " + text(position)
    : PictureOption("Position") + " " + args.CameraPosition;
  const std::string to =
    args.LookAt.empty() ? "the scene's look-at point " + text(focal) : PictureOption("LookAt") + " " + args.LookAt;
  const double view[3] = { focal[0] - position[0], focal[1] - position[1], focal[2] - position[2] };
  const double length = std::sqrt(view[0] * view[0] + view[1] * view[1] + view[2] * view[2]);
  if (!(length > 0))
  {
    throw Failure(from + " and " + to +
        ": the camera is at the point it looks at, so there is no view direction",
      2);
  }
  if (!std::isfinite(length))
  {
    throw Failure(from + " and " + to + ": too far apart for a view direction", 2);
  }
  const double cross[3] = { up[1] * view[2] - up[2] * view[1], up[2] * view[0] - up[0] * view[2],
    up[0] * view[1] - up[1] * view[0] };
  const double upLength = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
  const double sine = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]) /
    (upLength * length);
  if (!(sine > 1e-9))
  {
    throw Failure(
      (args.ViewUp.empty() ? "the scene's view-up " + text(up) : PictureOption("ViewUp") + " " + args.ViewUp) +
        " is parallel to the view direction (from " + from + " to " + to +
        "), so the picture has no up: give a " + PictureOption("ViewUp") + " across the view",
      2);
  }
}

void ApplyCameraOptions(vtkCamera* camera, const RenderArguments& args)
{
  double v[3];
  if (!args.CameraPosition.empty())
  {
    ParseVector3(args.CameraPosition, PictureOption("Position"), v);
    camera->SetPosition(v);
  }
  if (!args.LookAt.empty())
  {
    ParseVector3(args.LookAt, PictureOption("LookAt"), v);
    camera->SetFocalPoint(v);
  }
  if (!args.ViewUp.empty())
  {
    ParseVector3(args.ViewUp, PictureOption("ViewUp"), v);
    camera->SetViewUp(v);
  }
  if (args.Fov > 0)
  {
    camera->SetViewAngle(args.Fov);
  }
}

/// Refuses option combinations that make no sense, before any work.
void CheckRenderOptions(const RenderArguments& args)
{
  const std::string extension = Extension(args.Output);
  if (extension != "png" && extension != "exr" && extension != "ogv")
  {
    throw Failure("-o " + args.Output + ": the output must end in .png, .exr or .ogv (a film)", 2);
  }
  if (extension == "ogv" && (!args.Reference.empty() || !args.HitErrorImage.empty()))
  {
    throw Failure("-o " + args.Output + ": a film cannot be compared with --reference or carry "
                  "--hit-error-image; write .png frames",
      2);
  }
  // Theora codes colour on 2 x 2 blocks.
  if (extension == "ogv" && (args.Width % 2 || args.Height % 2))
  {
    throw Failure("-o " + args.Output + ": a film's frames need even sides, not " +
        std::to_string(args.Width) + "x" + std::to_string(args.Height),
      2);
  }
  if (args.Backend != "cpu" && (args.Samples > 1 || args.HitError || !args.HitErrorImage.empty()))
  {
    throw Failure(PictureOption("SamplesPerPixel") + ", --hit-error and --hit-error-image need --backend cpu", 2);
  }
  if (args.Backend == "cpu" && args.GpuPath != "auto")
  {
    throw Failure(PictureOption("GPUPath") + " " + args.GpuPath + " chooses the GPU pass's shader path: it needs "
                  "--backend gpu",
      2);
  }
  if (IsDistributed() && args.Backend != "cpu")
  {
    throw Failure("under mpirun, render needs --backend cpu: each rank traces its piece of the "
                  "picture on the CPU (the GPU pass draws a whole picture in one process)",
      2);
  }
  if (args.Equirectangular && args.Projection == "perspective")
  {
    throw Failure("--equirectangular and --projection perspective ask for two projections", 2);
  }
  if (!args.Reference.empty() && args.Frames > 1)
  {
    throw Failure("--reference compares one picture: it cannot be used with --frames", 2);
  }
  // Before any work: 16384 x 16384 once failed only after the whole render.
  const double pixels = static_cast<double>(args.Width) * args.Height;
  if (pixels > vtkRiemannCPURayTracer::MaximumNumberOfPixels)
  {
    throw Failure("--width " + std::to_string(args.Width) + " --height " +
        std::to_string(args.Height) + ": " + FormatNumber(pixels / 1e6) +
        " million pixels; a picture has at most " +
        FormatNumber(vtkRiemannCPURayTracer::MaximumNumberOfPixels / 1e6) +
        " million (8192 x 8192)",
      2);
  }
}

/// The scene (its file read once), and the metric: --metric, else the
/// scene's (already parsed with the scene), else the paper's bump.
vtkSmartPointer<vtkRiemannMetric> LoadSceneAndMetric(
  const RenderArguments& args, vtkRiemannScene* scene)
{
  if (!args.Scene.empty() && !scene->SetDefinitionFile(args.Scene.c_str()))
  {
    throw Failure(std::string("bad scene: ") + scene->GetLastError());
  }
  if (!args.Metric.empty())
  {
    return LoadMetric(args.Metric);
  }
  auto metric = vtkSmartPointer<vtkRiemannMetric>::New();
  const std::shared_ptr<const riemann::Scene> snapshot = scene->GetSceneSnapshot();
  const bool ok = snapshot->ParsedMetric ? metric->SetParsedDefinition(snapshot->MetricDefinition,
                                             snapshot->ParsedMetric, snapshot->MetricDirectory)
                                         : metric->SetDefinition(DefaultMetric);
  if (!ok)
  {
    throw Failure(std::string("bad metric in the scene: ") + metric->GetLastError());
  }
  return metric;
}

/// The projection: --projection (or --equirectangular), else the scene's
/// camera's, else the declared default.
riemann::Projection ChosenProjection(const RenderArguments& args, const riemann::Scene& scene)
{
  if (args.Equirectangular)
  {
    return riemann::Projection::Equirectangular;
  }
  if (!args.Projection.empty())
  {
    return static_cast<riemann::Projection>(riemann::ChoiceIndex(
      *riemann::declared::vtkRiemannPictureSettings::Settings.Find("Projection"), args.Projection));
  }
  return scene.HasCamera ? scene.Camera.Mode : riemann::CameraSettings().Mode;
}

/// The scene's integration, with what the options give in its place.
void SetUpRays(const RenderArguments& args, const riemann::Scene& scene, RaySetup& rays)
{
  const bool overrides = !args.Integration->Given().empty();
  vtkRiemannIntegrationSettings* settings = rays.Settings;
  settings->SetIntegratorType(static_cast<int>(scene.Rays.Integrator));
  settings->SetInitialIntegrationStep(scene.Rays.Step);
  settings->SetMaximumNumberOfSteps(scene.Rays.MaximumSteps);
  settings->SetMaximumPropagation(scene.Rays.MaximumLength);
  settings->SetMaximumError(scene.Rays.Tolerance);
  ApplyIntegrationOptions(*args.Integration, settings);
  const bool projectionGiven = !args.Projection.empty() || args.Equirectangular;
  rays.UseSceneSettings = !overrides && !projectionGiven;
  rays.Projection = ChosenProjection(args, scene) == riemann::Projection::Equirectangular
    ? vtkRiemannRayTracePass::EQUIRECTANGULAR
    : vtkRiemannRayTracePass::PERSPECTIVE;
}

/// WriteImage, its ImageFileError told as the command's failure (exit 1).
void WritePicture(const std::string& path, const Image& picture)
{
  try
  {
    WriteImage(path, picture);
  }
  catch (const riemann::ImageFileError& e)
  {
    throw Failure(e.what());
  }
}

/**
 * Collective: the pixels of every rank's piece (the tracer's output, read
 * from its arrays: vtkRiemannCPURayTracer::PixelResultsOf) gathered into the
 * whole picture's pixels on rank 0, colour and every arbitrary output
 * variable with them; nothing on the other ranks. In a single process: the
 * output's pixels, which are the whole picture's.
 */
std::vector<riemann::PixelResult> GatherPixels(vtkRiemannCPURayTracer* tracer)
{
  vtkImageData* output = tracer->GetOutput();
  std::vector<riemann::PixelResult> piece = vtkRiemannCPURayTracer::PixelResultsOf(output);
  if (!IsDistributed())
  {
    return piece;
  }
  // This rank's extent x0, x1, y0, y1, then its pixels (rows from the bottom).
  // Every rank runs the same executable, so the struct's bytes mean the same.
  static_assert(std::is_trivially_copyable<riemann::PixelResult>::value, "sent as bytes");
  const int width = tracer->GetWidth();
  int extent[6] = { 0, -1, 0, -1, 0, 0 };
  if (!piece.empty())
  {
    output->GetExtent(extent);
  }
  const size_t pieceBytes = piece.size() * sizeof(riemann::PixelResult);
  std::vector<char> bytes(4 * sizeof(int) + pieceBytes);
  std::memcpy(bytes.data(), extent, 4 * sizeof(int));
  if (pieceBytes > 0)
  {
    std::memcpy(bytes.data() + 4 * sizeof(int), piece.data(), pieceBytes);
  }
  const std::vector<char> all = GatherBytes(bytes);
  std::vector<riemann::PixelResult> whole;
  if (Rank() != 0)
  {
    return whole;
  }
  whole.resize(static_cast<size_t>(width) * tracer->GetHeight());
  for (size_t at = 0; at < all.size();)
  {
    int piece[4];
    std::memcpy(piece, all.data() + at, sizeof(piece));
    at += sizeof(piece);
    const size_t pieceColumns = static_cast<size_t>(std::max(0, piece[1] - piece[0] + 1));
    const size_t pieceRows = static_cast<size_t>(std::max(0, piece[3] - piece[2] + 1));
    for (size_t row = 0; row < pieceRows; ++row)
    {
      const size_t first = (piece[2] + row) * static_cast<size_t>(width) + piece[0];
      std::memcpy(&whole[first], all.data() + at, pieceColumns * sizeof(riemann::PixelResult));
      at += pieceColumns * sizeof(riemann::PixelResult);
    }
  }
  return whole;
}

/// Draws the frames of one backend; only the requested backend is built.
class FrameRenderer
{
public:
  virtual ~FrameRenderer() = default;
  /// The picture at the metric's current time (rows top first).
  virtual Image RenderFrame(int frame, int frames) = 0;
};

/// The GPU pass in an offscreen window.
class GpuFrames : public FrameRenderer
{
public:
  GpuFrames(vtkRiemannMetric* metric, vtkRiemannScene* scene, vtkCamera* camera,
    const RaySetup& rays, const RenderArguments& args, ErrorCollector* errors)
    : Errors(errors)
  {
    // Debian's VTK draws through GLX: without an X display its window aborts
    // the process (after a message that the output window would hold back).
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
    {
      throw Failure("the GPU backend needs an X display and DISPLAY is not set: run under "
                    "xvfb-run (xvfb-run -a riemann render ...), or use --backend cpu");
    }
    errors->Observe(this->Pass);
    this->Pass->SetMetric(metric);
    this->Pass->SetScene(scene);
    this->Pass->SetGPUPath(args.GpuPath == "compute" ? vtkRiemannRayTracePass::COMPUTE
        : args.GpuPath == "fragment"               ? vtkRiemannRayTracePass::FRAGMENT
                                                   : vtkRiemannRayTracePass::AUTO);
    rays.ApplyTo(this->Pass.Get());
    this->Renderer->SetPass(this->Pass);
    this->Renderer->SetActiveCamera(camera);
    errors->Observe(this->Renderer);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    this->Window->SetSize(args.Width, args.Height);
    errors->Observe(this->Window);
  }

  Image RenderFrame(int, int) override
  {
    this->Window->Render();
    this->Errors->ThrowIfAny("rendering failed:");
    return Grab(this->Window);
  }

private:
  ErrorCollector* Errors;
  vtkNew<vtkRiemannRayTracePass> Pass;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
};

/// The CPU tracer; its pixels are written as the core computed them.
class CpuFrames : public FrameRenderer
{
public:
  CpuFrames(vtkRiemannMetric* metric, vtkRiemannScene* scene, vtkCamera* camera,
    const RaySetup& rays, const RenderArguments& args, ErrorCollector* errors)
    : Errors(errors)
    , Arguments(args)
  {
    const bool hitError = args.HitError || !args.HitErrorImage.empty();
    if (hitError && metric->GetMetric()->FamilyName() != "diffeo")
    {
      throw Failure("--hit-error: the metric is not a diffeomorphism metric (\"type\": "
                    "\"diffeo\"), so there is no exact reference to compare with",
        2);
    }
    errors->Observe(this->Tracer);
    this->Tracer->SetMetric(metric);
    this->Tracer->SetScene(scene);
    this->Tracer->SetCamera(camera);
    this->Tracer->SetWidth(args.Width);
    this->Tracer->SetHeight(args.Height);
    this->Tracer->SetSamplesPerPixel(args.Samples);
    this->Tracer->SetComputeHitError(hitError);
    rays.ApplyTo(this->Tracer.Get());
    // A bar where someone watches (a terminal) or the wait is long; tests stay quiet.
    const double count = static_cast<double>(args.Width) * args.Height * args.Samples;
    this->Progress->Observe(this->Tracer, "riemann render",
      !args.Quiet && (args.Progress || ProgressBar::StderrIsTerminal() || count >= 4e6));
  }

  Image RenderFrame(int frame, int frames) override
  {
    this->Tracer->Modified();
    // This rank's piece of the picture (all of it in a single process).
    UpdateThisRanksPiece(this->Tracer);
    this->Progress->Finish();
    this->Errors->ThrowIfAny("rendering failed:");
    AgreeToGoOn();
    const RenderArguments& args = this->Arguments;
    const std::vector<riemann::PixelResult> pixels = GatherPixels(this->Tracer);
    if (Rank() != 0)
    {
      return Image(); // rank 0 writes the picture
    }
    if (this->Tracer->GetHitErrorComputed())
    {
      const bool numbered = frames > 1 && !args.HitErrorImage.empty();
      this->ReportHitError(
        pixels, numbered ? FramePath(args.HitErrorImage, frame) : args.HitErrorImage);
    }
    return riemann::PixelImage(pixels, args.Width, args.Height, Extension(args.Output) == "exr",
      this->Tracer->GetHitErrorComputed());
  }

private:
  void ReportHitError(
    const std::vector<riemann::PixelResult>& pixels, const std::string& picturePath)
  {
    const riemann::HitErrorSummary summary = riemann::SummarizeHitError(pixels);
    std::cerr << "riemann render: hit error against the exact geodesic: max " << summary.Maximum
              << ", median " << summary.Median << ", 99th percentile " << summary.Percentile99
              << " over " << summary.Compared << " pixels; " << summary.Disagreeing
              << " pixels where only one of the two rays hits\n";
    if (!this->Arguments.HitErrorImage.empty())
    {
      WritePicture(picturePath,
        riemann::HitErrorPicture(pixels, this->Arguments.Width, this->Arguments.Height));
    }
  }

  ErrorCollector* Errors;
  const RenderArguments& Arguments;
  vtkNew<vtkRiemannCPURayTracer> Tracer;
  vtkNew<ProgressBar> Progress;
};

/// The --reference picture, read before any work: one that cannot be read
/// is an error before the output is written (usage, status 2).
Image ReadReference(const RenderArguments& args)
{
  Image reference;
  if (!args.Reference.empty())
  {
    try
    {
      reference = ReadImage(args.Reference);
    }
    catch (const riemann::ImageFileError& e)
    {
      throw Failure(std::string("--reference: ") + e.what(), 2);
    }
  }
  return reference;
}

/// Compares the picture with the reference; throws (exit 3) when it differs.
void CompareWithReference(const Image& picture, const Image& reference, const RenderArguments& args)
{
  const double difference = ImageDifference(picture, reference);
  if (difference < 0)
  {
    throw Failure("the picture (" + std::to_string(picture.Width) + "x" +
        std::to_string(picture.Height) + ") and the reference (" + std::to_string(reference.Width) +
        "x" + std::to_string(reference.Height) + ") differ in size",
      3);
  }
  std::cerr << "riemann render: difference to " << args.Reference << ": " << difference
            << " (threshold " << args.Threshold << ")\n";
  if (difference > args.Threshold)
  {
    throw Failure("the picture differs from the reference: " + std::to_string(difference) +
        " > threshold " + std::to_string(args.Threshold),
      3);
  }
}

void RunRender(const RenderArguments& args)
{
  CheckRenderOptions(args);
  CheckFilePaths({ { "-m", args.Metric }, { "-s", args.Scene }, { "--reference", args.Reference },
                   { "--camera-path", args.CameraPath } },
    { { "-o", args.Output }, { "--hit-error-image", args.HitErrorImage } });
  const Image reference = ReadReference(args);
  vtkNew<vtkRiemannScene> scene;
  const vtkSmartPointer<vtkRiemannMetric> metric = LoadSceneAndMetric(args, scene);
  RaySetup rays;
  SetUpRays(args, scene->GetScene(), rays);
  // The scene's camera, else the declared picture settings' (not vtkCamera's own
  // defaults), then what the options change.
  vtkNew<vtkCamera> camera;
  if (!scene->ApplyCamera(camera))
  {
    vtkRiemannScene::ApplyDefaultCamera(camera);
  }
  ApplyCameraOptions(camera, args);
  CheckCamera(camera, args);

  vtkNew<ErrorCollector> errors;
  std::unique_ptr<FrameRenderer> frames;
  if (args.Backend == "cpu")
  {
    frames.reset(new CpuFrames(metric, scene, camera, rays, args, errors));
  }
  else
  {
    frames.reset(new GpuFrames(metric, scene, camera, rays, args, errors));
  }
  // What each frame shows (t, and the flight of --camera-path), and where it goes.
  const FilmPlan plan(args.CameraPath, args.Frames, metric);
  FrameSink sink(args.Output, args.Frames);
  for (int frame = 0; frame < args.Frames; ++frame)
  {
    const double t = plan.TimeAt(frame);
    if (!metric->SetTime(t))
    {
      throw Failure(std::string("bad metric: ") + metric->GetLastError());
    }
    plan.PlaceCamera(frame, camera);
    Image picture = frames->RenderFrame(frame, args.Frames);
    if (Rank() != 0)
    {
      continue; // rank 0 writes, and speaks for the job
    }
    if (args.Bundle > 0)
    {
      picture = SideBySide(picture, RenderOutside(metric, scene, camera, rays, args, errors));
    }
    const std::string path = sink.Add(frame, picture);
    if (args.Frames > 1)
    {
      std::cerr << "riemann render: frame " << frame + 1 << "/" << args.Frames << " (t = " << t
                << ") -> " << path << "\n";
    }
    if (!args.Reference.empty())
    {
      CompareWithReference(picture, reference, args);
    }
  }
  if (Rank() == 0)
  {
    sink.Finish();
  }
}
} // namespace

void RegisterRenderCommand(CLI::App& app)
{
  auto args = std::make_shared<RenderArguments>();
  CLI::App* command = app.add_subcommand("render", RenderCommandDescription);
  command
    ->add_option("--metric,-m", args->Metric,
      "Metric definition (JSON file); default: the scene's metric, else the paper's bump")
    ->check(CLI::ExistingFile);
  command
    ->add_option(
      "--scene,-s", args->Scene, "Scene (JSON file, see Data/scenes); default: the paper's grid")
    ->check(CLI::ExistingFile);
  // The picture's and the camera's options are vtkRiemannPictureSettings's
  // declared settings, the integration's vtkRiemannIntegrationSettings's.
  const riemann::SettingTable& picture = riemann::declared::vtkRiemannPictureSettings::Settings;
  args->Picture = std::make_unique<DeclaredOptions>(command, picture, CameraSettingNames);
  command->add_flag("--hit-error", args->HitError,
    "Diffeomorphism metrics, --backend cpu: compare each pixel's hit with the exact geodesic "
    "(a HitError EXR channel, max and median on stderr)");
  command->add_option("--hit-error-image", args->HitErrorImage,
    "Also write a picture of the hit error (log scale; red: only one of the rays hits)");
  command->add_flag("--progress", args->Progress, "Show a progress bar on stderr (--backend cpu)");
  command->add_flag("--quiet", args->Quiet, "Never show a progress bar");
  args->Camera = std::make_unique<DeclaredOptions>(command, picture, PictureOutputSettingNames,
    nlohmann::json::object(), "the scene's camera, else {}");
  command->add_flag("--equirectangular", args->Equirectangular,
    "The short form of --projection equirectangular");
  // The rays' adaptive steps are bounded relative to the step (RiemannScene.h):
  // no options of their own.
  args->Integration = AddIntegrationOptions(command, vtkNew<vtkRiemannIntegrationSettings>(),
    "MinimumIntegrationStep,MaximumIntegrationStep", "the scene's");
  command
    ->add_option("--frames", args->Frames,
      "Animate over N frames: the metric's time t from 0 to 1 (or the camera path's times) and "
      "the camera along --camera-path; written as OUT_0000.png, ... or one film -o OUT.ogv")
    ->check(WholeNumber(1, 100000));
  command
    ->add_option("--camera-path", args->CameraPath,
      "Fly the observer along a geodesic or a spline of key positions (JSON, see "
      "Documentation/CameraPaths.md), its view frame transported by the metric, over --frames")
    ->check(CLI::ExistingFile);
  command
    ->add_option("--bundle", args->Bundle,
      "Also draw an outside view with an N x N bundle of the rays, side by side")
    ->check(WholeNumber(1, 256));
  command
    ->add_option("--reference", args->Reference, "Compare with this picture; exit 3 if it differs")
    ->check(CLI::ExistingFile);
  command
    ->add_option("--threshold", args->Threshold,
      "Largest accepted mean per-pixel difference to the reference, 0-255 (default 1)")
    ->check(FiniteNumber(0.0, 255.0));
  command
    ->add_option("--output,-o", args->Output,
      "Output picture: .png or .exr; or a film, .ogv (Ogg Theora, 24 frames per second)")
    ->required();
  command->callback(
    [args]()
    {
      TakePictureOptions(*args);
      RunRender(*args);
    });
}
} // namespace cli
} // namespace riemann
