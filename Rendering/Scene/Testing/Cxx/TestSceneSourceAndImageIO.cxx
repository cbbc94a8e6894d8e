// vtkRiemannSceneSource (the scene as Euclidean VTK geometry) and
// RiemannImageIO (PNG/EXR through OpenImageIO), against exact answers.
//
// Scene source:
// - one grid, sphere, plane and box: the pieces in object order with the
//   expected numbers of points (a grid of spacing 1 on [-1,1]^3 is 3 axes x
//   3 x 3 lattice lines = 27 bars of 24 points each), every bar's box
//   (cross section: lattice line +- thickness/2; along: the extent), the
//   grid's bounds (extent +- thickness/2), the plane patch (PlaneSize), and
//   point data "Colors" (3 unsigned chars) equal to riemann::SurfaceColor at
//   every vertex, with the position pseudo-colour written out at known
//   vertices;
// - no scene: the default scene's grid; an empty scene: empty output.
// Image IO:
// - PNG round trip within 8-bit quantisation (and clamping to [0, 1]);
// - EXR round trip with exact floats and the channel names (AOVs);
// - ImageDifference: 0 for equal pictures, the mean of per-pixel maxima for
//   one changed pixel, negative for different sizes;
// - errors: a missing folder, a target that cannot be replaced (no
//   *.partial-* file left behind), an unsupported extension, a bad image, an
//   unreadable file.
#include "vtkRiemannScene.h"
#include "vtkRiemannSceneSource.h"
#include "RiemannSceneIntersection.h"
#include "RiemannShading.h"

#include "RiemannImageIO.h"
#include "RiemannScene.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <unistd.h> // getpid

namespace
{
namespace fs = std::filesystem;
using riemann::Vec3;

/// A fresh scratch folder for one test, removed at the end. The process id
/// keeps two runs of the same test (two ctest runs on one build tree) apart.
struct ScratchDirectory
{
  fs::path Path;
  explicit ScratchDirectory(const std::string& name)
  {
    const char* out = std::getenv("RIEMANN_TEST_OUTPUT_DIR");
    this->Path = (out && *out ? fs::path(out) : fs::temp_directory_path()) /
      "TestSceneSourceAndImageIO" / (name + "-" + std::to_string(::getpid()));
    fs::remove_all(this->Path);
    fs::create_directories(this->Path);
  }
  ~ScratchDirectory()
  {
    std::error_code ignored;
    fs::remove_all(this->Path, ignored);
  }
};

/// Bounds of points [first, first + count) of `data`.
std::array<double, 6> BoundsOf(vtkPolyData* data, vtkIdType first, vtkIdType count)
{
  std::array<double, 6> b{ VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (vtkIdType i = first; i < first + count; ++i)
  {
    double p[3];
    data->GetPoint(i, p);
    for (int c = 0; c < 3; ++c)
    {
      b[2 * c] = std::min(b[2 * c], p[c]);
      b[2 * c + 1] = std::max(b[2 * c + 1], p[c]);
    }
  }
  return b;
}

void ExpectBounds(const std::array<double, 6>& actual, const std::array<double, 6>& expected,
  double tolerance, const std::string& what)
{
  for (int c = 0; c < 6; ++c)
  {
    EXPECT_NEAR(actual[c], expected[c], tolerance) << what << ", bound " << c;
  }
}

std::array<int, 3> Rounded(const Vec3& color)
{
  std::array<int, 3> rgb;
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = static_cast<int>(std::lround(255.0 * std::clamp(color[c], 0.0, 1.0)));
  }
  return rgb;
}

/// Colour of the output point nearest to `p`; fails if none lies within `tolerance`.
std::array<int, 3> ColorAt(vtkPolyData* data, const Vec3& p, double tolerance = 1e-6)
{
  auto* colors = vtkUnsignedCharArray::SafeDownCast(data->GetPointData()->GetArray("Colors"));
  vtkIdType nearest = -1;
  double distance = tolerance;
  for (vtkIdType i = 0; colors && i < data->GetNumberOfPoints(); ++i)
  {
    double q[3];
    data->GetPoint(i, q);
    const double d = (Vec3(q[0], q[1], q[2]) - p).norm();
    if (d <= distance)
    {
      nearest = i;
      distance = d;
    }
  }
  if (nearest < 0)
  {
    ADD_FAILURE() << "no vertex at (" << p.transpose() << ")";
    return { -1, -1, -1 };
  }
  return { colors->GetTypedComponent(nearest, 0), colors->GetTypedComponent(nearest, 1),
    colors->GetTypedComponent(nearest, 2) };
}

constexpr double Thickness = 0.1;
constexpr double H = 0.5 * Thickness;

constexpr const char* FourObjectsJson = R"({
  "objects": [
    {"type": "grid", "spacing": 1, "thickness": 0.1, "extent": [-1, 1, -1, 1, -1, 1]},
    {"type": "sphere", "center": [3, 0.5, 0], "radius": 0.5,
     "material": {"type": "solid", "color": [0.2, 0.4, 0.6]}},
    {"type": "plane", "point": [0, -3, 0], "normal": [0, 2, 0],
     "material": {"type": "checker", "color": [1, 1, 1], "color2": [0, 0, 0], "size": 1}},
    {"type": "box", "min": [-4, -1, -1], "max": [-3, 1, 2]}]})";

