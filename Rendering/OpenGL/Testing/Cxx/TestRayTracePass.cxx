// vtkRiemannRayTracePass: the GLSL ray tracer against exact answers.
//
// - Euclidean space and one sphere: exact colours (centre: the sphere's
//   solid colour, corner: the background) and captured hit points equal to
//   the analytic ray-sphere intersections (float accuracy);
// - the twist (a flat metric, MATH.md Family 2): every geodesic is exactly
//   Phi^-1(Phi(p) + s J(p) v); the exact curve is marched finely on the CPU
//   through riemann::IntersectSegment and its hits are compared with the
//   GPU's for Euler, RK4 and the adaptive step (and with the CPU reference
//   tracer riemann::TraceRay);
// - uniforms, not recompiles: a new Gaussian amplitude changes the picture
//   but not the program;
// - errors: a metric without GLSL, a broken shader, a missing metric each
//   raise a VTK error naming the cause, and the view turns red;
// - the equirectangular centre pixel sees what the perspective one sees;
// - Lambert lighting measured with g and fog by arc length, pixel by pixel;
// - a degenerate metric shows magenta; the environment image is looked up
//   by the escaping ray's direction.
//
// Rendering runs on Mesa llvmpipe under Xvfb: images stay tiny.
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "RiemannSceneIntersection.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannScene.h"

#include "Metric.h"
#include "ObserverCamera.h"
#include "RiemannRay.h"
#include "RiemannScene.h"
#include "TensorMetric.h"

#include "vtkAutoInit.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include "RenderingTestUtilities.h"
#include <Eigen/LU> // inverse

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

VTK_MODULE_INIT(vtkRenderingOpenGL2);

namespace
{
using riemann::Vec3;
using riemann::testing::ErrorObserver;
using riemann::testing::KeepXServerConnection;
using riemann::testing::SetUpOffscreenView;

constexpr const char* EuclideanJson = R"({"type": "euclidean"})";
constexpr const char* TwistJson = R"({"type": "diffeo", "preset": "twist", "rate": 1})";

/// A sphere of radius 1 at the origin in a solid colour on a plain
/// background; the colours are multiples of 1/255 (exact in 8 bits).
constexpr const char* SphereSceneJson = R"({
  "background": [0.4, 0.2, 0.0],
  "integrator": {"method": "rk4", "step": 0.25, "max_steps": 200, "max_length": 12},
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
               "material": {"type": "solid", "color": [0.2, 0.6, 1.0]}}]})";

/// An offscreen window whose renderer draws with the pass.
struct View
{
  int Width;
  int Height;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRiemannRayTracePass> Pass;
  vtkNew<vtkRiemannMetric> Metric;
  vtkNew<vtkRiemannScene> Scene;

  View(int width, int height)
    : Width(width)
    , Height(height)
  {
    SetUpOffscreenView(this->Window, this->Renderer, this->Pass, width, height);
    this->Pass->SetMetric(this->Metric);
    this->Pass->SetScene(this->Scene);
  }

  void SetCamera(const Vec3& position, const Vec3& focal, const Vec3& up, double angle)
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(position.data());
    camera->SetFocalPoint(focal.data());
    camera->SetViewUp(up.data());
    camera->SetViewAngle(angle);
  }

  riemann::CameraSettings CameraSettings(riemann::Projection mode) const
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    riemann::CameraSettings settings;
    settings.Position = Vec3(camera->GetPosition());
    settings.LookAt = Vec3(camera->GetFocalPoint());
    settings.ViewUp = Vec3(camera->GetViewUp());
    settings.ViewAngle = camera->GetViewAngle();
    settings.Mode = mode;
    return settings;
  }

  /// Render and return the RGB pixels, row 0 at the bottom.
  std::vector<unsigned char> Render()
  {
    this->Window->Render();
    vtkNew<vtkUnsignedCharArray> pixels;
    this->Window->GetPixelData(0, 0, this->Width - 1, this->Height - 1, 1, pixels);
    return std::vector<unsigned char>(
      pixels->GetPointer(0), pixels->GetPointer(0) + 3 * this->Width * this->Height);
  }

  std::array<int, 3> Pixel(const std::vector<unsigned char>& image, int column, int row) const
  {
    const std::size_t i = 3 * (static_cast<std::size_t>(row) * this->Width + column);
    return { image[i], image[i + 1], image[i + 2] };
  }

  /// (x, y, z, s) of the captured hit of a pixel.
  std::array<double, 4> Hit(int column, int row) const
  {
    return riemann::testing::HitOfPixel(this->Pass->GetHitImage(), this->Width, column, row);
  }
};

