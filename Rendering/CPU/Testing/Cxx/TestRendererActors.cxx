// A renderer's vtkActors in the inside view (vtkRiemannRayTracePass with
// UseRendererProps, riemann::MeshFromActor):
// - a torus coloured by its scalars and a sphere through a transform, in the
//   two-bump metric: the GPU pass draws them as the CPU tracer does
//   (AddActor), per-pixel statistics as for the shipped scenes;
// - in Euclidean space they cover the pixels VTK's own rendering covers;
// - moving the camera rebuilds nothing, moving or recolouring an actor
//   rebuilds the meshes' buffers and never recompiles the shader;
// - the depth written is the hit's Euclidean distance mapped to the clipping
//   range, the far plane where nothing is hit; text overlays are drawn on top;
// - a composite mapper's actor (ParaView's) is drawn as its polydata leaves.
#include "vtkRiemannCPURayTracer.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannScene.h"

#include "vtkActor.h"
#include "vtkAutoInit.h"
#include "vtkCamera.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTransform.h"

#include "ImageComparison.h"
#include "RenderingTestUtilities.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingFreeType);

namespace
{
using riemann::testing::Compare;
using riemann::testing::CpuPixels;
using riemann::testing::ErrorObserver;
using riemann::testing::KeepXServerConnection;
using riemann::testing::WindowPixels;

constexpr int Width = 160;
constexpr int Height = 120;

const char* const TwoBumps = R"({"type": "graph", "gaussians": [
  {"amplitude": 1.0, "center": [-0.6, 0, -1.5], "sigma": 0.5},
  {"amplitude": -0.8, "center": [0.9, 0.2, -2.0], "sigma": 0.6}]})";
const char* const Euclidean = R"({"type": "euclidean"})";

/// A checker floor around the actors, or nothing at all.
std::string SceneJson(bool floor)
{
  return std::string(R"({"camera": {"position": [0, 0.6, 4.5], "look_at": [0, -0.2, -1.0],
    "view_up": [0, 1, 0], "fov": 55},
    "integrator": {"method": "rk4", "step": 0.02, "max_steps": 1500, "max_length": 25},
    "background": [0.05, 0.05, 0.08], "lighting": "observer", "objects": [)") +
    (floor ? R"({"type": "plane", "point": [0, -2, 0], "normal": [0, 1, 0],
      "material": {"type": "checker", "color": [0.85, 0.85, 0.85],
      "color2": [0.25, 0.25, 0.3], "size": 0.5}})"
           : "") +
    "]}";
}

/// The issue's actors: a torus coloured by z through its mapper's lookup
/// table, and a sphere moved and scaled by a user transform.
struct Actors
{
  vtkNew<vtkParametricTorus> Torus;
  vtkNew<vtkParametricFunctionSource> TorusSource;
  vtkNew<vtkPolyDataMapper> TorusMapper;
  vtkNew<vtkActor> TorusActor;
  vtkNew<vtkSphereSource> Sphere;
  vtkNew<vtkPolyDataMapper> SphereMapper;
  vtkNew<vtkTransform> SphereTransform;
  vtkNew<vtkActor> SphereActor;

  Actors()
  {
    this->Torus->SetRingRadius(1.0);
    this->Torus->SetCrossSectionRadius(0.35);
    this->TorusSource->SetParametricFunction(this->Torus);
    this->TorusSource->SetUResolution(64);
    this->TorusSource->SetVResolution(24);
    this->TorusSource->SetScalarModeToZ();
    this->TorusMapper->SetInputConnection(this->TorusSource->GetOutputPort());
    this->TorusMapper->SetScalarRange(-0.35, 0.35);
    this->TorusActor->SetMapper(this->TorusMapper);
    this->TorusActor->SetPosition(-0.9, -0.3, -1.5);
    this->TorusActor->RotateX(60);

    this->Sphere->SetThetaResolution(48);
    this->Sphere->SetPhiResolution(24);
    this->SphereMapper->SetInputConnection(this->Sphere->GetOutputPort());
    this->SphereTransform->Translate(1.3, -0.6, -2.2);
    this->SphereTransform->Scale(1.2, 0.8, 1.2);
    this->SphereActor->SetMapper(this->SphereMapper);
    this->SphereActor->SetUserTransform(this->SphereTransform);
    this->SphereActor->GetProperty()->SetColor(0.95, 0.55, 0.2);
  }

