#include "vtkRiemannOutsideScene.h"

#include "RiemannScene.h"
#include "vtkRiemannScene.h"
#include "vtkRiemannSceneSource.h"

#include "vtkActor.h"
#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTubeFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkRiemannOutsideScene);
vtkCxxSetObjectMacro(vtkRiemannOutsideScene, Observer, vtkCamera);
vtkCxxSetObjectMacro(vtkRiemannOutsideScene, Rays, vtkPolyData);

namespace
{
void SetUpActor(vtkActor* actor, vtkAlgorithmOutput* input, vtkPolyData* data)
{
  vtkNew<vtkPolyDataMapper> mapper;
  if (input)
  {
    mapper->SetInputConnection(input);
  }
  else
  {
    mapper->SetInputData(data);
  }
  actor->SetMapper(mapper);
}

/// Light grey: an escaped ray, visible on the dark background.
constexpr unsigned char EscapedRayGrey = 200;
}

vtkRiemannOutsideScene::vtkRiemannOutsideScene()
{
  // The scene, translucent, in its material colours.
  SetUpActor(this->SceneActor, this->SceneGeometry->GetOutputPort(), nullptr);
  vtkPolyDataMapper::SafeDownCast(this->SceneActor->GetMapper())->SetColorModeToDirectScalars();
  this->SceneActor->GetProperty()->SetOpacity(0.2);
  // The observer: a white eye and its pale yellow frustum.
  SetUpActor(this->EyeActor, this->Eye->GetOutputPort(), nullptr);
  this->EyeActor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  this->EyeActor->PickableOff();
  SetUpActor(this->FrustumActor, nullptr, this->FrustumLines);
  this->FrustumActor->GetProperty()->SetColor(1.0, 1.0, 0.6);
  this->FrustumActor->GetProperty()->SetLineWidth(1.5);
  this->FrustumActor->PickableOff();
  // The rays: tubes in their own colours (cell array RayColor).
  this->RayTubes->SetInputData(this->ColouredRays);
  this->RayTubes->SetNumberOfSides(6);
  SetUpActor(this->RaysActor, this->RayTubes->GetOutputPort(), nullptr);
  auto* rayMapper = vtkPolyDataMapper::SafeDownCast(this->RaysActor->GetMapper());
  rayMapper->SetScalarModeToUseCellFieldData();
  rayMapper->SelectColorArray("RayColor");
  rayMapper->SetColorModeToDirectScalars();
  this->RaysActor->PickableOff();
  this->RaysActor->VisibilityOff();
}

vtkRiemannOutsideScene::~vtkRiemannOutsideScene()
{
  this->SetObserver(nullptr);
  this->SetRays(nullptr);
}

void vtkRiemannOutsideScene::SetScene(vtkRiemannScene* scene)
{
  this->SceneGeometry->SetScene(scene);
  this->Modified();
}

vtkRiemannScene* vtkRiemannOutsideScene::GetScene()
{
  return this->SceneGeometry->GetScene();
}

void vtkRiemannOutsideScene::GetFramedBounds(double bounds[6])
{
  // Asked on every observer move (the frustum's length): walk the scene's
  // cells only when its geometry changed.
  this->SceneGeometry->Update();
  vtkPolyData* geometry = this->SceneGeometry->GetOutput();
  if (geometry->GetMTime() != this->FramedGeometryTime)
  {
    this->ComputeFramedBounds(geometry);
    this->FramedGeometryTime = geometry->GetMTime();
  }
  std::copy(this->Framed, this->Framed + 6, bounds);
}

void vtkRiemannOutsideScene::ComputeFramedBounds(vtkPolyData* geometry)
{
  vtkBoundingBox box;
  vtkDataArray* objects = geometry->GetCellData()->GetArray("ObjectIndex");
  vtkRiemannScene* scene = this->SceneGeometry->GetScene();
  if (objects && scene)
  {
    const riemann::Scene description = scene->GetScene();
    for (vtkIdType cell = 0; cell < geometry->GetNumberOfCells(); ++cell)
    {
      const int object = static_cast<int>(objects->GetTuple1(cell));
      if (object >= 0 && object < static_cast<int>(description.Objects.size()) &&
        description.Objects[object].Type != riemann::ObjectType::Plane)
      {
        double cellBounds[6];
        geometry->GetCellBounds(cell, cellBounds);
        box.AddBounds(cellBounds);
      }
    }
  }
  if (!box.IsValid() && geometry->GetNumberOfPoints() > 0)
  {
    box.AddBounds(geometry->GetBounds());
  }
  if (!box.IsValid())
  {
    const double unit[6] = { -1, 1, -1, 1, -1, 1 };
    box.AddBounds(unit);
  }
  box.GetBounds(this->Framed);
}

double vtkRiemannOutsideScene::GetSceneSize()
{
  double bounds[6];
  this->GetFramedBounds(bounds);
  return std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1.0 });
}

double vtkRiemannOutsideScene::GetFrustumLength()
{
  return 0.2 * this->GetSceneSize();
}

void vtkRiemannOutsideScene::Update()
{
  const double length = this->GetFrustumLength();
  this->UpdateObserver(length);
  this->UpdateRays(length);
}

