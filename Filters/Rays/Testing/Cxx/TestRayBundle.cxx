// vtkRiemannRayBundle: the pixels' rays as polylines, against real answers.
//
// - The bundle is the pass's rays: for the twist (a flat but curved-ray
//   metric) and the paper's one Gaussian bump, the bundle's hit of each
//   sub-grid pixel equals the hit that vtkRiemannRayTracePass captured on the
//   GPU for that pixel (float accuracy; a ray that grazes an edge may
//   legitimately go either way: at most 2 of 64 may differ, and are printed),
//   hit flags and arc lengths agree, and every line ends at its hit.
// - Euclidean space: every line is straight, starts at the camera, leaves
//   along ObserverCamera::PixelDirection of its pixel; ArcLength grows and
//   ends at Length; Length of a hit is the distance to the analytic hit.
// - Pixels: the N x N sub-grid's block centres; a strided region (clipped,
//   either corner order).
// - EndColor: riemann::SurfaceColor at the hit (x 255, rounded), or the
//   background for a miss.
// - No metric (or one without a definition): a VTK error, empty output.
//
// Rendering runs on Mesa llvmpipe under Xvfb: images stay tiny.
#include "RiemannSceneIntersection.h"
#include "RiemannShading.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayBundle.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannScene.h"

#include "GeodesicTrace.h" // HitSurface
#include "Metric.h"
#include "ObserverCamera.h"
#include "RiemannScene.h"

#include "vtkAutoInit.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include "RenderingTestUtilities.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

VTK_MODULE_INIT(vtkRenderingOpenGL2);

