#include "vtkRiemannExponentialMap.h"

#include "JacobiField.h"
#include "Metric.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRiemannDirectionGrid.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannParallelBatches.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkRiemannExponentialMap);

vtkRiemannExponentialMap::vtkRiemannExponentialMap()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
  // Defaults of this filter: a bundle of moderate length, fine steps.
  vtkRiemannIntegrationSettings* settings = this->GetIntegrationSettings();
  settings->SetMaximumPropagation(5.0);
  settings->SetMaximumIntegrationStep(0.1);
  settings->SetMaximumNumberOfSteps(100000);
}

vtkRiemannExponentialMap::~vtkRiemannExponentialMap() = default;

void vtkRiemannExponentialMap::AddRadius(double radius)
{
  this->Radii.push_back(radius);
  this->Modified();
}

void vtkRiemannExponentialMap::RemoveAllRadii()
{
  if (!this->Radii.empty())
  {
    this->Radii.clear();
    this->Modified();
  }
}

double vtkRiemannExponentialMap::GetRadius(int i) const
{
  return i >= 0 && i < this->GetNumberOfRadii() ? this->Radii[i] : 0.0;
}

namespace
{
vtkSmartPointer<vtkDoubleArray> NewArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

vtkSmartPointer<vtkIntArray> NewIntArray(const char* name, vtkIdType tuples)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfTuples(tuples);
  return array;
}

/// Index of the sample landed on arc length r, or -1 if the geodesic
/// stopped before it.
long SampleAtRadius(const std::vector<riemann::JacobiSample>& samples, double r)
{
  const auto found = std::lower_bound(samples.begin(), samples.end(), r,
    [](const riemann::JacobiSample& s, double value) { return s.ArcLength < value; });
  if (found == samples.end() || std::abs(found->ArcLength - r) > 1e-9 * std::max(1.0, r))
  {
    return -1;
  }
  return static_cast<long>(found - samples.begin());
}
}