void ExpectAllRed(View& view, const std::vector<unsigned char>& image)
{
  for (int row = 0; row < view.Height; row += view.Height - 1)
  {
    for (int column = 0; column < view.Width; column += view.Width - 1)
    {
      const auto p = view.Pixel(image, column, row);
      EXPECT_EQ(p[0], 255);
      EXPECT_EQ(p[1], 0);
      EXPECT_EQ(p[2], 0);
    }
  }
}

double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// ---- the twist, written out (independent of the library's TwistMap) --------
Vec3 TwistPhi(const Vec3& p)
{
  const double c = std::cos(p.z());
  const double s = std::sin(p.z());
  return Vec3(c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z());
}

Vec3 TwistPhiInverse(const Vec3& q)
{
  const double c = std::cos(q.z());
  const double s = std::sin(q.z());
  return Vec3(c * q.x() + s * q.y(), -s * q.x() + c * q.y(), q.z());
}

riemann::Mat3 TwistJacobian(const Vec3& p)
{
  const double c = std::cos(p.z());
  const double s = std::sin(p.z());
  riemann::Mat3 j;
  j << c, -s, -s * p.x() - c * p.y(), //
    s, c, c * p.x() - s * p.y(),      //
    0, 0, 1;
  return j;
}

/// The exact first hit of the twist geodesic from p with unit-speed v:
/// chords of ds on gamma(s) = Phi^-1(Phi(p) + s J(p) v) against the scene.
bool ExactTwistHit(const riemann::Scene& scene, const Vec3& p, const Vec3& v, double maximumLength,
  double ds, Vec3& hit, double& length)
{
  const Vec3 start = TwistPhi(p);
  const Vec3 direction = TwistJacobian(p) * v;
  Vec3 previous = p;
  for (double s = ds; s <= maximumLength + 0.5 * ds; s += ds)
  {
    const Vec3 next = TwistPhiInverse(start + s * direction);
    riemann::SceneHit sceneHit;
    if (riemann::IntersectSegment(scene, previous, next, sceneHit))
    {
      hit = sceneHit.Position;
      length = s - ds + sceneHit.Fraction * ds;
      return true;
    }
    previous = next;
  }
  return false;
}

/// A tensor field without a GLSL form: g = (1 + x^2) I.
class VaryingTensorField : public riemann::TensorField
{
public:
  void Evaluate(
    const Vec3& p, bool withDerivatives, riemann::Mat3& g, riemann::Mat3Stack& dg) const override
  {
    g = (1.0 + p.x() * p.x()) * riemann::Mat3::Identity();
    if (withDerivatives)
    {
      dg[0] = 2.0 * p.x() * riemann::Mat3::Identity();
      dg[1].setZero();
      dg[2].setZero();
    }
  }
  std::string Describe() const override { return "(1 + x^2) I (test field)"; }
};

/// Euclidean where x < 1 and degenerate beyond, on the CPU and in GLSL.
class HalfSpaceMetric : public riemann::Metric
{
public:
  std::string FamilyName() const override { return "test"; }
  std::string Describe() const override { return "Euclidean for x < 1, degenerate beyond"; }
  bool Tensor(const Vec3& p, riemann::Mat3& g) const override
  {
    g.setIdentity();
    return p.x() < 1.0;
  }
  bool TensorDerivatives(const Vec3& p, riemann::Mat3& g, riemann::Mat3Stack& dg) const override
  {
    for (riemann::Mat3& m : dg)
    {
      m.setZero();
    }
    return this->Tensor(p, g);
  }
  bool Christoffel(const Vec3& p, riemann::Mat3Stack& gamma) const override
  {
    for (riemann::Mat3& m : gamma)
    {
      m.setZero();
    }
    return p.x() < 1.0;
  }
  void EmitGlsl(riemann::GlslBuilder& builder) const override
  {
    builder.AddFunction("bool rt_metric_tensor(vec3 p, out mat3 g)\n"
                        "{\n  g = mat3(1.0);\n  return p.x < 1.0;\n}\n");
    builder.AddFunction("bool rt_metric_acceleration(vec3 p, vec3 v, out vec3 a)\n"
                        "{\n  a = vec3(0.0);\n  return p.x < 1.0;\n}\n");
  }
};

/// A pass that renders a core metric given directly (no JSON definition).
class CoreMetricPass : public vtkRiemannRayTracePass
{
public:
  static CoreMetricPass* New();
  vtkTypeMacro(CoreMetricPass, vtkRiemannRayTracePass);
  std::shared_ptr<const riemann::Metric> Core;

protected:
  std::shared_ptr<const riemann::Metric> GetCoreMetric() override { return this->Core; }
};
vtkStandardNewMacro(CoreMetricPass);
} // namespace

