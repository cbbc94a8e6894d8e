#include "vtkRiemannGeodesicTracer.h"

#include "GeodesicTrace.h"
#include "JacobiField.h"
#include "Metric.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannParallelBatches.h"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkRiemannGeodesicTracer);

// The public enums mirror the core's numbering, which is part of the file formats.
static_assert(static_cast<int>(vtkRiemannGeodesicTracer::DEGENERATE_METRIC) ==
      static_cast<int>(riemann::DegenerateMetric) &&
    static_cast<int>(vtkRiemannGeodesicTracer::HIT_SURFACE) ==
      static_cast<int>(riemann::HitSurface) &&
    static_cast<int>(vtkRiemannGeodesicTracer::OUT_OF_LENGTH) ==
      static_cast<int>(riemann::OutOfLength),
  "termination codes must match the core");
static_assert(vtkRiemannIntegrationSettings::DORMAND_PRINCE45 ==
    static_cast<int>(riemann::IntegratorType::DormandPrince45),
  "integrator codes must match the core");

vtkRiemannGeodesicTracer::vtkRiemannGeodesicTracer()
{
  this->SetDirectionArrayName("Direction");
}

vtkRiemannGeodesicTracer::~vtkRiemannGeodesicTracer()
{
  this->SetDirectionArrayName(nullptr);
}

int vtkRiemannGeodesicTracer::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

namespace
{
struct Seed
{
  riemann::Vec3 Position;
  riemann::Vec3 Direction;
  vtkIdType Id;
  bool Backward;
};

/// The geodesic with its Jacobi fields, as a GeodesicPath plus the
/// transverse Jacobian (determinant, singular values) at every point.
void TraceWithJacobian(const riemann::Metric& metric, const Seed& seed,
  const riemann::GeodesicOptions& options, riemann::GeodesicPath& path,
  std::vector<std::array<double, 3>>& jacobian)
{
  riemann::JacobiTrace trace;
  riemann::TraceJacobiFields(metric, seed.Position, seed.Direction, options, trace, seed.Backward);
  path.Clear();
  jacobian.clear();
  path.Reason = trace.Reason;
  const double sign = seed.Backward ? -1.0 : 1.0;
  for (const riemann::JacobiSample& sample : trace.Samples)
  {
    path.Points.push_back(sample.Point);
    // Velocity is dx/ds of the forward parametrisation, as TraceGeodesic's.
    path.Velocities.push_back(sign * sample.Velocity);
    path.ArcLength.push_back(sample.ArcLength);
    path.SpeedDrift.push_back(sample.SpeedDrift);
    jacobian.push_back(
      { sample.Determinant, sample.SingularValues[0], sample.SingularValues[1] });
  }
}
}