// vtkSphereSource, theta 48 x phi 24, both poles: 2 + 48 (24 - 2) points.
constexpr vtkIdType SpherePoints = 2 + 48 * 22;
// vtkPlaneSource, 64 x 64 quads.
constexpr vtkIdType PlanePoints = 65 * 65;
// vtkCubeSource: 24 points (4 per face), 6 quads -> 12 triangles.
constexpr vtkIdType CubePoints = 24;
constexpr vtkIdType Bars = 3 * 3 * 3;
} // namespace

//------------------------------------------------------------------------------
TEST(SceneSource, GridSphereBoxPlane)
{
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(FourObjectsJson)) << scene->GetLastError();
  vtkNew<vtkRiemannSceneSource> source;
  source->SetScene(scene);
  EXPECT_EQ(source->GetPlaneSize(), 10.0);
  source->Update();
  vtkPolyData* output = source->GetOutput();

  // The pieces, in object order.
  const vtkIdType gridFirst = 0;
  const vtkIdType sphereFirst = gridFirst + Bars * CubePoints;
  const vtkIdType planeFirst = sphereFirst + SpherePoints;
  const vtkIdType boxFirst = planeFirst + PlanePoints;
  ASSERT_EQ(output->GetNumberOfPoints(), boxFirst + CubePoints);
  // Triangles only: 12 per cube, 2 per plane quad, the sphere's.
  EXPECT_EQ(output->GetNumberOfVerts(), 0);
  EXPECT_EQ(output->GetNumberOfLines(), 0);
  EXPECT_EQ(output->GetNumberOfStrips(), 0);
  EXPECT_EQ(output->GetNumberOfPolys(), (Bars + 1) * 12 + 2 * 64 * 64 + 2 * 48 + 2 * 48 * 21);
  {
    vtkCellArray* polys = output->GetPolys();
    EXPECT_EQ(polys->GetNumberOfConnectivityIds(), 3 * polys->GetNumberOfCells()) << "triangles";
  }

  // Every bar: 24 points; the bar along axis a through lattice line (i, j)
  // of axes b = a+1, c = a+2 (mod 3); bars in order of a, then i, then j.
  const double along = 1.0; // extent [-1, 1] on every axis
  std::vector<double> barLengths;
  vtkIdType next = gridFirst;
  for (int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3;
    const int c = (a + 2) % 3;
    for (int i = -1; i <= 1; ++i)
    {
      for (int j = -1; j <= 1; ++j, next += CubePoints)
      {
        const std::string what = "bar along axis " + std::to_string(a) + " through (" +
          std::to_string(i) + ", " + std::to_string(j) + ")";
        const auto bounds = BoundsOf(output, next, CubePoints);
        // Cross section: the lattice line +- thickness / 2 (float points).
        EXPECT_NEAR(bounds[2 * b], i - H, 1e-6) << what;
        EXPECT_NEAR(bounds[2 * b + 1], i + H, 1e-6) << what;
        EXPECT_NEAR(bounds[2 * c], j - H, 1e-6) << what;
        EXPECT_NEAR(bounds[2 * c + 1], j + H, 1e-6) << what;
        // Along: the extent (RiemannScene.h documents the extent grown by h
        // for the ray tracer; see GridMatchesTheRayTracersBars).
        EXPECT_LE(bounds[2 * a], -along + 1e-6) << what;
        EXPECT_GE(bounds[2 * a], -along - H - 1e-6) << what;
        EXPECT_GE(bounds[2 * a + 1], along - 1e-6) << what;
        EXPECT_LE(bounds[2 * a + 1], along + H + 1e-6) << what;
        barLengths.push_back(bounds[2 * a + 1] - bounds[2 * a]);
      }
    }
  }
  // All bars alike.
  for (double length : barLengths)
  {
    EXPECT_NEAR(length, barLengths[0], 1e-6);
  }
  // The whole grid: the extent grown by thickness / 2 on every axis.
  ExpectBounds(BoundsOf(output, gridFirst, Bars * CubePoints),
    { -1 - H, 1 + H, -1 - H, 1 + H, -1 - H, 1 + H }, 1e-6, "grid");

  // The sphere: every point at the radius from the centre.
  const Vec3 center(3, 0.5, 0);
  double worstRadius = 0.0;
  for (vtkIdType i = sphereFirst; i < planeFirst; ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    worstRadius = std::max(worstRadius, std::abs((Vec3(p[0], p[1], p[2]) - center).norm() - 0.5));
  }
  EXPECT_LT(worstRadius, 1e-6);
  ExpectBounds(
    BoundsOf(output, sphereFirst, SpherePoints), { 2.5, 3.5, 0, 1, -0.5, 0.5 }, 1e-2, "sphere");

  // The plane: a 10 x 10 patch around its point, in the plane y = -3.
  ExpectBounds(BoundsOf(output, planeFirst, PlanePoints), { -5, 5, -3, -3, -5, 5 }, 1e-6, "plane");

  // The box: exactly its corners.
  ExpectBounds(BoundsOf(output, boxFirst, CubePoints), { -4, -3, -1, 1, -1, 2 }, 1e-6, "box");

  // Colours: a point-data array of 3 unsigned chars, the scalars.
  auto* colors = vtkUnsignedCharArray::SafeDownCast(output->GetPointData()->GetArray("Colors"));
  ASSERT_NE(colors, nullptr) << "point data \"Colors\" (unsigned char)";
  EXPECT_EQ(colors->GetNumberOfComponents(), 3);
  EXPECT_EQ(colors->GetNumberOfTuples(), output->GetNumberOfPoints());
  EXPECT_EQ(output->GetPointData()->GetScalars(), colors);

  // Every vertex: riemann::SurfaceColor of its object at the vertex.
  const riemann::Scene& s = scene->GetScene();
  const vtkIdType firsts[5] = { gridFirst, sphereFirst, planeFirst, boxFirst,
    output->GetNumberOfPoints() };
  int whiteChecks = 0;
  int blackChecks = 0;
  for (int object = 0; object < 4; ++object)
  {
    for (vtkIdType i = firsts[object]; i < firsts[object + 1]; ++i)
    {
      double p[3];
      output->GetPoint(i, p);
      riemann::SceneHit hit;
      hit.Object = object;
      hit.Position = Vec3(p[0], p[1], p[2]);
      const std::array<int, 3> actual = { colors->GetTypedComponent(i, 0),
        colors->GetTypedComponent(i, 1), colors->GetTypedComponent(i, 2) };
      ASSERT_EQ(actual, Rounded(riemann::SurfaceColor(s, hit)))
        << "object " << object << ", point " << i << " at (" << hit.Position.transpose() << ")";
      if (object == 2)
      {
        (actual[0] == 255 ? whiteChecks : blackChecks)++;
      }
    }
  }
  EXPECT_GT(whiteChecks, 1000) << "the checker shows both colours";
  EXPECT_GT(blackChecks, 1000) << "the checker shows both colours";

  // The position pseudo-colour written out: (p - lo) / (hi - lo), the
  // grid's bounds being its extent [-1, 1]^3 and the box's its corners.
  // (The end of a bar along its axis is the extent, or the extent + h as
  // RiemannScene.h documents; both clamp to the same colour: look up the
  // nearest vertex.)
  // Bar along x through (0, 0), vertex (1, h, h): (1, 0.525, 0.525) -> 255, 134, 134.
  EXPECT_EQ(ColorAt(output, Vec3(1, H, H), 0.6 * Thickness), (std::array<int, 3>{ 255, 134, 134 }));
  // Bar along z through (x, y) = (-1, 0), vertex (-1 - h, -h, 1): (0, 0.475, 1) -> 0, 121, 255.
  EXPECT_EQ(
    ColorAt(output, Vec3(-1 - H, -H, 1), 0.6 * Thickness), (std::array<int, 3>{ 0, 121, 255 }));
  // The box's corners: black at min, white at max, (1, 0, 1) at (-3, -1, 2).
  EXPECT_EQ(ColorAt(output, Vec3(-4, -1, -1)), (std::array<int, 3>{ 0, 0, 0 }));
  EXPECT_EQ(ColorAt(output, Vec3(-3, 1, 2)), (std::array<int, 3>{ 255, 255, 255 }));
  EXPECT_EQ(ColorAt(output, Vec3(-3, -1, 2)), (std::array<int, 3>{ 255, 0, 255 }));
  // The solid sphere.
  EXPECT_EQ(ColorAt(output, Vec3(3, 0.5, 0.5)), (std::array<int, 3>{ 51, 102, 153 }));
  // Checker cells: floor(x) + floor(y) + floor(z) even is white (y = -3):
  // (0.5, -3, 0.5) -> -3 odd: black; (1.5, -3, 0.5) -> -2 even: white; the
  // patch's vertices at x = -5 + 10 k / 64 include x = 0.625 and 1.25.
  EXPECT_EQ(ColorAt(output, Vec3(0.625, -3, 0.625)), (std::array<int, 3>{ 0, 0, 0 }));
  EXPECT_EQ(ColorAt(output, Vec3(1.25, -3, 0.625)), (std::array<int, 3>{ 255, 255, 255 }));

  // PlaneSize: the patch's side.
  source->SetPlaneSize(4);
  source->Update();
  output = source->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), boxFirst + CubePoints);
  ExpectBounds(BoundsOf(output, planeFirst, PlanePoints), { -2, 2, -3, -3, -2, 2 }, 1e-6, "plane");

  // The source follows the scene: a new definition is a new output.
  ASSERT_TRUE(
    scene->SetDefinition(R"({"objects": [{"type": "box", "min": [0, 0, 0], "max": [1, 2, 3]}]})"));
  source->Update();
  output = source->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), CubePoints);
  ExpectBounds(BoundsOf(output, 0, CubePoints), { 0, 1, 0, 2, 0, 3 }, 1e-6, "new box");
}