//------------------------------------------------------------------------------
TEST(RayTracePass, EuclideanSphereColours)
{
  View view(64, 48);
  ASSERT_TRUE(view.Metric->SetDefinition(EuclideanJson)) << view.Metric->GetLastError();
  ASSERT_TRUE(view.Scene->SetDefinition(SphereSceneJson)) << view.Scene->GetLastError();
  view.SetCamera(Vec3(0, 0, 5), Vec3(0, 0, 0), Vec3(0, 1, 0), 30);
  ErrorObserver errors(view.Pass);
  const auto image = view.Render();
  EXPECT_TRUE(errors.Messages.empty()) << errors.All();
  EXPECT_STREQ(view.Pass->GetLastError(), "");
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), 1);

  // The centre pixel sees the sphere (0.2, 0.6, 1.0), a corner the background (0.4, 0.2, 0).
  EXPECT_EQ(view.Pixel(image, 32, 24), (std::array<int, 3>{ 51, 153, 255 }));
  EXPECT_EQ(view.Pixel(image, 0, 0), (std::array<int, 3>{ 102, 51, 0 }));
  EXPECT_EQ(view.Pixel(image, 63, 47), (std::array<int, 3>{ 102, 51, 0 }));
}

TEST(RayTracePass, EuclideanHitsAreAnalytic)
{
  View view(64, 48);
  ASSERT_TRUE(view.Metric->SetDefinition(EuclideanJson));
  ASSERT_TRUE(view.Scene->SetDefinition(SphereSceneJson));
  view.SetCamera(Vec3(0, 0, 5), Vec3(0.1, -0.05, 0), Vec3(0, 1, 0), 30);
  view.Pass->CaptureHitsOn();
  ErrorObserver errors(view.Pass);
  view.Render();
  EXPECT_TRUE(errors.Messages.empty()) << errors.All();
  ASSERT_EQ(view.Pass->GetHitImageWidth(), 64);
  ASSERT_EQ(view.Pass->GetHitImageHeight(), 48);
  ASSERT_EQ(view.Pass->GetHitImage()->GetNumberOfTuples(), 64 * 48);
  ASSERT_EQ(view.Pass->GetHitImage()->GetNumberOfComponents(), 4);

  const riemann::ObserverCamera observer(
    *view.Metric->GetMetric(), view.CameraSettings(riemann::Projection::Perspective));
  const Vec3 eye(0, 0, 5);
  int hits = 0;
  int misses = 0;
  double worstPosition = 0.0;
  double worstLength = 0.0;
  for (int row = 0; row < 48; ++row)
  {
    for (int column = 0; column < 64; ++column)
    {
      const Vec3 d = observer.PixelDirection(column, row, 64, 48);
      // |eye + t d|^2 = 1 with |d| = 1.
      const double b = eye.dot(d);
      const double discriminant = b * b - (eye.squaredNorm() - 1.0);
      const auto gpu = view.Hit(column, row);
      if (std::abs(discriminant) < 1e-3)
      {
        continue; // grazing: float may decide either way
      }
      if (discriminant < 0)
      {
        ++misses;
        EXPECT_EQ(gpu[3], -1.0) << "pixel " << column << "," << row << " should miss";
        continue;
      }
      ++hits;
      const double t = -b - std::sqrt(discriminant);
      const Vec3 exact = eye + t * d;
      ASSERT_GE(gpu[3], 0.0) << "pixel " << column << "," << row << " should hit";
      worstPosition =
        std::max(worstPosition, (Vec3(gpu[0], gpu[1], gpu[2]) - exact).lpNorm<Eigen::Infinity>());
      worstLength = std::max(worstLength, std::abs(gpu[3] - t));
    }
  }
  std::printf("[ figures  ] Euclidean sphere, %d hit pixels, %d misses: max |hit - exact| = %.2e, "
              "max |s - t| = %.2e\n",
    hits, misses, worstPosition, worstLength);
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 100);
  EXPECT_LT(worstPosition, 1e-4);
  EXPECT_LT(worstLength, 1e-4);
}

