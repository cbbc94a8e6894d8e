#include "vtkRiemannRayTracePass.h"

#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannObserverSettings.h"
#include "vtkRiemannScene.h"

#include "GlslSource.h"
#include "Metric.h"
#include "MetricGlsl.h"
#include "ObserverCamera.h"
#include "RiemannActorMesh.h"
#include "RiemannComputeProgram.h"
#include "RiemannImageIO.h"
#include "RiemannMeshTextures.h"
#include "RiemannSceneUniformBuffer.h"
#include "RiemannMetricTextures.h"
#include "RiemannReducedView.h"
#include "RiemannScene.h"
#include "RiemannSceneUniforms.h"
#include "RiemannShading.h"

// GLSL embedded at build time (vtk_encode_string).
#include "RiemannRayTraceShader.h"

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
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTextureUnitManager.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <chrono>
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

/**
 * The GL state a full-screen quad of this pass changes (viewport, scissor,
 * depth test, blending), saved for the scope and restored after it; depth
 * test and blending are turned off, the scissor test on.
 */
class ScopedQuadState
{
public:
  explicit ScopedQuadState(vtkOpenGLState* state)
    : Viewport(state)
    , Scissor(state)
    , ScissorTest(state, GL_SCISSOR_TEST)
    , DepthTest(state, GL_DEPTH_TEST)
    , Blend(state, GL_BLEND)
  {
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglEnable(GL_SCISSOR_TEST);
  }

private:
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglScissor Scissor;
  vtkOpenGLState::ScopedglEnableDisable ScissorTest;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglEnableDisable Blend;
};

/// The compute path's lattice (RiemannRayTraceCS.glsl): every level-th
/// pixel from row originRow, `columns` wide; `rows` rows, or with
/// `skipCoarse` (the points of the coarser lattice left out, packed) `rows`
/// pairs of rows.
void SetLattice(vtkShaderProgram* program, int level, int originRow, int columns, int rows,
  bool skipCoarse)
{
  program->SetUniformi("rt_lattice", level);
  const int origin[2] = { 0, originRow };
  program->SetUniform2i("rt_lattice_origin", origin);
  const int size[2] = { columns, rows };
  program->SetUniform2i("rt_lattice_size", size);
  program->SetUniformi("rt_skip_coarse", skipCoarse ? 1 : 0);
}

