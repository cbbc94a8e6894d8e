#include "vtkRiemannCameraPath.h"

#include "CameraPath.h"
#include "RiemannCameraPathDeclaration.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkRiemannCameraPath);
vtkCxxSetObjectMacro(vtkRiemannCameraPath, KeyPositions, vtkPoints);

namespace
{
namespace CameraPathDefault = riemann::declared::vtkRiemannCameraPath::Default;

riemann::Vec3 ToVec3(const double v[3])
{
  return riemann::Vec3(v[0], v[1], v[2]);
}

vtkNew<vtkDoubleArray> VectorArray(const char* name, vtkIdType frames)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(frames);
  return array;
}
} // namespace

vtkRiemannCameraPath::vtkRiemannCameraPath()
  : PathType(CameraPathDefault::PathType)
  , Length(CameraPathDefault::Length)
  , NumberOfFrames(static_cast<int>(CameraPathDefault::NumberOfFrames))
  , Step(CameraPathDefault::Step)
{
  this->SetNumberOfDataPorts(0);
  std::copy(CameraPathDefault::Position, CameraPathDefault::Position + 3, this->Position);
  std::copy(CameraPathDefault::LookAt, CameraPathDefault::LookAt + 3, this->LookAt);
  std::copy(CameraPathDefault::ViewUp, CameraPathDefault::ViewUp + 3, this->ViewUp);
}

vtkRiemannCameraPath::~vtkRiemannCameraPath()
{
  this->SetKeyPositions(nullptr);
}

int vtkRiemannCameraPath::FillDataPortInformation(int, vtkInformation*)
{
  return 1;
}

vtkMTimeType vtkRiemannCameraPath::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->KeyPositions)
  {
    time = std::max(time, this->KeyPositions->GetMTime());
  }
  return time;
}

int vtkRiemannCameraPath::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const std::shared_ptr<const riemann::Metric> metric = this->CheckMetricAndSettings();
  if (!metric)
  {
    return 1;
  }
  // Step 1: the settings, as the core takes them.
  riemann::CameraPathSettings settings;
  settings.Kind = static_cast<riemann::CameraPathKind>(this->PathType);
  settings.Start.Position = ToVec3(this->Position);
  settings.Start.LookAt = ToVec3(this->LookAt);
  settings.Start.ViewUp = ToVec3(this->ViewUp);
  settings.Length = this->Length;
  settings.Frames = this->NumberOfFrames;
  settings.Step = this->Step;
  if (this->KeyPositions)
  {
    for (vtkIdType k = 0; k < this->KeyPositions->GetNumberOfPoints(); ++k)
    {
      double key[3];
      this->KeyPositions->GetPoint(k, key);
      settings.Keys.push_back(ToVec3(key));
    }
  }
  // Step 2: the flight, reporting progress and stopping on AbortExecute.
  std::vector<riemann::CameraFrame> frames;
  try
  {
    frames = riemann::ComputeCameraPath(*metric, settings, [this](double fraction) {
      this->UpdateProgress(fraction);
      return !this->GetAbortExecute();
    });
  }
  catch (const riemann::CameraPathError& e)
  {
    this->ReportError(std::string("Camera path: ") + e.what());
    return 1;
  }
  // Step 3: one polyline with the frame on its points.
  const vtkIdType count = static_cast<vtkIdType>(frames.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  auto forward = VectorArray("Forward", count);
  auto up = VectorArray("Up", count);
  auto right = VectorArray("Right", count);
  vtkNew<vtkDoubleArray> arcLength;
  arcLength->SetName("ArcLength");
  arcLength->SetNumberOfTuples(count);
  vtkNew<vtkCellArray> line;
  line->InsertNextCell(count);
  for (vtkIdType k = 0; k < count; ++k)
  {
    const riemann::CameraFrame& frame = frames[static_cast<size_t>(k)];
    points->SetPoint(k, frame.Position.data());
    forward->SetTypedTuple(k, frame.Forward.data());
    up->SetTypedTuple(k, frame.Up.data());
    right->SetTypedTuple(k, frame.Right.data());
    arcLength->SetValue(k, frame.ArcLength);
    line->InsertCellPoint(k);
  }
  output->SetPoints(points);
  output->SetLines(line);
  output->GetPointData()->AddArray(forward);
  output->GetPointData()->AddArray(up);
  output->GetPointData()->AddArray(right);
  output->GetPointData()->AddArray(arcLength);
  return 1;
}

bool vtkRiemannCameraPath::ApplyFrame(vtkPolyData* path, vtkIdType frame, vtkCamera* camera)
{
  if (!path || !camera || frame < 0 || frame >= path->GetNumberOfPoints())
  {
    return false;
  }
  vtkDataArray* forward = path->GetPointData()->GetArray("Forward");
  vtkDataArray* up = path->GetPointData()->GetArray("Up");
  if (!forward || !up || forward->GetNumberOfComponents() != 3 || up->GetNumberOfComponents() != 3)
  {
    return false;
  }
  double position[3], ahead[3], viewUp[3];
  path->GetPoint(frame, position);
  forward->GetTuple(frame, ahead);
  up->GetTuple(frame, viewUp);
  camera->SetPosition(position);
  camera->SetFocalPoint(position[0] + ahead[0], position[1] + ahead[1], position[2] + ahead[2]);
  camera->SetViewUp(viewUp);
  return true;
}

void vtkRiemannCameraPath::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PathType: " << (this->PathType == SPLINE ? "SPLINE" : "GEODESIC") << "\n";
  os << indent << "Position: " << this->Position[0] << " " << this->Position[1] << " "
     << this->Position[2] << "\n";
  os << indent << "LookAt: " << this->LookAt[0] << " " << this->LookAt[1] << " " << this->LookAt[2]
     << "\n";
  os << indent << "ViewUp: " << this->ViewUp[0] << " " << this->ViewUp[1] << " " << this->ViewUp[2]
     << "\n";
  os << indent << "Length: " << this->Length << "\n";
  os << indent << "KeyPositions: " << this->KeyPositions << "\n";
  os << indent << "NumberOfFrames: " << this->NumberOfFrames << "\n";
  os << indent << "Step: " << this->Step << "\n";
}