TEST(RayTracePass, TwistHitsEulerVersusRungeKutta)
{
  // A wall behind a sphere, seen from off the twist axis: every ray curves.
  constexpr const char* sceneJson = R"({
    "objects": [
      {"type": "sphere", "center": [0.3, 0.2, 0], "radius": 0.7},
      {"type": "plane", "point": [0, 0, -1.5], "normal": [0, 0, 1]}]})";
  constexpr int width = 48;
  constexpr int height = 36;
  constexpr double step = 0.02;
  constexpr double maximumLength = 10.0;
  constexpr double tolerance = 1e-5;
  View view(width, height);
  ASSERT_TRUE(view.Metric->SetDefinition(TwistJson)) << view.Metric->GetLastError();
  ASSERT_TRUE(view.Scene->SetDefinition(sceneJson)) << view.Scene->GetLastError();
  view.SetCamera(Vec3(1.0, 0.5, 2.5), Vec3(0, 0, -0.5), Vec3(0, 1, 0), 50);
  view.Pass->UseSceneSettingsOff();
  view.Pass->GetIntegrationSettings()->SetInitialIntegrationStep(step);
  view.Pass->GetIntegrationSettings()->SetMaximumPropagation(maximumLength);
  view.Pass->GetIntegrationSettings()->SetMaximumNumberOfSteps(2000);
  view.Pass->GetIntegrationSettings()->SetMaximumError(tolerance);
  view.Pass->CaptureHitsOn();
  ErrorObserver errors(view.Pass);

  // GPU hits of each integrator, same step, same program.
  const int integrators[3] = { vtkRiemannIntegrationSettings::EULER, vtkRiemannIntegrationSettings::RUNGE_KUTTA4,
    vtkRiemannIntegrationSettings::DORMAND_PRINCE45 };
  std::vector<float> gpu[3];
  for (int k = 0; k < 3; ++k)
  {
    view.Pass->GetIntegrationSettings()->SetIntegratorType(integrators[k]);
    view.Render();
    ASSERT_EQ(view.Pass->GetHitImageWidth(), width);
    gpu[k].assign(view.Pass->GetHitImage()->GetPointer(0),
      view.Pass->GetHitImage()->GetPointer(0) + 4 * width * height);
  }
  EXPECT_TRUE(errors.Messages.empty()) << errors.All();
  // The integrator is the one compile-time choice (one program each, cached).
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), 3);
  view.Pass->GetIntegrationSettings()->SetIntegratorType(integrators[0]);
  view.Render();
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), 3) << "switching back reuses the program";

  const riemann::Scene& scene = view.Scene->GetScene();
  const riemann::Metric& metric = *view.Metric->GetMetric();
  const riemann::ObserverCamera observer(
    metric, view.CameraSettings(riemann::Projection::Perspective));
  const Vec3 eye(1.0, 0.5, 2.5);
  // Errors against the exact hit: GPU (float) for each integrator, and the
  // CPU reference tracer riemann::TraceRay (double) with the same settings.
  std::vector<double> gpuErrors[3];
  std::vector<double> cpuErrors[3];
  std::vector<double> gpuLengthErrors[3];
  std::vector<double> gpuVersusCpu[3];
  int missing = 0;
  // A sub-grid of pixels (every third column and row).
  for (int row = 1; row < height; row += 3)
  {
    for (int column = 1; column < width; column += 3)
    {
      const Vec3 v = observer.PixelDirection(column, row, width, height);
      Vec3 exact;
      double exactLength = 0.0;
      const bool hit = ExactTwistHit(scene, eye, v, maximumLength, 1e-3, exact, exactLength);
      const std::size_t i = 4 * (static_cast<std::size_t>(row) * width + column);
      if (!hit)
      {
        EXPECT_LT(gpu[1][i + 3], 0.0f) << "pixel " << column << "," << row;
        continue;
      }
      bool all = true;
      for (int k = 0; k < 3; ++k)
      {
        all = all && gpu[k][i + 3] >= 0;
      }
      if (!all)
      {
        ++missing;
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        const Vec3 g(gpu[k][i], gpu[k][i + 1], gpu[k][i + 2]);
        gpuErrors[k].push_back((g - exact).norm());
        gpuLengthErrors[k].push_back(std::abs(gpu[k][i + 3] - exactLength));
        riemann::RaySettings settings;
        settings.Integrator = static_cast<riemann::IntegratorType>(integrators[k]);
        settings.Step = step;
        settings.MaximumSteps = 2000;
        settings.MaximumLength = maximumLength;
        settings.Tolerance = tolerance;
        riemann::RayPath path;
        riemann::TraceRay(metric, scene, eye, v, settings, path, false);
        if (path.Hit)
        {
          cpuErrors[k].push_back((path.HitInfo.Position - exact).norm());
          gpuVersusCpu[k].push_back((g - path.HitInfo.Position).norm());
        }
      }
    }
  }
  ASSERT_GT(gpuErrors[1].size(), 100u);
  const char* names[3] = { "Euler   ", "RK4     ", "adaptive" };
  std::printf("[ figures  ] twist (rate 1), step %.3g (adaptive: initial step, tolerance %.0e), "
              "%zu pixels: |hit - exact|, exact = first hit of Phi^-1(Phi(p) + s J(p) v)\n",
    step, tolerance, gpuErrors[1].size());
  double maxima[3];
  double medians[3];
  for (int k = 0; k < 3; ++k)
  {
    maxima[k] = *std::max_element(gpuErrors[k].begin(), gpuErrors[k].end());
    medians[k] = Median(gpuErrors[k]);
    std::printf("[ figures  ]   %s GPU (float): max %.3e median %.3e | arc length max %.3e | "
                "CPU TraceRay (double): max %.3e median %.3e | GPU-CPU max %.3e\n",
      names[k], maxima[k], medians[k],
      *std::max_element(gpuLengthErrors[k].begin(), gpuLengthErrors[k].end()),
      cpuErrors[k].empty() ? 0.0 : *std::max_element(cpuErrors[k].begin(), cpuErrors[k].end()),
      Median(cpuErrors[k]),
      gpuVersusCpu[k].empty() ? 0.0
                              : *std::max_element(gpuVersusCpu[k].begin(), gpuVersusCpu[k].end()));
  }
  EXPECT_EQ(missing, 0);
  // RK4 is limited by float arithmetic; Euler by its first-order error.
  EXPECT_LT(maxima[1], 1e-3);
  EXPECT_LT(100.0 * medians[1], medians[0]);
  EXPECT_LT(10.0 * maxima[1], maxima[0]);
  // The GPU follows the CPU reference tracer (same rules, float vs double).
  // (RK4's remaining error is the chord's: a hit is found on the straight
  // segment of a step, off the curve by up to h^2 kappa / 8. The adaptive
  // steps grow to 100 x step, as riemann::TraceRay's, so their chords cut
  // corners: the figure above shows it; here it must only match the CPU.)
  EXPECT_LT(*std::max_element(gpuVersusCpu[0].begin(), gpuVersusCpu[0].end()), 1e-3);
  EXPECT_LT(*std::max_element(gpuVersusCpu[1].begin(), gpuVersusCpu[1].end()), 1e-3);
  EXPECT_LT(Median(gpuVersusCpu[2]), 1e-3);
  EXPECT_LT(*std::max_element(gpuVersusCpu[2].begin(), gpuVersusCpu[2].end()), 5e-2);
}