namespace
{
using riemann::Vec3;
using riemann::testing::ErrorObserver;
using riemann::testing::SetUpOffscreenView;

std::filesystem::path DataDirectory()
{
  const char* dir = std::getenv("RIEMANN_DATA_DIR");
  return dir && *dir ? std::filesystem::path(dir) : std::filesystem::path(RIEMANN_TEST_DATA_DIR);
}

constexpr const char* EuclideanJson = R"({"type": "euclidean"})";
constexpr const char* TwistJson = R"({"type": "diffeo", "preset": "twist", "rate": 1})";

/// One line of the bundle, read back from the output.
struct Line
{
  int Column = 0;
  int Row = 0;
  bool Hit = false;
  Vec3 HitPosition = Vec3::Zero();
  std::array<int, 3> EndColor{};
  double Length = 0.0;
  int Reason = 0;
  std::vector<Vec3> Points;
  std::vector<double> ArcLength;
};

/// The lines of a bundle output; fails (ADD_FAILURE) when arrays are missing.
std::vector<Line> ReadLines(vtkPolyData* output)
{
  std::vector<Line> lines;
  vtkCellData* cd = output->GetCellData();
  auto* pixelIndex = vtkIntArray::SafeDownCast(cd->GetArray("PixelIndex"));
  auto* hit = vtkIntArray::SafeDownCast(cd->GetArray("Hit"));
  auto* hitPosition = vtkDoubleArray::SafeDownCast(cd->GetArray("HitPosition"));
  auto* endColor = vtkUnsignedCharArray::SafeDownCast(cd->GetArray("EndColor"));
  auto* length = vtkDoubleArray::SafeDownCast(cd->GetArray("Length"));
  auto* reason = vtkIntArray::SafeDownCast(cd->GetArray("ReasonForTermination"));
  auto* arcLength = vtkDoubleArray::SafeDownCast(output->GetPointData()->GetArray("ArcLength"));
  if (!pixelIndex || !hit || !hitPosition || !endColor || !length || !reason || !arcLength)
  {
    ADD_FAILURE() << "the bundle lacks one of its arrays";
    return lines;
  }
  EXPECT_EQ(pixelIndex->GetNumberOfComponents(), 2);
  EXPECT_EQ(hitPosition->GetNumberOfComponents(), 3);
  EXPECT_EQ(endColor->GetNumberOfComponents(), 3);
  EXPECT_EQ(output->GetNumberOfCells(), output->GetNumberOfLines());
  EXPECT_EQ(cd->GetScalars(), endColor) << "EndColor colours the lines";
  vtkCellArray* cells = output->GetLines();
  vtkNew<vtkIdList> ids;
  cells->InitTraversal();
  for (vtkIdType k = 0; cells->GetNextCell(ids); ++k)
  {
    Line line;
    line.Column = pixelIndex->GetTypedComponent(k, 0);
    line.Row = pixelIndex->GetTypedComponent(k, 1);
    line.Hit = hit->GetValue(k) != 0;
    for (int c = 0; c < 3; ++c)
    {
      line.HitPosition[c] = hitPosition->GetTypedComponent(k, c);
      line.EndColor[c] = endColor->GetTypedComponent(k, c);
    }
    line.Length = length->GetValue(k);
    line.Reason = reason->GetValue(k);
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
    {
      double p[3];
      output->GetPoint(ids->GetId(i), p);
      line.Points.emplace_back(p[0], p[1], p[2]);
      line.ArcLength.push_back(arcLength->GetValue(ids->GetId(i)));
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

/// What every line must satisfy whatever the metric.
void ExpectConsistentLine(const Line& line, const Vec3& eye)
{
  const std::string where = "pixel " + std::to_string(line.Column) + "," + std::to_string(line.Row);
  ASSERT_GE(line.Points.size(), 2u) << where;
  ASSERT_EQ(line.Points.size(), line.ArcLength.size()) << where;
  EXPECT_LT((line.Points.front() - eye).norm(), 1e-12) << where << ": starts at the eye";
  EXPECT_EQ(line.ArcLength.front(), 0.0) << where;
  for (size_t i = 1; i < line.ArcLength.size(); ++i)
  {
    EXPECT_GT(line.ArcLength[i], line.ArcLength[i - 1]) << where << ", point " << i;
  }
  EXPECT_NEAR(line.ArcLength.back(), line.Length, 1e-12) << where;
  if (line.Hit)
  {
    EXPECT_EQ(line.Reason, riemann::HitSurface) << where;
    EXPECT_TRUE(line.HitPosition.allFinite()) << where;
    EXPECT_LT((line.Points.back() - line.HitPosition).norm(), 1e-12)
      << where << ": the line ends at its hit";
  }
  else
  {
    EXPECT_NE(line.Reason, riemann::HitSurface) << where;
    EXPECT_TRUE(std::isnan(line.HitPosition[0]) && std::isnan(line.HitPosition[1]) &&
      std::isnan(line.HitPosition[2]))
      << where << ": HitPosition is NaN without a hit";
  }
}

/// An offscreen window whose renderer draws with the pass (hits captured).
struct View
{
  int Width;
  int Height;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRiemannRayTracePass> Pass;

  View(int width, int height, vtkRiemannMetric* metric, vtkRiemannScene* scene)
    : Width(width)
    , Height(height)
  {
    SetUpOffscreenView(this->Window, this->Renderer, this->Pass, width, height);
    this->Pass->SetMetric(metric);
    this->Pass->SetScene(scene);
    this->Pass->CaptureHitsOn();
  }

  vtkCamera* Camera() { return this->Renderer->GetActiveCamera(); }

  /// (x, y, z, s) of the captured hit of a pixel (row 0 at the bottom).
  std::array<double, 4> Hit(int column, int row)
  {
    return riemann::testing::HitOfPixel(this->Pass->GetHitImage(), this->Width, column, row);
  }
};

/**
 * Render the view with the pass, trace the bundle of the same pixels on the
 * CPU with the renderer's camera, and compare pixel by pixel.
 */
void ExpectBundleIsThePassRays(const char* name, vtkRiemannMetric* metric, vtkRiemannScene* scene,
  View& view, int bundleProjection = -1)
{
  ErrorObserver passErrors(view.Pass);
  view.Window->Render();
  ASSERT_TRUE(passErrors.Messages.empty()) << passErrors.All();
  ASSERT_STREQ(view.Pass->GetLastError(), "");
  ASSERT_EQ(view.Pass->GetHitImageWidth(), view.Width);
  ASSERT_EQ(view.Pass->GetHitImageHeight(), view.Height);

  vtkNew<vtkRiemannRayBundle> bundle;
  bundle->SetMetric(metric);
  bundle->SetScene(scene);
  bundle->SetCamera(view.Camera());
  bundle->SetWidth(view.Width);
  bundle->SetHeight(view.Height);
  bundle->SetSubgridResolution(8);
  if (bundleProjection >= 0)
  {
    bundle->SetProjection(bundleProjection);
  }
  ErrorObserver bundleErrors(bundle);
  bundle->Update();
  ASSERT_TRUE(bundleErrors.Messages.empty()) << bundleErrors.All();
  const std::vector<Line> lines = ReadLines(bundle->GetOutput());
  ASSERT_EQ(lines.size(), 64u);

  const Vec3 eye(view.Camera()->GetPosition());
  int hits = 0;
  int differing = 0;
  double worstPosition = 0.0;
  double worstLength = 0.0;
  for (const Line& line : lines)
  {
    ExpectConsistentLine(line, eye);
    const auto gpu = view.Hit(line.Column, line.Row);
    const bool gpuHit = gpu[3] >= 0.0;
    EXPECT_NE(gpu[3], -2.0) << "pixel " << line.Column << "," << line.Row << ": failed on the GPU";
    const double positionError =
      line.Hit && gpuHit ? (Vec3(gpu[0], gpu[1], gpu[2]) - line.HitPosition).norm() : 0.0;
    const double lengthError = line.Hit && gpuHit ? std::abs(gpu[3] - line.Length) : 0.0;
    if (gpuHit != line.Hit || positionError > 1e-3 || lengthError > 1e-3)
    {
      ++differing;
      std::printf("[ differs  ] %s pixel %d,%d: bundle hit %d (%.6f, %.6f, %.6f) s %.6f | "
                  "GPU (%.6f, %.6f, %.6f) s %.6f\n",
        name, line.Column, line.Row, line.Hit ? 1 : 0, line.HitPosition[0], line.HitPosition[1],
        line.HitPosition[2], line.Length, gpu[0], gpu[1], gpu[2], gpu[3]);
      continue;
    }
    hits += line.Hit ? 1 : 0;
    worstPosition = std::max(worstPosition, positionError);
    worstLength = std::max(worstLength, lengthError);
  }
  std::printf("[ figures  ] %s: %zu bundle lines, %d hits, %d differing from the GPU; "
              "max |hit - GPU hit| = %.2e, max |s - GPU s| = %.2e\n",
    name, lines.size(), hits, differing, worstPosition, worstLength);
  EXPECT_LE(differing, 2) << "rays that graze an edge may differ, not more";
  EXPECT_GE(hits, 16) << "the comparison needs hits";
  EXPECT_LT(worstPosition, 1e-3);
  EXPECT_LT(worstLength, 1e-3);
}
} // namespace

//------------------------------------------------------------------------------
TEST(RayBundle, IsThePassRaysInTheTwist)
{
  // A sphere in front of a wall, seen from off the twist axis: every ray curves.
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(TwistJson)) << metric->GetLastError();
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(R"({
    "integrator": {"method": "rk4", "step": 0.02, "max_steps": 2000, "max_length": 10},
    "objects": [
      {"type": "sphere", "center": [0.3, 0.2, 0], "radius": 0.7},
      {"type": "plane", "point": [0, 0, -1.5], "normal": [0, 0, 1]}]})"))
    << scene->GetLastError();
  View view(64, 48, metric, scene);
  vtkCamera* camera = view.Camera();
  camera->SetPosition(1.0, 0.5, 2.5);
  camera->SetFocalPoint(0, 0, -0.5);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(50);
  ExpectBundleIsThePassRays("twist", metric, scene, view);

  // The twist really bends the rays: a line's interior leaves its chord.
  vtkNew<vtkRiemannRayBundle> bundle;
  bundle->SetMetric(metric);
  bundle->SetScene(scene);
  bundle->SetCamera(camera);
  bundle->SetWidth(64);
  bundle->SetHeight(48);
  bundle->Update();
  double bend = 0.0;
  for (const Line& line : ReadLines(bundle->GetOutput()))
  {
    const Vec3 a = line.Points.front();
    const Vec3 chord = (line.Points.back() - a).normalized();
    for (const Vec3& p : line.Points)
    {
      bend = std::max(bend, ((p - a) - (p - a).dot(chord) * chord).norm());
    }
  }
  EXPECT_GT(bend, 0.05) << "twisted rays are not straight";
}

TEST(RayBundle, IsThePassRaysForThePaperBump)
{
  const std::filesystem::path data = DataDirectory();
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinitionFile((data / "metrics" / "gaussian-bump.json").c_str()))
    << metric->GetLastError();
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinitionFile((data / "scenes" / "paper-one-bump.json").c_str()))
    << scene->GetLastError();
  View view(64, 48, metric, scene);
  ASSERT_TRUE(scene->ApplyCamera(view.Camera()));
  ExpectBundleIsThePassRays("one bump", metric, scene, view);
}

