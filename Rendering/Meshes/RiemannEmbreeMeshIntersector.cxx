#include "RiemannEmbreeMeshIntersector.h"
#include "RiemannSceneIntersection.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace riemann
{
struct EmbreeMeshIntersector::Internals
{
  const Scene* Source = nullptr;
  RTCDevice Device = nullptr;
  RTCScene Handle = nullptr;
  /// Embree geometry id -> index in Scene::Objects.
  std::vector<int> ObjectOfGeometry;

  ~Internals()
  {
    if (this->Handle)
    {
      rtcReleaseScene(this->Handle);
    }
    if (this->Device)
    {
      rtcReleaseDevice(this->Device);
    }
  }

  [[noreturn]] void Fail(const std::string& what) const
  {
    const RTCError code = this->Device ? rtcGetDeviceError(this->Device) : RTC_ERROR_UNKNOWN;
    throw std::runtime_error("Embree: " + what + " (error code " +
      std::to_string(static_cast<int>(code)) + ")");
  }
};

EmbreeMeshIntersector::EmbreeMeshIntersector(const Scene& scene)
  : Impl(new Internals)
{
  Internals& impl = *this->Impl;
  impl.Source = &scene;
  if (!scene.HasMeshes())
  {
    return;
  }
  impl.Device = rtcNewDevice(nullptr);
  if (!impl.Device)
  {
    impl.Fail("cannot create a device");
  }
  impl.Handle = rtcNewScene(impl.Device);
  // Robust: rays through an edge or a vertex shared by two triangles must
  // not slip between them (a hole in a closed surface would show the far side).
  rtcSetSceneFlags(impl.Handle, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl.Handle, RTC_BUILD_QUALITY_HIGH);
  for (std::size_t index = 0; index < scene.Objects.size(); ++index)
  {
    const SceneObject& object = scene.Objects[index];
    if (object.Type != ObjectType::Mesh)
    {
      continue;
    }
    const TriangleMesh& mesh = *ObjectMesh(scene, index);
    RTCGeometry geometry = rtcNewGeometry(impl.Device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree's own buffers (aligned and padded as it requires), filled once.
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry,
      RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.NumberOfPoints()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX,
      0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.NumberOfTriangles()));
    if (!vertices || !indices)
    {
      rtcReleaseGeometry(geometry);
      impl.Fail("cannot allocate the buffers of a mesh of " +
        std::to_string(mesh.NumberOfTriangles()) + " triangles");
    }
    std::memcpy(vertices, mesh.Points.data(), mesh.Points.size() * sizeof(float));
    std::memcpy(indices, mesh.Triangles.data(), mesh.Triangles.size() * sizeof(unsigned));
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(impl.Handle, geometry);
    rtcReleaseGeometry(geometry);
    if (impl.ObjectOfGeometry.size() <= id)
    {
      impl.ObjectOfGeometry.resize(id + 1, -1);
    }
    impl.ObjectOfGeometry[id] = static_cast<int>(index);
    this->Triangles += mesh.NumberOfTriangles();
  }
  rtcCommitScene(impl.Handle);
  if (rtcGetDeviceError(impl.Device) != RTC_ERROR_NONE)
  {
    impl.Fail("cannot build the scene");
  }
}

EmbreeMeshIntersector::~EmbreeMeshIntersector() = default;

bool EmbreeMeshIntersector::Empty() const
{
  return this->Impl->Handle == nullptr;
}

namespace
{
/// One segment as an Embree ray; false for a segment of zero length.
bool MakeRay(const Vec3& a, const Vec3& b, RTCRayHit& ray, double& length)
{
  const Vec3 d = b - a;
  length = d.norm();
  std::memset(&ray, 0, sizeof(ray));
  ray.ray.org_x = static_cast<float>(a.x());
  ray.ray.org_y = static_cast<float>(a.y());
  ray.ray.org_z = static_cast<float>(a.z());
  ray.ray.tnear = 0.0f;
  ray.ray.mask = 0xFFFFFFFFu;
  ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  ray.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  if (!(length > 0) || !std::isfinite(length))
  {
    // Never hits: an empty interval.
    ray.ray.tfar = -1.0f;
    ray.ray.dir_z = 1.0f;
    return false;
  }
  const Vec3 unit = d / length;
  ray.ray.dir_x = static_cast<float>(unit.x());
  ray.ray.dir_y = static_cast<float>(unit.y());
  ray.ray.dir_z = static_cast<float>(unit.z());
  ray.ray.tfar = static_cast<float>(length);
  return true;
}
}

void EmbreeMeshIntersector::Intersect(const Vec3* a, const Vec3* b, std::size_t count, SceneHit* hits,
  bool* found, bool stream) const
{
  const Internals& impl = *this->Impl;
  for (std::size_t i = 0; i < count; ++i)
  {
    found[i] = false;
  }
  if (!impl.Handle || count == 0)
  {
    return;
  }
  std::vector<RTCRayHit> rays(count);
  std::vector<double> lengths(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    MakeRay(a[i], b[i], rays[i], lengths[i]);
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  if (stream)
  {
    // Neighbouring pixels' segments: coherent.
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect1M(impl.Handle, &context, rays.data(), static_cast<unsigned>(count), sizeof(RTCRayHit));
  }
  else
  {
    for (std::size_t i = 0; i < count; ++i)
    {
      if (rays[i].ray.tfar >= 0.0f)
      {
        rtcIntersect1(impl.Handle, &context, &rays[i]);
      }
    }
  }
  const Scene& scene = *impl.Source;
  for (std::size_t i = 0; i < count; ++i)
  {
    const RTCRayHit& ray = rays[i];
    if (ray.hit.geomID == RTC_INVALID_GEOMETRY_ID || ray.hit.geomID >= impl.ObjectOfGeometry.size())
    {
      continue;
    }
    const int object = impl.ObjectOfGeometry[ray.hit.geomID];
    const TriangleMesh& mesh = *scene.Meshes[scene.Objects[object].Mesh];
    SceneHit& hit = hits[i];
    const Vec3 d = b[i] - a[i];
    hit.Fraction = std::clamp(static_cast<double>(ray.ray.tfar) / lengths[i], 0.0, 1.0);
    hit.Position = a[i] + hit.Fraction * d;
    hit.Object = object;
    hit.Primitive = static_cast<int>(ray.hit.primID);
    hit.U = ray.hit.u;
    hit.V = ray.hit.v;
    Vec3 normal(ray.hit.Ng_x, ray.hit.Ng_y, ray.hit.Ng_z);
    if (!mesh.Normals.empty())
    {
      const unsigned* corner = &mesh.Triangles[3 * static_cast<std::size_t>(ray.hit.primID)];
      const double w[3] = { 1.0 - hit.U - hit.V, hit.U, hit.V };
      Vec3 smooth = Vec3::Zero();
      for (int k = 0; k < 3; ++k)
      {
        const float* n = &mesh.Normals[3 * static_cast<std::size_t>(corner[k])];
        smooth += w[k] * Vec3(n[0], n[1], n[2]);
      }
      if (smooth.squaredNorm() > 0)
      {
        normal = smooth;
      }
    }
    const double length = normal.norm();
    normal = length > 0 ? Vec3(normal / length) : Vec3(Vec3::Zero());
    if (normal.dot(d) > 0)
    {
      normal = -normal;
    }
    hit.Normal = normal;
    found[i] = true;
  }
}
} // namespace riemann
