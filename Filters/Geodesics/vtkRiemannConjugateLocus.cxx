#include "vtkRiemannConjugateLocus.h"

#include "JacobiField.h"
#include "Metric.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRiemannMetric.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkRiemannConjugateLocus);
vtkCxxSetObjectMacro(vtkRiemannConjugateLocus, Metric, vtkRiemannMetric);

vtkRiemannConjugateLocus::vtkRiemannConjugateLocus()
{
  this->SetNumberOfInputPorts(0);
}

vtkRiemannConjugateLocus::~vtkRiemannConjugateLocus()
{
  this->SetMetric(nullptr);
}

vtkMTimeType vtkRiemannConjugateLocus::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Metric)
  {
    time = std::max(time, this->Metric->GetMTime());
  }
  return time;
}

namespace
{
riemann::Vec3 Cross(const riemann::Vec3& a, const riemann::Vec3& b)
{
  return riemann::Vec3(
    a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

/// Fibonacci lattice of `count` unit vectors over the cap {cos(angle to axis)
/// >= cosine} (cosine = -1: the whole sphere), even in area.
std::vector<riemann::Vec3> FibonacciDirections(int count, const riemann::Vec3& axis, double cosine)
{
  std::vector<riemann::Vec3> directions(static_cast<size_t>(std::max(count, 0)));
  // An orthonormal frame (u, w, axis).
  const riemann::Vec3 a = axis.normalized();
  const riemann::Vec3 helper =
    std::abs(a[0]) < 0.9 ? riemann::Vec3(1.0, 0.0, 0.0) : riemann::Vec3(0.0, 1.0, 0.0);
  const riemann::Vec3 u = Cross(a, helper).normalized();
  const riemann::Vec3 w = Cross(a, u);
  const double goldenAngle = vtkMath::Pi() * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i)
  {
    // Heights evenly spaced in [cosine, 1] (equal areas, Archimedes).
    const double z = 1.0 - (1.0 - cosine) * (i + 0.5) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = goldenAngle * i;
    directions[i] = z * a + r * std::cos(phi) * u + r * std::sin(phi) * w;
  }
  return directions;
}
}

int vtkRiemannConjugateLocus::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  if (!this->Metric || !this->Metric->HasDefinition())
  {
    vtkErrorMacro(<< "No metric: call SetMetric() with a vtkRiemannMetric that has a valid "
                     "definition.");
    return 1;
  }
  const riemann::Vec3 axis(this->ConeAxis[0], this->ConeAxis[1], this->ConeAxis[2]);
  if (this->ConeAngle < 180.0 && !(axis.norm() > 0.0 && axis.allFinite()))
  {
    vtkErrorMacro(<< "ConeAxis must be a finite nonzero vector.");
    return 1;
  }
  const riemann::Vec3 observer(this->Observer[0], this->Observer[1], this->Observer[2]);
  if (!observer.allFinite())
  {
    vtkErrorMacro(<< "Observer must be finite.");
    return 1;
  }
  // Hold the metric for the whole computation (SetDefinition may replace it).
  const std::shared_ptr<const riemann::Metric> metric = this->Metric->GetMetric();

  const double cosine =
    this->ConeAngle >= 180.0 ? -1.0 : std::cos(vtkMath::RadiansFromDegrees(this->ConeAngle));
  const std::vector<riemann::Vec3> directions = FibonacciDirections(this->NumberOfDirections,
    this->ConeAngle >= 180.0 ? riemann::Vec3(0.0, 0.0, 1.0) : axis, cosine);

  // Search in parallel, in batches so that progress and abort are handled on
  // this thread (VTK events must not fire from worker threads).
  const vtkIdType count = static_cast<vtkIdType>(directions.size());
  std::vector<std::vector<riemann::ConjugatePoint>> found(directions.size());
  const vtkIdType batch = std::max<vtkIdType>(64, count / 50);
  const double step = this->IntegrationStep;
  const double length = this->MaximumPropagation;
  const double tolerance = this->Tolerance;
  const int maximumCount = this->MaximumNumberOfConjugatePoints;
  vtkIdType done = 0;
  this->UpdateProgress(0.0);
  while (done < count && !this->GetAbortExecute())
  {
    const vtkIdType end = std::min(count, done + batch);
    vtkSMPTools::For(done, end,
      [&](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType i = first; i < last; ++i)
        {
          found[i] = riemann::FindConjugatePoints(
            *metric, observer, directions[i], step, length, tolerance, maximumCount);
        }
      });
    done = end;
    this->UpdateProgress(static_cast<double>(done) / count);
  }

  vtkIdType pointCount = 0;
  for (vtkIdType i = 0; i < done; ++i)
  {
    pointCount += static_cast<vtkIdType>(found[i].size());
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(pointCount);
  vtkNew<vtkCellArray> vertices;
  vertices->AllocateExact(pointCount, pointCount);
  vtkNew<vtkDoubleArray> arcLength;
  arcLength->SetName("ArcLength");
  arcLength->SetNumberOfTuples(pointCount);
  vtkNew<vtkIntArray> multiplicity, index, directionId;
  multiplicity->SetName("Multiplicity");
  multiplicity->SetNumberOfTuples(pointCount);
  index->SetName("ConjugateIndex");
  index->SetNumberOfTuples(pointCount);
  directionId->SetName("DirectionId");
  directionId->SetNumberOfTuples(pointCount);
  vtkIdType next = 0;
  for (vtkIdType i = 0; i < done; ++i)
  {
    for (const riemann::ConjugatePoint& point : found[i])
    {
      points->SetPoint(next, point.Point.data());
      vertices->InsertNextCell(1, &next);
      arcLength->SetValue(next, point.ArcLength);
      multiplicity->SetValue(next, point.Multiplicity);
      index->SetValue(next, point.Index);
      directionId->SetValue(next, static_cast<int>(i));
      ++next;
    }
  }
  output->SetPoints(points);
  output->SetVerts(vertices);
  output->GetPointData()->AddArray(arcLength);
  output->GetPointData()->AddArray(multiplicity);
  output->GetPointData()->AddArray(index);
  output->GetPointData()->AddArray(directionId);
  return 1;
}

void vtkRiemannConjugateLocus::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Metric: " << this->Metric << "\n";
  os << indent << "Observer: " << this->Observer[0] << " " << this->Observer[1] << " "
     << this->Observer[2] << "\n";
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "ConeAxis: " << this->ConeAxis[0] << " " << this->ConeAxis[1] << " "
     << this->ConeAxis[2] << "\n";
  os << indent << "ConeAngle: " << this->ConeAngle << "\n";
  os << indent << "MaximumPropagation: " << this->MaximumPropagation << "\n";
  os << indent << "IntegrationStep: " << this->IntegrationStep << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaximumNumberOfConjugatePoints: " << this->MaximumNumberOfConjugatePoints
     << "\n";
}