TEST(RayTracePass, NewAmplitudeIsAUniformNotARecompile)
{
  auto bump = [](double amplitude)
  {
    return std::string(R"({"type": "graph", "gaussians": [{"amplitude": )") +
      std::to_string(amplitude) + R"(, "center": [0, 0, 0], "sigma": [0.8, 0.8, 0.8]}]})";
  };
  constexpr const char* sceneJson = R"({
    "integrator": {"method": "rk4", "step": 0.05, "max_steps": 300, "max_length": 12},
    "objects": [{"type": "grid", "spacing": 1, "thickness": 0.1, "extent": [-2, 2, -2, 2, -2, 2]}]})";
  View view(48, 36);
  ASSERT_TRUE(view.Metric->SetDefinition(bump(0.5).c_str())) << view.Metric->GetLastError();
  ASSERT_TRUE(view.Scene->SetDefinition(sceneJson)) << view.Scene->GetLastError();
  view.SetCamera(Vec3(0.2, 0.3, 5), Vec3(0, 0, 0), Vec3(0, 1, 0), 45);
  ErrorObserver errors(view.Pass);
  const auto first = view.Render();
  ASSERT_EQ(view.Pass->GetNumberOfShaderCompilations(), 1);
  ASSERT_TRUE(view.Metric->SetDefinition(bump(1.5).c_str()));
  const auto second = view.Render();
  EXPECT_TRUE(errors.Messages.empty()) << errors.All();
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), 1) << "same structure, same program";
  EXPECT_NE(first, second) << "the new amplitude must change the picture";

  // A different structure (two bumps) is a new program.
  ASSERT_TRUE(view.Metric->SetDefinition(R"({"type": "graph", "gaussians": [
    {"amplitude": 0.5, "center": [0, 0, 0], "sigma": 0.8},
    {"amplitude": 0.5, "center": [1, 0, 0], "sigma": 0.8}]})"));
  view.Render();
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), 2);
  // Back to one bump: the cached program again.
  ASSERT_TRUE(view.Metric->SetDefinition(bump(0.7).c_str()));
  view.Render();
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), 2);
  EXPECT_TRUE(errors.Messages.empty()) << errors.All();
}

TEST(RayTracePass, MetricWithoutGlslIsAnError)
{
  KeepXServerConnection();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(32, 24);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<CoreMetricPass> pass;
  pass->Core = std::make_shared<riemann::TensorMetric>(std::make_shared<VaryingTensorField>());
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(SphereSceneJson));
  pass->SetScene(scene);
  renderer->SetPass(pass);
  renderer->GetActiveCamera()->SetPosition(0, 0, 5);
  ErrorObserver errors(pass);
  window->Render();
  ASSERT_EQ(errors.Messages.size(), 1u);
  EXPECT_NE(errors.Messages[0].find("GLSL"), std::string::npos) << errors.Messages[0];
  EXPECT_NE(errors.Messages[0].find("has no GLSL form"), std::string::npos) << errors.Messages[0];
  EXPECT_NE(std::string(pass->GetLastError()).find("(1 + x^2) I (test field)"), std::string::npos)
    << pass->GetLastError();
  EXPECT_EQ(pass->GetNumberOfShaderCompilations(), 0);

  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, 31, 23, 1, pixels);
  EXPECT_EQ(pixels->GetValue(0), 255);
  EXPECT_EQ(pixels->GetValue(1), 0);
  EXPECT_EQ(pixels->GetValue(2), 0);
}

