// The meshes' hierarchy for the GPU (RiemannMeshBVH.h). BuildMeshBVH's steps:
// CollectMeshes (vertex arrays, one build primitive per triangle) ->
// rtcBuildBVH with our node callbacks (BuildTree) -> Flatten (depth first into
// the texel records). IntersectMeshBVH mirrors RiemannRayTraceMeshes.glsl.
#include "RiemannMeshBVH.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>

namespace riemann
{
std::size_t MeshBVH::ByteSize() const
{
  return this->Nodes.size() * sizeof(MeshBVHNode) +
    this->Triangles.size() * sizeof(MeshBVHTriangle) +
    this->Corners.size() * sizeof(MeshBVHCorners) +
    (this->VertexNormals.size() + this->VertexColors.size()) * sizeof(float);
}

namespace
{
/// A mesh object as the builder sees it.
struct MeshInput
{
  int Object;
  const TriangleMesh* Mesh;
  /// Index of its first vertex in the vertex arrays.
  std::int32_t FirstVertex;
};

/// The meshes of the scene, their vertex arrays filled into `bvh`.
std::vector<MeshInput> CollectMeshes(const Scene& scene, MeshBVH& bvh)
{
  std::vector<MeshInput> meshes;
  std::size_t vertices = 0;
  for (std::size_t index = 0; index < scene.Objects.size(); ++index)
  {
    const SceneObject& object = scene.Objects[index];
    if (object.Type != ObjectType::Mesh)
    {
      continue;
    }
    const TriangleMesh& mesh = *ObjectMesh(scene, index);
    if (vertices + mesh.NumberOfPoints() > static_cast<std::size_t>(MeshBVHMaximumIndex))
    {
      throw std::runtime_error("the scene's meshes have more than " +
        std::to_string(MeshBVHMaximumIndex) + " vertices, more than the GPU pass can index");
    }
    meshes.push_back({ static_cast<int>(index), &mesh, static_cast<std::int32_t>(vertices) });
    vertices += mesh.NumberOfPoints();
  }
  bvh.VertexNormals.assign(4 * vertices, 0.0f);
  bvh.VertexColors.assign(4 * vertices, 0.0f);
  for (const MeshInput& input : meshes)
  {
    const TriangleMesh& mesh = *input.Mesh;
    for (std::size_t v = 0; v < mesh.NumberOfPoints(); ++v)
    {
      const std::size_t to = 4 * (static_cast<std::size_t>(input.FirstVertex) + v);
      for (int c = 0; c < 3; ++c)
      {
        if (!mesh.Normals.empty())
        {
          bvh.VertexNormals[to + c] = mesh.Normals[3 * v + c];
        }
        if (!mesh.Colors.empty())
        {
          bvh.VertexColors[to + c] = mesh.Colors[3 * v + c];
        }
      }
    }
  }
  return meshes;
}

/// One build primitive per triangle: geomID = the mesh's place in `meshes`.
std::vector<RTCBuildPrimitive> MakePrimitives(const std::vector<MeshInput>& meshes)
{
  std::vector<RTCBuildPrimitive> primitives;
  for (std::size_t m = 0; m < meshes.size(); ++m)
  {
    const TriangleMesh& mesh = *meshes[m].Mesh;
    for (std::size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
    {
      RTCBuildPrimitive primitive;
      float lo[3] = { INFINITY, INFINITY, INFINITY };
      float hi[3] = { -INFINITY, -INFINITY, -INFINITY };
      for (int k = 0; k < 3; ++k)
      {
        const float* p = &mesh.Points[3 * static_cast<std::size_t>(mesh.Triangles[3 * t + k])];
        for (int c = 0; c < 3; ++c)
        {
          lo[c] = std::min(lo[c], p[c]);
          hi[c] = std::max(hi[c], p[c]);
        }
      }
      primitive.lower_x = lo[0];
      primitive.lower_y = lo[1];
      primitive.lower_z = lo[2];
      primitive.upper_x = hi[0];
      primitive.upper_y = hi[1];
      primitive.upper_z = hi[2];
      primitive.geomID = static_cast<unsigned>(m);
      primitive.primID = static_cast<unsigned>(t);
      primitives.push_back(primitive);
    }
  }
  return primitives;
}

// ---- the builder's nodes (in Embree's thread-local memory) ----

struct BuildNode
{
  bool Leaf;
};

struct InnerBuildNode : BuildNode
{
  const BuildNode* Children[2];
  RTCBounds Bounds[2];
};

struct LeafItem
{
  unsigned Mesh;
  unsigned Primitive;
};

/// A leaf: its header, then Count LeafItems.
struct LeafBuildNode : BuildNode
{
  unsigned Count;
  const LeafItem* Items() const { return reinterpret_cast<const LeafItem*>(this + 1); }
};

void* CreateInnerNode(RTCThreadLocalAllocator allocator, unsigned int, void*)
{
  void* memory = rtcThreadLocalAlloc(allocator, sizeof(InnerBuildNode), 16);
  auto* node = new (memory) InnerBuildNode;
  node->Leaf = false;
  node->Children[0] = node->Children[1] = nullptr;
  return node;
}

void SetChildren(void* node, void** children, unsigned int count, void*)
{
  auto* inner = static_cast<InnerBuildNode*>(static_cast<BuildNode*>(node));
  for (unsigned int i = 0; i < count && i < 2; ++i)
  {
    inner->Children[i] = static_cast<const BuildNode*>(children[i]);
  }
}

void SetBounds(void* node, const RTCBounds** bounds, unsigned int count, void*)
{
  auto* inner = static_cast<InnerBuildNode*>(static_cast<BuildNode*>(node));
  for (unsigned int i = 0; i < count && i < 2; ++i)
  {
    inner->Bounds[i] = *bounds[i];
  }
}

void* CreateLeaf(
  RTCThreadLocalAllocator allocator, const RTCBuildPrimitive* primitives, size_t count, void*)
{
  void* memory =
    rtcThreadLocalAlloc(allocator, sizeof(LeafBuildNode) + count * sizeof(LeafItem), 16);
  auto* leaf = new (memory) LeafBuildNode;
  leaf->Leaf = true;
  leaf->Count = static_cast<unsigned>(count);
  auto* items = new (leaf + 1) LeafItem[count];
  for (size_t i = 0; i < count; ++i)
  {
    items[i] = { primitives[i].geomID, primitives[i].primID };
  }
  return leaf;
}

/// The build's progress callback and whether it asked to stop (Embree
/// may finish a small build anyway).
struct BuildProgress
{
  const std::function<bool(double)>* Callback;
  bool Cancelled = false;
};

bool ReportProgress(void* user, double fraction)
{
  auto* progress = static_cast<BuildProgress*>(user);
  if (*progress->Callback && !(*progress->Callback)(fraction))
  {
    progress->Cancelled = true;
  }
  return !progress->Cancelled;
}

/// Depth-first layout of the built tree into `bvh`.
class Flattener
{
public:
  Flattener(const std::vector<MeshInput>& meshes, MeshBVH& bvh)
    : Meshes(meshes)
    , Result(bvh)
  {
  }

  /// Append `node` (whose box is lo, hi) and its subtree; returns its index.
  std::int32_t Append(const BuildNode* node, const float lo[3], const float hi[3], int depth)
  {
    this->Result.Depth = std::max(this->Result.Depth, depth);
    if (depth >= MeshBVHStackSize)
    {
      throw std::runtime_error("the meshes' hierarchy is deeper than the GPU traversal allows (" +
        std::to_string(MeshBVHStackSize) + " levels)");
    }
    const auto index = static_cast<std::int32_t>(this->Result.Nodes.size());
    MeshBVHNode record{};
    std::copy(lo, lo + 3, record.Lower);
    std::copy(hi, hi + 3, record.Upper);
    this->Result.Nodes.push_back(record);
    if (node->Leaf)
    {
      const auto* leaf = static_cast<const LeafBuildNode*>(node);
      this->Result.Nodes[index].Link = static_cast<float>(this->Result.Triangles.size());
      this->Result.Nodes[index].Count = static_cast<float>(leaf->Count);
      for (unsigned i = 0; i < leaf->Count; ++i)
      {
        this->AppendTriangle(leaf->Items()[i]);
      }
      return index;
    }
    const auto* inner = static_cast<const InnerBuildNode*>(node);
    for (int child = 0; child < 2; ++child)
    {
      const RTCBounds& b = inner->Bounds[child];
      const float childLo[3] = { b.lower_x, b.lower_y, b.lower_z };
      const float childHi[3] = { b.upper_x, b.upper_y, b.upper_z };
      const std::int32_t at = this->Append(inner->Children[child], childLo, childHi, depth + 1);
      if (child == 1)
      {
        this->Result.Nodes[index].Link = static_cast<float>(at);
      }
    }
    return index;
  }

private:
  void AppendTriangle(const LeafItem& item)
  {
    const MeshInput& input = this->Meshes[item.Mesh];
    const TriangleMesh& mesh = *input.Mesh;
    const unsigned* corner = &mesh.Triangles[3 * static_cast<std::size_t>(item.Primitive)];
    MeshBVHTriangle triangle{};
    float* vertices[3] = { triangle.V0, triangle.V1, triangle.V2 };
    MeshBVHCorners corners{};
    for (int k = 0; k < 3; ++k)
    {
      const float* p = &mesh.Points[3 * static_cast<std::size_t>(corner[k])];
      std::copy(p, p + 3, vertices[k]);
      corners.Vertex[k] =
        static_cast<float>(input.FirstVertex + static_cast<std::int32_t>(corner[k]));
    }
    triangle.Object = static_cast<float>(input.Object);
    triangle.Primitive = static_cast<float>(item.Primitive);
    triangle.Attributes = static_cast<float>(
      (mesh.Normals.empty() ? 0 : MeshHasNormals) + (mesh.Colors.empty() ? 0 : MeshHasColors));
    this->Result.Triangles.push_back(triangle);
    this->Result.Corners.push_back(corners);
  }

  const std::vector<MeshInput>& Meshes;
  MeshBVH& Result;
};

/// Releases Embree's device and hierarchy however the build ends.
struct EmbreeBuild
{
  RTCDevice Device = nullptr;
  RTCBVH Tree = nullptr;
  ~EmbreeBuild()
  {
    if (this->Tree)
    {
      rtcReleaseBVH(this->Tree);
    }
    if (this->Device)
    {
      rtcReleaseDevice(this->Device);
    }
  }
};
} // namespace

MeshBVH BuildMeshBVH(const Scene& scene, const std::function<bool(double)>& progress)
{
  MeshBVH bvh;
  const std::vector<MeshInput> meshes = CollectMeshes(scene, bvh);
  std::vector<RTCBuildPrimitive> primitives = MakePrimitives(meshes);
  if (primitives.empty())
  {
    return MeshBVH();
  }
  if (primitives.size() > static_cast<std::size_t>(MeshBVHMaximumIndex) / 2)
  {
    // Nodes number up to twice the triangles.
    throw std::runtime_error("the scene's meshes have more than " +
      std::to_string(MeshBVHMaximumIndex / 2) + " triangles, more than the GPU pass can index");
  }
  float lo[3] = { INFINITY, INFINITY, INFINITY };
  float hi[3] = { -INFINITY, -INFINITY, -INFINITY };
  for (const RTCBuildPrimitive& p : primitives)
  {
    lo[0] = std::min(lo[0], p.lower_x);
    lo[1] = std::min(lo[1], p.lower_y);
    lo[2] = std::min(lo[2], p.lower_z);
    hi[0] = std::max(hi[0], p.upper_x);
    hi[1] = std::max(hi[1], p.upper_y);
    hi[2] = std::max(hi[2], p.upper_z);
  }

  EmbreeBuild build;
  build.Device = rtcNewDevice(nullptr);
  if (!build.Device)
  {
    throw std::runtime_error("Embree: cannot create a device");
  }
  build.Tree = rtcNewBVH(build.Device);
  RTCBuildArguments arguments = rtcDefaultBuildArguments();
  arguments.buildQuality = RTC_BUILD_QUALITY_MEDIUM; // binned SAH (HIGH needs split callbacks)
  arguments.maxBranchingFactor = 2;
  arguments.maxDepth = MeshBVHStackSize - 16; // room for the leaves Embree adds past it
  arguments.maxLeafSize = 4;
  arguments.bvh = build.Tree;
  arguments.primitives = primitives.data();
  arguments.primitiveCount = primitives.size();
  arguments.primitiveArrayCapacity = primitives.size();
  arguments.createNode = CreateInnerNode;
  arguments.setNodeChildren = SetChildren;
  arguments.setNodeBounds = SetBounds;
  arguments.createLeaf = CreateLeaf;
  BuildProgress monitor{ &progress };
  arguments.buildProgress = ReportProgress;
  arguments.userPtr = &monitor;
  const auto* root = static_cast<const BuildNode*>(rtcBuildBVH(&arguments));
  if (monitor.Cancelled)
  {
    return MeshBVH();
  }
  if (!root)
  {
    throw std::runtime_error("Embree: cannot build the meshes' hierarchy (error code " +
      std::to_string(static_cast<int>(rtcGetDeviceError(build.Device))) + ")");
  }
  bvh.Nodes.reserve(2 * primitives.size() / arguments.maxLeafSize + 1);
  bvh.Triangles.reserve(primitives.size());
  bvh.Corners.reserve(primitives.size());
  Flattener(meshes, bvh).Append(root, lo, hi, 1);
  return bvh;
}

// ---- the traversal: a mirror of RiemannRayTraceMeshes.glsl, in float ----

namespace
{
struct Float3
{
  float X, Y, Z;
};

Float3 Make(const float* p)
{
  return { p[0], p[1], p[2] };
}
Float3 operator-(const Float3& a, const Float3& b)
{
  return { a.X - b.X, a.Y - b.Y, a.Z - b.Z };
}
Float3 operator+(const Float3& a, const Float3& b)
{
  return { a.X + b.X, a.Y + b.Y, a.Z + b.Z };
}
Float3 operator*(float s, const Float3& a)
{
  return { s * a.X, s * a.Y, s * a.Z };
}
float Dot(const Float3& a, const Float3& b)
{
  return a.X * b.X + a.Y * b.Y + a.Z * b.Z;
}
Float3 Cross(const Float3& a, const Float3& b)
{
  return { a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X };
}

/// 1 / d per axis, +-1e30 for an axis the segment does not move along
/// (GLSL's division by zero is undefined).
float SafeInverse(float d)
{
  return d != 0.0f ? 1.0f / d : 1e30f;
}

/// Whether the segment a + t d, t in [0, limit], meets the node's box.
bool OverlapsBox(const MeshBVHNode& node, const Float3& a, const Float3& inverse, float limit)
{
  const float origin[3] = { a.X, a.Y, a.Z };
  const float inv[3] = { inverse.X, inverse.Y, inverse.Z };
  float enter = 0.0f;
  float exit = limit;
  for (int i = 0; i < 3; ++i)
  {
    const float t0 = (node.Lower[i] - origin[i]) * inv[i];
    const float t1 = (node.Upper[i] - origin[i]) * inv[i];
    enter = std::max(enter, std::min(t0, t1));
    exit = std::min(exit, std::max(t0, t1));
  }
  return enter <= exit;
}

/// Barycentric slack: segments through a shared edge must not slip between
/// its two triangles in float.
constexpr float EdgeSlack = 1e-6f;

/// Moller-Trumbore against the segment a + t d: t in [0, best), with u, v.
bool IntersectTriangle(const MeshBVHTriangle& triangle, const Float3& a, const Float3& d,
  float best, float& t, float& u, float& v)
{
  const Float3 v0 = Make(triangle.V0);
  const Float3 e1 = Make(triangle.V1) - v0;
  const Float3 e2 = Make(triangle.V2) - v0;
  const Float3 p = Cross(d, e2);
  const float det = Dot(e1, p);
  if (det == 0.0f)
  {
    return false;
  }
  const float inverse = 1.0f / det;
  const Float3 s = a - v0;
  u = Dot(s, p) * inverse;
  if (u < -EdgeSlack || u > 1.0f + EdgeSlack)
  {
    return false;
  }
  const Float3 q = Cross(s, e1);
  v = Dot(d, q) * inverse;
  if (v < -EdgeSlack || u + v > 1.0f + EdgeSlack)
  {
    return false;
  }
  t = Dot(e2, q) * inverse;
  return t >= 0.0f && t <= 1.0f && t < best;
}

/// The normal of a hit on triangle `index`, facing d (see IntersectMeshBVH).
Vec3 HitNormal(const MeshBVH& bvh, std::int32_t index, float u, float v, const Float3& d)
{
  const MeshBVHTriangle& triangle = bvh.Triangles[static_cast<std::size_t>(index)];
  const Float3 v0 = Make(triangle.V0);
  Float3 normal = Cross(Make(triangle.V1) - v0, Make(triangle.V2) - v0);
  if ((static_cast<int>(triangle.Attributes) & MeshHasNormals) != 0)
  {
    const MeshBVHCorners& corners = bvh.Corners[static_cast<std::size_t>(index)];
    const float w[3] = { 1.0f - u - v, u, v };
    Float3 smooth = { 0.0f, 0.0f, 0.0f };
    for (int k = 0; k < 3; ++k)
    {
      smooth =
        smooth + w[k] * Make(&bvh.VertexNormals[4 * static_cast<std::size_t>(corners.Vertex[k])]);
    }
    if (Dot(smooth, smooth) > 0.0f)
    {
      normal = smooth;
    }
  }
  const float length = std::sqrt(Dot(normal, normal));
  normal = length > 0.0f ? (1.0f / length) * normal : Float3{ 0.0f, 0.0f, 0.0f };
  if (Dot(normal, d) > 0.0f)
  {
    normal = -1.0f * normal;
  }
  return Vec3(normal.X, normal.Y, normal.Z);
}
} // namespace

bool IntersectMeshBVH(const MeshBVH& bvh, const Vec3& a, const Vec3& b, SceneHit& hit)
{
  if (bvh.Empty())
  {
    return false;
  }
  const Float3 origin = { static_cast<float>(a.x()), static_cast<float>(a.y()),
    static_cast<float>(a.z()) };
  const Float3 d =
    Float3{ static_cast<float>(b.x()), static_cast<float>(b.y()), static_cast<float>(b.z()) } -
    origin;
  const Float3 inverse = { SafeInverse(d.X), SafeInverse(d.Y), SafeInverse(d.Z) };
  std::int32_t stack[MeshBVHStackSize];
  int top = 0;
  stack[top++] = 0;
  float best = 2.0f; // above any fraction: the first hit in [0, 1] is taken
  std::int32_t nearest = -1;
  float nearestU = 0.0f;
  float nearestV = 0.0f;
  while (top > 0)
  {
    const std::int32_t index = stack[--top];
    const MeshBVHNode& node = bvh.Nodes[static_cast<std::size_t>(index)];
    if (!OverlapsBox(node, origin, inverse, std::min(best, 1.0f)))
    {
      continue;
    }
    const auto link = static_cast<std::int32_t>(node.Link);
    const auto count = static_cast<std::int32_t>(node.Count);
    if (count == 0)
    {
      stack[top++] = link; // the second child, visited after the first
      stack[top++] = index + 1;
      continue;
    }
    for (std::int32_t k = link; k < link + count; ++k)
    {
      float t;
      float u;
      float v;
      if (IntersectTriangle(bvh.Triangles[static_cast<std::size_t>(k)], origin, d, best, t, u, v))
      {
        best = t;
        nearest = k;
        nearestU = u;
        nearestV = v;
      }
    }
  }
  if (nearest < 0)
  {
    return false;
  }
  const MeshBVHTriangle& triangle = bvh.Triangles[static_cast<std::size_t>(nearest)];
  hit.Fraction = best;
  hit.Position = a + static_cast<double>(best) * (b - a);
  hit.Normal = HitNormal(bvh, nearest, nearestU, nearestV, d);
  hit.Object = static_cast<int>(triangle.Object);
  hit.Primitive = static_cast<int>(triangle.Primitive);
  hit.U = nearestU;
  hit.V = nearestV;
  return true;
}
} // namespace riemann