/// The first lattice of a refinement: the smallest power of two up to 32
/// whose rays (pixels / d^2) take at most `budget` at `secondsPerRay` (8
/// before any measurement).
int FirstRefinementLevel(double pixels, double secondsPerRay, double budget)
{
  if (!(secondsPerRay > 0.0))
  {
    return 8;
  }
  int level = 1;
  while (level < 32 && pixels / (double(level) * level) * secondsPerRay > budget)
  {
    level *= 2;
  }
  return level;
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
/// A built program of either path: a quad (fragment) or a compute program.
struct vtkRiemannRayTracePass::CachedProgram
{
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  vtkSmartPointer<vtkRiemannComputeProgram> Compute;
  unsigned long long LastUse = 0;

  /// Still usable: the window may have released the quad's program behind our back.
  bool IsValid() const
  {
    return this->Compute ? this->Compute->IsReady() : (this->Quad && this->Quad->Program);
  }
};

//------------------------------------------------------------------------------
class vtkRiemannRayTracePass::vtkInternals
{
public:
  /// The window whose context holds the resources below.
  vtkOpenGLRenderWindow* Context = nullptr;
  /// Built programs by source, and sources that failed with their message.
  std::map<std::string, CachedProgram> Programs;
  std::map<std::string, std::string> FailedPrograms;
  unsigned long long UseCounter = 0;

  /// What a program is made of besides the fixed GLSL (ComposeSource).
  /// What the last program was composed from: its choices and its texts.
  struct ProgramIngredients
  {
    riemann::RayTraceShaderChoices Choices;
    std::string MetricSource;
    std::string Extra;
  };
  /// The last frame's ingredients and program: while a frame's ingredients
  /// are the same (a new camera, time, parameter value or scene object
  /// changes none of them), its source is neither composed nor looked up.
  ProgramIngredients LastIngredients;
  CachedProgram* LastProgram = nullptr;
  int NumberOfSourceCompositions = 0;

  vtkSmartPointer<vtkTextureObject> Environment;
  std::string EnvironmentPath;
  std::string EnvironmentError;
  /// A free unit that rt_environment points at while no image is bound (-1:
  /// none): left at unit 0 it could share a unit with a mesh buffer sampler,
  /// and two sampler types on one unit make the draw call fail.
  int IdleEnvironmentUnit = -1;

  vtkSmartPointer<vtkOpenGLFramebufferObject> HitFramebuffer;
  vtkSmartPointer<vtkTextureObject> HitTexture;
  vtkNew<vtkFloatArray> HitImage;

  /// The scene's objects as a uniform buffer.
  riemann::SceneUniformBuffer SceneBlock;
  /// The scene's triangle meshes as buffer textures.
  riemann::MeshTextures Meshes;
  /// A sampled metric's tensor volume as 3D textures.
  riemann::MetricTextures MetricVolumes;
  /// The renderer's actors as one mesh (UseRendererProps).
  riemann::RendererActorMeshes Actors;

  /// The offscreen target of views traced at a lower resolution.
  riemann::ReducedView Reduced;

  /// What a progressive refinement has traced, and of which view.
  struct Refinement
  {
    /// The view: the pass's modification time (metric, scene, settings),
    /// the actors' mesh, the viewport and the camera's numbers (not its
    /// modification time: the renderer sets its clipping range every frame).
    std::vector<double> Key;
    bool Started = false;
    bool Complete = true;
    /// The lattice being traced (every Level-th pixel), the first one, and
    /// the rows of the image it has covered.
    int Level = 1;
    int Coarsest = 1;
    int RowsDone = 0;
    /// Measured wall seconds per traced ray (0: not yet).
    double SecondsPerRay = 0.0;
  } Refine;
  /// The full-resolution images a refinement accumulates (apart from
  /// Reduced, which interactive frames overwrite).
  riemann::ReducedView Refined;
  /// Wall seconds of the last timed ray tracing, at which image sample
  /// distance (-1: none yet).
  double TraceSeconds = -1.0;
  double TraceDistance = 1.0;

  /// Keep a built program, dropping the least recently used beyond the cache's size.
  std::map<std::string, CachedProgram>::iterator StoreProgram(
    const std::string& source, CachedProgram program)
  {
    if (this->Programs.size() >= MaximumCachedPrograms)
    {
      auto oldest = this->Programs.begin();
      for (auto it = this->Programs.begin(); it != this->Programs.end(); ++it)
      {
        oldest = it->second.LastUse < oldest->second.LastUse ? it : oldest;
      }
      this->ErasePrograms(oldest, std::next(oldest), this->Context);
    }
    return this->Programs.emplace(source, std::move(program)).first;
  }

  /// Drop programs; a compute program's GL objects are deleted in `window`'s context
  /// (VTK's shader cache owns the quads' programs).
  void ErasePrograms(std::map<std::string, CachedProgram>::iterator first,
    std::map<std::string, CachedProgram>::iterator last, vtkWindow* window)
  {
    for (auto it = first; it != last; ++it)
    {
      if (it->second.Compute)
      {
        it->second.Compute->ReleaseProgram(window);
      }
      if (&it->second == this->LastProgram)
      {
        this->LastProgram = nullptr;
      }
    }
    this->Programs.erase(first, last); // each quad helper frees its VAO
  }

  /// Read the environment image at `path` into a texture (EnvironmentError says why not).
  void LoadEnvironment(const std::string& path, vtkOpenGLRenderWindow* window)
  {
    this->EnvironmentPath = path;
    this->EnvironmentError.clear();
    if (this->Environment)
    {
      this->Environment->ReleaseGraphicsResources(window);
      this->Environment = nullptr;
    }
    riemann::EnvironmentMap map; // float RGB rows, top row first
    try
    {
      map = riemann::ReadEnvironmentMap(path);
    }
    catch (const riemann::ImageFileError& e)
    {
      this->EnvironmentError = e.what();
      Trim(this->EnvironmentError);
      return;
    }
    vtkNew<vtkTextureObject> texture;
    texture->SetContext(window);
    texture->SetWrapS(vtkTextureObject::Repeat);
    texture->SetWrapT(vtkTextureObject::ClampToEdge);
    texture->SetMinificationFilter(vtkTextureObject::Linear);
    texture->SetMagnificationFilter(vtkTextureObject::Linear);
    // Rows top first: texture coordinate t = 0 is the top (latitude +90).
    if (texture->Create2DFromRaw(map.Width, map.Height, 3, VTK_FLOAT, map.Rgb.data()))
    {
      this->Environment = texture;
    }
    else
    {
      this->EnvironmentError = "could not upload the texture";
    }
  }

  /// The float texture and framebuffer of the hit capture, at this size.
  void ReadyHitTarget(vtkOpenGLRenderWindow* window, int width, int height)
  {
    if (!this->HitTexture)
    {
      this->HitTexture = vtkSmartPointer<vtkTextureObject>::New();
      this->HitTexture->SetContext(window);
    }
    if (static_cast<int>(this->HitTexture->GetWidth()) != width ||
      static_cast<int>(this->HitTexture->GetHeight()) != height)
    {
      this->HitTexture->ReleaseGraphicsResources(window);
      this->HitTexture->SetContext(window);
      this->HitTexture->SetInternalFormat(GL_RGBA32F);
      this->HitTexture->SetFormat(GL_RGBA);
      this->HitTexture->SetDataType(GL_FLOAT);
      this->HitTexture->SetMinificationFilter(vtkTextureObject::Nearest);
      this->HitTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
      this->HitTexture->Allocate2D(width, height, 4, VTK_FLOAT);
    }
    if (!this->HitFramebuffer)
    {
      this->HitFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      this->HitFramebuffer->SetContext(window);
    }
  }

  void Release(vtkWindow* window)
  {
    this->ErasePrograms(this->Programs.begin(), this->Programs.end(),
      window ? window : static_cast<vtkWindow*>(this->Context));
    this->FailedPrograms.clear();
    if (this->Environment)
    {
      this->Environment->ReleaseGraphicsResources(window);
      this->Environment = nullptr;
    }
    this->EnvironmentPath.clear();
    this->EnvironmentError.clear();
    // Release(nullptr) comes from the destructor or a switch to another
    // window: the buffer's context may not be current then.
    this->SceneBlock.Release(window != nullptr);
    this->Meshes.Release(window);
    this->MetricVolumes.Release(window);
    this->Reduced.Release(window);
    this->Refined.Release(window);
    this->Refine = Refinement();
    this->TraceSeconds = -1.0;
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
  : IntegrationSettings(vtkRiemannIntegrationSettings::New())
  , Internals(new vtkInternals)
{
  vtkRiemannSetRayDefaults(this->IntegrationSettings);
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
  this->IntegrationSettings->Delete();
}

vtkCxxSetObjectMacro(vtkRiemannRayTracePass, Metric, vtkRiemannMetric);
vtkCxxSetObjectMacro(vtkRiemannRayTracePass, Scene, vtkRiemannScene);

void vtkRiemannRayTracePass::SetIntegrationSettings(vtkRiemannIntegrationSettings* settings)
{
  if (vtkRiemannIntegrationSettings::Share(this, this->IntegrationSettings, settings))
  {
    this->Modified();
  }
}

vtkMTimeType vtkRiemannRayTracePass::GetMTime()
{
  vtkMTimeType time = std::max(this->Superclass::GetMTime(), this->IntegrationSettings->GetMTime());
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

const char* vtkRiemannRayTracePass::GetGPUPathAsString(int path)
{
  switch (path)
  {
    case AUTO:
      return "Auto";
    case FRAGMENT:
      return "Fragment";
    case COMPUTE:
      return "Compute";
    default:
      return "Unknown";
  }
}

void vtkRiemannRayTracePass::SetComputeWorkgroupSize(int x, int y)
{
  if (x < 1 || y < 1 || x > 64 || y > 64 || x * y > 1024)
  {
    vtkErrorMacro(<< "ComputeWorkgroupSize " << x << " x " << y
                  << ": each side must be 1 to 64 and x * y at most 1024 (OpenGL 4.3's "
                     "guaranteed minimum); kept "
                  << this->ComputeWorkgroupSize[0] << " x " << this->ComputeWorkgroupSize[1]);
    return;
  }
  if (x != this->ComputeWorkgroupSize[0] || y != this->ComputeWorkgroupSize[1])
  {
    this->ComputeWorkgroupSize[0] = x;
    this->ComputeWorkgroupSize[1] = y;
    this->Modified();
  }
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
  ostate->vtkglClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
}

//------------------------------------------------------------------------------
struct vtkRiemannRayTracePass::FrameState
{
  vtkRenderer* Renderer = nullptr;
  vtkOpenGLRenderWindow* Window = nullptr;
  /// x, y, width, height of the image in the target.
  int Viewport[4] = { 0, 0, 0, 0 };
  std::shared_ptr<const riemann::Metric> Metric;
  std::shared_ptr<const riemann::Scene> Scene;
  riemann::MetricGlsl MetricGlsl;
  riemann::RaySettings Rays;
  riemann::CameraSettings Camera;
  std::unique_ptr<riemann::ObserverCamera> Observer;
  /// The path of this frame (ChooseGPUPath), and its program: Quad on the
  /// fragment path, Compute on the compute path.
  bool UseCompute = false;
  /// The renderer's actors as one mesh (UseRendererProps; null without).
  const void* ActorMesh = nullptr;
  vtkOpenGLQuadHelper* Quad = nullptr;
  vtkRiemannComputeProgram* Compute = nullptr;
};

//------------------------------------------------------------------------------
void vtkRiemannRayTracePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  FrameState frame;
  if (!this->PrepareFrame(s, frame))
  {
    return;
  }
  vtkShaderProgram* program = this->ReadyProgram(frame);
  if (!program || !this->SetMetricUniforms(program, frame) ||
    !this->ActivateMetricTextures(program, frame))
  {
    return;
  }
  if (!this->SetSceneUniforms(program, frame) || !this->ActivateMeshes(program, frame))
  {
    this->Internals->MetricVolumes.Deactivate();
    return;
  }
  this->SetObserverUniforms(program, frame);
  const bool useEnvironment = this->ActivateEnvironment(program, frame);
  const bool drawn = this->DrawView(program, frame);
  if (drawn && this->CaptureHits && this->GetRefinementComplete())
  {
    this->CaptureHitImage(program, frame);
  }
  else if (drawn && this->CaptureHits)
  {
    // Refining: the hits of an earlier view must not pass for this one's.
    this->HitImageWidth = 0;
    this->HitImageHeight = 0;
    this->Internals->HitImage->SetNumberOfTuples(0);
    this->Internals->HitImage->Modified();
  }
  if (drawn)
  {
    this->RenderOverlays(s);
  }
  if (useEnvironment)
  {
    this->Internals->Environment->Deactivate();
  }
  else if (this->Internals->IdleEnvironmentUnit >= 0)
  {
    frame.Window->GetTextureUnitManager()->Free(this->Internals->IdleEnvironmentUnit);
    this->Internals->IdleEnvironmentUnit = -1;
  }
  this->Internals->Meshes.Deactivate();
  this->Internals->MetricVolumes.Deactivate();
  if (drawn)
  {
    this->LastError.clear();
  }
}

//------------------------------------------------------------------------------
bool vtkRiemannRayTracePass::PrepareFrame(const vtkRenderState* s, FrameState& frame)
{
  // The window, and the image: the renderer's viewport in the window, or the
  // whole target of an enclosing pass's framebuffer.
  frame.Renderer = s->GetRenderer();
  frame.Window = vtkOpenGLRenderWindow::SafeDownCast(
    frame.Renderer ? frame.Renderer->GetRenderWindow() : nullptr);
  if (!frame.Window)
  {
    this->Fail("the renderer has no OpenGL render window", nullptr, nullptr);
    return false;
  }
  vtkInternals& internals = *this->Internals;
  if (internals.Context && internals.Context != frame.Window)
  {
    internals.Release(nullptr); // another window: start afresh in this one
  }
  internals.Context = frame.Window;
  int* viewport = frame.Viewport;
  if (s->GetFrameBuffer())
  {
    s->GetWindowSize(viewport + 2);
  }
  else
  {
    frame.Renderer->GetTiledSizeAndOrigin(&viewport[2], &viewport[3], &viewport[0], &viewport[1]);
  }
  if (viewport[2] <= 0 || viewport[3] <= 0)
  {
    return false;
  }

  // What to render: the metric (as GLSL) and the scene's analytic objects.
  frame.Metric = this->GetCoreMetric();
  if (!frame.Metric)
  {
    this->Fail(this->Metric ? "the metric has no definition: call SetDefinition() on it"
                            : "no metric: call SetMetric() with a vtkRiemannMetric",
      frame.Window, viewport);
    return false;
  }
  if (!this->Scene)
  {
    this->Fail("no scene: call SetScene() with a vtkRiemannScene", frame.Window, viewport);
    return false;
  }
  frame.Scene = this->Scene->GetSceneSnapshot();
  if (this->UseRendererProps && !this->AddRendererActors(frame))
  {
    return false;
  }
  if (frame.Scene->HasMeshes() &&
    frame.Scene->Objects.size() > static_cast<std::size_t>(riemann::MaximumSceneUniformObjects))
  {
    // A mesh object past the uniform slots would have no material.
    this->Fail("the scene has " + std::to_string(frame.Scene->Objects.size()) +
        " objects; with meshes the GPU pass draws at most " +
        std::to_string(riemann::MaximumSceneUniformObjects) +
        " (render this scene with vtkRiemannCPURayTracer)",
      frame.Window, viewport);
    return false;
  }
  try
  {
    riemann::GlslEmitOptions options;
    options.FilteredTextureReads = this->FilteredTextureReads;
    frame.MetricGlsl = riemann::EmitMetricGlsl(*frame.Metric, options);
  }
  catch (const riemann::GlslUnsupportedError& e)
  {
    this->Fail(std::string("the GLSL backend cannot express this metric: ") + e.what(),
      frame.Window, viewport);
    return false;
  }
  catch (const std::exception& e)
  {
    this->Fail(
      std::string("could not write the metric's GLSL: ") + e.what(), frame.Window, viewport);
    return false;
  }

  // How rays go, and from where (vtkRiemannObserverSettings.h: as the CPU tracer).
  if (!this->UseSceneSettings)
  {
    const std::string settingsError = this->IntegrationSettings->CheckSettings();
    if (!settingsError.empty())
    {
      this->Fail("integration settings: " + settingsError, frame.Window, viewport);
      return false;
    }
  }
  frame.Rays =
    vtkRiemannResolveRaySettings(this->UseSceneSettings, *frame.Scene, this->IntegrationSettings);
  frame.Camera = vtkRiemannCameraSettings(frame.Renderer->GetActiveCamera(),
    static_cast<double>(viewport[2]) / viewport[3], riemann::CameraSettings(),
    vtkRiemannResolveProjection(this->UseSceneSettings, *frame.Scene, this->Projection));
  try
  {
    frame.Observer.reset(new riemann::ObserverCamera(*frame.Metric, frame.Camera));
  }
  catch (const std::exception& e)
  {
    this->Fail(std::string("cannot place the observer: ") + e.what(), frame.Window, viewport);
    return false;
  }
  return this->ChooseGPUPath(frame);
}

//------------------------------------------------------------------------------
bool vtkRiemannRayTracePass::ChooseGPUPath(FrameState& frame)
{
  const bool available = riemann::ComputeShadersAvailable();
  if (this->GPUPath == COMPUTE && !available)
  {
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    this->Fail(std::string("GPUPath Compute needs OpenGL 4.3 compute shaders, and this context "
                           "has OpenGL ") +
        (version ? version : "(unknown)") + " without them: use GPUPath Fragment or Auto",
      frame.Window, frame.Viewport);
    return false;
  }
  frame.UseCompute = this->GPUPath == COMPUTE || (this->GPUPath == AUTO && available);
  this->LastGPUPath = frame.UseCompute ? COMPUTE : FRAGMENT;
  return true;
}

//------------------------------------------------------------------------------
bool vtkRiemannRayTracePass::AddRendererActors(FrameState& frame)
{
  std::shared_ptr<const riemann::TriangleMesh> actors;
  try
  {
    actors = this->Internals->Actors.Update(frame.Renderer);
  }
  catch (const std::exception& e)
  {
    this->Fail(
      std::string("cannot draw the renderer's actors: ") + e.what(), frame.Window, frame.Viewport);
    return false;
  }
  this->NumberOfRenderedProps = this->Internals->Actors.GetNumberOfActors();
  frame.ActorMesh = actors.get();
  if (actors)
  {
    // The same mesh object while the actors do not change: nothing is rebuilt.
    auto scene = std::make_shared<riemann::Scene>(*frame.Scene);
    riemann::AddMesh(*scene, actors, riemann::Material());
    frame.Scene = scene;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkRiemannRayTracePass::ComposeSource(const FrameState& frame) const
{
  return riemann::ComposeRayTraceShader(
    this->ProgramChoices(frame), frame.MetricGlsl.Source, this->ExtraShaderCode ? this->ExtraShaderCode : "");
}

//------------------------------------------------------------------------------
riemann::RayTraceShaderChoices vtkRiemannRayTracePass::ProgramChoices(const FrameState& frame) const
{
  riemann::RayTraceShaderChoices choices;
  choices.Integrator = static_cast<int>(frame.Rays.Integrator);
  choices.Meshes = frame.Scene->HasMeshes();
  choices.Compute = frame.UseCompute;
  choices.Group[0] = frame.UseCompute ? this->ComputeWorkgroupSize[0] : 0;
  choices.Group[1] = frame.UseCompute ? this->ComputeWorkgroupSize[1] : 0;
  return choices;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkRiemannRayTracePass::ReadyProgram(FrameState& frame)
{
  vtkInternals& internals = *this->Internals;
  // Step 1: the same ingredients as the last frame: the same program.
  const riemann::RayTraceShaderChoices choices = this->ProgramChoices(frame);
  const char* extra = this->ExtraShaderCode ? this->ExtraShaderCode : "";
  const vtkInternals::ProgramIngredients& last = internals.LastIngredients;
  // The texts are compared where they are, not copied, while nothing changes.
  if (internals.LastProgram && internals.LastProgram->IsValid() && choices == last.Choices &&
    last.Extra == extra && last.MetricSource == frame.MetricGlsl.Source)
  {
    return this->BindProgram(*internals.LastProgram, frame);
  }
  internals.LastProgram = nullptr;

  // Step 2: compose the source; programs are cached by it.
  const std::string source = this->ComposeSource(frame);
  ++internals.NumberOfSourceCompositions;
  (frame.UseCompute ? this->ComputeShaderSource : this->FragmentShaderSource) = source;

  // Programs are cached by source; one that failed is not tried again.
  const auto failed = internals.FailedPrograms.find(source);
  if (failed != internals.FailedPrograms.end())
  {
    this->Fail(failed->second, frame.Window, frame.Viewport);
    return nullptr;
  }
  auto found = internals.Programs.find(source);
  if (found != internals.Programs.end() && !found->second.IsValid())
  {
    // The window released its graphics resources behind our back.
    internals.ErasePrograms(found, std::next(found), frame.Window);
    found = internals.Programs.end();
  }
  if (found == internals.Programs.end())
  {
    std::string message;
    CachedProgram built;
    if (frame.UseCompute)
    {
      ++this->NumberOfShaderCompilations;
      built.Compute = vtkSmartPointer<vtkRiemannComputeProgram>::New();
      if (!built.Compute->Build(source, message))
      {
        message = "the ray-tracing compute shader failed to compile or link: " + message;
        built.Compute = nullptr;
      }
    }
    else
    {
      built.Quad = this->BuildProgram(source, frame, message);
    }
    if (!built.IsValid())
    {
      internals.FailedPrograms[source] = message;
      this->Fail(message, frame.Window, frame.Viewport);
      return nullptr;
    }
    found = internals.StoreProgram(source, std::move(built));
  }
  internals.LastIngredients = { choices, frame.MetricGlsl.Source, extra };
  internals.LastProgram = &found->second;
  return this->BindProgram(found->second, frame);
}

vtkShaderProgram* vtkRiemannRayTracePass::BindProgram(CachedProgram& cached, FrameState& frame)
{
  cached.LastUse = ++this->Internals->UseCounter;
  if (frame.UseCompute)
  {
    frame.Compute = cached.Compute;
    frame.Compute->Use(frame.Window);
    return frame.Compute;
  }
  frame.Quad = cached.Quad.get();
  vtkShaderProgram* program =
    frame.Window->GetShaderCache()->ReadyShaderProgram(frame.Quad->Program);
  if (!program)
  {
    this->Fail("the ray-tracing shader could not be bound", frame.Window, frame.Viewport);
  }
  return program;
}

int vtkRiemannRayTracePass::GetNumberOfSourceCompositions() const
{
  return this->Internals->NumberOfSourceCompositions;
}

//------------------------------------------------------------------------------
std::unique_ptr<vtkOpenGLQuadHelper> vtkRiemannRayTracePass::BuildProgram(
  const std::string& source, const FrameState& frame, std::string& message)
{
  ++this->NumberOfShaderCompilations;
  // The fragment shader alone first: its log, without VTK's listing of the source.
  const std::string log = CheckFragmentShader(source);
  if (!log.empty())
  {
    message = "the ray-tracing shader failed to compile: " + log;
    return nullptr;
  }
  std::string vtkMessages;
  std::unique_ptr<vtkOpenGLQuadHelper> quad;
  {
    ScopedOutputCollector collector;
    quad.reset(new vtkOpenGLQuadHelper(frame.Window, nullptr, source.c_str(), ""));
    vtkMessages = collector.Summary();
  }
  Trim(vtkMessages);
  if (!quad->Program || !quad->Program->GetCompiled())
  {
    message = "the ray-tracing shader failed to compile or link: " +
      (vtkMessages.empty() ? std::string("(no log)") : vtkMessages);
    return nullptr;
  }
  return quad;
}

//------------------------------------------------------------------------------
bool vtkRiemannRayTracePass::SetMetricUniforms(vtkShaderProgram* program, FrameState& frame)
{
  for (const riemann::GlslUniform& uniform : frame.MetricGlsl.Uniforms)
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
        frame.Window, frame.Viewport);
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkRiemannRayTracePass::SetSceneUniforms(vtkShaderProgram* program, const FrameState& frame)
{
  const riemann::SceneUniforms packed = riemann::PackSceneUniforms(*frame.Scene);
  if (packed.Truncated)
  {
    vtkWarningMacro(<< "the scene has " << frame.Scene->Objects.size()
                    << " objects; the GPU pass draws the first "
                    << riemann::MaximumSceneUniformObjects);
  }
  program->SetUniformi("rt_object_count", packed.ObjectCount);
  std::string error;
  if (!this->Internals->SceneBlock.Bind(
        riemann::SceneUniformBlock(packed), program->GetHandle(), error))
  {
    this->Fail(error, frame.Window, frame.Viewport);
    return false;
  }

  const riemann::Scene& scene = *frame.Scene;
  float v3[3];
  ToFloat(scene.Background, v3);
  program->SetUniform3f("rt_background", v3);
  ToFloat(scene.FogColor, v3);
  program->SetUniform3f("rt_fog_color", v3);
  program->SetUniformf("rt_fog_density", static_cast<float>(scene.FogDensity));
  program->SetUniformi("rt_observer_light", scene.ObserverLight ? 1 : 0);
  return true;
}

//------------------------------------------------------------------------------
void vtkRiemannRayTracePass::SetObserverUniforms(vtkShaderProgram* program, const FrameState& frame)
{
  // The g-orthonormal frame at the eye.
  float v3[3];
  ToFloat(frame.Camera.Position, v3);
  program->SetUniform3f("rt_eye", v3);
  ToFloat(frame.Observer->GetForward(), v3);
  program->SetUniform3f("rt_forward", v3);
  ToFloat(frame.Observer->GetUp(), v3);
  program->SetUniform3f("rt_up", v3);
  ToFloat(frame.Observer->GetRight(), v3);
  program->SetUniform3f("rt_right", v3);
  program->SetUniformf("rt_tan_half_angle",
    static_cast<float>(std::tan(0.5 * vtkMath::RadiansFromDegrees(frame.Camera.ViewAngle))));
  program->SetUniformi("rt_projection", static_cast<int>(frame.Camera.Mode));

  // The integration; the adaptive step's range as riemann::TraceRay's.
  const riemann::RaySettings& rays = frame.Rays;
  program->SetUniformf("rt_step", static_cast<float>(rays.Step));
  program->SetUniformi("rt_max_steps", rays.MaximumSteps);
  program->SetUniformf("rt_max_length", static_cast<float>(rays.MaximumLength));
  program->SetUniformf("rt_tolerance", static_cast<float>(rays.Tolerance));
  program->SetUniformf(
    "rt_min_step", static_cast<float>(riemann::AdaptiveMinimumStepFactor * rays.Step));
  program->SetUniformf(
    "rt_max_step", static_cast<float>(riemann::AdaptiveMaximumStepFactor * rays.Step));
}

//------------------------------------------------------------------------------
bool vtkRiemannRayTracePass::ActivateMeshes(vtkShaderProgram* program, const FrameState& frame)
{
  if (!frame.Scene->HasMeshes())
  {
    return true;
  }
  // The hierarchy is built and uploaded when the meshes change, not per frame.
  riemann::MeshTextures& meshes = this->Internals->Meshes;
  std::string error;
  if (!meshes.Update(*frame.Scene, frame.Window, error))
  {
    this->Fail("cannot draw the scene's meshes: " + error, frame.Window, frame.Viewport);
    return false;
  }
  meshes.Activate(program);
  return true;
}

bool vtkRiemannRayTracePass::ActivateMetricTextures(
  vtkShaderProgram* program, const FrameState& frame)
{
  // Uploaded when the volume changes, not per frame.
  riemann::MetricTextures& volumes = this->Internals->MetricVolumes;
  std::string error;
  if (!volumes.Update(frame.MetricGlsl.Textures, frame.Window, error))
  {
    this->Fail("cannot draw the sampled metric: " + error, frame.Window, frame.Viewport);
    return false;
  }
  volumes.Activate(program);
  return true;
}

int vtkRiemannRayTracePass::GetNumberOfMetricTextureUploads() const
{
  return this->Internals->MetricVolumes.GetNumberOfUploads();
}

int vtkRiemannRayTracePass::GetNumberOfMeshBuilds() const
{
  return this->Internals->Meshes.GetNumberOfBuilds();
}

//------------------------------------------------------------------------------
bool vtkRiemannRayTracePass::ActivateEnvironment(vtkShaderProgram* program, const FrameState& frame)
{
  vtkInternals& internals = *this->Internals;
  const std::string& path = frame.Scene->EnvironmentImage;
  if (!path.empty() && path != internals.EnvironmentPath)
  {
    internals.LoadEnvironment(path, frame.Window);
    if (!internals.EnvironmentError.empty())
    {
      // Reported once per image; the background colour stands in for it.
      vtkErrorMacro(<< "cannot use the environment image " << path << ": "
                    << internals.EnvironmentError << " (the background colour is shown instead)");
    }
  }
  const bool useEnvironment = !path.empty() && internals.Environment != nullptr;
  if (useEnvironment)
  {
    internals.Environment->Activate();
    program->SetUniformi("rt_environment", internals.Environment->GetTextureUnit());
  }
  else
  {
    internals.IdleEnvironmentUnit = frame.Window->GetTextureUnitManager()->Allocate();
    program->SetUniformi("rt_environment", std::max(internals.IdleEnvironmentUnit, 0));
  }
  program->SetUniformi("rt_use_environment", useEnvironment ? 1 : 0);
  return useEnvironment;
}

//------------------------------------------------------------------------------
bool vtkRiemannRayTracePass::DrawView(vtkShaderProgram* program, const FrameState& frame)
{
  const int* viewport = frame.Viewport;
  vtkOpenGLState* ostate = frame.Window->GetState();
  const ScopedQuadState quadState(ostate);
  program->SetUniformi("rt_output", 0);

  // Every pixel's depth is written (gl_FragDepth), whatever was there.
  vtkOpenGLState::ScopedglDepthFunc depthFunction(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  double range[2] = { 0.0, 0.0 };
  frame.Renderer->GetActiveCamera()->GetClippingRange(range);
  const float clipping[2] = { static_cast<float>(range[0]), static_cast<float>(range[1]) };
  program->SetUniform2f("rt_clipping_range", clipping);

  // One ray per pixel, or per d x d pixels magnified (ReducedView).
  double distance = this->ChooseImageSampleDistance(frame);
  if (frame.UseCompute && this->ProgressiveRefinement && distance == 1.0 &&
    !this->IsInteractive(frame))
  {
    return this->RefineView(program, frame);
  }
  this->Internals->Refine.Started = false; // a whole frame: a later refinement starts afresh
  this->Internals->Refine.Complete = true;
  if (frame.UseCompute)
  {
    return this->DrawViewByCompute(program, frame, distance);
  }
  if (distance > 1.0)
  {
    const int width = riemann::TracedPixels(viewport[2], distance);
    const int height = riemann::TracedPixels(viewport[3], distance);
    std::string error;
    riemann::ReducedView& reduced = this->Internals->Reduced;
    if (reduced.Bind(frame.Window, width, height, error))
    {
      ostate->vtkglViewport(0, 0, width, height);
      ostate->vtkglScissor(0, 0, width, height);
      // The viewport measured in traced pixels: pixel i's ray is the one
      // through the full view's point (i + 1/2) d, and the aspect is kept.
      const float traced[4] = { 0.0f, 0.0f, static_cast<float>(viewport[2] / distance),
        static_cast<float>(viewport[3] / distance) };
      program->SetUniform4f("rt_viewport", traced);
      this->TraceView(frame, distance, width, height);
      reduced.Unbind(frame.Window);
      const double extent[2] = { viewport[2] / distance, viewport[3] / distance };
      const bool magnified = reduced.Magnify(frame.Window, viewport, extent, error);
      // The ray-tracing program is current again (the hit capture draws with it).
      frame.Window->GetShaderCache()->ReadyShaderProgram(program);
      if (magnified)
      {
        this->LastImageSampleDistance = distance;
        return true;
      }
    }
    // Nothing is lost: the view is traced at full resolution instead.
    vtkWarningMacro(<< "tracing one ray per pixel: " << error);
    distance = 1.0;
  }
  ostate->vtkglViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  ostate->vtkglScissor(viewport[0], viewport[1], viewport[2], viewport[3]);
  const float window[4] = { static_cast<float>(viewport[0]), static_cast<float>(viewport[1]),
    static_cast<float>(viewport[2]), static_cast<float>(viewport[3]) };
  program->SetUniform4f("rt_viewport", window);
  this->TraceView(frame, distance, viewport[2], viewport[3]);
  this->LastImageSampleDistance = distance;
  return true;
}

bool vtkRiemannRayTracePass::DrawViewByCompute(
  vtkShaderProgram* program, const FrameState& frame, double distance)
{
  // Step 1: the images, one pixel per traced ray (all pixels at distance 1).
  const int* viewport = frame.Viewport;
  const int width = riemann::TracedPixels(viewport[2], distance);
  const int height = riemann::TracedPixels(viewport[3], distance);
  riemann::ReducedView& reduced = this->Internals->Reduced;
  std::string error;
  if (!reduced.BindImages(frame.Window, width, height, error))
  {
    frame.Compute->Unuse();
    this->Fail("the compute path cannot draw: " + error, frame.Window, frame.Viewport);
    return false;
  }

  // Step 2: trace. The viewport is measured in traced pixels, so pixel i's
  // ray is the one through the full view's point (i + 1/2) d, as on the
  // fragment path.
  const float traced[4] = { 0.0f, 0.0f, static_cast<float>(viewport[2] / distance),
    static_cast<float>(viewport[3] / distance) };
  program->SetUniform4f("rt_viewport", traced);
  const int size[2] = { width, height };
  program->SetUniform2i("rt_traced_size", size);
  SetLattice(program, 1, 0, width, height, false);
  this->TraceView(frame, distance, width, height);
  reduced.UnbindImages();
  frame.Compute->Unuse();

  // Step 3: compose colour and depth into the viewport (exact at distance 1).
  const double extent[2] = { viewport[2] / distance, viewport[3] / distance };
  if (!reduced.Magnify(frame.Window, viewport, extent, error))
  {
    this->Fail("the compute path cannot compose its image: " + error, frame.Window, viewport);
    return false;
  }
  this->LastImageSampleDistance = distance;
  return true;
}

//------------------------------------------------------------------------------
bool vtkRiemannRayTracePass::RefineView(vtkShaderProgram* program, const FrameState& frame)
{
  vtkInternals& internals = *this->Internals;
  vtkInternals::Refinement& refine = internals.Refine;
  const int* viewport = frame.Viewport;
  const int width = viewport[2];
  const int height = viewport[3];

  // Step 1: the view refined so far, or a new one from the coarsest lattice.
  vtkCamera* camera = frame.Renderer->GetActiveCamera();
  std::vector<double> key = { static_cast<double>(this->GetMTime()),
    static_cast<double>(reinterpret_cast<std::uintptr_t>(frame.ActorMesh)),
    static_cast<double>(viewport[0]), static_cast<double>(viewport[1]),
    static_cast<double>(width), static_cast<double>(height), camera->GetViewAngle() };
  for (const double* numbers : { camera->GetPosition(), camera->GetFocalPoint(),
         camera->GetViewUp() })
  {
    key.insert(key.end(), numbers, numbers + 3);
  }
  const double* clipping = camera->GetClippingRange();
  key.insert(key.end(), clipping, clipping + 2);
  if (!refine.Started || key != refine.Key)
  {
    refine.Key = key;
    refine.Started = true;
    refine.Complete = false;
    refine.Level = FirstRefinementLevel(
      static_cast<double>(width) * height, refine.SecondsPerRay, this->RefinementSeconds);
    refine.Coarsest = refine.Level;
    refine.RowsDone = 0;
  }
  riemann::ReducedView& target = internals.Refined;
  std::string error;
  if (!target.BindImages(frame.Window, width, height, error))
  {
    frame.Compute->Unuse();
    this->Fail("the compute path cannot draw: " + error, frame.Window, viewport);
    return false;
  }

  // Step 2: the next piece: the whole first lattice, then bands of rows of
  // the finer ones (in pairs of rows: RiemannRayTraceCS.glsl) that take
  // about RefinementSeconds.
  if (!refine.Complete)
  {
    const bool first = refine.Level == refine.Coarsest;
    const int level = refine.Level;
    const int columns = (width + level - 1) / level;
    const int rowsLeft = (height - refine.RowsDone + level - 1) / level;
    // Lattice rows of this piece, and the rays new in each.
    int rows = rowsLeft;
    const double newPerRow = first ? columns : 0.75 * columns;
    if (!first && refine.SecondsPerRay > 0.0)
    {
      // Pairs of rows (the packing's unit). Rounding up to whole workgroups
      // would idle no invocation, but on llvmpipe it made pieces of 16 rows
      // take 6 times the budget; a partly idle workgroup costs little.
      const double fit = this->RefinementSeconds / (newPerRow * refine.SecondsPerRay);
      const int fitted = std::max(2, static_cast<int>(std::min<double>(rowsLeft, fit)));
      rows = std::min(rowsLeft, (fitted + 1) / 2 * 2);
    }
    const float full[4] = { 0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height) };
    program->SetUniform4f("rt_viewport", full);
    const int size[2] = { width, height };
    program->SetUniform2i("rt_traced_size", size);
    const int pairs = (rows + 1) / 2;
    SetLattice(program, level, refine.RowsDone, columns, first ? rows : pairs, !first);
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    if (first)
    {
      this->DispatchRays(frame, columns, rows);
    }
    else
    {
      this->DispatchRays(frame, columns + columns / 2, pairs);
    }
    glFinish();
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    refine.SecondsPerRay = elapsed.count() / std::max(1.0, newPerRow * rows);
    // What a whole frame would take, for the interactive frames' distance.
    internals.TraceSeconds = refine.SecondsPerRay * width * height;
    internals.TraceDistance = 1.0;
    refine.RowsDone += (first ? rows : 2 * pairs) * level;
    if (refine.RowsDone >= height)
    {
      refine.Complete = level == 1;
      refine.Level = std::max(1, level / 2);
      refine.RowsDone = refine.Complete ? height : 0;
    }
  }
  target.UnbindImages();
  frame.Compute->Unuse();

  // Step 3: compose, each pixel from the finest lattice traced there.
  if (!target.ComposeLattice(frame.Window, viewport, refine.Level, refine.RowsDone, error))
  {
    this->Fail("the compute path cannot compose its image: " + error, frame.Window, viewport);
    return false;
  }
  this->LastImageSampleDistance = this->GetRefinementLevel();
  return true;
}

void vtkRiemannRayTracePass::SetRefinementSeconds(double seconds)
{
  this->RefinementSeconds = std::min(10.0, std::max(0.001, seconds));
}

bool vtkRiemannRayTracePass::GetRefinementComplete() const
{
  return this->Internals->Refine.Complete;
}

int vtkRiemannRayTracePass::GetRefinementLevel() const
{
  // Until the lattice being traced has covered rows, the picture is the one before it.
  const vtkInternals::Refinement& refine = this->Internals->Refine;
  return refine.Complete ? 1 : (refine.RowsDone > 0 ? refine.Level : 2 * refine.Level);
}

bool vtkRiemannRayTracePass::IsInteractive(const FrameState& frame) const
{
  vtkRenderWindow* window = frame.Renderer->GetRenderWindow();
  vtkRenderWindowInteractor* interactor = window->GetInteractor();
  const double stillRate = interactor ? interactor->GetStillUpdateRate() : 0.0001;
  return window->GetDesiredUpdateRate() > stillRate;
}

double vtkRiemannRayTracePass::ChooseImageSampleDistance(const FrameState& frame) const
{
  // Still renders: the distance asked for (1: every pixel).
  if (!this->AutoAdjustSampleDistances || !this->IsInteractive(frame))
  {
    return this->ImageSampleDistance;
  }
  // Interactive: the distance that fits the renderer's share of the frame.
  const vtkInternals& internals = *this->Internals;
  const double distance =
    internals.TraceSeconds > 0.0 ? internals.TraceDistance : this->ImageSampleDistance;
  return riemann::AdjustedImageSampleDistance(distance, internals.TraceSeconds,
    frame.Renderer->GetAllocatedRenderTime(), this->MinimumImageSampleDistance,
    this->MaximumImageSampleDistance);
}

void vtkRiemannRayTracePass::DispatchRays(const FrameState& frame, int width, int height)
{
  if (frame.UseCompute)
  {
    frame.Compute->Dispatch(
      width, height, this->ComputeWorkgroupSize[0], this->ComputeWorkgroupSize[1]);
  }
  else
  {
    frame.Quad->Render();
  }
}

void vtkRiemannRayTracePass::TraceView(
  const FrameState& frame, double distance, int width, int height)
{
  if (!this->AutoAdjustSampleDistances)
  {
    this->DispatchRays(frame, width, height);
    return;
  }
  // Timed to the end of the GPU's work: glFinish before (what earlier draws
  // left) and after. The stall is small next to a traced frame.
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  this->DispatchRays(frame, width, height);
  glFinish();
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  this->Internals->TraceSeconds = elapsed.count();
  this->Internals->TraceDistance = distance;
}

//------------------------------------------------------------------------------
void vtkRiemannRayTracePass::RenderOverlays(const vtkRenderState* s)
{
  // As vtkDefaultPass::RenderOverlay: text, scalar bars and other 2D props on
  // top. A 2D actor lays itself out in its opaque pass (a text actor renders
  // its string into a texture there) and draws in the overlay; its opaque
  // pass draws nothing, so it runs here, after the view.
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (prop->IsA("vtkActor2D"))
    {
      prop->RenderOpaqueGeometry(s->GetRenderer());
    }
    this->NumberOfRenderedProps += prop->RenderOverlay(s->GetRenderer());
  }
}

//------------------------------------------------------------------------------
void vtkRiemannRayTracePass::CaptureHitImage(vtkShaderProgram* program, const FrameState& frame)
{
  vtkInternals& internals = *this->Internals;
  const int width = frame.Viewport[2];
  const int height = frame.Viewport[3];
  vtkOpenGLState* ostate = frame.Window->GetState();
  const ScopedQuadState quadState(ostate);

  // The same rays into a float target: (x, y, z, arc length) per pixel.
  internals.ReadyHitTarget(frame.Window, width, height);
  ostate->PushFramebufferBindings();
  internals.HitFramebuffer->Bind();
  internals.HitFramebuffer->AddColorAttachment(0, internals.HitTexture);
  internals.HitFramebuffer->ActivateDrawBuffer(0);
  internals.HitFramebuffer->ActivateReadBuffer(0);
  const char* status = nullptr;
  const bool complete = vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_FRAMEBUFFER, status);
  if (complete)
  {
    ostate->vtkglViewport(0, 0, width, height);
    ostate->vtkglScissor(0, 0, width, height);
    if (frame.UseCompute)
    {
      // Into the same texture as an image (unit 2 of RiemannRayTraceCS.glsl).
      frame.Compute->Use(frame.Window);
      glBindImageTexture(
        2, internals.HitTexture->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
      const int size[2] = { width, height };
      program->SetUniform2i("rt_traced_size", size);
      SetLattice(program, 1, 0, width, height, false);
    }
    float target[4] = { 0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height) };
    program->SetUniform4f("rt_viewport", target);
    program->SetUniformi("rt_output", 1);
    this->DispatchRays(frame, width, height);
    program->SetUniformi("rt_output", 0);
    if (frame.UseCompute)
    {
      glBindImageTexture(2, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
      frame.Compute->Unuse();
    }
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

//------------------------------------------------------------------------------
void vtkRiemannRayTracePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* projections[] = { "Perspective", "Equirectangular" };
  os << indent << "Metric: " << this->Metric << "\n";
  os << indent << "Scene: " << this->Scene << "\n";
  os << indent << "UseSceneSettings: " << (this->UseSceneSettings ? "On" : "Off") << "\n";
  os << indent << "IntegrationSettings:\n";
  this->IntegrationSettings->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Projection: " << projections[this->Projection] << "\n";
  os << indent << "CaptureHits: " << (this->CaptureHits ? "On" : "Off") << "\n";
  os << indent << "ImageSampleDistance: " << this->ImageSampleDistance << "\n";
  os << indent << "AutoAdjustSampleDistances: " << (this->AutoAdjustSampleDistances ? "On" : "Off")
     << "\n";
  os << indent << "MinimumImageSampleDistance: " << this->MinimumImageSampleDistance << "\n";
  os << indent << "MaximumImageSampleDistance: " << this->MaximumImageSampleDistance << "\n";
  os << indent << "LastImageSampleDistance: " << this->LastImageSampleDistance << "\n";
  os << indent << "FilteredTextureReads: " << (this->FilteredTextureReads ? "On" : "Off") << "\n";
  os << indent << "GPUPath: " << GetGPUPathAsString(this->GPUPath) << "\n";
  os << indent << "LastGPUPath: " << GetGPUPathAsString(this->LastGPUPath) << "\n";
  os << indent << "ComputeWorkgroupSize: " << this->ComputeWorkgroupSize[0] << " x "
     << this->ComputeWorkgroupSize[1] << "\n";
  os << indent << "ProgressiveRefinement: " << (this->ProgressiveRefinement ? "On" : "Off")
     << " (pieces of " << this->RefinementSeconds << " s)\n";
  os << indent << "HitImage: " << this->HitImageWidth << " x " << this->HitImageHeight << "\n";
  os << indent << "NumberOfShaderCompilations: " << this->NumberOfShaderCompilations << "\n";
  os << indent << "ExtraShaderCode: " << (this->ExtraShaderCode ? "(set)" : "(none)") << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
}