/// Every family's GLSL (graph sums and quadratics, twist, bumps with a
/// direction or an affine field, compositions, conformal, constant tensor,
/// Euclidean), run on the GPU, gives the CPU's rays: each example metric in
/// Data/metrics, seen through a sphere-and-wall scene.
TEST(RayBundle, IsThePassRaysForEveryExampleMetric)
{
  const std::filesystem::path data = DataDirectory();
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(R"({
    "integrator": {"method": "rk4", "step": 0.02, "max_steps": 1500, "max_length": 12},
    "objects": [
      {"type": "sphere", "center": [0.1, 0.05, 0], "radius": 0.3},
      {"type": "plane", "point": [0, 0, -1], "normal": [0, 0, 1]}]})"))
    << scene->GetLastError();
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(data / "metrics"))
  {
    files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 10u);
  for (const std::filesystem::path& file : files)
  {
    vtkNew<vtkRiemannMetric> metric;
    ASSERT_TRUE(metric->SetDefinitionFile(file.c_str())) << metric->GetLastError();
    const double eye[3] = { 0.35, 0.2, 1.4 };
    double g[9];
    if (!metric->EvaluateMetricTensor(eye, g))
    {
      // The Poincare ball is only a metric inside the unit ball: this
      // observer is outside (the pass reports that, tested elsewhere).
      std::printf("[ skipped  ] %s: not defined at the observer\n", file.filename().c_str());
      continue;
    }
    View view(40, 30, metric, scene);
    vtkCamera* camera = view.Camera();
    // Off every axis, so that no symmetry hides a wrong term; close, so that
    // even the steep quadratics (|grad f| grows like 2|p|) let rays hit.
    camera->SetPosition(0.35, 0.2, 1.4);
    camera->SetFocalPoint(0.05, 0.0, -0.25);
    camera->SetViewUp(0, 1, 0);
    camera->SetViewAngle(45);
    const std::string name = file.filename().string();
    ExpectBundleIsThePassRays(name.c_str(), metric, scene, view);
  }
}

