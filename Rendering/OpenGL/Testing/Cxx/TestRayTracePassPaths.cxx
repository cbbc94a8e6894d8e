// vtkRiemannRayTracePass's two GPU paths: the fragment shader and the
// compute shader run the same GLSL (RiemannRayTracePixel.glsl), so they must
// draw the same pictures.
//
// - Every shipped scene (Data/scenes) at 160 x 120: colour, window depth and
//   the hit capture of both paths, per pixel. Stated tolerances: the mean
//   colour difference under 0.02 (of 255), at most 0.05% of the pixels (10
//   of 19,200) differing by more than 1 level, and the same for depth (more
//   than 1e-5 apart) and for hits (more than 1e-4 apart). Measured on Mesa
//   llvmpipe: every colour, depth and hit equal in all 8 scenes. (A first
//   build of the compute shader rounded one float otherwise, and one
//   grid-edge pixel of paper-saddle-along-z landed on the other side of a
//   bar after hundreds of steps: the margin is for such compilers.)
// - Reduced views (one ray per d x d pixels) are the same on both paths.
// - The workgroup size (also one that does not divide the image) changes
//   the schedule, never a pixel.
// - Auto takes the compute path where the context has it (llvmpipe: 4.5);
//   a bad workgroup size is refused; a broken compute shader is an error
//   quoting the GLSL compiler, as on the fragment path.
//
// Rendering runs on Mesa llvmpipe under Xvfb: images stay small.
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannScene.h"

#include "vtkAutoInit.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "ImageComparison.h"
#include "RenderingTestUtilities.h"
#include "RiemannComputeProgram.h"
#include "TestDataDirectory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

VTK_MODULE_INIT(vtkRenderingOpenGL2);

namespace
{
namespace fs = std::filesystem;
using riemann::testing::Compare;
using riemann::testing::DifferenceStatistics;
using riemann::testing::ErrorObserver;
using riemann::testing::SetUpOffscreenView;
using riemann::testing::WindowPixels;

using riemann::testing::DataDirectory;

/// What one render of one path gives: colour, window depth and hits.
struct Picture
{
  std::vector<unsigned char> Colour;
  std::vector<float> Depth;
  std::vector<float> Hits;
  int Path = vtkRiemannRayTracePass::AUTO;
};

/// An offscreen window whose renderer draws a scene with the pass.
struct View
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRiemannRayTracePass> Pass;
  vtkNew<vtkRiemannMetric> Metric;
  vtkNew<vtkRiemannScene> Scene;
  int Width;
  int Height;

  View(int width, int height)
    : Width(width)
    , Height(height)
  {
    SetUpOffscreenView(this->Window, this->Renderer, this->Pass, width, height);
    this->Pass->SetMetric(this->Metric);
    this->Pass->SetScene(this->Scene);
    this->Pass->CaptureHitsOn();
  }

  /// Read the scene file and its metric (Euclidean when it has none), and take its camera.
  void Load(const fs::path& file)
  {
    ASSERT_TRUE(this->Scene->SetDefinitionFile(file.c_str())) << this->Scene->GetLastError();
    ASSERT_TRUE(this->Metric->SetDefinition(this->Scene->HasMetricDefinition()
        ? this->Scene->GetMetricDefinition().c_str()
        : R"({"type": "euclidean"})"))
      << this->Metric->GetLastError();
    this->Scene->ApplyCamera(this->Renderer->GetActiveCamera());
  }

  Picture Render(int path)
  {
    this->Pass->SetGPUPath(path);
    this->Window->Render();
    Picture picture;
    picture.Path = this->Pass->GetLastGPUPath();
    picture.Colour = WindowPixels(this->Window);
    vtkNew<vtkFloatArray> depth;
    this->Window->GetZbufferData(0, 0, this->Width - 1, this->Height - 1, depth);
    picture.Depth.assign(depth->GetPointer(0), depth->GetPointer(0) + this->Width * this->Height);
    vtkFloatArray* hits = this->Pass->GetHitImage();
    picture.Hits.assign(
      hits->GetPointer(0), hits->GetPointer(0) + 4 * hits->GetNumberOfTuples());
    return picture;
  }
};