TEST(SceneSource, DefaultAndEmptyScenes)
{
  // No scene: the default scene, the paper's grid (spacing 1, [-4, 4]^3,
  // thickness 0.06): 3 axes x 9 x 9 lattice lines.
  vtkNew<vtkRiemannSceneSource> source;
  source->Update();
  vtkPolyData* output = source->GetOutput();
  EXPECT_EQ(output->GetNumberOfPoints(), 3 * 9 * 9 * CubePoints);
  EXPECT_EQ(output->GetNumberOfPolys(), 3 * 9 * 9 * 12);
  double bounds[6];
  output->GetBounds(bounds);
  for (int c = 0; c < 6; ++c)
  {
    EXPECT_NEAR(bounds[c], c % 2 ? 4.03 : -4.03, 1e-6);
  }

  // A scene without objects: nothing.
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(R"({"objects": []})")) << scene->GetLastError();
  source->SetScene(scene);
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(source->GetOutput()->GetNumberOfCells(), 0);
}

// The geometry should be the ray tracer's (RiemannScene.h, "Precisely ..."):
// the bar along k spans [E0_k - h, E1_k + h], and the lattice lines inside
// the extent are found with a 1e-9 slack (IntersectGrid), so an extent such
// as [-0.3, 0.3] with spacing 0.1 (-0.3 / 0.1 = -2.9999999999999996) has 7
// lines per axis. vtkRiemannSceneSource must draw exactly those bars.
TEST(SceneSource, GridMatchesTheRayTracersBars)
{
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(R"({"objects": [
    {"type": "grid", "spacing": 0.1, "thickness": 0.02, "extent": [-0.3, 0.3, -0.3, 0.3, -0.3, 0.3]}]})"))
    << scene->GetLastError();
  vtkNew<vtkRiemannSceneSource> source;
  source->SetScene(scene);
  source->Update();
  vtkPolyData* output = source->GetOutput();
  EXPECT_EQ(output->GetNumberOfPoints(), 3 * 7 * 7 * CubePoints) << "7 x 7 lattice lines per axis";
  // The first bar (along x through y = z = -0.3): [-0.31, 0.31] x [-0.31, -0.29]^2.
  ASSERT_GE(output->GetNumberOfPoints(), CubePoints);
  ExpectBounds(BoundsOf(output, 0, CubePoints), { -0.31, 0.31, -0.31, -0.29, -0.31, -0.29 }, 1e-6,
    "first bar");
  // The ray tracer agrees: a segment along x at y = z = -0.3 enters at x = -0.31.
  riemann::SceneHit hit;
  ASSERT_TRUE(
    riemann::IntersectSegment(scene->GetScene(), Vec3(-1, -0.3, -0.3), Vec3(1, -0.3, -0.3), hit));
  EXPECT_NEAR(hit.Position.x(), -0.31, 1e-12);
}