/// The paper's bump seen from inside the grid, all around (equirectangular).
constexpr const char* EquirectangularSceneJson = R"({
  "camera": {"position": [0.4, 0.3, 1.6], "look_at": [0, 0, 0], "view_up": [0, 1, 0],
             "projection": "equirectangular"},
  "integrator": {"method": "rk4", "step": 0.03, "max_steps": 600, "max_length": 12},
  "objects": [{"type": "grid", "spacing": 1, "thickness": 0.08, "extent": [-2, 2, -2, 2, -2, 2]}]})";

TEST(RayBundle, IsThePassRaysEquirectangular)
{
  // The scene's camera block makes the pass equirectangular; the bundle is
  // told so with SetProjection.
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(
    metric->SetDefinitionFile((DataDirectory() / "metrics" / "gaussian-bump.json").c_str()))
    << metric->GetLastError();
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(EquirectangularSceneJson)) << scene->GetLastError();
  View view(64, 48, metric, scene);
  ASSERT_TRUE(scene->ApplyCamera(view.Camera()));
  ExpectBundleIsThePassRays(
    "bump, equirectangular", metric, scene, view, vtkRiemannRayBundle::EQUIRECTANGULAR);
}

// vtkRiemannRayBundle's header: integration settings come from the scene
// "exactly as for vtkRiemannRayTracePass", the projection "as the pass". The
// pass takes the projection of the scene's camera block when
// UseSceneSettings is on, and so must the bundle, or with such a scene it
// would trace other rays than the pass draws.
TEST(RayBundle, TakesTheScenesProjectionAsThePass)
{
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(
    metric->SetDefinitionFile((DataDirectory() / "metrics" / "gaussian-bump.json").c_str()))
    << metric->GetLastError();
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(EquirectangularSceneJson)) << scene->GetLastError();
  View view(64, 48, metric, scene);
  ASSERT_TRUE(scene->ApplyCamera(view.Camera()));
  ExpectBundleIsThePassRays("bump, projection from the scene", metric, scene, view);
}