/// The fraction of the values whose difference exceeds `threshold`, counted per pixel
/// (`components` values each).
double FractionApart(
  const std::vector<float>& a, const std::vector<float>& b, int components, double threshold)
{
  if (a.size() != b.size())
  {
    return 1.0;
  }
  if (a.empty())
  {
    return 0.0; // nothing captured on either path
  }
  std::size_t apart = 0;
  for (std::size_t i = 0; i < a.size(); i += components)
  {
    bool differs = false;
    for (int c = 0; c < components; ++c)
    {
      differs = differs || !(std::abs(a[i + c] - b[i + c]) <= threshold);
    }
    apart += differs ? 1 : 0;
  }
  return static_cast<double>(apart) / static_cast<double>(a.size() / components);
}

/// The stated tolerances of this file (see the top).
void ExpectTheSamePicture(const Picture& fragment, const Picture& compute, const std::string& label)
{
  ASSERT_EQ(fragment.Colour.size(), compute.Colour.size()) << label;
  const DifferenceStatistics s = Compare(fragment.Colour, compute.Colour, 1);
  const double depthApart = FractionApart(fragment.Depth, compute.Depth, 1, 1e-5);
  const double hitsApart = FractionApart(fragment.Hits, compute.Hits, 4, 1e-4);
  std::cout << label << ": colour mean " << s.Mean << ", pixels > 1: " << 100.0 * s.FractionAbove
            << "%, depth apart: " << 100.0 * depthApart << "%, hits apart: " << 100.0 * hitsApart
            << "%\n";
  EXPECT_LT(s.Mean, 0.02) << label;
  EXPECT_LE(s.FractionAbove, 0.0005) << label;
  EXPECT_LE(depthApart, 0.0005) << label;
  EXPECT_LE(hitsApart, 0.0005) << label;
}
} // namespace

//------------------------------------------------------------------------------
TEST(RayTracePassPaths, EveryShippedSceneIsTheSameOnBothPaths)
{
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(DataDirectory() / "scenes"))
  {
    if (entry.path().extension() == ".json")
    {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files)
  {
    SCOPED_TRACE(file.filename().string());
    View view(160, 120);
    view.Load(file);
    ErrorObserver errors(view.Pass);
    const Picture fragment = view.Render(vtkRiemannRayTracePass::FRAGMENT);
    const Picture compute = view.Render(vtkRiemannRayTracePass::COMPUTE);
    ASSERT_TRUE(errors.Messages.empty()) << errors.All();
    EXPECT_EQ(fragment.Path, vtkRiemannRayTracePass::FRAGMENT);
    EXPECT_EQ(compute.Path, vtkRiemannRayTracePass::COMPUTE);
    ASSERT_EQ(compute.Hits.size(), 4u * 160 * 120);
    ExpectTheSamePicture(fragment, compute, file.filename().string());
  }
  EXPECT_GE(files.size(), 8u) << "the paper's six figures, the showcase and the mesh scene";
}

TEST(RayTracePassPaths, ReducedViewsAreTheSameOnBothPaths)
{
  View view(160, 120);
  view.Load(DataDirectory() / "scenes/paper-two-bumps.json");
  view.Pass->CaptureHitsOff();
  ErrorObserver errors(view.Pass);
  for (double distance : { 2.0, 3.0, 4.5 })
  {
    view.Pass->SetImageSampleDistance(distance);
    const Picture fragment = view.Render(vtkRiemannRayTracePass::FRAGMENT);
    const Picture compute = view.Render(vtkRiemannRayTracePass::COMPUTE);
    EXPECT_EQ(view.Pass->GetLastImageSampleDistance(), distance);
    ExpectTheSamePicture(fragment, compute, "distance " + std::to_string(distance));
  }
  ASSERT_TRUE(errors.Messages.empty()) << errors.All();
}