  void AddTo(vtkRenderer* renderer)
  {
    renderer->AddActor(this->TorusActor);
    renderer->AddActor(this->SphereActor);
  }
};

/// A window whose renderer holds the actors and is drawn by the pass.
struct PassView
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRiemannRayTracePass> Pass;
  vtkNew<vtkRiemannMetric> Metric;
  vtkNew<vtkRiemannScene> Scene;

  PassView(const char* metric, bool floor)
  {
    KeepXServerConnection();
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(Width, Height);
    this->Window->AddRenderer(this->Renderer);
    EXPECT_TRUE(this->Metric->SetDefinition(metric));
    EXPECT_TRUE(this->Scene->SetDefinition(SceneJson(floor).c_str()))
      << this->Scene->GetLastError();
    this->Pass->SetMetric(this->Metric);
    this->Pass->SetScene(this->Scene);
    this->Pass->UseRendererPropsOn();
    this->Renderer->SetPass(this->Pass);
    this->Scene->ApplyCamera(this->Renderer->GetActiveCamera());
  }
};

std::vector<unsigned char> CpuPicture(vtkRiemannMetric* metric, vtkRiemannScene* scene,
  vtkCamera* camera, const std::vector<vtkActor*>& actors)
{
  vtkNew<vtkRiemannCPURayTracer> tracer;
  ErrorObserver errors(tracer);
  tracer->SetMetric(metric);
  tracer->SetScene(scene);
  for (vtkActor* actor : actors)
  {
    tracer->AddActor(actor);
  }
  tracer->SetCamera(camera);
  tracer->SetWidth(Width);
  tracer->SetHeight(Height);
  tracer->Update();
  EXPECT_TRUE(errors.Messages.empty()) << errors.All();
  return CpuPixels(tracer->GetOutput());
}
} // namespace

TEST(RendererActors, GpuDrawsActorsAsTheCpuTracer)
{
  // Stated tolerances as for the shipped scenes (TestCPURayTracer): mean
  // difference under 0.05 of 255, 99th percentile at most 1, at most 0.1 %
  // of the pixels apart by more than 24 (float rays against double ones
  // land across a silhouette after hundreds of steps).
  Actors actors;
  PassView view(TwoBumps, true);
  ErrorObserver errors(view.Pass);
  actors.AddTo(view.Renderer);
  view.Window->Render();
  ASSERT_TRUE(errors.Messages.empty()) << errors.All();
  EXPECT_EQ(view.Pass->GetNumberOfRenderedProps(), 2);
  const std::vector<unsigned char> gpu = WindowPixels(view.Window);
  const std::vector<unsigned char> cpu = CpuPicture(view.Metric, view.Scene,
    view.Renderer->GetActiveCamera(), { actors.TorusActor, actors.SphereActor });
  const riemann::testing::DifferenceStatistics s = Compare(gpu, cpu, 24);
  std::cout << "actors in two bumps, GPU vs CPU: mean " << s.Mean << ", 99th percentile "
            << s.Percentile99 << ", pixels > 24: " << 100.0 * s.FractionAbove << "%\n";
  EXPECT_LT(s.Mean, 0.05);
  EXPECT_LE(s.Percentile99, 1.0);
  EXPECT_LT(s.FractionAbove, 0.001);

  // The actors show: many pixels are neither the background nor the floor's grey.
  int coloured = 0;
  for (std::size_t i = 0; i < gpu.size(); i += 3)
  {
    const int r = gpu[i];
    const int g = gpu[i + 1];
    const int b = gpu[i + 2];
    coloured += std::max({ std::abs(r - g), std::abs(g - b), std::abs(r - b) }) > 40 ? 1 : 0;
  }
  EXPECT_GT(coloured, Width * Height / 50);
}