TEST(RayBundle, EuclideanLinesAreStraight)
{
  constexpr int width = 40;
  constexpr int height = 30;
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(EuclideanJson));
  vtkNew<vtkRiemannScene> scene;
  // One sphere; rays that miss run to the maximum length (not a step multiple).
  ASSERT_TRUE(scene->SetDefinition(R"({
    "integrator": {"method": "rk4", "step": 0.3, "max_steps": 100, "max_length": 9.1},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})"));
  vtkNew<vtkCamera> camera;
  const Vec3 eye(0.4, -0.3, 5);
  camera->SetPosition(eye.data());
  camera->SetFocalPoint(0.1, 0.05, 0);
  camera->SetViewUp(0.1, 1, 0);
  camera->SetViewAngle(35);

  vtkNew<vtkRiemannRayBundle> bundle;
  bundle->SetMetric(metric);
  bundle->SetScene(scene);
  bundle->SetCamera(camera);
  bundle->SetWidth(width);
  bundle->SetHeight(height);
  bundle->SetSubgridResolution(6);
  bundle->Update();
  const std::vector<Line> lines = ReadLines(bundle->GetOutput());
  ASSERT_EQ(lines.size(), 36u);

  riemann::CameraSettings settings;
  settings.Position = eye;
  settings.LookAt = Vec3(camera->GetFocalPoint());
  settings.ViewUp = Vec3(camera->GetViewUp());
  settings.ViewAngle = 35;
  const riemann::ObserverCamera observer(*metric->GetMetric(), settings);

  int hits = 0;
  int misses = 0;
  double worstOffLine = 0.0;
  for (const Line& line : lines)
  {
    const std::string where =
      "pixel " + std::to_string(line.Column) + "," + std::to_string(line.Row);
    ExpectConsistentLine(line, eye);
    const Vec3 d = observer.PixelDirection(line.Column, line.Row, width, height);
    EXPECT_NEAR(d.norm(), 1.0, 1e-12);
    // Leaves along the pixel's direction...
    const Vec3 first = (line.Points[1] - line.Points[0]).normalized();
    EXPECT_LT((first - d).norm(), 1e-9) << where;
    // ...and stays on the line eye + s d, s the arc length.
    for (size_t i = 0; i < line.Points.size(); ++i)
    {
      worstOffLine =
        std::max(worstOffLine, (line.Points[i] - (eye + line.ArcLength[i] * d)).norm());
    }
    // The analytic answer: |eye + t d| = 1.
    const double b = eye.dot(d);
    const double discriminant = b * b - (eye.squaredNorm() - 1.0);
    if (std::abs(discriminant) < 1e-3)
    {
      continue; // grazing
    }
    if (discriminant < 0)
    {
      ++misses;
      EXPECT_FALSE(line.Hit) << where;
      EXPECT_NEAR(line.Length, 9.1, 1e-9) << where << ": a miss runs to the maximum length";
      EXPECT_EQ(line.Reason, riemann::OutOfLength) << where;
      continue;
    }
    ++hits;
    const double t = -b - std::sqrt(discriminant);
    ASSERT_TRUE(line.Hit) << where;
    EXPECT_NEAR(line.Length, t, 1e-9) << where;
    EXPECT_LT((line.HitPosition - (eye + t * d)).norm(), 1e-9) << where;
  }
  EXPECT_LT(worstOffLine, 1e-9);
  EXPECT_GT(hits, 4);
  EXPECT_GT(misses, 4);
}

TEST(RayBundle, SubgridPixelsAreBlockCentres)
{
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(EuclideanJson));
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(R"({
    "integrator": {"method": "rk4", "step": 0.5, "max_steps": 20, "max_length": 4}})"));
  vtkNew<vtkRiemannRayBundle> bundle;
  bundle->SetMetric(metric);
  bundle->SetScene(scene);
  bundle->SetWidth(64);
  bundle->SetHeight(48);
  bundle->SetSubgridResolution(8);
  bundle->Update();
  const std::vector<Line> lines = ReadLines(bundle->GetOutput());
  ASSERT_EQ(lines.size(), 64u);
  // Block centres: columns 4, 12, ..., 60; rows 3, 9, ..., 45; rows outer.
  for (int j = 0; j < 8; ++j)
  {
    for (int i = 0; i < 8; ++i)
    {
      const Line& line = lines[j * 8 + i];
      EXPECT_EQ(line.Column, 8 * i + 4);
      EXPECT_EQ(line.Row, 6 * j + 3);
    }
  }

  // Without a vtkCamera: the scene's camera...
  ASSERT_TRUE(scene->SetDefinition(R"({
    "camera": {"position": [1, 2, 6], "look_at": [0, 0, 0], "view_up": [0, 1, 0], "fov": 40},
    "integrator": {"method": "rk4", "step": 0.5, "max_steps": 20, "max_length": 4}})"));
  bundle->Update();
  const std::vector<Line> fromScene = ReadLines(bundle->GetOutput());
  ASSERT_EQ(fromScene.size(), 64u);
  EXPECT_LT((fromScene[0].Points[0] - Vec3(1, 2, 6)).norm(), 1e-12);
  // ...and without a scene, the default scene's, at (0, 0, 7.5).
  bundle->SetScene(nullptr);
  bundle->Update();
  const std::vector<Line> fromDefault = ReadLines(bundle->GetOutput());
  ASSERT_EQ(fromDefault.size(), 64u);
  EXPECT_LT((fromDefault[0].Points[0] - riemann::DefaultScene().Camera.Position).norm(), 1e-12);
  EXPECT_LT((fromDefault[0].Points[0] - Vec3(0, 0, 7.5)).norm(), 1e-12);
}