TEST(RayTracePassPaths, WorkgroupsNeverChangeAPixel)
{
  View view(150, 110); // no workgroup below divides both sides
  view.Load(DataDirectory() / "scenes/paper-one-bump.json");
  ErrorObserver errors(view.Pass);
  const Picture reference = view.Render(vtkRiemannRayTracePass::COMPUTE);
  const int compilations = view.Pass->GetNumberOfShaderCompilations();
  const std::array<int, 2> sizes[] = { { 16, 4 }, { 13, 7 }, { 32, 32 }, { 1, 64 } };
  for (const std::array<int, 2>& size : sizes)
  {
    const std::string label = std::to_string(size[0]) + " x " + std::to_string(size[1]);
    view.Pass->SetComputeWorkgroupSize(size[0], size[1]);
    const Picture picture = view.Render(vtkRiemannRayTracePass::COMPUTE);
    // The same per-pixel code in another schedule: every value equal.
    EXPECT_EQ(picture.Colour, reference.Colour) << label;
    EXPECT_EQ(picture.Depth, reference.Depth) << label;
    EXPECT_EQ(picture.Hits, reference.Hits) << label;
  }
  ASSERT_TRUE(errors.Messages.empty()) << errors.All();
  // One program per workgroup size.
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), compilations + 4);
}

TEST(RayTracePassPaths, AutoTakesComputeWhereTheContextHasIt)
{
  View view(32, 24);
  view.Load(DataDirectory() / "scenes/paper-grid.json");
  EXPECT_EQ(view.Pass->GetGPUPath(), vtkRiemannRayTracePass::AUTO);
  EXPECT_EQ(view.Pass->GetLastGPUPath(), vtkRiemannRayTracePass::AUTO) << "before any render";
  view.Render(vtkRiemannRayTracePass::AUTO);
  // Mesa's llvmpipe gives VTK an OpenGL 4.5 core context.
  EXPECT_EQ(view.Pass->GetLastGPUPath(), vtkRiemannRayTracePass::COMPUTE);
  EXPECT_STREQ(vtkRiemannRayTracePass::GetGPUPathAsString(vtkRiemannRayTracePass::COMPUTE),
    "Compute");
  EXPECT_STREQ(vtkRiemannRayTracePass::GetGPUPathAsString(7), "Unknown");
  EXPECT_NE(std::string(view.Pass->GetComputeShaderSource()).find("#version 430"),
    std::string::npos);
}

TEST(RayTracePassPaths, BadWorkgroupSizesAreRefused)
{
  vtkNew<vtkRiemannRayTracePass> pass;
  ErrorObserver errors(pass);
  for (const auto& size : { std::array<int, 2>{ 0, 8 }, std::array<int, 2>{ 65, 1 },
         std::array<int, 2>{ 64, 64 }, std::array<int, 2>{ -3, 4 } })
  {
    pass->SetComputeWorkgroupSize(size[0], size[1]);
  }
  ASSERT_EQ(errors.Messages.size(), 4u);
  EXPECT_NE(errors.Messages[2].find("at most 1024"), std::string::npos) << errors.Messages[2];
  EXPECT_EQ(pass->GetComputeWorkgroupSize()[0], 8);
  EXPECT_EQ(pass->GetComputeWorkgroupSize()[1], 8);
  pass->SetComputeWorkgroupSize(32, 32);
  EXPECT_EQ(errors.Messages.size(), 4u);
  EXPECT_EQ(pass->GetComputeWorkgroupSize()[0], 32);
}