//------------------------------------------------------------------------------
/// "" when riemann::WriteImage succeeds, else its ImageFileError's text.
std::string WriteError(const std::string& path, const riemann::Image& image)
{
  try
  {
    riemann::WriteImage(path, image);
  }
  catch (const riemann::ImageFileError& e)
  {
    return e.what();
  }
  return std::string();
}

/// riemann::ReadImage into `image`: "" when it succeeds, else its ImageFileError's text.
std::string ReadError(const std::string& path, riemann::Image& image)
{
  try
  {
    image = riemann::ReadImage(path);
  }
  catch (const riemann::ImageFileError& e)
  {
    return e.what();
  }
  return std::string();
}

TEST(ImageIO, PngRoundTripWithin8Bits)
{
  const ScratchDirectory scratch("Png");
  const fs::path& dir = scratch.Path;
  riemann::Image image;
  image.Width = 7;
  image.Height = 5;
  image.Channels = 3;
  image.ChannelNames = { "R", "G", "B" };
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int i = 0; i < 7 * 5 * 3; ++i)
  {
    image.Pixels.push_back(unit(random));
  }
  // Exact 8-bit levels, and values that 8 bits clamp.
  image.Pixels[0] = 0.0f;
  image.Pixels[1] = 1.0f;
  image.Pixels[2] = 51.0f / 255.0f;
  image.Pixels[3] = 1.7f;
  image.Pixels[4] = -0.25f;

  const fs::path file = dir / "round-trip.png";
  ASSERT_EQ(WriteError(file.string(), image), "");
  ASSERT_TRUE(fs::is_regular_file(file));
  riemann::Image back;
  ASSERT_EQ(ReadError(file.string(), back), "");
  EXPECT_EQ(back.Width, 7);
  EXPECT_EQ(back.Height, 5);
  EXPECT_EQ(back.Channels, 3);
  ASSERT_EQ(back.Pixels.size(), image.Pixels.size());
  double worst = 0.0;
  for (size_t i = 0; i < image.Pixels.size(); ++i)
  {
    const double expected = std::clamp(double(image.Pixels[i]), 0.0, 1.0);
    worst = std::max(worst, std::abs(double(back.Pixels[i]) - expected));
    // Read back as 8-bit levels.
    EXPECT_NEAR(back.Pixels[i] * 255.0, std::round(back.Pixels[i] * 255.0), 1e-4) << i;
  }
  EXPECT_LE(worst, 0.5 / 255.0 + 1e-6);
  EXPECT_EQ(back.Pixels[0], 0.0f);
  EXPECT_EQ(back.Pixels[1], 1.0f);
  EXPECT_NEAR(back.Pixels[2] * 255.0, 51.0, 1e-4);
  EXPECT_EQ(back.Pixels[3], 1.0f) << "clamped to 1";
  EXPECT_EQ(back.Pixels[4], 0.0f) << "clamped to 0";
  // Same picture (once clamped), within half a level.
  riemann::Image clamped = image;
  for (float& value : clamped.Pixels)
  {
    value = std::clamp(value, 0.0f, 1.0f);
  }
  EXPECT_LE(riemann::ImageDifference(clamped, back), 0.5 + 1e-6);

  // The extension's case does not matter; no temporary is left behind.
  const fs::path upper = dir / "UPPER.PNG";
  EXPECT_EQ(WriteError(upper.string(), image), "");
  EXPECT_TRUE(fs::is_regular_file(upper));
  for (const auto& entry : fs::directory_iterator(dir))
  {
    EXPECT_EQ(entry.path().filename().string().find(".partial-"), std::string::npos)
      << entry.path();
  }
}

