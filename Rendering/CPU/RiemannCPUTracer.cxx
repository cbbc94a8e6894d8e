#include "RiemannCPUTracer.h"

#include "RiemannEmbreeMeshIntersector.h"
#include "RiemannSceneIntersection.h"
#include "RiemannRay.h"
#include "RiemannShading.h"

#include "DiffeoMetric.h"
#include "GeodesicTrace.h" // TerminationReason
#include "SpaceMap.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace riemann
{
namespace
{
constexpr float NaN = std::numeric_limits<float>::quiet_NaN();

/// A 32-bit integer hash (a PCG output permutation): decorrelates the seeds.
std::uint32_t Hash(std::uint32_t x)
{
  std::uint32_t state = x * 747796405u + 2891336453u;
  std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

/// Uniform in [0, 1) from a hash.
double Uniform(std::uint32_t bits)
{
  return (bits >> 8) * (1.0 / 16777216.0);
}
} // namespace

/// The exact geodesics of a diffeomorphism metric from the eye.
struct CPUTracer::Exact
{
  const SpaceMap* Map = nullptr;
  Vec3 Eye;
  Vec3 Start;
  Mat3 Jacobian;
};

CPUTracer::CPUTracer(std::shared_ptr<const Metric> metric, std::shared_ptr<const Scene> scene,
  const CameraSettings& camera, const RaySettings& rays, const CPUTracerSettings& settings,
  std::shared_ptr<const EnvironmentMap> environment)
  : MetricPointer(std::move(metric))
  , ScenePointer(std::move(scene))
  , Environment(std::move(environment))
  , Rays(rays)
  , Settings(settings)
{
  if (!this->MetricPointer || !this->ScenePointer)
  {
    throw std::runtime_error("no metric or no scene");
  }
  if (settings.Width <= 0 || settings.Height <= 0 || settings.SamplesPerPixel <= 0)
  {
    throw std::runtime_error("the image size and the samples per pixel must be positive");
  }
  if (!(rays.Step > 0) || rays.MaximumSteps < 1 || !(rays.MaximumLength > 0))
  {
    throw std::runtime_error("the step, the maximum steps and the maximum length must be positive");
  }
  this->Camera.reset(new ObserverCamera(*this->MetricPointer, camera));
  this->Meshes.reset(new EmbreeMeshIntersector(*this->ScenePointer));
  if (const auto* diffeo = dynamic_cast<const DiffeoMetric*>(this->MetricPointer.get()))
  {
    this->Reference.reset(new Exact);
    this->Reference->Map = &diffeo->GetMap();
    this->Reference->Eye = camera.Position;
    VectorJet jet;
    this->Reference->Map->Evaluate(camera.Position, FirstDerivatives, jet);
    this->Reference->Start = jet.Value;
    this->Reference->Jacobian = jet.Jacobian;
  }
}

CPUTracer::~CPUTracer() = default;

std::size_t CPUTracer::NumberOfTriangles() const
{
  return this->Meshes->NumberOfTriangles();
}

bool CPUTracer::HasExactReference() const
{
  return this->Reference != nullptr;
}

Vec3 CPUTracer::Direction(double px, double py) const
{
  const double x = 2.0 * px / this->Settings.Width - 1.0;
  const double y = 2.0 * py / this->Settings.Height - 1.0;
  return this->Camera->Direction(
    x, y, static_cast<double>(this->Settings.Width) / this->Settings.Height);
}

bool CPUTracer::ExactHit(const Vec3& v, Vec3& position, double& length) const
{
  if (!this->Reference)
  {
    return false;
  }
  const Exact& exact = *this->Reference;
  const Scene& scene = *this->ScenePointer;
  const Vec3 direction = exact.Jacobian * v;
  // gamma(s), warm-started Newton (the map's own inverse when it has a closed form).
  auto gamma = [&](double s, Vec3& p) { return exact.Map->Inverse(exact.Start + s * direction, p); };
  // First hit on the chords of [s0, s1] cut into `pieces`; meshes count too.
  auto firstHit = [&](double s0, double s1, int pieces, double& hitStart, SceneHit& hit)
  {
    Vec3 previous;
    if (!gamma(s0, previous))
    {
      return false;
    }
    for (int k = 1; k <= pieces; ++k)
    {
      const double a = s0 + (s1 - s0) * (k - 1) / pieces;
      const double b = k == pieces ? s1 : s0 + (s1 - s0) * k / pieces;
      Vec3 next;
      if (!gamma(b, next))
      {
        return false;
      }
      SceneHit found;
      if (IntersectSceneSegment(scene, this->Meshes.get(), previous, next, found))
      {
        hit = found;
        hitStart = a;
        (void)b;
        return true;
      }
      previous = next;
    }
    return false;
  };
  const double chord = this->Settings.ExactChord;
  const double maximum = this->Rays.MaximumLength;
  const int pieces = static_cast<int>(std::ceil(maximum / chord));
  double s0 = 0.0;
  SceneHit hit;
  if (!firstHit(0.0, maximum, pieces, s0, hit))
  {
    return false;
  }
  // Refine: the hitting chord in 32 pieces, three times (chords of 3e-5 chord).
  double width = maximum / pieces;
  for (int level = 0; level < 3; ++level)
  {
    double start = s0;
    SceneHit finer;
    if (!firstHit(s0, std::min(s0 + width, maximum), 32, start, finer))
    {
      break; // the finer chords pass by (a grazing hit): keep the coarse one
    }
    hit = finer;
    s0 = start;
    width /= 32;
  }
  position = hit.Position;
  length = s0 + hit.Fraction * width;
  return true;
}

// RenderTile as named steps: StartRays -> MarchWavefront -> GatherPixels.
long long CPUTracer::RenderTile(int x0, int y0, int x1, int y1, PixelResult* image) const
{
  if (x1 - x0 <= 0 || y1 - y0 <= 0)
  {
    return 0;
  }
  std::vector<TileRay> rays;
  std::vector<RayMarcher> marchers;
  this->StartRays(x0, y0, x1, y1, rays, marchers);
  const long long steps = this->MarchWavefront(marchers);
  this->GatherPixels(rays, marchers, image);
  return steps;
}

// Step 1: every ray of the tile started at the eye, pixel by pixel: the
// pixel-centre ray alone with one sample; with N > 1 the centre ray (for the
// AOVs) then N rays through stratified jitter in an nx x ny grid of cells of
// the pixel, hashed from Seed, pixel and sample (the same on any thread).
void CPUTracer::StartRays(int x0, int y0, int x1, int y1, std::vector<TileRay>& rays,
  std::vector<RayMarcher>& marchers) const
{
  const CPUTracerSettings& settings = this->Settings;
  const int samples = settings.SamplesPerPixel;
  const int nx = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(samples))));
  const int ny = (samples + nx - 1) / nx;
  const int perPixel = samples > 1 ? samples + 1 : 1;
  rays.reserve(static_cast<std::size_t>(x1 - x0) * (y1 - y0) * perPixel);
  marchers.reserve(rays.capacity());
  for (int row = y0; row < y1; ++row)
  {
    for (int column = x0; column < x1; ++column)
    {
      const int pixel = row * settings.Width + column;
      for (int sample = samples > 1 ? -1 : 0; sample < (samples > 1 ? samples : 1); ++sample)
      {
        double px = column + 0.5;
        double py = row + 0.5;
        if (samples > 1 && sample >= 0)
        {
          const std::uint32_t h = Hash(settings.Seed ^ Hash(static_cast<std::uint32_t>(pixel) ^
                                                       Hash(static_cast<std::uint32_t>(sample))));
          px = column + ((sample % nx) + Uniform(h)) / nx;
          py = row + ((sample / nx) + Uniform(Hash(h))) / ny;
        }
        rays.push_back({ pixel, samples > 1 ? sample : -1 });
        marchers.emplace_back(this->Rays);
        marchers.back().Start(this->Camera->GetSettings().Position, this->Direction(px, py));
      }
    }
  }
}

