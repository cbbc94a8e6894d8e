// vtkRiemannOutsideScene: the outside view's picture, checked as geometry
// (no rendering): what is framed, the frustum's shape, the rays' colours,
// and a camera that sees the scene and the observer.
#include "vtkRiemannOutsideScene.h"

#include "vtkRiemannScene.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace
{
constexpr const char* SphereAndFloor = R"({"objects": [
  {"type": "sphere", "center": [1, 2, 3], "radius": 0.5},
  {"type": "plane", "point": [0, 0, -2], "normal": [0, 0, 1]}]})";

void LookFrom(vtkCamera* camera, const double eye[3], const double focal[3])
{
  camera->SetPosition(eye[0], eye[1], eye[2]);
  camera->SetFocalPoint(focal[0], focal[1], focal[2]);
  camera->SetViewUp(0.0, 0.0, 1.0);
}

/// Where `point` lands in `camera`'s normalised view (x and y in [-1, 1]
/// when it is in the picture), for a square picture.
void Project(vtkCamera* camera, const double point[3], double view[3])
{
  vtkMatrix4x4* matrix = camera->GetCompositeProjectionTransformMatrix(1.0, -1.0, 1.0);
  const double in[4] = { point[0], point[1], point[2], 1.0 };
  double out[4];
  matrix->MultiplyPoint(in, out);
  for (int i = 0; i < 3; ++i)
  {
    view[i] = out[i] / out[3];
  }
}
}

TEST(OutsideScene, FramesTheObjectsNotThePlanes)
{
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(SphereAndFloor)) << scene->GetLastError();
  vtkNew<vtkRiemannOutsideScene> outside;
  outside->SetScene(scene);
  double bounds[6];
  outside->GetFramedBounds(bounds);
  // The sphere's box (triangulated: within its tessellation of the radius);
  // the floor (a 10 x 10 patch at z = -2) is left out.
  const double expected[6] = { 0.5, 1.5, 1.5, 2.5, 2.5, 3.5 };
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(bounds[i], expected[i], 0.02) << i;
  }
  EXPECT_DOUBLE_EQ(outside->GetSceneSize(), 1.0); // at least 1
  EXPECT_DOUBLE_EQ(outside->GetFrustumLength(), 0.2);

  // Nothing but a plane: the plane is what there is to frame.
  ASSERT_TRUE(scene->SetDefinition(
    R"({"objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}]})"));
  outside->GetFramedBounds(bounds);
  EXPECT_NEAR(bounds[1] - bounds[0], 10.0, 1e-9);
  EXPECT_NEAR(outside->GetSceneSize(), 10.0, 1e-9);
  EXPECT_NEAR(outside->GetFrustumLength(), 2.0, 1e-9);
}

TEST(OutsideScene, TheFrustumIsTheObserversView)
{
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(
    R"({"objects": [{"type": "box", "min": [-2, -2, -2], "max": [2, 2, 2]}]})"))
    << scene->GetLastError();
  vtkNew<vtkCamera> observer;
  const double eye[3] = { 0.0, -6.0, 0.0 }, focal[3] = { 0.0, 0.0, 0.0 };
  LookFrom(observer, eye, focal);
  observer->SetViewAngle(40.0);
  vtkNew<vtkRiemannOutsideScene> outside;
  outside->SetScene(scene);
  outside->SetObserver(observer);
  outside->SetAspectRatio(2.0);
  outside->Update();

  vtkPolyData* frustum = outside->GetFrustum();
  ASSERT_EQ(frustum->GetNumberOfPoints(), 5);
  EXPECT_EQ(frustum->GetNumberOfLines(), 8); // four edges, four rim lines
  double apex[3];
  frustum->GetPoint(0, apex);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_DOUBLE_EQ(apex[i], eye[i]);
  }
  // A fifth of the box's side ahead, half-height L tan(20 deg), the
  // half-width twice that (the aspect ratio); points are stored as floats.
  const double length = 0.2 * 4.0;
  const double halfHeight = length * std::tan(vtkMath::RadiansFromDegrees(20.0));
  double corner[4][3];
  for (int k = 0; k < 4; ++k)
  {
    frustum->GetPoint(k + 1, corner[k]);
    EXPECT_NEAR(corner[k][1], eye[1] + length, 1e-6) << k;
    EXPECT_NEAR(std::abs(corner[k][0]), 2.0 * halfHeight, 1e-6) << k;
    EXPECT_NEAR(std::abs(corner[k][2]), halfHeight, 1e-6) << k;
  }
  EXPECT_TRUE(outside->GetEyeActor()->GetVisibility());
  EXPECT_FALSE(outside->GetEyeActor()->GetPickable());
  EXPECT_FALSE(outside->GetRaysActor()->GetVisibility()); // no rays given
}