TEST(RendererActors, EuclideanViewCoversWhatVtkDraws)
{
  // Straight rays: the actors cover the pixels VTK's rasteriser covers (the
  // same camera); only silhouette pixels may differ.
  const std::array<double, 3> background = { 0.05, 0.05, 0.08 };
  auto covered = [&](const std::vector<unsigned char>& pixels)
  {
    std::vector<bool> mask(pixels.size() / 3);
    for (std::size_t i = 0; i < mask.size(); ++i)
    {
      int difference = 0;
      for (int c = 0; c < 3; ++c)
      {
        difference = std::max(
          difference, std::abs(int(pixels[3 * i + c]) - int(std::lround(255 * background[c]))));
      }
      mask[i] = difference > 3;
    }
    return mask;
  };
  Actors actors;
  PassView view(Euclidean, false);
  actors.AddTo(view.Renderer);
  view.Renderer->ResetCameraClippingRange();
  view.Window->Render();
  const std::vector<bool> ours = covered(WindowPixels(view.Window));

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(Width, Height);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(background.data());
  window->AddRenderer(renderer);
  actors.AddTo(renderer);
  renderer->GetActiveCamera()->DeepCopy(view.Renderer->GetActiveCamera());
  renderer->ResetCameraClippingRange();
  window->Render();
  const std::vector<bool> vtks = covered(WindowPixels(window));

  int both = 0;
  int either = 0;
  for (std::size_t i = 0; i < ours.size(); ++i)
  {
    both += ours[i] && vtks[i] ? 1 : 0;
    either += ours[i] || vtks[i] ? 1 : 0;
  }
  std::cout << "Euclidean coverage: " << both << " pixels in both of " << either << "\n";
  ASSERT_GT(both, Width * Height / 20);
  EXPECT_GT(static_cast<double>(both) / either, 0.97);
}

TEST(RendererActors, ModificationsRebuildBuffersNeverTheShader)
{
  Actors actors;
  PassView view(TwoBumps, false);
  actors.AddTo(view.Renderer);
  view.Window->Render();
  const int compilations = view.Pass->GetNumberOfShaderCompilations();
  EXPECT_EQ(view.Pass->GetNumberOfMeshBuilds(), 1);
  view.Window->Render();
  view.Renderer->GetActiveCamera()->Azimuth(10);
  view.Window->Render();
  EXPECT_EQ(view.Pass->GetNumberOfMeshBuilds(), 1) << "nothing changed but the camera";
  const std::vector<unsigned char> before = WindowPixels(view.Window);

  actors.SphereActor->SetPosition(0.2, 0.0, 0.0);
  view.Window->Render();
  EXPECT_EQ(view.Pass->GetNumberOfMeshBuilds(), 2) << "an actor moved";
  actors.SphereActor->GetProperty()->SetColor(0.2, 0.4, 0.9);
  view.Window->Render();
  EXPECT_EQ(view.Pass->GetNumberOfMeshBuilds(), 3) << "an actor was recoloured";
  actors.TorusMapper->SetScalarRange(-1.0, 1.0);
  view.Window->Render();
  EXPECT_EQ(view.Pass->GetNumberOfMeshBuilds(), 4) << "the scalar colouring changed";
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), compilations);
  EXPECT_GT(riemann::testing::Compare(before, WindowPixels(view.Window), 24).FractionAbove, 0.01);

  // A hidden actor is not drawn; an actor of opacity 0 neither.
  actors.SphereActor->VisibilityOff();
  actors.TorusActor->GetProperty()->SetOpacity(0.0);
  view.Window->Render();
  EXPECT_EQ(view.Pass->GetNumberOfRenderedProps(), 0);
  EXPECT_STREQ(view.Pass->GetLastError(), "");
}