TEST(ImageIO, ExrRoundTripIsExactWithChannelNames)
{
  const ScratchDirectory scratch("Exr");
  const fs::path& dir = scratch.Path;
  riemann::Image image;
  image.Width = 4;
  image.Height = 3;
  image.Channels = 4;
  image.ChannelNames = { "R", "G", "B", "HitX" };
  for (int i = 0; i < 4 * 3 * 4; ++i)
  {
    // Beyond [0, 1], negative, and not representable in fewer bits.
    image.Pixels.push_back(static_cast<float>(std::sin(1.0 + i) * (1.0 + i) / 3.0 + 1e-7 * i));
  }
  image.Pixels[5] = 1234.5678f;
  image.Pixels[6] = -0.0001234f;
  const fs::path file = dir / "aovs.exr";
  ASSERT_EQ(WriteError(file.string(), image), "");
  riemann::Image back;
  ASSERT_EQ(ReadError(file.string(), back), "");
  EXPECT_EQ(back.Width, 4);
  EXPECT_EQ(back.Height, 3);
  EXPECT_EQ(back.Channels, 4);
  EXPECT_EQ(back.ChannelNames, image.ChannelNames);
  EXPECT_EQ(back.Pixels, image.Pixels) << "32-bit floats, exactly";
  // Row 0 is the top: the first pixel of the file is the first written.
  EXPECT_EQ(back.Pixels[0], image.Pixels[0]);
  EXPECT_EQ(riemann::ImageDifference(image, back), 0.0);
}

