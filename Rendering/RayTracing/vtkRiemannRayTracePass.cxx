#include "vtkRiemannRayTracePass.h"

#include "vtkRiemannMetric.h"
#include "vtkRiemannScene.h"

#include "GlslSource.h"
#include "Metric.h"
#include "ObserverCamera.h"
#include "RiemannImageIO.h"
#include "RiemannScene.h"

// GLSL embedded at build time (vtk_encode_string).
#include "RiemannRayTraceFS.h"
#include "RiemannRayTraceIntegrators.h"
#include "RiemannRayTraceScene.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOutputWindow.h"
#include "vtkRenderState.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

vtkStandardNewMacro(vtkRiemannRayTracePass);

namespace
{
/// Programs kept per pass; beyond this the least recently built are dropped
/// (VTK's shader cache still holds their compiled code).
constexpr std::size_t MaximumCachedPrograms = 8;

/**
 * Collects what VTK reports through the output window while a program is
 * built, so that a failure can be told in one message of this pass (with the
 * GLSL log) instead of VTK's listing of the whole source.
 */
class vtkRiemannCollectingOutputWindow : public vtkOutputWindow
{
public:
  static vtkRiemannCollectingOutputWindow* New();
  vtkTypeMacro(vtkRiemannCollectingOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override { this->Add(text); }
  void DisplayErrorText(const char* text) override { this->Add(text); }
  void DisplayWarningText(const char* text) override { this->Add(text); }
  void DisplayGenericWarningText(const char* text) override { this->Add(text); }
  void DisplayDebugText(const char*) override {}

  std::vector<std::string> Messages;

protected:
  vtkRiemannCollectingOutputWindow() = default;
  ~vtkRiemannCollectingOutputWindow() override = default;

private:
  void Add(const char* text)
  {
    if (text)
    {
      this->Messages.emplace_back(text);
    }
  }
};
vtkStandardNewMacro(vtkRiemannCollectingOutputWindow);

/// Routes the output window to a collector for the lifetime of the scope.
class ScopedOutputCollector
{
public:
  ScopedOutputCollector()
    : Previous(vtkOutputWindow::GetInstance())
  {
    vtkOutputWindow::SetInstance(this->Collector);
  }
  ~ScopedOutputCollector() { vtkOutputWindow::SetInstance(this->Previous); }
  ScopedOutputCollector(const ScopedOutputCollector&) = delete;
  ScopedOutputCollector& operator=(const ScopedOutputCollector&) = delete;

  /// The collected messages that do not list source lines ("   12: ...").
  std::string Summary() const
  {
    std::string summary;
    for (const std::string& message : this->Collector->Messages)
    {
      const std::size_t colon = message.find("): ");
      const std::string body = colon == std::string::npos ? message : message.substr(colon + 3);
      std::size_t first = body.find_first_not_of(" \n");
      if (first != std::string::npos && std::isdigit(static_cast<unsigned char>(body[first])) &&
        body.find(": ", first) < first + 8)
      {
        continue; // VTK's numbered listing of the shader source
      }
      summary += body;
    }
    return summary;
  }

private:
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkNew<vtkRiemannCollectingOutputWindow> Collector;
};

void Trim(std::string& text)
{
  const std::size_t end = text.find_last_not_of(" \n\r\t");
  text.erase(end == std::string::npos ? 0 : end + 1);
}

void Replace(std::string& text, const std::string& tag, const std::string& value)
{
  const std::size_t at = text.find(tag);
  if (at != std::string::npos)
  {
    text.replace(at, tag.size(), value);
  }
}

/**
 * Compile a fragment shader on its own (no output window, no program) and
 * return the GLSL compiler's log, empty on success. VTK's shader cache
 * reports failures by listing the whole source; this gives the log alone.
 */
std::string CheckFragmentShader(const std::string& source)
{
  std::string text = source;
  // What vtkOpenGLShaderCache::ReplaceShaderValues does for a desktop context.
  Replace(text, "//VTK::System::Dec",
    "#version 150\n#define highp\n#define mediump\n#define lowp\n#define varying in\n");
  Replace(text, "//VTK::Output::Dec", "out vec4 fragOutput0;\n");
  vtkShaderProgram::Substitute(text, "gl_FragData[0]", "fragOutput0");
  vtkNew<vtkShader> shader;
  shader->SetType(vtkShader::Fragment);
  shader->SetSource(text);
  if (shader->Compile())
  {
    return std::string();
  }
  std::string log = shader->GetError();
  Trim(log);
  return log.empty() ? std::string("(the GLSL compiler gave no log)") : log;
}

/// Read an image file (OpenImageIO, RiemannImageIO.h) as float RGB rows, top row first.
bool ReadEnvironmentImage(
  const std::string& path, std::vector<float>& rgb, int& width, int& height, std::string& error)
{
  riemann::Image image;
  error = riemann::ReadImage(path, image);
  Trim(error);
  if (!error.empty())
  {
    return false;
  }
  width = image.Width;
  height = image.Height;
  const int channels = image.Channels;
  if (width <= 0 || height <= 0 || channels <= 0)
  {
    error = "empty image";
    return false;
  }
  rgb.resize(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t i = 0, n = static_cast<std::size_t>(width) * height; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      // Grey images repeat their one channel; two-channel ones are grey + alpha.
      const int source = channels >= 3 ? c : 0;
      rgb[3 * i + c] = image.Pixels[i * channels + source];
    }
  }
  return true;
}

void ToFloat(const riemann::Vec3& v, float out[3])
{
  for (int i = 0; i < 3; ++i)
  {
    out[i] = static_cast<float>(v[i]);
  }
}
} // namespace