TEST(RayTracePass, BrokenShaderIsAnErrorWithTheCompilerLog)
{
  View view(32, 24);
  ASSERT_TRUE(view.Metric->SetDefinition(EuclideanJson));
  ASSERT_TRUE(view.Scene->SetDefinition(SphereSceneJson));
  view.SetCamera(Vec3(0, 0, 5), Vec3(0, 0, 0), Vec3(0, 1, 0), 30);
  view.Pass->SetExtraShaderCode("float rt_broken() { return rt_no_such_variable; }\n");
  ErrorObserver errors(view.Pass);
  const auto image = view.Render();
  ASSERT_EQ(errors.Messages.size(), 1u);
  const std::string& message = errors.Messages[0];
  EXPECT_NE(message.find("failed to compile"), std::string::npos) << message;
  // The GLSL compiler's log names the culprit.
  EXPECT_NE(message.find("rt_no_such_variable"), std::string::npos) << message;
  ExpectAllRed(view, image);

  // Rendering again reports again (no silent frames) without recompiling.
  view.Render();
  EXPECT_EQ(errors.Messages.size(), 2u);
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), 1);

  // Fixed code: the picture comes back.
  view.Pass->SetExtraShaderCode(nullptr);
  const auto fixed = view.Render();
  EXPECT_EQ(errors.Messages.size(), 2u) << errors.All();
  EXPECT_EQ(view.Pixel(fixed, 16, 12), (std::array<int, 3>{ 51, 153, 255 }));
}

TEST(RayTracePass, MissingMetricIsAnError)
{
  View view(32, 24);
  view.Pass->SetMetric(nullptr);
  ASSERT_TRUE(view.Scene->SetDefinition(SphereSceneJson));
  ErrorObserver errors(view.Pass);
  const auto image = view.Render();
  ASSERT_EQ(errors.Messages.size(), 1u);
  EXPECT_NE(errors.Messages[0].find("no metric"), std::string::npos) << errors.Messages[0];
  ExpectAllRed(view, image);

  // A metric object without a definition.
  view.Pass->SetMetric(view.Metric);
  view.Render();
  ASSERT_EQ(errors.Messages.size(), 2u);
  EXPECT_NE(errors.Messages[1].find("no definition"), std::string::npos) << errors.Messages[1];

  // No scene.
  ASSERT_TRUE(view.Metric->SetDefinition(EuclideanJson));
  view.Pass->SetScene(nullptr);
  view.Render();
  ASSERT_EQ(errors.Messages.size(), 3u);
  EXPECT_NE(errors.Messages[2].find("no scene"), std::string::npos) << errors.Messages[2];
}

TEST(RayTracePass, EquirectangularCentreSeesThePerspectiveCentre)
{
  // Odd sizes: the centre pixel's ray is the view direction itself.
  constexpr int width = 65;
  constexpr int height = 49;
  View view(width, height);
  ASSERT_TRUE(view.Metric->SetDefinition(
    R"({"type": "graph", "gaussians": [{"amplitude": 0.8, "center": [0.3, 0.1, 1.5], "sigma": 0.7}]})"));
  ASSERT_TRUE(view.Scene->SetDefinition(R"({
    "integrator": {"method": "rk4", "step": 0.05, "max_steps": 400, "max_length": 15},
    "objects": [{"type": "grid", "spacing": 1, "thickness": 0.12, "extent": [-2, 2, -2, 2, -2, 2]}]})"));
  view.SetCamera(Vec3(0.25, 0.15, 5), Vec3(0.25, 0.15, 0), Vec3(0, 1, 0), 40);
  view.Pass->UseSceneSettingsOff();
  view.Pass->GetIntegrationSettings()->SetInitialIntegrationStep(0.05);
  view.Pass->GetIntegrationSettings()->SetMaximumNumberOfSteps(400);
  view.Pass->GetIntegrationSettings()->SetMaximumPropagation(15);
  view.Pass->CaptureHitsOn();
  ErrorObserver errors(view.Pass);

  view.Pass->SetProjectionToPerspective();
  const auto perspective = view.Render();
  const auto perspectiveHit = view.Hit(width / 2, height / 2);
  view.Pass->SetProjectionToEquirectangular();
  const auto equirectangular = view.Render();
  const auto equirectangularHit = view.Hit(width / 2, height / 2);
  EXPECT_TRUE(errors.Messages.empty()) << errors.All();
  EXPECT_EQ(view.Pass->GetNumberOfShaderCompilations(), 1) << "the projection is a uniform";

  ASSERT_GE(perspectiveHit[3], 0.0) << "the centre ray should hit the grid";
  for (int c = 0; c < 4; ++c)
  {
    EXPECT_NEAR(equirectangularHit[c], perspectiveHit[c], 1e-5) << "component " << c;
  }
  EXPECT_EQ(view.Pixel(equirectangular, width / 2, height / 2),
    view.Pixel(perspective, width / 2, height / 2));
  // The panorama shows more than the perspective view (a different picture),
  // and neither is a failure colour.
  EXPECT_NE(perspective, equirectangular);
  EXPECT_NE(view.Pixel(equirectangular, width / 2, height / 2), (std::array<int, 3>{ 255, 0, 0 }));
}