TEST(ImageIO, ImageDifference)
{
  riemann::Image a;
  a.Width = 4;
  a.Height = 4;
  a.Channels = 3;
  a.Pixels.assign(4 * 4 * 3, 0.5f);
  riemann::Image b = a;
  EXPECT_EQ(riemann::ImageDifference(a, b), 0.0);
  EXPECT_EQ(riemann::ImageDifference(a, a), 0.0);

  // One pixel of 16 changes: R by 0.1, B by 0.3: the pixel's worst channel
  // (0.3, in 8-bit units 76.5) averaged over 16 pixels.
  b.Pixels[3 * 5 + 0] += 0.1f;
  b.Pixels[3 * 5 + 2] -= 0.3f;
  const double expected = 255.0 * (0.5 - double(b.Pixels[3 * 5 + 2])) / 16.0;
  EXPECT_NEAR(riemann::ImageDifference(a, b), expected, 1e-9);
  EXPECT_NEAR(riemann::ImageDifference(a, b), 255.0 * 0.3 / 16.0, 1e-5);
  EXPECT_EQ(riemann::ImageDifference(a, b), riemann::ImageDifference(b, a)) << "symmetric";

  // A second changed pixel adds its own worst channel.
  b.Pixels[3 * 15 + 1] = 0.0f;
  EXPECT_NEAR(riemann::ImageDifference(a, b), expected + 255.0 * 0.5 / 16.0, 1e-9);

  // Only the first three channels count: RGBA with a different alpha is the same picture.
  riemann::Image rgba;
  rgba.Width = 4;
  rgba.Height = 4;
  rgba.Channels = 4;
  for (int i = 0; i < 16; ++i)
  {
    rgba.Pixels.insert(rgba.Pixels.end(), { 0.5f, 0.5f, 0.5f, (i % 2) ? 0.0f : 1.0f });
  }
  EXPECT_EQ(riemann::ImageDifference(a, rgba), 0.0);

  // Different sizes, or fewer than three channels: negative.
  riemann::Image wide = a;
  wide.Width = 8;
  wide.Height = 2;
  EXPECT_LT(riemann::ImageDifference(a, wide), 0.0);
  riemann::Image small = a;
  small.Width = 2;
  small.Height = 2;
  small.Pixels.resize(2 * 2 * 3);
  EXPECT_LT(riemann::ImageDifference(a, small), 0.0);
  EXPECT_LT(riemann::ImageDifference(small, a), 0.0);
  riemann::Image gray;
  gray.Width = 4;
  gray.Height = 4;
  gray.Channels = 1;
  gray.Pixels.assign(16, 0.5f);
  EXPECT_LT(riemann::ImageDifference(a, gray), 0.0);
}