// Step 2: the wavefront. Every live ray takes a step (PacketWidth rays at a
// time in the packet engine; the live rays are repacked after every step,
// so a packet never carries a finished ray), then all the new
// segments go to Embree in one stream query and each is tested against the
// analytic objects; the nearer hit wins, and rays that hit leave the front.
// Returns the number of steps taken.
long long CPUTracer::MarchWavefront(std::vector<RayMarcher>& marchers) const
{
  const Metric& metric = *this->MetricPointer;
  const Scene& scene = *this->ScenePointer;
  const std::size_t count = marchers.size();
  std::vector<std::size_t> live(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    live[i] = i;
  }
  std::vector<std::size_t> stepped;
  std::vector<Vec3> a;
  std::vector<Vec3> b;
  std::vector<SceneHit> meshHits;
  std::unique_ptr<bool[]> meshFound(new bool[count]);
  const bool meshes = !this->Meshes->Empty();
  long long steps = 0;
  while (!live.empty())
  {
    stepped.clear();
    a.clear();
    b.clear();
    // The live rays step PacketWidth at a time through the packet engine.
    for (std::size_t first = 0; first < live.size(); first += PacketWidth)
    {
      const int count = static_cast<int>(std::min<std::size_t>(PacketWidth, live.size() - first));
      RayMarcher* packet[PacketWidth];
      bool advanced[PacketWidth];
      for (int l = 0; l < count; ++l)
      {
        packet[l] = &marchers[live[first + l]];
      }
      AdvanceRayPacket(metric, packet, count, advanced);
      for (int l = 0; l < count; ++l)
      {
        if (advanced[l])
        {
          const std::size_t i = live[first + l];
          stepped.push_back(i);
          a.push_back(marchers[i].SegmentStart());
          b.push_back(marchers[i].SegmentEnd());
        }
      }
    }
    steps += static_cast<long long>(stepped.size());
    if (meshes)
    {
      meshHits.assign(stepped.size(), SceneHit());
      this->Meshes->Intersect(a.data(), b.data(), stepped.size(), meshHits.data(), meshFound.get(),
        this->Settings.UseRayStreams);
    }
    live.clear();
    for (std::size_t k = 0; k < stepped.size(); ++k)
    {
      RayMarcher& ray = marchers[stepped[k]];
      SceneHit hit;
      bool found = IntersectSegment(scene, a[k], b[k], hit);
      if (meshes && meshFound[k] && (!found || meshHits[k].Fraction < hit.Fraction))
      {
        hit = meshHits[k];
        found = true;
      }
      if (found)
      {
        ray.Hit(hit);
      }
      else
      {
        ray.Miss();
        live.push_back(stepped[k]);
      }
    }
  }
  return steps;
}

