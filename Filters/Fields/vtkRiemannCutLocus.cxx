#include "vtkRiemannCutLocus.h"

#include "CutLocus.h"
#include "RiemannCutLocusDeclaration.h"
#include "EuclideanMetric.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
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
#include "vtkRiemannDistanceImage.h"
#include "vtkRiemannReportError.h"

#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkRiemannCutLocus);
vtkCxxSetObjectMacro(vtkRiemannCutLocus, Metric, vtkRiemannMetric);

vtkRiemannCutLocus::vtkRiemannCutLocus()
  : MinimumAngle(riemann::declared::vtkRiemannCutLocus::Default::MinimumAngle)
  , SmoothFactor(riemann::declared::vtkRiemannCutLocus::Default::SmoothFactor)
{
  // The distance field, then the metric (optional).
  this->SetNumberOfInputPorts(2);
}

vtkRiemannCutLocus::~vtkRiemannCutLocus()
{
  this->SetMetric(nullptr);
}

vtkMTimeType vtkRiemannCutLocus::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Metric)
  {
    time = std::max(time, this->Metric->GetMTime());
  }
  return time;
}

void vtkRiemannCutLocus::SetMetricConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(GetMetricPort(), output);
}

int vtkRiemannCutLocus::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == GetMetricPort())
  {
    vtkRiemannMetricInput::FillPortInformation(info);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}


// RequestData as named steps: vtkRiemannReadDistanceImage -> ExtractCutLocus ->
// the squares.
int vtkRiemannCutLocus::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  this->LastError.clear();
  if (!(this->MinimumAngle > 0 && this->MinimumAngle < 180) || !(this->SmoothFactor >= 1) ||
    !std::isfinite(this->SmoothFactor))
  {
    vtkRiemannReportErrorMacro(this->LastError,
      << "MinimumAngle must be in (0, 180) degrees and SmoothFactor at least 1 (they are "
      << this->MinimumAngle << " and " << this->SmoothFactor << ").");
    return 1;
  }
  riemann::DistanceGrid grid;
  riemann::DistanceFieldResult field;
  if (!input || !vtkRiemannReadDistanceImage(input, grid, field))
  {
    vtkRiemannReportErrorMacro(this->LastError,
      << "The input must be a distance field: point arrays Distance, ArrivalDirection (3 "
         "components) and SeedId, as vtkRiemannDistanceField makes them.");
    return 1;
  }
  // The pipeline's metric, else SetMetric()'s, else edges measured as in R^3.
  std::shared_ptr<const riemann::Metric> metric;
  if (this->Metric || vtkRiemannMetricInput::IsConnected(this, GetMetricPort()))
  {
    std::string error;
    vtkRiemannMetric* handle = this->MetricInput.Resolve(this, GetMetricPort(), this->Metric, error);
    if (!handle)
    {
      vtkRiemannReportErrorMacro(this->LastError, << error);
      return 1;
    }
    metric = handle->GetMetric();
  }
  const riemann::EuclideanMetric flat;
  riemann::CutLocusOptions options;
  options.MinimumAngle = vtkMath::RadiansFromDegrees(this->MinimumAngle);
  options.SmoothFactor = this->SmoothFactor;
  const riemann::CutLocusSurface cut =
    riemann::ExtractCutLocus(metric ? *metric : flat, grid, field, options);

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(cut.Points.size()));
  for (std::size_t p = 0; p < cut.Points.size(); ++p)
  {
    points->SetPoint(static_cast<vtkIdType>(p), cut.Points[p].data());
  }
  vtkNew<vtkCellArray> squares;
  vtkNew<vtkDoubleArray> angle, distance, crossing;
  angle->SetName("Angle");
  distance->SetName("Distance");
  crossing->SetName("CutPoint");
  crossing->SetNumberOfComponents(3);
  vtkNew<vtkIntArray> kind;
  kind->SetName("Kind");
  for (std::size_t s = 0; s < cut.Quads.size(); ++s)
  {
    const vtkIdType ids[4] = { cut.Quads[s][0], cut.Quads[s][1], cut.Quads[s][2], cut.Quads[s][3] };
    squares->InsertNextCell(4, ids);
    angle->InsertNextValue(vtkMath::DegreesFromRadians(cut.Angle[s]));
    kind->InsertNextValue(cut.Kind[s]);
    distance->InsertNextValue(cut.Distance[s]);
    crossing->InsertNextTuple(cut.Centres[s].data());
  }
  output->SetPoints(points);
  output->SetPolys(squares);
  output->GetCellData()->AddArray(angle);
  output->GetCellData()->AddArray(kind);
  output->GetCellData()->AddArray(distance);
  output->GetCellData()->AddArray(crossing);
  output->GetCellData()->AddArray(crossing);
  return 1;
}

void vtkRiemannCutLocus::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Metric: " << this->Metric << "\n";
  os << indent << "MinimumAngle: " << this->MinimumAngle << "\n";
  os << indent << "SmoothFactor: " << this->SmoothFactor << "\n";
}