TEST(ImageIO, ErrorsLeaveNoFiles)
{
  const ScratchDirectory scratch("Errors");
  const fs::path& dir = scratch.Path;
  riemann::Image image;
  image.Width = 2;
  image.Height = 2;
  image.Channels = 3;
  image.Pixels.assign(12, 0.25f);
  auto noPartialFiles = [](const fs::path& folder)
  {
    for (const auto& entry : fs::recursive_directory_iterator(folder))
    {
      EXPECT_EQ(entry.path().filename().string().find(".partial-"), std::string::npos)
        << "left behind: " << entry.path();
    }
  };

  // A folder that does not exist: an error, no file.
  const fs::path missing = dir / "no-such-folder" / "out.png";
  std::string error = WriteError(missing.string(), image);
  EXPECT_NE(error, "");
  EXPECT_NE(error.find(missing.string()), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(missing));
  EXPECT_FALSE(fs::exists(dir / "no-such-folder"));
  noPartialFiles(dir);
  error = WriteError((dir / "no-such-folder" / "out.exr").string(), image);
  EXPECT_NE(error, "");
  noPartialFiles(dir);

  // A target that cannot be replaced (a folder of that name): the temporary
  // file is written next to it, the rename fails, the temporary goes.
  const fs::path blocked = dir / "blocked.png";
  fs::create_directories(blocked / "keep");
  error = WriteError(blocked.string(), image);
  EXPECT_NE(error, "");
  EXPECT_NE(error.find("could not write"), std::string::npos) << error;
  EXPECT_TRUE(fs::is_directory(blocked / "keep")) << "the folder is untouched";
  noPartialFiles(dir);

  // An existing file is replaced whole.
  const fs::path existing = dir / "existing.png";
  std::ofstream(existing) << "old contents";
  EXPECT_EQ(WriteError(existing.string(), image), "");
  riemann::Image back;
  EXPECT_EQ(ReadError(existing.string(), back), "");
  EXPECT_EQ(back.Width, 2);
  noPartialFiles(dir);

  // Unsupported extensions, and none.
  for (const char* name : { "out.jpg", "out.tif", "out", "out.png.txt" })
  {
    error = WriteError((dir / name).string(), image);
    EXPECT_NE(error.find("unsupported image format"), std::string::npos) << name << ": " << error;
    EXPECT_FALSE(fs::exists(dir / name)) << name;
  }
  // A dot in a folder name is no extension.
  fs::create_directories(dir / "folder.png");
  error = WriteError((dir / "folder.png" / "out").string(), image);
  EXPECT_NE(error.find("unsupported image format"), std::string::npos) << error;

  // An empty or inconsistent image.
  riemann::Image empty;
  EXPECT_NE(WriteError((dir / "empty.png").string(), empty), "");
  riemann::Image inconsistent = image;
  inconsistent.Pixels.pop_back();
  EXPECT_NE(WriteError((dir / "inconsistent.png").string(), inconsistent), "");
  EXPECT_FALSE(fs::exists(dir / "empty.png"));
  EXPECT_FALSE(fs::exists(dir / "inconsistent.png"));
  noPartialFiles(dir);

  // Reading: a missing file, and a file that is no image.
  EXPECT_NE(ReadError((dir / "nothing-here.png").string(), back), "");
  std::ofstream(dir / "garbage.png") << "not a png";
  EXPECT_NE(ReadError((dir / "garbage.png").string(), back), "");
}