// Step 3: shade and gather. The colour is the mean of the samples (the
// centre ray alone with one sample); the centre ray gives the AOVs.
void CPUTracer::GatherPixels(const std::vector<TileRay>& rays,
  const std::vector<RayMarcher>& marchers, PixelResult* image) const
{
  const Metric& metric = *this->MetricPointer;
  const Scene& scene = *this->ScenePointer;
  const int samples = this->Settings.SamplesPerPixel;
  for (const TileRay& ray : rays)
  {
    for (float& c : image[ray.Pixel].Color)
    {
      c = 0.0f;
    }
  }
  const double weight = 1.0 / samples;
  for (std::size_t i = 0; i < rays.size(); ++i)
  {
    const RayMarcher& ray = marchers[i];
    PixelResult& pixel = image[rays[i].Pixel];
    const bool centre = rays[i].Sample < 0;
    if (samples == 1 || !centre)
    {
      const Vec3 color = ShadeRay(metric, scene, ray.IsHit(), ray.HitInfo(), ray.Reason(),
        ray.Length(), ray.Velocity(), this->Environment.get());
      for (int c = 0; c < 3; ++c)
      {
        pixel.Color[c] += static_cast<float>(weight * color[c]);
      }
    }
    if (centre)
    {
      this->WriteCentreRay(ray, rays[i].Pixel, pixel);
    }
  }
}

// The arbitrary output variables of a pixel-centre ray, and its distance to
// the exact hit when ComputeHitError and the metric has an exact reference
// (infinite when only one of them hits).
void CPUTracer::WriteCentreRay(const RayMarcher& ray, int pixelIndex, PixelResult& pixel) const
{
  const CPUTracerSettings& settings = this->Settings;
  const Vec3 position = ray.Position();
  for (int c = 0; c < 3; ++c)
  {
    pixel.HitPosition[c] = ray.IsHit() ? static_cast<float>(position[c]) : NaN;
  }
  pixel.ArcLength = static_cast<float>(ray.Length());
  pixel.Steps = ray.Steps();
  pixel.Reason = ray.Reason();
  const Vec3 velocity = ray.Velocity();
  const double speed = this->MetricPointer->InnerProduct(position, velocity, velocity);
  pixel.SpeedDrift = std::isfinite(speed) ? static_cast<float>(speed - 1.0) : NaN;
  pixel.HitError = NaN;
  if (settings.ComputeHitError && this->Reference)
  {
    const int column = pixelIndex % settings.Width;
    const int row = pixelIndex / settings.Width;
    Vec3 exactPosition;
    double exactLength = 0.0;
    const bool exactHit =
      this->ExactHit(this->Direction(column + 0.5, row + 0.5), exactPosition, exactLength);
    if (exactHit && ray.IsHit())
    {
      pixel.HitError = static_cast<float>((exactPosition - position).norm());
    }
    else if (exactHit != ray.IsHit())
    {
      pixel.HitError = std::numeric_limits<float>::infinity();
    }
  }
}
} // namespace riemann