void vtkRiemannOutsideScene::UpdateObserver(double length)
{
  this->EyeActor->SetVisibility(this->Observer != nullptr);
  this->FrustumActor->SetVisibility(this->Observer != nullptr);
  if (!this->Observer)
  {
    return;
  }
  double eye[3], focal[3], up[3];
  this->Observer->GetPosition(eye);
  this->Observer->GetFocalPoint(focal);
  this->Observer->GetViewUp(up);
  double forward[3] = { focal[0] - eye[0], focal[1] - eye[1], focal[2] - eye[2] };
  vtkMath::Normalize(forward);
  double right[3];
  vtkMath::Cross(forward, up, right);
  vtkMath::Normalize(right);
  vtkMath::Cross(right, forward, up);

  // The frustum's four edges and its rim, `length` ahead of the eye.
  const double halfHeight =
    length * std::tan(vtkMath::RadiansFromDegrees(0.5 * this->Observer->GetViewAngle()));
  const double halfWidth = halfHeight * this->AspectRatio;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(eye);
  const double corners[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
  for (const auto& corner : corners)
  {
    double p[3];
    for (int i = 0; i < 3; ++i)
    {
      p[i] = eye[i] + length * forward[i] + corner[0] * halfWidth * right[i] +
        corner[1] * halfHeight * up[i];
    }
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> lines;
  for (vtkIdType corner = 1; corner <= 4; ++corner)
  {
    const vtkIdType edge[2] = { 0, corner };
    lines->InsertNextCell(2, edge);
    const vtkIdType rim[2] = { corner, corner % 4 + 1 };
    lines->InsertNextCell(2, rim);
  }
  this->FrustumLines->SetPoints(points);
  this->FrustumLines->SetLines(lines);
  this->FrustumLines->Modified();

  this->Eye->SetCenter(eye);
  this->Eye->SetRadius(0.06 * length);
}

void vtkRiemannOutsideScene::UpdateRays(double length)
{
  const bool shown = this->Rays && this->Rays->GetNumberOfCells() > 0;
  this->RaysActor->SetVisibility(shown);
  if (!shown)
  {
    this->ColouredRays->Initialize();
    return;
  }
  // A ray that hit in the colour of where it ended; one that escaped grey.
  this->ColouredRays->ShallowCopy(this->Rays);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("RayColor");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(this->ColouredRays->GetNumberOfCells());
  vtkDataArray* ends = this->ColouredRays->GetCellData()->GetArray("EndColor");
  vtkDataArray* hits = this->ColouredRays->GetCellData()->GetArray("Hit");
  for (vtkIdType ray = 0; ray < colours->GetNumberOfTuples(); ++ray)
  {
    const bool hit = hits && ends && hits->GetTuple1(ray) != 0;
    for (int c = 0; c < 3; ++c)
    {
      colours->SetTypedComponent(ray, c,
        hit ? static_cast<unsigned char>(ends->GetComponent(ray, c)) : EscapedRayGrey);
    }
  }
  this->ColouredRays->GetCellData()->AddArray(colours);
  this->RayTubes->SetRadius(0.015 * length);
}

void vtkRiemannOutsideScene::AddToRenderer(vtkRenderer* renderer)
{
  this->Update();
  // Dark blue-grey, lighter at the top: light grey rays and the white eye
  // stand out.
  renderer->SetBackground(0.12, 0.13, 0.16);
  renderer->SetBackground2(0.30, 0.32, 0.38);
  renderer->GradientBackgroundOn();
  for (vtkActor* actor : { this->SceneActor.Get(), this->RaysActor.Get(), this->EyeActor.Get(),
         this->FrustumActor.Get() })
  {
    if (!renderer->HasViewProp(actor))
    {
      renderer->AddActor(actor);
    }
  }
}

void vtkRiemannOutsideScene::PlaceCamera(vtkRenderer* renderer)
{
  double frame[6];
  this->GetFramedBounds(frame);
  double eye[3] = { 0.0, 0.0, 5.0 }, forward[3] = { 0.0, 0.0, -1.0 }, up[3] = { 0.0, 1.0, 0.0 };
  if (this->Observer)
  {
    this->Observer->GetPosition(eye);
    const double* focal = this->Observer->GetFocalPoint();
    for (int i = 0; i < 3; ++i)
    {
      forward[i] = focal[i] - eye[i];
    }
    vtkMath::Normalize(forward);
    this->Observer->GetViewUp(up);
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    frame[2 * axis] = std::min(frame[2 * axis], eye[axis]);
    frame[2 * axis + 1] = std::max(frame[2 * axis + 1], eye[axis]);
  }
  double side[3];
  vtkMath::Cross(forward, up, side);
  vtkMath::Normalize(side);
  const double center[3] = { 0.5 * (frame[0] + frame[1]), 0.5 * (frame[2] + frame[3]),
    0.5 * (frame[4] + frame[5]) };
  // Behind the observer, to its right and above: ResetCamera then sets the
  // distance that frames the box.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] - forward[0] + 1.2 * side[0] + 0.8 * up[0],
    center[1] - forward[1] + 1.2 * side[1] + 0.8 * up[1],
    center[2] - forward[2] + 1.2 * side[2] + 0.8 * up[2]);
  camera->SetViewUp(up);
  renderer->ResetCamera(frame);
}

vtkActor* vtkRiemannOutsideScene::GetSceneActor()
{
  return this->SceneActor;
}

vtkActor* vtkRiemannOutsideScene::GetEyeActor()
{
  return this->EyeActor;
}

vtkActor* vtkRiemannOutsideScene::GetFrustumActor()
{
  return this->FrustumActor;
}

vtkActor* vtkRiemannOutsideScene::GetRaysActor()
{
  return this->RaysActor;
}

vtkPolyData* vtkRiemannOutsideScene::GetFrustum()
{
  return this->FrustumLines;
}

void vtkRiemannOutsideScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scene: " << this->GetScene() << "\n";
  os << indent << "Observer: " << this->Observer << "\n";
  os << indent << "AspectRatio: " << this->AspectRatio << "\n";
  os << indent << "Rays: " << this->Rays << "\n";
}