TEST(RayBundle, PiecesAppendedInOrderAreTheWholeBundle)
{
  // What an MPI job asks: piece p of N traces a share of the pixels; in
  // order, the pieces are the whole bundle, bitwise, in the paper's bump.
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinitionFile((DataDirectory() / "scenes/paper-one-bump.json").c_str()));
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(scene->GetMetricDefinition().c_str()));
  vtkNew<vtkRiemannRayBundle> bundle;
  bundle->SetMetric(metric);
  bundle->SetScene(scene);
  bundle->SetWidth(64);
  bundle->SetHeight(48);
  bundle->SetSubgridResolution(7);
  bundle->Update();
  const std::vector<Line> whole = ReadLines(bundle->GetOutput());
  ASSERT_EQ(whole.size(), 49u);
  for (int pieces : { 2, 3, 4 })
  {
    SCOPED_TRACE("pieces " + std::to_string(pieces));
    std::vector<Line> appended;
    for (int piece = 0; piece < pieces; ++piece)
    {
      bundle->UpdatePiece(piece, pieces, 0);
      const std::vector<Line> part = ReadLines(bundle->GetOutput());
      appended.insert(appended.end(), part.begin(), part.end());
    }
    ASSERT_EQ(appended.size(), whole.size());
    for (std::size_t k = 0; k < whole.size(); ++k)
    {
      EXPECT_EQ(appended[k].Column, whole[k].Column);
      EXPECT_EQ(appended[k].Row, whole[k].Row);
      ASSERT_EQ(appended[k].Points.size(), whole[k].Points.size()) << "line " << k;
      for (std::size_t i = 0; i < whole[k].Points.size(); ++i)
      {
        ASSERT_EQ(appended[k].Points[i], whole[k].Points[i]) << "line " << k << " point " << i;
      }
    }
  }
}

TEST(RayBundle, PixelRegionWithStride)
{
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(EuclideanJson));
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(R"({
    "integrator": {"method": "rk4", "step": 0.5, "max_steps": 20, "max_length": 4}})"));
  vtkNew<vtkRiemannRayBundle> bundle;
  bundle->SetMetric(metric);
  bundle->SetScene(scene);
  bundle->SetWidth(32);
  bundle->SetHeight(24);
  bundle->UsePixelRegionOn();

  auto pixelsOf = [&]()
  {
    bundle->Update();
    std::vector<std::pair<int, int>> pixels;
    for (const Line& line : ReadLines(bundle->GetOutput()))
    {
      pixels.emplace_back(line.Column, line.Row);
    }
    return pixels;
  };
  using Pixels = std::vector<std::pair<int, int>>;

  // Columns 3..10, rows 2..7, every third: columns 3, 6, 9; rows 2, 5.
  bundle->SetPixelRegion(3, 10, 2, 7);
  bundle->SetPixelStride(3);
  EXPECT_EQ(pixelsOf(), (Pixels{ { 3, 2 }, { 6, 2 }, { 9, 2 }, { 3, 5 }, { 6, 5 }, { 9, 5 } }));

  // The corners in either order give the same pixels.
  bundle->SetPixelRegion(10, 3, 7, 2);
  EXPECT_EQ(pixelsOf(), (Pixels{ { 3, 2 }, { 6, 2 }, { 9, 2 }, { 3, 5 }, { 6, 5 }, { 9, 5 } }));

  // Stride 1: every pixel of the region, inclusive.
  bundle->SetPixelRegion(5, 7, 0, 1);
  bundle->SetPixelStride(1);
  EXPECT_EQ(pixelsOf(), (Pixels{ { 5, 0 }, { 6, 0 }, { 7, 0 }, { 5, 1 }, { 6, 1 }, { 7, 1 } }));

  // A region beyond the image is clipped to it: the four corners with stride 31 x 23.
  bundle->SetPixelRegion(-100, 100, -5, 23);
  bundle->SetPixelStride(31);
  EXPECT_EQ(pixelsOf(), (Pixels{ { 0, 0 }, { 31, 0 } }));
  bundle->SetPixelRegion(0, 31, 0, 23);
  bundle->SetPixelStride(23);
  EXPECT_EQ(pixelsOf(), (Pixels{ { 0, 0 }, { 23, 0 }, { 0, 23 }, { 23, 23 } }));

  // A single pixel.
  bundle->SetPixelRegion(17, 17, 11, 11);
  EXPECT_EQ(pixelsOf(), (Pixels{ { 17, 11 } }));

  // Back to the sub-grid.
  bundle->UsePixelRegionOff();
  bundle->SetSubgridResolution(2);
  EXPECT_EQ(pixelsOf(), (Pixels{ { 8, 6 }, { 24, 6 }, { 8, 18 }, { 24, 18 } }));
}