TEST(RayTracePass, SceneSettingsDriveTheIntegrator)
{
  // The scene's integrator block: a maximum length shorter than the distance
  // to the sphere makes every ray escape; switching UseSceneSettings off lets
  // the pass's own (longer) maximum length reach it.
  View view(32, 24);
  ASSERT_TRUE(view.Metric->SetDefinition(EuclideanJson));
  ASSERT_TRUE(view.Scene->SetDefinition(R"({
    "background": [0.4, 0.2, 0.0],
    "integrator": {"method": "euler", "step": 0.25, "max_steps": 100, "max_length": 2},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                 "material": {"type": "solid", "color": [0.2, 0.6, 1.0]}}]})"));
  view.SetCamera(Vec3(0, 0, 5), Vec3(0, 0, 0), Vec3(0, 1, 0), 30);
  const auto short_ = view.Render();
  EXPECT_EQ(view.Pixel(short_, 16, 12), (std::array<int, 3>{ 102, 51, 0 }));
  view.Pass->UseSceneSettingsOff();
  view.Pass->GetIntegrationSettings()->SetMaximumPropagation(10);
  const auto long_ = view.Render();
  EXPECT_EQ(view.Pixel(long_, 16, 12), (std::array<int, 3>{ 51, 153, 255 }));
}

TEST(RayTracePass, DegenerateMetricIsMagenta)
{
  // Rays to the right of x = 1 reach the degenerate half-space: magenta, and
  // -2 in the hit image; rays to the left see the background.
  KeepXServerConnection();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(32, 24);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<CoreMetricPass> pass;
  pass->Core = std::make_shared<HalfSpaceMetric>();
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(R"({"background": [0.4, 0.2, 0.0],
    "integrator": {"method": "rk4", "step": 0.1, "max_steps": 200, "max_length": 10}})"));
  pass->SetScene(scene);
  pass->CaptureHitsOn();
  renderer->SetPass(pass);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(60);
  ErrorObserver errors(pass);
  window->Render();
  EXPECT_TRUE(errors.Messages.empty()) << errors.All();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, 31, 23, 1, pixels);
  auto pixel = [&](int column, int row)
  {
    const int i = 3 * (row * 32 + column);
    return std::array<int, 3>{ pixels->GetValue(i), pixels->GetValue(i + 1),
      pixels->GetValue(i + 2) };
  };
  EXPECT_EQ(pixel(31, 12), (std::array<int, 3>{ 255, 0, 255 }));
  EXPECT_EQ(pixel(0, 12), (std::array<int, 3>{ 102, 51, 0 }));
  EXPECT_EQ(pass->GetHitImage()->GetComponent(12 * 32 + 31, 3), -2.0);
  EXPECT_EQ(pass->GetHitImage()->GetComponent(12 * 32 + 0, 3), -1.0);
}