TEST(OutsideScene, RaysAreColouredByWhereTheyEnd)
{
  vtkNew<vtkPolyData> rays;
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 4; ++i)
  {
    points->InsertNextPoint(i, 0.0, 0.0);
  }
  rays->SetPoints(points);
  vtkNew<vtkCellArray> lines;
  const vtkIdType first[2] = { 0, 1 }, second[2] = { 2, 3 };
  lines->InsertNextCell(2, first);
  lines->InsertNextCell(2, second);
  rays->SetLines(lines);
  vtkNew<vtkIntArray> hit;
  hit->SetName("Hit");
  hit->InsertNextValue(1);
  hit->InsertNextValue(0);
  vtkNew<vtkUnsignedCharArray> ends;
  ends->SetName("EndColor");
  ends->SetNumberOfComponents(3);
  ends->InsertNextTypedTuple(std::array<unsigned char, 3>{ 10, 20, 30 }.data());
  ends->InsertNextTypedTuple(std::array<unsigned char, 3>{ 40, 50, 60 }.data());
  rays->GetCellData()->AddArray(hit);
  rays->GetCellData()->AddArray(ends);

  vtkNew<vtkRiemannOutsideScene> outside;
  outside->SetRays(rays);
  outside->Update();
  ASSERT_TRUE(outside->GetRaysActor()->GetVisibility());
  auto* mapper = vtkPolyDataMapper::SafeDownCast(outside->GetRaysActor()->GetMapper());
  mapper->GetInputAlgorithm()->Update();
  vtkPolyData* tubes = mapper->GetInput();
  ASSERT_GT(tubes->GetNumberOfCells(), 0);
  vtkDataArray* colours = tubes->GetCellData()->GetArray("RayColor");
  ASSERT_NE(colours, nullptr);
  // Each ray's tube cells carry its colour: the hit in its end's colour, the
  // escaped one light grey. The rays' own arrays are left as they were.
  bool sawHit = false, sawEscaped = false;
  for (vtkIdType cell = 0; cell < colours->GetNumberOfTuples(); ++cell)
  {
    const double* rgb = colours->GetTuple3(cell);
    sawHit |= rgb[0] == 10 && rgb[1] == 20 && rgb[2] == 30;
    sawEscaped |= rgb[0] == 200 && rgb[1] == 200 && rgb[2] == 200;
    EXPECT_TRUE((rgb[0] == 10 && rgb[2] == 30) || rgb[0] == 200) << cell;
  }
  EXPECT_TRUE(sawHit && sawEscaped);
  EXPECT_EQ(rays->GetCellData()->GetArray("RayColor"), nullptr);

  outside->SetRays(nullptr);
  outside->Update();
  EXPECT_FALSE(outside->GetRaysActor()->GetVisibility());
}

TEST(OutsideScene, TheCameraSeesTheSceneAndTheObserverFromTheSide)
{
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinition(SphereAndFloor));
  vtkNew<vtkCamera> observer;
  const double eye[3] = { 1.0, -4.0, 3.0 }, focal[3] = { 1.0, 2.0, 3.0 };
  LookFrom(observer, eye, focal);
  vtkNew<vtkRiemannOutsideScene> outside;
  outside->SetScene(scene);
  outside->SetObserver(observer);
  vtkNew<vtkRenderer> renderer;
  outside->AddToRenderer(renderer);
  EXPECT_EQ(renderer->GetActors()->GetNumberOfItems(), 4);
  outside->AddToRenderer(renderer); // once
  EXPECT_EQ(renderer->GetActors()->GetNumberOfItems(), 4);
  outside->PlaceCamera(renderer);

  vtkCamera* camera = renderer->GetActiveCamera();
  double bounds[6];
  outside->GetFramedBounds(bounds);
  // Every corner of the framed box, and the eye, is in the picture.
  for (int corner = 0; corner < 9; ++corner)
  {
    const double point[3] = { corner == 8 ? eye[0] : bounds[corner & 1],
      corner == 8 ? eye[1] : bounds[2 + ((corner >> 1) & 1)],
      corner == 8 ? eye[2] : bounds[4 + ((corner >> 2) & 1)] };
    double view[3];
    Project(camera, point, view);
    EXPECT_LE(std::abs(view[0]), 1.0) << corner;
    EXPECT_LE(std::abs(view[1]), 1.0) << corner;
  }
  // Behind the observer (its view is +y), to its right (+x: forward x up)
  // and above (+z).
  const double* position = camera->GetPosition();
  const double* center = camera->GetFocalPoint();
  EXPECT_LT(position[1], center[1]);
  EXPECT_GT(position[0], center[0]);
  EXPECT_GT(position[2], center[2]);
}