int vtkRiemannExponentialMap::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* bundle = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* wavefronts = vtkPolyData::GetData(outputVector, 1);
  bundle->Initialize();
  wavefronts->Initialize();
  const std::shared_ptr<const riemann::Metric> metric = this->CheckMetricAndSettings();
  if (!metric)
  {
    return 1;
  }
  const riemann::Vec3 observer(this->Observer[0], this->Observer[1], this->Observer[2]);
  if (!observer.allFinite())
  {
    this->ReportError("Observer must be finite.");
    return 1;
  }
  for (double r : this->Radii)
  {
    if (!(r > 0.0) || !std::isfinite(r))
    {
      std::ostringstream error;
      error << "Every radius must be a positive number; got " << r << ".";
      this->ReportError(error.str());
      return 1;
    }
  }
  const double stepsPerGeodesic = this->IntegrationSettings->GetMaximumPropagation() /
    this->IntegrationSettings->GetInitialIntegrationStep();
  const double samples = static_cast<double>(this->NumberOfDirections) * (stepsPerGeodesic + 1.0);
  if (samples > MaximumNumberOfSamples)
  {
    std::ostringstream error;
    error << "Too many samples: " << this->NumberOfDirections << " directions x "
          << stepsPerGeodesic << " steps is more than " << MaximumNumberOfSamples
          << " (about 8 GiB); use fewer directions or a longer InitialIntegrationStep.";
    this->ReportError(error.str());
    return 1;
  }
  vtkNew<vtkPolyData> grid;
  std::string message;
  if (!vtkRiemannDirectionGrid::Build(
        this->NumberOfDirections, this->ConeAxis, this->ConeAngle, grid, message))
  {
    this->ReportError("ConeAxis: " + message + ".");
    return 1;
  }

  const riemann::GeodesicOptions options = this->MakeGeodesicOptions();

  // Trace in parallel (progress and abort between batches).
  const vtkIdType count = grid->GetNumberOfPoints();
  std::vector<riemann::JacobiTrace> traces(static_cast<size_t>(count));
  const vtkIdType done = vtkRiemannForInBatches(this, count, 64,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        double d[3];
        grid->GetPoint(i, d);
        riemann::TraceJacobiFields(*metric, observer, riemann::Vec3(d[0], d[1], d[2]), options,
          traces[i], false, this->Radii);
      }
    });
  if (done < count)
  {
    return 1; // aborted: empty outputs
  }

  // Port 0: the ray bundle.
  vtkIdType pointCount = 0;
  vtkIdType lineCount = 0;
  for (const riemann::JacobiTrace& trace : traces)
  {
    if (trace.Samples.size() >= 2)
    {
      pointCount += static_cast<vtkIdType>(trace.Samples.size());
      ++lineCount;
    }
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(pointCount);
  vtkNew<vtkCellArray> lines;
  lines->AllocateExact(lineCount, pointCount);
  auto arcLength = NewArray("ArcLength", 1, pointCount);
  auto speedDrift = NewArray("SpeedDrift", 1, pointCount);
  auto determinant = NewArray("TransverseJacobian", 1, pointCount);
  auto singular = NewArray("TransverseJacobianSingularValues", 2, pointCount);
  auto lineDirection = NewIntArray("DirectionId", lineCount);
  auto reasons = NewIntArray("ReasonForTermination", lineCount);
  vtkIdType next = 0;
  vtkIdType line = 0;
  std::vector<vtkIdType> ids;
  for (vtkIdType i = 0; i < count; ++i)
  {
    const std::vector<riemann::JacobiSample>& samples = traces[i].Samples;
    if (samples.size() < 2)
    {
      continue;
    }
    ids.resize(samples.size());
    for (size_t k = 0; k < samples.size(); ++k, ++next)
    {
      ids[k] = next;
      points->SetPoint(next, samples[k].Point.data());
      arcLength->SetValue(next, samples[k].ArcLength);
      speedDrift->SetValue(next, samples[k].SpeedDrift);
      determinant->SetValue(next, samples[k].Determinant);
      singular->SetTypedTuple(next, samples[k].SingularValues);
    }
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    lineDirection->SetValue(line, static_cast<int>(i));
    reasons->SetValue(line, traces[i].Reason);
    ++line;
  }
  bundle->SetPoints(points);
  bundle->SetLines(lines);
  bundle->GetPointData()->AddArray(arcLength);
  bundle->GetPointData()->AddArray(speedDrift);
  bundle->GetPointData()->AddArray(determinant);
  bundle->GetPointData()->AddArray(singular);
  bundle->GetCellData()->AddArray(lineDirection);
  bundle->GetCellData()->AddArray(reasons);

  // Port 1: one geodesic sphere per radius, over the grid's triangles.
  vtkNew<vtkPoints> spherePoints;
  spherePoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkDoubleArray> sphereDeterminant, sphereSingular, pointRadius, cellRadius;
  sphereDeterminant->SetName("TransverseJacobian");
  sphereSingular->SetName("TransverseJacobianSingularValues");
  sphereSingular->SetNumberOfComponents(2);
  pointRadius->SetName("Radius");
  cellRadius->SetName("Radius");
  vtkNew<vtkIntArray> sphereDirection;
  sphereDirection->SetName("DirectionId");
  std::vector<vtkIdType> local(static_cast<size_t>(count));
  for (double r : this->Radii)
  {
    if (r > this->IntegrationSettings->GetMaximumPropagation())
    {
      vtkWarningMacro(<< "Radius " << r << " is beyond MaximumPropagation ("
                      << this->IntegrationSettings->GetMaximumPropagation()
                      << "): no wavefront there.");
      continue;
    }
    for (vtkIdType i = 0; i < count; ++i)
    {
      const long k = SampleAtRadius(traces[i].Samples, r);
      local[i] = -1;
      if (k >= 0)
      {
        const riemann::JacobiSample& sample = traces[i].Samples[k];
        local[i] = spherePoints->InsertNextPoint(sample.Point.data());
        sphereDeterminant->InsertNextValue(sample.Determinant);
        sphereSingular->InsertNextTypedTuple(sample.SingularValues);
        pointRadius->InsertNextValue(r);
        sphereDirection->InsertNextValue(static_cast<int>(i));
      }
    }
    const vtkIdType appended = vtkRiemannDirectionGrid::AppendTriangles(grid, local, triangles);
    for (vtkIdType t = 0; t < appended; ++t)
    {
      cellRadius->InsertNextValue(r);
    }
  }
  wavefronts->SetPoints(spherePoints);
  wavefronts->SetPolys(triangles);
  wavefronts->GetPointData()->AddArray(sphereDeterminant);
  wavefronts->GetPointData()->AddArray(sphereSingular);
  wavefronts->GetPointData()->AddArray(sphereDirection);
  wavefronts->GetPointData()->AddArray(pointRadius);
  wavefronts->GetCellData()->AddArray(cellRadius);
  return 1;
}

void vtkRiemannExponentialMap::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Observer: " << this->Observer[0] << " " << this->Observer[1] << " "
     << this->Observer[2] << "\n";
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "ConeAxis: " << this->ConeAxis[0] << " " << this->ConeAxis[1] << " "
     << this->ConeAxis[2] << "\n";
  os << indent << "ConeAngle: " << this->ConeAngle << "\n";
  os << indent << "Radii:";
  for (double r : this->Radii)
  {
    os << " " << r;
  }
  os << "\n";
}