TEST(RayTracePass, EnvironmentImageByDirection)
{
  // An 8 x 4 equirectangular image: red in the upper half (rows from the
  // top), blue in the lower half; green where the longitude is east of -z
  // (the right half of the image).
  const char* output = std::getenv("RIEMANN_TEST_OUTPUT_DIR");
  const std::filesystem::path file =
    std::filesystem::path(output && *output ? output : std::filesystem::temp_directory_path()) /
    "TestRayTracePassEnvironment.ppm";
  {
    std::ofstream ppm(file, std::ios::binary);
    ppm << "P6\n8 4\n255\n";
    for (int row = 0; row < 4; ++row)
    {
      for (int column = 0; column < 8; ++column)
      {
        const unsigned char rgb[3] = { static_cast<unsigned char>(row < 2 ? 255 : 0),
          static_cast<unsigned char>(column >= 4 ? 255 : 0),
          static_cast<unsigned char>(row < 2 ? 0 : 255) };
        ppm.write(reinterpret_cast<const char*>(rgb), 3);
      }
    }
  }
  View view(33, 25);
  ASSERT_TRUE(view.Metric->SetDefinition(EuclideanJson));
  const std::string sceneJson = R"({"background": {"environment": ")" + file.string() + R"("},
        "integrator": {"method": "rk4", "step": 0.5, "max_steps": 20, "max_length": 5}})";
  ASSERT_TRUE(view.Scene->SetDefinition(sceneJson.c_str())) << view.Scene->GetLastError();
  view.SetCamera(Vec3(0, 0, 0), Vec3(0, 0, -1), Vec3(0, 1, 0), 90);
  ErrorObserver errors(view.Pass);
  const auto image = view.Render();
  EXPECT_TRUE(errors.Messages.empty()) << errors.All();
  // Up and to the right (+x): red + green; down and to the left: blue.
  EXPECT_EQ(view.Pixel(image, 32, 24), (std::array<int, 3>{ 255, 255, 0 }));
  EXPECT_EQ(view.Pixel(image, 0, 24), (std::array<int, 3>{ 255, 0, 0 }));
  EXPECT_EQ(view.Pixel(image, 0, 0), (std::array<int, 3>{ 0, 0, 255 }));
  EXPECT_EQ(view.Pixel(image, 32, 0), (std::array<int, 3>{ 0, 255, 255 }));

  // An unreadable image is reported, and the background colour stands in.
  std::ofstream(file, std::ios::binary) << "not an image";
  vtkNew<vtkRiemannScene> broken;
  ASSERT_TRUE(broken->SetDefinition(sceneJson.c_str()));
  view.Pass->SetScene(broken);
  view.Pass->ReleaseGraphicsResources(view.Window); // forget the loaded image
  view.Render();
  ASSERT_EQ(errors.Messages.size(), 1u);
  EXPECT_NE(errors.Messages[0].find("environment image"), std::string::npos) << errors.Messages[0];
}

TEST(RayTracePass, ObserverLightingAndFog)
{
  // A constant metric g = diag(4, 1, 1): rays are straight in coordinates,
  // but the Lambert cosine is measured with g, |nu(v)| / (|nu|_{g^-1} |v|_g),
  // and black fog scales the colour by exp(-density s).
  constexpr int width = 48;
  constexpr int height = 36;
  constexpr double density = 0.1;
  View view(width, height);
  ASSERT_TRUE(view.Metric->SetDefinition(
    R"({"type": "tensor", "matrix": [[4, 0, 0], [0, 1, 0], [0, 0, 1]]})"))
    << view.Metric->GetLastError();
  ASSERT_TRUE(view.Scene->SetDefinition(R"({
    "background": [0, 0, 0], "lighting": "observer", "fog": {"color": [0, 0, 0], "density": 0.1},
    "integrator": {"method": "rk4", "step": 0.25, "max_steps": 200, "max_length": 12},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                 "material": {"type": "solid", "color": [1, 1, 1]}}]})"))
    << view.Scene->GetLastError();
  view.SetCamera(Vec3(0.5, 0.3, 4), Vec3(0, 0, 0), Vec3(0, 1, 0), 40);
  ErrorObserver errors(view.Pass);
  const auto image = view.Render();
  EXPECT_TRUE(errors.Messages.empty()) << errors.All();

  const riemann::Metric& metric = *view.Metric->GetMetric();
  const riemann::ObserverCamera observer(
    metric, view.CameraSettings(riemann::Projection::Perspective));
  riemann::Mat3 g;
  ASSERT_TRUE(metric.Tensor(Vec3::Zero(), g));
  const riemann::Mat3 gInverse = g.inverse();
  const Vec3 eye(0.5, 0.3, 4);
  int checked = 0;
  int worst = 0;
  for (int row = 0; row < height; ++row)
  {
    for (int column = 0; column < width; ++column)
    {
      const Vec3 v = observer.PixelDirection(column, row, width, height);
      // |eye + s v|^2 = 1 in coordinates.
      const double a = v.squaredNorm();
      const double b = eye.dot(v);
      const double discriminant = b * b - a * (eye.squaredNorm() - 1.0);
      if (discriminant < 1e-2 * a)
      {
        continue; // misses, or grazes
      }
      const double s = (-b - std::sqrt(discriminant)) / a;
      const Vec3 nu = eye + s * v; // the outward normal covector, unit radius
      const double cosine =
        std::abs(nu.dot(v)) / (std::sqrt(nu.dot(gInverse * nu)) * std::sqrt(v.dot(g * v)));
      const int expected =
        static_cast<int>(std::lround(255.0 * std::min(1.0, cosine) * std::exp(-density * s)));
      const auto p = view.Pixel(image, column, row);
      worst = std::max(worst, std::abs(p[0] - expected));
      EXPECT_NEAR(p[0], expected, 1) << "pixel " << column << "," << row;
      EXPECT_EQ(p[0], p[1]);
      EXPECT_EQ(p[0], p[2]);
      ++checked;
    }
  }
  EXPECT_GT(checked, 200);
  std::printf("[ figures  ] observer lighting + fog, g = diag(4,1,1): %d pixels, worst %d/255\n",
    checked, worst);
}