int vtkRiemannGeodesicTracer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  const std::shared_ptr<const riemann::Metric> metric = this->CheckMetricAndSettings();
  if (!metric)
  {
    return 1;
  }

  // Gather seeds: the input's points with their directions, or the start ivars.
  std::vector<Seed> seeds;
  const riemann::Vec3 startDirection(
    this->StartDirection[0], this->StartDirection[1], this->StartDirection[2]);
  vtkDataSet* input =
    this->GetNumberOfInputConnections(0) > 0 ? vtkDataSet::GetData(inputVector[0], 0) : nullptr;
  std::vector<std::pair<riemann::Vec3, riemann::Vec3>> starts;
  if (input)
  {
    vtkDataArray* directions = this->DirectionArrayName
      ? input->GetPointData()->GetArray(this->DirectionArrayName)
      : nullptr;
    if (directions && directions->GetNumberOfComponents() != 3)
    {
      this->ReportError(std::string("The seeds' array \"") + this->DirectionArrayName + "\" has " +
        std::to_string(directions->GetNumberOfComponents()) + " components; it needs 3.");
      return 1;
    }
    if (!directions && input->GetNumberOfPoints() > 0)
    {
      vtkWarningMacro(<< "The seeds have no point-data array \""
                      << (this->DirectionArrayName ? this->DirectionArrayName : "")
                      << "\"; every seed uses StartDirection.");
    }
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      double p[3], d[3];
      input->GetPoint(i, p);
      riemann::Vec3 direction = startDirection;
      if (directions)
      {
        directions->GetTuple(i, d);
        direction = riemann::Vec3(d[0], d[1], d[2]);
      }
      starts.emplace_back(riemann::Vec3(p[0], p[1], p[2]), direction);
    }
  }
  else
  {
    starts.emplace_back(
      riemann::Vec3(this->StartPosition[0], this->StartPosition[1], this->StartPosition[2]),
      startDirection);
  }
  for (size_t i = 0; i < starts.size(); ++i)
  {
    if (this->IntegrationDirection != BACKWARD)
    {
      seeds.push_back({ starts[i].first, starts[i].second, static_cast<vtkIdType>(i), false });
    }
    if (this->IntegrationDirection != FORWARD)
    {
      seeds.push_back({ starts[i].first, starts[i].second, static_cast<vtkIdType>(i), true });
    }
  }

  riemann::GeodesicOptions options = this->MakeGeodesicOptions();
  options.UseBounds = this->UseDomainBounds;
  std::copy(this->DomainBounds, this->DomainBounds + 6, options.Bounds);

  // Trace in parallel (progress and abort between batches).
  std::vector<riemann::GeodesicPath> paths(seeds.size());
  // Per path point: determinant and the two singular values (when asked).
  const bool jacobian = this->ComputeTransverseJacobian;
  std::vector<std::vector<std::array<double, 3>>> jacobians(jacobian ? seeds.size() : 0);
  const vtkIdType count = static_cast<vtkIdType>(seeds.size());
  const vtkIdType traced = vtkRiemannForInBatches(this, count, 256,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        const Seed& seed = seeds[i];
        riemann::Vec3 velocity;
        if (!riemann::UnitSpeedVelocity(*metric, seed.Position, seed.Direction, velocity))
        {
          paths[i].Clear();
          continue;
        }
        if (jacobian)
        {
          TraceWithJacobian(*metric, seed, options, paths[i], jacobians[i]);
        }
        else
        {
          riemann::TraceGeodesic(
            *metric, seed.Position, velocity, options, paths[i], seed.Backward);
        }
      }
    });

  // Assemble the polylines in seed order. A path of one point (a seed outside
  // DomainBounds, a zero length or step budget) makes no line; say so.
  vtkIdType pointCount = 0;
  vtkIdType lineCount = 0;
  vtkIdType unstarted = 0;
  vtkIdType stillborn = 0;
  for (vtkIdType i = 0; i < traced; ++i)
  {
    const size_t n = paths[i].Points.size();
    unstarted += n == 0 ? 1 : 0;
    stillborn += n == 1 ? 1 : 0;
    if (n >= 2)
    {
      pointCount += static_cast<vtkIdType>(n);
      ++lineCount;
    }
  }
  if (unstarted > 0)
  {
    vtkWarningMacro(<< unstarted << " of " << traced
                    << " geodesics could not start: zero or non-finite direction, or a "
                       "degenerate metric at the seed.");
  }
  if (stillborn > 0)
  {
    vtkWarningMacro(<< stillborn << " of " << traced
                    << " geodesics made no step: the seed is outside DomainBounds.");
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(pointCount);
  vtkNew<vtkCellArray> lines;
  lines->AllocateExact(lineCount, pointCount);
  auto makeArray = [](vtkDoubleArray* array, const char* name, int components, vtkIdType tuples)
  {
    array->SetName(name);
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(tuples);
  };
  vtkNew<vtkDoubleArray> arcLength, velocity, speedDrift;
  makeArray(arcLength, "ArcLength", 1, pointCount);
  makeArray(velocity, "Velocity", 3, pointCount);
  makeArray(speedDrift, "SpeedDrift", 1, pointCount);
  vtkNew<vtkDoubleArray> determinant, singularValues;
  if (jacobian)
  {
    makeArray(determinant, "TransverseJacobian", 1, pointCount);
    makeArray(singularValues, "TransverseJacobianSingularValues", 2, pointCount);
  }
  vtkNew<vtkIntArray> seedIds, reasons;
  seedIds->SetName("SeedIds");
  seedIds->SetNumberOfTuples(lineCount);
  reasons->SetName("ReasonForTermination");
  reasons->SetNumberOfTuples(lineCount);

  vtkIdType next = 0;
  vtkIdType line = 0;
  std::vector<vtkIdType> ids;
  for (vtkIdType i = 0; i < traced; ++i)
  {
    const riemann::GeodesicPath& path = paths[i];
    if (path.Points.size() < 2)
    {
      continue;
    }
    ids.resize(path.Points.size());
    for (size_t k = 0; k < path.Points.size(); ++k, ++next)
    {
      ids[k] = next;
      points->SetPoint(next, path.Points[k].data());
      arcLength->SetValue(next, path.ArcLength[k]);
      velocity->SetTypedTuple(next, path.Velocities[k].data());
      speedDrift->SetValue(next, path.SpeedDrift[k]);
      if (jacobian)
      {
        determinant->SetValue(next, jacobians[i][k][0]);
        singularValues->SetTypedTuple(next, jacobians[i][k].data() + 1);
      }
    }
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    seedIds->SetValue(line, static_cast<int>(seeds[i].Id));
    reasons->SetValue(line, path.Reason);
    ++line;
  }

  output->SetPoints(points);
  output->SetLines(lines);
  output->GetPointData()->AddArray(arcLength);
  output->GetPointData()->AddArray(velocity);
  output->GetPointData()->SetVectors(velocity);
  output->GetPointData()->AddArray(speedDrift);
  if (jacobian)
  {
    output->GetPointData()->AddArray(determinant);
    output->GetPointData()->AddArray(singularValues);
  }
  output->GetCellData()->AddArray(seedIds);
  output->GetCellData()->AddArray(reasons);
  return 1;
}

void vtkRiemannGeodesicTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StartPosition: " << this->StartPosition[0] << " " << this->StartPosition[1]
     << " " << this->StartPosition[2] << "\n";
  os << indent << "StartDirection: " << this->StartDirection[0] << " " << this->StartDirection[1]
     << " " << this->StartDirection[2] << "\n";
  os << indent
     << "DirectionArrayName: " << (this->DirectionArrayName ? this->DirectionArrayName : "(none)")
     << "\n";
  os << indent << "IntegrationDirection: " << this->IntegrationDirection << "\n";
  os << indent << "UseDomainBounds: " << this->UseDomainBounds << "\n";
  os << indent << "DomainBounds: " << this->DomainBounds[0] << " " << this->DomainBounds[1] << " "
     << this->DomainBounds[2] << " " << this->DomainBounds[3] << " " << this->DomainBounds[4] << " "
     << this->DomainBounds[5] << "\n";
  os << indent << "ComputeTransverseJacobian: " << this->ComputeTransverseJacobian << "\n";
}
