// The meshes' flat hierarchy for the GPU (RiemannMeshBVH.h) against Embree's
// own intersector, without a GPU:
// - the layout is a hierarchy: every box holds its children's boxes and its
//   triangles, every triangle is stored once, the depth fits the stack;
// - the traversal (the CPU mirror of the GLSL) finds the same nearest hits
//   as EmbreeMeshIntersector on thousands of random segments: same object
//   and triangle, fractions and normals equal to float precision;
// - empty scenes, cancelled builds and mesh objects without triangles.
#include "RiemannEmbreeMeshIntersector.h"
#include "RiemannMeshBVH.h"
#include "RiemannPolyDataMesh.h"
#include "RiemannScene.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <utility>

namespace
{
using riemann::MeshBVH;
using riemann::Scene;
using riemann::SceneHit;
using riemann::Vec3;

/// A sphere with normals and a torus coloured by its z, both through VTK's
/// sources and MeshFromPolyData, as a scene's mesh objects (after a sphere
/// that is not a mesh, so that object indices are not mesh indices).
Scene TwoMeshScene()
{
  Scene scene;
  riemann::SceneObject analytic;
  analytic.Type = riemann::ObjectType::Sphere;
  analytic.A = Vec3(5, 5, 5);
  analytic.Radius = 0.5;
  scene.Objects.push_back(analytic);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(32);
  sphere->SetRadius(1.0);
  sphere->SetCenter(-0.8, 0.1, 0.0);
  sphere->Update();
  riemann::AddMesh(scene, riemann::MeshFromPolyData(sphere->GetOutput()), riemann::Material());

  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(1.2);
  torus->SetCrossSectionRadius(0.35);
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(torus);
  source->SetUResolution(64);
  source->SetVResolution(24);
  source->SetScalarModeToZ();
  source->Update();
  riemann::MeshColoring coloring;
  coloring.Array = source->GetOutput()->GetPointData()->GetScalars()->GetName();
  riemann::AddMesh(
    scene, riemann::MeshFromPolyData(source->GetOutput(), coloring), riemann::Material());
  return scene;
}

bool Contains(const riemann::MeshBVHNode& outer, const float lo[3], const float hi[3])
{
  for (int i = 0; i < 3; ++i)
  {
    if (lo[i] < outer.Lower[i] || hi[i] > outer.Upper[i])
    {
      return false;
    }
  }
  return true;
}

/// Checks the subtree at `index`; returns its depth.
int CheckSubtree(const MeshBVH& bvh, std::int32_t index)
{
  const riemann::MeshBVHNode& node = bvh.Nodes.at(static_cast<std::size_t>(index));
  if (node.Count > 0)
  {
    EXPECT_LE(node.Count, 4) << "leaf " << index; // the builder's maximum
    for (auto k = static_cast<std::int32_t>(node.Link); k < node.Link + node.Count; ++k)
    {
      const riemann::MeshBVHTriangle& t = bvh.Triangles.at(static_cast<std::size_t>(k));
      for (const float* v : { t.V0, t.V1, t.V2 })
      {
        EXPECT_TRUE(Contains(node, v, v)) << "triangle " << k << " outside leaf " << index;
      }
    }
    return 1;
  }
  const auto second = static_cast<std::int32_t>(node.Link);
  EXPECT_GT(second, index + 1) << "node " << index;
  for (std::int32_t child : { index + 1, second })
  {
    const riemann::MeshBVHNode& c = bvh.Nodes.at(static_cast<std::size_t>(child));
    EXPECT_TRUE(Contains(node, c.Lower, c.Upper)) << "child " << child << " of " << index;
  }
  return 1 + std::max(CheckSubtree(bvh, index + 1), CheckSubtree(bvh, second));
}
} // namespace