TEST(RayBundle, EndColorIsTheSurfaceColourOrTheBackground)
{
  // Euclidean space: a position-coloured sphere (bounds: its own box) in
  // front of a solid wall, on a background whose colour is not a multiple
  // of 1/255 (so rounding is exercised).
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(EuclideanJson));
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(R"({
    "background": [0.1, 0.3, 0.7],
    "integrator": {"method": "rk4", "step": 0.25, "max_steps": 100, "max_length": 12},
    "objects": [
      {"type": "sphere", "center": [0.2, 0.1, 0], "radius": 1},
      {"type": "box", "min": [-0.5, -4, -3], "max": [4, 4, -2.5],
       "material": {"type": "solid", "color": [0.9, 0.5, 0.123]}}]})"))
    << scene->GetLastError();
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(50);
  vtkNew<vtkRiemannRayBundle> bundle;
  bundle->SetMetric(metric);
  bundle->SetScene(scene);
  bundle->SetCamera(camera);
  bundle->SetWidth(48);
  bundle->SetHeight(36);
  bundle->SetSubgridResolution(12);
  bundle->Update();
  const std::vector<Line> lines = ReadLines(bundle->GetOutput());
  ASSERT_EQ(lines.size(), 144u);

  const riemann::Scene& s = scene->GetScene();
  auto rounded = [](const Vec3& color)
  {
    std::array<int, 3> rgb;
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] = static_cast<int>(std::lround(255.0 * std::clamp(color[c], 0.0, 1.0)));
    }
    return rgb;
  };
  const Vec3 center(0.2, 0.1, 0);
  int onSphere = 0;
  int onBox = 0;
  int misses = 0;
  for (const Line& line : lines)
  {
    const std::string where =
      "pixel " + std::to_string(line.Column) + "," + std::to_string(line.Row);
    if (!line.Hit)
    {
      ++misses;
      EXPECT_EQ(line.EndColor, (std::array<int, 3>{ 26, 77, 179 })) << where;
      continue;
    }
    riemann::SceneHit hit;
    hit.Position = line.HitPosition;
    if (std::abs((line.HitPosition - center).norm() - 1.0) < 1e-9)
    {
      ++onSphere;
      hit.Object = 0;
      // The pseudo-colour, written out: (p - (c - r)) / 2r.
      const Vec3 expected = (line.HitPosition - center + Vec3::Ones()) / 2.0;
      EXPECT_EQ(line.EndColor, rounded(expected)) << where;
    }
    else
    {
      ++onBox;
      EXPECT_NEAR(line.HitPosition.z(), -2.5, 1e-9) << where << ": the box's front face";
      hit.Object = 1;
      EXPECT_EQ(line.EndColor, (std::array<int, 3>{ 230, 128, 31 })) << where;
    }
    EXPECT_EQ(line.EndColor, rounded(riemann::SurfaceColor(s, hit))) << where;
  }
  EXPECT_GT(onSphere, 10);
  EXPECT_GT(onBox, 10);
  EXPECT_GT(misses, 10);
}