TEST(RayTracePassPaths, BrokenShaderIsAnErrorOnBothPaths)
{
  for (int path : { vtkRiemannRayTracePass::FRAGMENT, vtkRiemannRayTracePass::COMPUTE })
  {
    const std::string label = vtkRiemannRayTracePass::GetGPUPathAsString(path);
    View view(32, 24);
    view.Load(DataDirectory() / "scenes/paper-grid.json");
    view.Pass->SetExtraShaderCode("float rt_broken() { return rt_no_such_variable; }\n");
    ErrorObserver errors(view.Pass);
    const Picture picture = view.Render(path);
    ASSERT_EQ(errors.Messages.size(), 1u) << label;
    EXPECT_NE(errors.Messages[0].find("failed to compile"), std::string::npos) << errors.All();
    EXPECT_NE(errors.Messages[0].find("rt_no_such_variable"), std::string::npos) << errors.All();
    EXPECT_NE(std::string(view.Pass->GetLastError()).find("rt_no_such_variable"),
      std::string::npos)
      << label;
    // The view is red, no hit image is left.
    EXPECT_EQ(picture.Colour[0], 255) << label;
    EXPECT_EQ(picture.Colour[1], 0) << label;
    EXPECT_EQ(view.Pass->GetHitImageWidth(), 0) << label;
  }
}

TEST(RayTracePassPaths, ProgressiveRefinementEndsInTheWholeFrame)
{
  // Pieces of 1 ms: many renders, each adding rays; the finished picture is
  // the whole frame's, every colour, depth and hit equal (the same rays).
  View view(96, 72);
  view.Load(DataDirectory() / "scenes/paper-two-bumps.json");
  ErrorObserver errors(view.Pass);
  const Picture whole = view.Render(vtkRiemannRayTracePass::COMPUTE);
  EXPECT_TRUE(view.Pass->GetRefinementComplete());

  view.Pass->ProgressiveRefinementOn();
  view.Pass->SetRefinementSeconds(0.001);
  Picture picture = view.Render(vtkRiemannRayTracePass::COMPUTE);
  EXPECT_FALSE(view.Pass->GetRefinementComplete());
  const int firstLevel = view.Pass->GetRefinementLevel();
  EXPECT_GE(firstLevel, 2) << "a coarse lattice first";
  EXPECT_EQ(view.Pass->GetHitImageWidth(), 0) << "hits come with the last piece";
  int renders = 1;
  int level = firstLevel;
  while (!view.Pass->GetRefinementComplete() && renders < 2000)
  {
    picture = view.Render(vtkRiemannRayTracePass::COMPUTE);
    EXPECT_LE(view.Pass->GetRefinementLevel(), level) << "the lattice only gets finer";
    level = view.Pass->GetRefinementLevel();
    ++renders;
  }
  ASSERT_TRUE(view.Pass->GetRefinementComplete());
  EXPECT_GT(renders, 4);
  EXPECT_EQ(view.Pass->GetRefinementLevel(), 1);
  EXPECT_EQ(picture.Colour, whole.Colour);
  EXPECT_EQ(picture.Depth, whole.Depth);
  EXPECT_EQ(picture.Hits, whole.Hits);

  // A finished picture stays (nothing traced again); a camera move starts over.
  picture = view.Render(vtkRiemannRayTracePass::COMPUTE);
  EXPECT_TRUE(view.Pass->GetRefinementComplete());
  EXPECT_EQ(picture.Colour, whole.Colour);
  view.Renderer->GetActiveCamera()->Azimuth(5.0);
  view.Render(vtkRiemannRayTracePass::COMPUTE);
  EXPECT_FALSE(view.Pass->GetRefinementComplete());
  EXPECT_GE(view.Pass->GetRefinementLevel(), 2);
  // Setting the piece's time changes no picture: the refinement goes on.
  const int before = view.Pass->GetRefinementLevel();
  view.Pass->SetRefinementSeconds(10.0);
  view.Render(vtkRiemannRayTracePass::COMPUTE);
  EXPECT_LE(view.Pass->GetRefinementLevel(), before / 2) << "went on with the next lattice";
  ASSERT_TRUE(errors.Messages.empty()) << errors.All();
}

TEST(RayTracePassPaths, TheFragmentPathDrawsWholeFrames)
{
  View view(48, 36);
  view.Load(DataDirectory() / "scenes/paper-grid.json");
  view.Pass->ProgressiveRefinementOn();
  view.Render(vtkRiemannRayTracePass::FRAGMENT);
  EXPECT_TRUE(view.Pass->GetRefinementComplete());
  EXPECT_EQ(view.Pass->GetRefinementLevel(), 1);
  EXPECT_EQ(view.Pass->GetHitImageWidth(), 48);
}