//------------------------------------------------------------------------------
class vtkRiemannRayTracePass::vtkInternals
{
public:
  struct CachedProgram
  {
    std::unique_ptr<vtkOpenGLQuadHelper> Quad;
    unsigned long long LastUse = 0;
  };

  /// The window whose context holds the resources below.
  vtkOpenGLRenderWindow* Context = nullptr;
  /// Built programs by fragment source, and sources that failed with their message.
  std::map<std::string, CachedProgram> Programs;
  std::map<std::string, std::string> FailedPrograms;
  unsigned long long UseCounter = 0;

  vtkSmartPointer<vtkTextureObject> Environment;
  std::string EnvironmentPath;
  std::string EnvironmentError;

  vtkSmartPointer<vtkOpenGLFramebufferObject> HitFramebuffer;
  vtkSmartPointer<vtkTextureObject> HitTexture;
  vtkNew<vtkFloatArray> HitImage;

  void Release(vtkWindow* window)
  {
    this->Programs.clear(); // each quad helper frees its VAO
    this->FailedPrograms.clear();
    if (this->Environment)
    {
      this->Environment->ReleaseGraphicsResources(window);
      this->Environment = nullptr;
    }
    this->EnvironmentPath.clear();
    this->EnvironmentError.clear();
    if (this->HitFramebuffer)
    {
      this->HitFramebuffer->ReleaseGraphicsResources(window);
      this->HitFramebuffer = nullptr;
    }
    if (this->HitTexture)
    {
      this->HitTexture->ReleaseGraphicsResources(window);
      this->HitTexture = nullptr;
    }
    this->Context = nullptr;
  }
};

//------------------------------------------------------------------------------
vtkRiemannRayTracePass::vtkRiemannRayTracePass()
  : Internals(new vtkInternals)
{
  this->Internals->HitImage->SetName("Hits");
  this->Internals->HitImage->SetNumberOfComponents(4);
}

vtkRiemannRayTracePass::~vtkRiemannRayTracePass()
{
  // The window may be gone already: release through the resources' own
  // callbacks (they know their window), not through a stored pointer.
  this->Internals->Release(nullptr);
  this->SetMetric(nullptr);
  this->SetScene(nullptr);
  this->SetExtraShaderCode(nullptr);
}

vtkCxxSetObjectMacro(vtkRiemannRayTracePass, Metric, vtkRiemannMetric);
vtkCxxSetObjectMacro(vtkRiemannRayTracePass, Scene, vtkRiemannScene);

vtkMTimeType vtkRiemannRayTracePass::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Metric)
  {
    time = std::max(time, this->Metric->GetMTime());
  }
  if (this->Scene)
  {
    time = std::max(time, this->Scene->GetMTime());
  }
  return time;
}

std::shared_ptr<const riemann::Metric> vtkRiemannRayTracePass::GetCoreMetric()
{
  return this->Metric ? this->Metric->GetMetric() : nullptr;
}

vtkFloatArray* vtkRiemannRayTracePass::GetHitImage()
{
  return this->Internals->HitImage;
}