TEST(MeshBVH, IsAHierarchyHoldingEveryTriangleOnce)
{
  const Scene scene = TwoMeshScene();
  const MeshBVH bvh = riemann::BuildMeshBVH(scene);
  std::size_t triangles = 0;
  std::size_t vertices = 0;
  for (const auto& mesh : scene.Meshes)
  {
    triangles += mesh->NumberOfTriangles();
    vertices += mesh->NumberOfPoints();
  }
  ASSERT_EQ(bvh.Triangles.size(), triangles);
  ASSERT_EQ(bvh.Corners.size(), triangles);
  ASSERT_EQ(bvh.VertexNormals.size(), 4 * vertices);
  ASSERT_EQ(bvh.VertexColors.size(), 4 * vertices);
  std::set<std::pair<float, float>> seen;
  for (std::size_t k = 0; k < bvh.Triangles.size(); ++k)
  {
    const riemann::MeshBVHTriangle& t = bvh.Triangles[k];
    EXPECT_TRUE(seen.insert({ t.Object, t.Primitive }).second) << "triangle stored twice";
    // The sphere (object 1) has normals, the torus (object 2) normals and colours.
    EXPECT_EQ(t.Attributes,
      t.Object == 1 ? riemann::MeshHasNormals : riemann::MeshHasNormals + riemann::MeshHasColors);
    for (float c : bvh.Corners[k].Vertex)
    {
      ASSERT_GE(c, 0);
      ASSERT_LT(static_cast<std::size_t>(c), vertices);
    }
  }
  EXPECT_EQ(CheckSubtree(bvh, 0), bvh.Depth);
  EXPECT_LT(bvh.Depth, riemann::MeshBVHStackSize);
}

TEST(MeshBVH, TraversalFindsEmbreesHits)
{
  // Random segments of length 0.05 to 1 around both meshes (the lengths of
  // ray steps): the nearest hit, or none, as Embree finds it.
  const Scene scene = TwoMeshScene();
  const MeshBVH bvh = riemann::BuildMeshBVH(scene);
  const riemann::EmbreeMeshIntersector embree(scene);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  std::uniform_real_distribution<double> length(0.05, 1.0);
  int hits = 0;
  int disagreements = 0;
  const int segments = 20000;
  for (int i = 0; i < segments; ++i)
  {
    const Vec3 a(coordinate(random), coordinate(random), coordinate(random));
    const Vec3 direction =
      Vec3(coordinate(random), coordinate(random), coordinate(random)).normalized();
    const Vec3 b = a + length(random) * direction;
    SceneHit ours;
    SceneHit theirs;
    bool theirsFound = false;
    const bool oursFound = riemann::IntersectMeshBVH(bvh, a, b, ours);
    embree.Intersect(&a, &b, 1, &theirs, &theirsFound, false);
    if (oursFound != theirsFound)
    {
      // Only a graze of an edge or a silhouette may differ between two float
      // implementations: then the hit is at the very end of the segment or
      // on a triangle's border.
      ++disagreements;
      continue;
    }
    if (!oursFound)
    {
      continue;
    }
    ++hits;
    ASSERT_EQ(ours.Object, theirs.Object) << "segment " << i;
    EXPECT_NEAR(ours.Fraction, theirs.Fraction, 1e-5) << "segment " << i;
    EXPECT_LT((ours.Position - theirs.Position).norm(), 1e-5) << "segment " << i;
    if (ours.Primitive == theirs.Primitive)
    {
      EXPECT_NEAR(ours.U, theirs.U, 1e-4);
      EXPECT_NEAR(ours.V, theirs.V, 1e-4);
      EXPECT_LT((ours.Normal - theirs.Normal).norm(), 1e-4) << "segment " << i;
    }
    else
    {
      ++disagreements; // two triangles at the same distance: an edge
    }
  }
  EXPECT_GT(hits, segments / 20);
  EXPECT_LE(disagreements, segments / 1000) << hits << " hits";
}

TEST(MeshBVH, EmptyScenesCancelledBuildsAndMissingTriangles)
{
  Scene empty;
  EXPECT_TRUE(riemann::BuildMeshBVH(empty).Empty());
  SceneHit hit;
  EXPECT_FALSE(riemann::IntersectMeshBVH(MeshBVH(), Vec3(0, 0, 0), Vec3(1, 1, 1), hit));

  const Scene scene = TwoMeshScene();
  int calls = 0;
  const MeshBVH cancelled = riemann::BuildMeshBVH(scene, [&](double) { return ++calls < 0; });
  EXPECT_TRUE(cancelled.Empty());
  EXPECT_GT(calls, 0);

  Scene missing;
  riemann::SceneObject mesh;
  mesh.Type = riemann::ObjectType::Mesh;
  missing.Objects.push_back(mesh);
  EXPECT_THROW(riemann::BuildMeshBVH(missing), std::runtime_error);
}