TEST(RayTracePassPaths, TheSourceIsComposedOnlyWhenItChanges)
{
  View view(32, 24);
  view.Load(DataDirectory() / "scenes/paper-one-bump.json");
  view.Pass->CaptureHitsOff();
  ErrorObserver errors(view.Pass);
  const char* bump = R"({"type": "graph", "gaussians": [{"amplitude": %g, "center": [0, 0, 0],
    "sigma": [0.5, 0.5, 0.5]}]})";
  char definition[256];
  std::snprintf(definition, sizeof(definition), bump, 1.0);
  ASSERT_TRUE(view.Metric->SetDefinition(definition)) << view.Metric->GetLastError();
  view.Render(vtkRiemannRayTracePass::COMPUTE);
  EXPECT_EQ(view.Pass->GetNumberOfSourceCompositions(), 1);

  // A camera move and a new amplitude (a uniform): nothing composed or compiled.
  view.Renderer->GetActiveCamera()->Azimuth(10.0);
  view.Render(vtkRiemannRayTracePass::COMPUTE);
  std::snprintf(definition, sizeof(definition), bump, 0.5);
  ASSERT_TRUE(view.Metric->SetDefinition(definition));
  const Picture flatter = view.Render(vtkRiemannRayTracePass::COMPUTE);
  EXPECT_EQ(view.Pass->GetNumberOfSourceCompositions(), 1);
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), 1);

  // The integrator, the path: composed (and built) once each.
  view.Pass->UseSceneSettingsOff();
  view.Pass->GetIntegrationSettings()->SetIntegratorType(vtkRiemannIntegrationSettings::EULER);
  view.Render(vtkRiemannRayTracePass::COMPUTE);
  view.Render(vtkRiemannRayTracePass::COMPUTE);
  EXPECT_EQ(view.Pass->GetNumberOfSourceCompositions(), 2);
  view.Render(vtkRiemannRayTracePass::FRAGMENT);
  view.Render(vtkRiemannRayTracePass::FRAGMENT);
  EXPECT_EQ(view.Pass->GetNumberOfSourceCompositions(), 3);
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), 3);
  // Back to the first program: composed again to find it, not compiled.
  view.Pass->UseSceneSettingsOn();
  const Picture again = view.Render(vtkRiemannRayTracePass::COMPUTE);
  EXPECT_EQ(view.Pass->GetNumberOfSourceCompositions(), 4);
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), 3);
  EXPECT_EQ(again.Colour, flatter.Colour);
  ASSERT_TRUE(errors.Messages.empty()) << errors.All();
}

TEST(RayTracePassPaths, TilesAreScatteredOnceEach)
{
  // n -> n * stride mod count visits every tile once, for the tile counts of
  // small and large views (2 x 2 pixels to 16384 x 16384 at 8 x 8), and the
  // shader's unsigned products do not wrap.
  for (unsigned int count : { 1u, 2u, 3u, 4u, 12u, 97u, 300u, 1024u, 32400u, 65536u, 262144u,
         4194304u })
  {
    const unsigned int stride = static_cast<unsigned int>(riemann::ScatteringStride(count));
    ASSERT_GE(stride, 1u);
    EXPECT_LE(static_cast<unsigned long long>(count) * stride, 0xffffffffull) << count;
    if (count > 4194304u / 64u)
    {
      continue; // the visit below is for the smaller counts
    }
    std::vector<bool> seen(count, false);
    for (unsigned int n = 0; n < count; ++n)
    {
      const unsigned int tile = (n * stride) % count;
      EXPECT_FALSE(seen[tile]) << count << " tiles, stride " << stride;
      seen[tile] = true;
    }
    if (count >= 100)
    {
      EXPECT_GT(stride, count / 4) << "consecutive workgroups land far apart";
    }
  }
}