TEST(RendererActors, DepthIsTheHitsDistanceAndOverlaysComposeOnTop)
{
  // A unit sphere 4 units in front of the eye, Euclidean: the centre pixel's
  // hit is at distance 4 - (a hair, the half-pixel offset).
  PassView view(Euclidean, false);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(48);
  // 5 units from the eye (0, 0.6, 4.5) along the view axis, towards (0, -0.2, -1).
  const double axis = std::sqrt(0.8 * 0.8 + 5.5 * 5.5);
  sphere->SetCenter(0.0, 0.6 - 5.0 * 0.8 / axis, 4.5 - 5.0 * 5.5 / axis);
  sphere->SetRadius(1.0);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  view.Renderer->AddActor(actor);
  view.Renderer->ResetCameraClippingRange();
  view.Window->Render();
  double range[2];
  view.Renderer->GetActiveCamera()->GetClippingRange(range);
  const double distance = 4.0;
  const double expected = (1.0 / range[0] - 1.0 / distance) / (1.0 / range[0] - 1.0 / range[1]);
  const double centre = view.Window->GetZbufferDataAtPoint(Width / 2, Height / 2);
  EXPECT_NEAR(centre, expected, 2e-3) << "clipping range " << range[0] << " " << range[1];
  EXPECT_EQ(view.Window->GetZbufferDataAtPoint(2, Height - 3), 1.0f) << "no hit: the far plane";

  // White text in the lower left corner, drawn over the view.
  auto whitePixels = [&]()
  {
    const std::vector<unsigned char> pixels = WindowPixels(view.Window);
    int white = 0;
    for (int y = 0; y < 40; ++y)
    {
      for (int x = 0; x < Width / 2; ++x)
      {
        const unsigned char* p = &pixels[3 * (static_cast<std::size_t>(y) * Width + x)];
        white += p[0] > 200 && p[1] > 200 && p[2] > 200 ? 1 : 0;
      }
    }
    return white;
  };
  EXPECT_EQ(whitePixels(), 0);
  vtkNew<vtkTextActor> text;
  text->SetInput("Overlay");
  text->GetTextProperty()->SetFontSize(24);
  text->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
  text->SetPosition(4, 4);
  view.Renderer->AddActor2D(text);
  view.Window->Render();
  EXPECT_GT(whitePixels(), 30);
  EXPECT_EQ(view.Pass->GetNumberOfRenderedProps(), 2) << "the sphere and the text";
}

// ParaView's representations give their mappers composite data (a
// vtkCompositePolyDataMapper2 over a vtkMultiBlockDataSet): the actor is
// drawn as its polydata leaves, the same picture as the same polydata under
// a vtkPolyDataMapper, and it is converted again only when the data change.
TEST(RendererActors, CompositeInputIsDrawnAsItsPolyDataLeaves)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  sphere->SetCenter(0.3, -0.2, -1.5);
  sphere->Update();
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, sphere->GetOutput());
  vtkNew<vtkCompositePolyDataMapper2> compositeMapper;
  compositeMapper->SetInputDataObject(blocks);
  vtkNew<vtkActor> compositeActor;
  compositeActor->SetMapper(compositeMapper);
  vtkNew<vtkPolyDataMapper> plainMapper;
  plainMapper->SetInputData(sphere->GetOutput());
  vtkNew<vtkActor> plainActor;
  plainActor->SetMapper(plainMapper);

  PassView composite(TwoBumps, false);
  composite.Renderer->AddActor(compositeActor);
  composite.Window->Render();
  EXPECT_STREQ(composite.Pass->GetLastError(), "");
  EXPECT_EQ(composite.Pass->GetNumberOfRenderedProps(), 1);
  PassView plain(TwoBumps, false);
  plain.Renderer->AddActor(plainActor);
  plain.Window->Render();
  EXPECT_EQ(WindowPixels(composite.Window), WindowPixels(plain.Window));
  composite.Window->Render();
  EXPECT_EQ(composite.Pass->GetNumberOfMeshBuilds(), 1) << "nothing changed";
}