TEST(RayBundle, NoMetricIsAnErrorAndEmptyOutput)
{
  vtkNew<vtkRiemannRayBundle> bundle;
  ErrorObserver errors(bundle);
  bundle->Update();
  ASSERT_EQ(errors.Messages.size(), 1u);
  EXPECT_NE(errors.Messages[0].find("No metric"), std::string::npos) << errors.Messages[0];
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfCells(), 0);

  // A metric object without a definition is no metric either.
  vtkNew<vtkRiemannMetric> metric;
  bundle->SetMetric(metric);
  bundle->Update();
  ASSERT_EQ(errors.Messages.size(), 2u);
  EXPECT_NE(errors.Messages[1].find("No metric"), std::string::npos) << errors.Messages[1];
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfCells(), 0);

  // A definition: lines (the default scene and camera, 8 x 8 pixels).
  ASSERT_TRUE(metric->SetDefinition(EuclideanJson));
  bundle->Update();
  EXPECT_EQ(errors.Messages.size(), 2u) << errors.All();
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfLines(), 64);

  // Removing the metric again empties the output (no stale lines).
  bundle->SetMetric(nullptr);
  bundle->Update();
  ASSERT_EQ(errors.Messages.size(), 3u);
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(bundle->GetOutput()->GetCellData()->GetNumberOfArrays(), 0);
}

// An observer the metric cannot place: an error kept in GetLastError(), empty output.
TEST(RayBundle, BadCameraIsKeptInGetLastError)
{
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(R"J({"type": "conformal", "n": "2/(1 - x^2 - y^2 - z^2)"})J"))
    << metric->GetLastError();
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0, 0, 3);
  vtkNew<vtkRiemannRayBundle> bundle;
  ErrorObserver errors(bundle);
  bundle->SetMetric(metric);
  bundle->SetCamera(camera);
  bundle->Update();
  ASSERT_EQ(errors.Messages.size(), 1u) << errors.All();
  EXPECT_STREQ(bundle->GetLastError(), "Bad camera: the metric is degenerate at the observer");
  EXPECT_NE(errors.Messages[0].find(bundle->GetLastError()), std::string::npos) << errors.All();
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfCells(), 0);

  // Inside the ball the observer is placed, and the error is gone.
  camera->SetPosition(0, 0, 0.5);
  bundle->SetSubgridResolution(2);
  bundle->Update();
  EXPECT_EQ(errors.Messages.size(), 1u) << errors.All();
  EXPECT_STREQ(bundle->GetLastError(), "");
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfLines(), 4);
}

// The bundle's own integration settings are checked only when they are used:
// with UseSceneSettings on (the default) the scene's "integrator" block
// applies, and a NaN InitialIntegrationStep left in the unused settings is
// no error; with it off the same setting is refused by name.
TEST(RayBundle, ChecksItsIntegrationSettingsOnlyWhenUsed)
{
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(EuclideanJson));
  vtkNew<vtkRiemannRayBundle> bundle;
  ErrorObserver errors(bundle);
  bundle->SetMetric(metric);
  bundle->SetSubgridResolution(4);
  bundle->GetIntegrationSettings()->SetInitialIntegrationStep(
    std::numeric_limits<double>::quiet_NaN());

  ASSERT_TRUE(bundle->GetUseSceneSettings());
  bundle->Update();
  EXPECT_TRUE(errors.Messages.empty()) << errors.All();
  EXPECT_STREQ(bundle->GetLastError(), "");
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfLines(), 16);

  bundle->UseSceneSettingsOff();
  bundle->Update();
  ASSERT_EQ(errors.Messages.size(), 1u) << errors.All();
  EXPECT_NE(errors.Messages[0].find("InitialIntegrationStep"), std::string::npos)
    << errors.Messages[0];
  EXPECT_STREQ(bundle->GetLastError(),
    "Integration settings: InitialIntegrationStep is nan: expected a number from 1e-09 to 1e+06 (arc length).");
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfCells(), 0);

  // A usable step: the bundle's own settings trace the rays.
  bundle->GetIntegrationSettings()->SetInitialIntegrationStep(0.05);
  bundle->Update();
  EXPECT_EQ(errors.Messages.size(), 1u) << errors.All();
  EXPECT_STREQ(bundle->GetLastError(), "");
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfLines(), 16);

  // Back to the scene's settings: the NaN is not looked at again.
  bundle->GetIntegrationSettings()->SetInitialIntegrationStep(
    std::numeric_limits<double>::quiet_NaN());
  bundle->UseSceneSettingsOn();
  bundle->Update();
  EXPECT_EQ(errors.Messages.size(), 1u) << errors.All();
  EXPECT_STREQ(bundle->GetLastError(), "");
  EXPECT_EQ(bundle->GetOutput()->GetNumberOfLines(), 16);
}