void vtkRiemannRayTracePass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Internals->Release(w);
}

//------------------------------------------------------------------------------
void vtkRiemannRayTracePass::Fail(
  const std::string& message, vtkOpenGLRenderWindow* renWin, const int viewport[4])
{
  this->LastError = message;
  this->HitImageWidth = 0;
  this->HitImageHeight = 0;
  this->Internals->HitImage->SetNumberOfTuples(0);
  vtkErrorMacro(<< message);
  if (!renWin || !viewport)
  {
    return;
  }
  // A clearly marked picture: the whole view red.
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglScissor(viewport[0], viewport[1], viewport[2], viewport[3]);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  ostate->vtkglClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
}

//------------------------------------------------------------------------------
void vtkRiemannRayTracePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkRenderer* renderer = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin =
    vtkOpenGLRenderWindow::SafeDownCast(renderer ? renderer->GetRenderWindow() : nullptr);
  if (!renWin)
  {
    this->Fail("the renderer has no OpenGL render window", nullptr, nullptr);
    return;
  }
  vtkInternals& internals = *this->Internals;
  if (internals.Context && internals.Context != renWin)
  {
    internals.Release(nullptr); // another window: start afresh in this one
  }
  internals.Context = renWin;

  // The image: the renderer's viewport in the window, or the whole target
  // of an enclosing pass's framebuffer.
  int viewport[4];
  if (s->GetFrameBuffer())
  {
    int size[2];
    s->GetWindowSize(size);
    viewport[0] = 0;
    viewport[1] = 0;
    viewport[2] = size[0];
    viewport[3] = size[1];
  }
  else
  {
    renderer->GetTiledSizeAndOrigin(&viewport[2], &viewport[3], &viewport[0], &viewport[1]);
  }
  if (viewport[2] <= 0 || viewport[3] <= 0)
  {
    return;
  }
  const double aspect = static_cast<double>(viewport[2]) / viewport[3];

  // ---- what to render -------------------------------------------------------
  const std::shared_ptr<const riemann::Metric> metric = this->GetCoreMetric();
  if (!metric)
  {
    this->Fail(this->Metric ? "the metric has no definition: call SetDefinition() on it"
                            : "no metric: call SetMetric() with a vtkRiemannMetric",
      renWin, viewport);
    return;
  }
  if (!this->Scene)
  {
    this->Fail("no scene: call SetScene() with a vtkRiemannScene", renWin, viewport);
    return;
  }
  const std::shared_ptr<const riemann::Scene> scenePointer = this->Scene->GetSceneSnapshot();
  const riemann::Scene& scene = *scenePointer;
  if (scene.HasMeshes())
  {
    // The shader draws the analytic objects only; triangle meshes are Embree's.
    this->Fail("mesh objects need --backend cpu: the GPU pass draws grids, spheres, planes and "
               "boxes; render this scene with vtkRiemannCPURayTracer",
      renWin, viewport);
    return;
  }

  riemann::MetricGlsl metricGlsl;
  try
  {
    metricGlsl = riemann::EmitMetricGlsl(*metric);
  }
  catch (const riemann::GlslUnsupportedError& e)
  {
    this->Fail(
      std::string("the GLSL backend cannot express this metric: ") + e.what(), renWin, viewport);
    return;
  }
  catch (const std::exception& e)
  {
    this->Fail(std::string("could not write the metric's GLSL: ") + e.what(), renWin, viewport);
    return;
  }

  riemann::RaySettings rays;
  int projection = this->Projection;
  if (this->UseSceneSettings)
  {
    rays = scene.Rays;
    if (scene.HasCamera)
    {
      projection = static_cast<int>(scene.Camera.Mode);
    }
  }
  else
  {
    rays.Integrator = static_cast<riemann::IntegratorType>(this->IntegratorType);
    rays.Step = this->StepSize;
    rays.MaximumSteps = this->MaximumNumberOfSteps;
    rays.MaximumLength = this->MaximumLength;
    rays.Tolerance = this->Tolerance;
  }

  vtkCamera* camera = renderer->GetActiveCamera();
  riemann::CameraSettings cameraSettings;
  cameraSettings.Position = riemann::Vec3(camera->GetPosition());
  cameraSettings.LookAt = riemann::Vec3(camera->GetFocalPoint());
  cameraSettings.ViewUp = riemann::Vec3(camera->GetViewUp());
  double viewAngle = camera->GetViewAngle();
  if (camera->GetUseHorizontalViewAngle())
  {
    viewAngle = 2.0 * std::atan(std::tan(0.5 * vtkMath::RadiansFromDegrees(viewAngle)) / aspect);
    viewAngle = vtkMath::DegreesFromRadians(viewAngle);
  }
  cameraSettings.ViewAngle = viewAngle;
  cameraSettings.Mode = static_cast<riemann::Projection>(projection);
  std::unique_ptr<riemann::ObserverCamera> observer;
  try
  {
    observer.reset(new riemann::ObserverCamera(*metric, cameraSettings));
  }
  catch (const std::exception& e)
  {
    this->Fail(std::string("cannot place the observer: ") + e.what(), renWin, viewport);
    return;
  }

  // ---- the program ----------------------------------------------------------
  const int maximumObjects = riemann::MaximumSpheres + riemann::MaximumPlanes +
    riemann::MaximumBoxes + riemann::MaximumGrids;
  std::ostringstream constants;
  constants << "// Scene limits (RiemannScene.h).\n"
            << "#define RT_MAX_SPHERES " << riemann::MaximumSpheres << "\n"
            << "#define RT_MAX_PLANES " << riemann::MaximumPlanes << "\n"
            << "#define RT_MAX_BOXES " << riemann::MaximumBoxes << "\n"
            << "#define RT_MAX_GRIDS " << riemann::MaximumGrids << "\n"
            << "#define RT_MAX_OBJECTS " << maximumObjects << "\n"
            << "// 0: Euler, 1: RK4, 2: adaptive Dormand-Prince 5(4).\n"
            << "#define RT_INTEGRATOR " << static_cast<int>(rays.Integrator) << "\n";
  std::string source = RiemannRayTraceFS;
  Replace(source, "//RT::Constants::Dec", constants.str());
  Replace(source, "//RT::Metric::Impl", metricGlsl.Source);
  Replace(source, "//RT::Scene::Impl", RiemannRayTraceScene);
  Replace(source, "//RT::Integrators::Impl", RiemannRayTraceIntegrators);
  Replace(source, "//RT::Extra::Impl",
    this->ExtraShaderCode ? std::string("// ExtraShaderCode\n") + this->ExtraShaderCode : "");
  this->FragmentShaderSource = source;

  const auto failed = internals.FailedPrograms.find(source);
  if (failed != internals.FailedPrograms.end())
  {
    this->Fail(failed->second, renWin, viewport);
    return;
  }
  auto found = internals.Programs.find(source);
  if (found != internals.Programs.end() && !found->second.Quad->Program)
  {
    // The window released its graphics resources behind our back.
    internals.Programs.erase(found);
    found = internals.Programs.end();
  }
  if (found == internals.Programs.end())
  {
    ++this->NumberOfShaderCompilations;
    std::string message;
    const std::string log = CheckFragmentShader(source);
    std::unique_ptr<vtkOpenGLQuadHelper> quad;
    if (!log.empty())
    {
      message = "the ray-tracing shader failed to compile: " + log;
    }
    else
    {
      std::string vtkMessages;
      {
        ScopedOutputCollector collector;
        quad.reset(new vtkOpenGLQuadHelper(renWin, nullptr, source.c_str(), ""));
        vtkMessages = collector.Summary();
      }
      Trim(vtkMessages);
      if (!quad->Program || !quad->Program->GetCompiled())
      {
        message = "the ray-tracing shader failed to compile or link: " +
          (vtkMessages.empty() ? std::string("(no log)") : vtkMessages);
      }
    }
    if (!message.empty())
    {
      internals.FailedPrograms[source] = message;
      this->Fail(message, renWin, viewport);
      return;
    }
    if (internals.Programs.size() >= MaximumCachedPrograms)
    {
      auto oldest = internals.Programs.begin();
      for (auto it = internals.Programs.begin(); it != internals.Programs.end(); ++it)
      {
        oldest = it->second.LastUse < oldest->second.LastUse ? it : oldest;
      }
      internals.Programs.erase(oldest);
    }
    found = internals.Programs.emplace(source, vtkInternals::CachedProgram()).first;
    found->second.Quad = std::move(quad);
  }
  found->second.LastUse = ++internals.UseCounter;
  vtkOpenGLQuadHelper* quad = found->second.Quad.get();
  vtkShaderProgram* program = renWin->GetShaderCache()->ReadyShaderProgram(quad->Program);
  if (!program)
  {
    this->Fail("the ray-tracing shader could not be bound", renWin, viewport);
    return;
  }

  // ---- uniforms: metric -----------------------------------------------------
  for (const riemann::GlslUniform& uniform : metricGlsl.Uniforms)
  {
    float values[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
    const std::size_t count = std::min<std::size_t>(uniform.Values.size(), 9);
    for (std::size_t i = 0; i < count; ++i)
    {
      values[i] = static_cast<float>(uniform.Values[i]);
    }
    // A uniform the compiler optimised away cannot be set; that is harmless.
    if (uniform.Type == "float" && count == 1)
    {
      program->SetUniformf(uniform.Name.c_str(), values[0]);
    }
    else if (uniform.Type == "vec3" && count == 3)
    {
      program->SetUniform3f(uniform.Name.c_str(), values);
    }
    else if (uniform.Type == "mat3" && count == 9)
    {
      program->SetUniformMatrix3x3(uniform.Name.c_str(), values);
    }
    else
    {
      this->Fail("the metric's GLSL has a uniform of unexpected type or size: " + uniform.Type +
          " " + uniform.Name,
        renWin, viewport);
      return;
    }
  }

  // ---- uniforms: scene ------------------------------------------------------
  const int objectCount =
    static_cast<int>(std::min<std::size_t>(scene.Objects.size(), maximumObjects));
  if (static_cast<std::size_t>(objectCount) < scene.Objects.size())
  {
    vtkWarningMacro(<< "the scene has " << scene.Objects.size()
                    << " objects; the GPU pass draws the first " << maximumObjects);
  }
  {
    std::vector<int> types(maximumObjects, 0);
    std::vector<int> materialTypes(maximumObjects, 0);
    std::vector<float> a(3 * maximumObjects, 0.0f);
    std::vector<float> b(3 * maximumObjects, 0.0f);
    std::vector<float> p(3 * maximumObjects, 0.0f);
    std::vector<float> color(3 * maximumObjects, 0.0f);
    std::vector<float> color2(3 * maximumObjects, 0.0f);
    std::vector<float> size(maximumObjects, 1.0f);
    std::vector<float> lo(3 * maximumObjects, 0.0f);
    std::vector<float> hi(3 * maximumObjects, 0.0f);
    for (int i = 0; i < objectCount; ++i)
    {
      const riemann::SceneObject& object = scene.Objects[i];
      types[i] = static_cast<int>(object.Type);
      if (object.Type == riemann::ObjectType::Grid)
      {
        for (int axis = 0; axis < 3; ++axis)
        {
          a[3 * i + axis] = static_cast<float>(object.Extent[2 * axis]);
          b[3 * i + axis] = static_cast<float>(object.Extent[2 * axis + 1]);
        }
      }
      else
      {
        ToFloat(object.A, &a[3 * i]);
        ToFloat(object.B, &b[3 * i]);
      }
      p[3 * i] = static_cast<float>(object.Radius);
      p[3 * i + 1] = static_cast<float>(object.Spacing);
      p[3 * i + 2] = static_cast<float>(object.Thickness);
      const riemann::Material& material = object.Surface;
      materialTypes[i] = static_cast<int>(material.Type);
      ToFloat(material.Color, &color[3 * i]);
      ToFloat(material.Color2, &color2[3 * i]);
      size[i] = static_cast<float>(material.Size);
      for (int axis = 0; axis < 3; ++axis)
      {
        lo[3 * i + axis] = static_cast<float>(material.Bounds[2 * axis]);
        hi[3 * i + axis] = static_cast<float>(material.Bounds[2 * axis + 1]);
      }
    }
    program->SetUniformi("rt_object_count", objectCount);
    program->SetUniform1iv("rt_object_type", maximumObjects, types.data());
    program->SetUniform3fv("rt_object_a", maximumObjects, a.data());
    program->SetUniform3fv("rt_object_b", maximumObjects, b.data());
    program->SetUniform3fv("rt_object_p", maximumObjects, p.data());
    program->SetUniform1iv("rt_material_type", maximumObjects, materialTypes.data());
    program->SetUniform3fv("rt_material_color", maximumObjects, color.data());
    program->SetUniform3fv("rt_material_color2", maximumObjects, color2.data());
    program->SetUniform1fv("rt_material_size", maximumObjects, size.data());
    program->SetUniform3fv("rt_material_lo", maximumObjects, lo.data());
    program->SetUniform3fv("rt_material_hi", maximumObjects, hi.data());
  }

  // ---- uniforms: observer, integration, shading ----------------------------
  float v3[3];
  ToFloat(cameraSettings.Position, v3);
  program->SetUniform3f("rt_eye", v3);
  ToFloat(observer->GetForward(), v3);
  program->SetUniform3f("rt_forward", v3);
  ToFloat(observer->GetUp(), v3);
  program->SetUniform3f("rt_up", v3);
  ToFloat(observer->GetRight(), v3);
  program->SetUniform3f("rt_right", v3);
  program->SetUniformf("rt_tan_half_angle",
    static_cast<float>(std::tan(0.5 * vtkMath::RadiansFromDegrees(cameraSettings.ViewAngle))));
  program->SetUniformi("rt_projection", projection);

  program->SetUniformf("rt_step", static_cast<float>(rays.Step));
  program->SetUniformi("rt_max_steps", rays.MaximumSteps);
  program->SetUniformf("rt_max_length", static_cast<float>(rays.MaximumLength));
  program->SetUniformf("rt_tolerance", static_cast<float>(rays.Tolerance));
  // The adaptive step's range, as riemann::TraceRay.
  program->SetUniformf(
    "rt_min_step", static_cast<float>(riemann::AdaptiveMinimumStepFactor * rays.Step));
  program->SetUniformf(
    "rt_max_step", static_cast<float>(riemann::AdaptiveMaximumStepFactor * rays.Step));

  ToFloat(scene.Background, v3);
  program->SetUniform3f("rt_background", v3);
  ToFloat(scene.FogColor, v3);
  program->SetUniform3f("rt_fog_color", v3);
  program->SetUniformf("rt_fog_density", static_cast<float>(scene.FogDensity));
  program->SetUniformi("rt_observer_light", scene.ObserverLight ? 1 : 0);

  // ---- environment image ----------------------------------------------------
  bool useEnvironment = false;
  if (!scene.EnvironmentImage.empty())
  {
    if (scene.EnvironmentImage != internals.EnvironmentPath)
    {
      internals.EnvironmentPath = scene.EnvironmentImage;
      internals.EnvironmentError.clear();
      if (internals.Environment)
      {
        internals.Environment->ReleaseGraphicsResources(renWin);
        internals.Environment = nullptr;
      }
      std::vector<float> rgb;
      int width = 0;
      int height = 0;
      std::string error;
      if (ReadEnvironmentImage(scene.EnvironmentImage, rgb, width, height, error))
      {
        vtkNew<vtkTextureObject> texture;
        texture->SetContext(renWin);
        texture->SetWrapS(vtkTextureObject::Repeat);
        texture->SetWrapT(vtkTextureObject::ClampToEdge);
        texture->SetMinificationFilter(vtkTextureObject::Linear);
        texture->SetMagnificationFilter(vtkTextureObject::Linear);
        // Rows top first: texture coordinate t = 0 is the top (latitude +90).
        if (texture->Create2DFromRaw(width, height, 3, VTK_FLOAT, rgb.data()))
        {
          internals.Environment = texture;
        }
        else
        {
          internals.EnvironmentError = "could not upload the texture";
        }
      }
      else
      {
        internals.EnvironmentError = error;
      }
      if (!internals.EnvironmentError.empty())
      {
        // Reported once per image; the background colour stands in for it.
        vtkErrorMacro(<< "cannot use the environment image " << scene.EnvironmentImage << ": "
                      << internals.EnvironmentError << " (the background colour is shown instead)");
      }
    }
    useEnvironment = internals.Environment != nullptr;
  }
  if (useEnvironment)
  {
    internals.Environment->Activate();
    program->SetUniformi("rt_environment", internals.Environment->GetTextureUnit());
  }
  program->SetUniformi("rt_use_environment", useEnvironment ? 1 : 0);

  // ---- draw -----------------------------------------------------------------
  vtkOpenGLState* ostate = renWin->GetState();
  {
    vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
    vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
    vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable depthTestSaver(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    ostate->vtkglScissor(viewport[0], viewport[1], viewport[2], viewport[3]);
    ostate->vtkglEnable(GL_SCISSOR_TEST);

    float window[4] = { static_cast<float>(viewport[0]), static_cast<float>(viewport[1]),
      static_cast<float>(viewport[2]), static_cast<float>(viewport[3]) };
    program->SetUniform4f("rt_viewport", window);
    program->SetUniformi("rt_output", 0);
    quad->Render();

    if (this->CaptureHits)
    {
      const int width = viewport[2];
      const int height = viewport[3];
      if (!internals.HitTexture)
      {
        internals.HitTexture = vtkSmartPointer<vtkTextureObject>::New();
        internals.HitTexture->SetContext(renWin);
      }
      if (static_cast<int>(internals.HitTexture->GetWidth()) != width ||
        static_cast<int>(internals.HitTexture->GetHeight()) != height)
      {
        internals.HitTexture->ReleaseGraphicsResources(renWin);
        internals.HitTexture->SetContext(renWin);
        internals.HitTexture->SetInternalFormat(GL_RGBA32F);
        internals.HitTexture->SetFormat(GL_RGBA);
        internals.HitTexture->SetDataType(GL_FLOAT);
        internals.HitTexture->SetMinificationFilter(vtkTextureObject::Nearest);
        internals.HitTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
        internals.HitTexture->Allocate2D(width, height, 4, VTK_FLOAT);
      }
      if (!internals.HitFramebuffer)
      {
        internals.HitFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
        internals.HitFramebuffer->SetContext(renWin);
      }
      ostate->PushFramebufferBindings();
      internals.HitFramebuffer->Bind();
      internals.HitFramebuffer->AddColorAttachment(0, internals.HitTexture);
      internals.HitFramebuffer->ActivateDrawBuffer(0);
      internals.HitFramebuffer->ActivateReadBuffer(0);
      const char* status = nullptr;
      const bool complete =
        vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_FRAMEBUFFER, status);
      if (complete)
      {
        ostate->vtkglViewport(0, 0, width, height);
        ostate->vtkglScissor(0, 0, width, height);
        float target[4] = { 0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height) };
        program->SetUniform4f("rt_viewport", target);
        program->SetUniformi("rt_output", 1);
        quad->Render();
        program->SetUniformi("rt_output", 0);
        internals.HitImage->SetNumberOfComponents(4);
        internals.HitImage->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
        ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, internals.HitImage->GetPointer(0));
        this->HitImageWidth = width;
        this->HitImageHeight = height;
      }
      ostate->PopFramebufferBindings();
      if (!complete)
      {
        this->HitImageWidth = 0;
        this->HitImageHeight = 0;
        internals.HitImage->SetNumberOfTuples(0);
        vtkErrorMacro(<< "hit capture: the float framebuffer is incomplete ("
                      << (status ? status : "unknown status") << ")");
      }
      internals.HitImage->Modified();
    }
  }
  if (useEnvironment)
  {
    internals.Environment->Deactivate();
  }
  this->LastError.clear();
}

//------------------------------------------------------------------------------
void vtkRiemannRayTracePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* integrators[] = { "Euler", "RungeKutta4", "Adaptive" };
  static const char* projections[] = { "Perspective", "Equirectangular" };
  os << indent << "Metric: " << this->Metric << "\n";
  os << indent << "Scene: " << this->Scene << "\n";
  os << indent << "UseSceneSettings: " << (this->UseSceneSettings ? "On" : "Off") << "\n";
  os << indent << "IntegratorType: " << integrators[this->IntegratorType] << "\n";
  os << indent << "StepSize: " << this->StepSize << "\n";
  os << indent << "MaximumNumberOfSteps: " << this->MaximumNumberOfSteps << "\n";
  os << indent << "MaximumLength: " << this->MaximumLength << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "Projection: " << projections[this->Projection] << "\n";
  os << indent << "CaptureHits: " << (this->CaptureHits ? "On" : "Off") << "\n";
  os << indent << "HitImage: " << this->HitImageWidth << " x " << this->HitImageHeight << "\n";
  os << indent << "NumberOfShaderCompilations: " << this->NumberOfShaderCompilations << "\n";
  os << indent << "ExtraShaderCode: " << (this->ExtraShaderCode ? "(set)" : "(none)") << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
}
