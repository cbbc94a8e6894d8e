#include "vtkRiemannFieldAlgorithm.h"

#include "RiemannFieldAlgorithmDeclaration.h"

#include "vtkRiemannReportError.h"

#include "Metric.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkExtentTranslator.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannParallelBatches.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkCxxSetObjectMacro(vtkRiemannFieldAlgorithm, Metric, vtkRiemannMetric);

namespace
{
// The CLI refuses more; the filter allows the same so that a typo in a
// script cannot ask for terabytes.
constexpr double MaximumGridPoints = 2e9;
}

vtkSmartPointer<vtkDoubleArray> vtkRiemannFieldAlgorithm::NewPointArray(
  const char* name, int components, vtkIdType count)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(count);
  return array;
}

namespace
{
/// The declared grid (a name of its own: unity batches join this file with the others').
namespace GridDefault = riemann::declared::vtkRiemannFieldAlgorithm::Default;
}

vtkRiemannFieldAlgorithm::vtkRiemannFieldAlgorithm()
  : Bounds{ GridDefault::Bounds[0], GridDefault::Bounds[1], GridDefault::Bounds[2],
    GridDefault::Bounds[3], GridDefault::Bounds[4], GridDefault::Bounds[5] }
  , Dimensions{ GridDefault::Dimensions[0], GridDefault::Dimensions[1], GridDefault::Dimensions[2] }
{
  // The dataset whose points are sampled (optional), then the metric port.
  this->SetNumberOfInputPorts(2);
}

void vtkRiemannFieldAlgorithm::SetMetricConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(GetMetricPort(), output);
}

vtkTypeBool vtkRiemannFieldAlgorithm::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const vtkTypeBool result = this->Superclass::ProcessRequest(request, inputVector, outputVector);
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()) &&
    vtkRiemannMetricInput::IsConnected(this, GetMetricPort()))
  {
    vtkRiemannMetricInput::CopyTimeSteps(inputVector[GetMetricPort()], outputVector);
  }
  return result;
}

vtkRiemannFieldAlgorithm::~vtkRiemannFieldAlgorithm()
{
  this->SetMetric(nullptr);
}

vtkMTimeType vtkRiemannFieldAlgorithm::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Metric)
  {
    time = std::max(time, this->Metric->GetMTime());
  }
  return time;
}

int vtkRiemannFieldAlgorithm::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == GetMetricPort())
  {
    vtkRiemannMetricInput::FillPortInformation(info);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkRiemannFieldAlgorithm::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataSet* input = this->SampledInput(inputVector);
  vtkDataSet* output = vtkDataSet::GetData(outInfo);
  if (input)
  {
    if (!output || !output->IsA(input->GetClassName()))
    {
      vtkDataSet* instance = input->NewInstance();
      outInfo->Set(vtkDataObject::DATA_OBJECT(), instance);
      instance->FastDelete();
    }
  }
  else if (!output || !vtkImageData::SafeDownCast(output))
  {
    vtkImageData* instance = vtkImageData::New();
    outInfo->Set(vtkDataObject::DATA_OBJECT(), instance);
    instance->FastDelete();
  }
  return 1;
}

vtkDataSet* vtkRiemannFieldAlgorithm::SampledInput(vtkInformationVector** inputVector)
{
  if (!this->SamplesInputPoints() || this->GetNumberOfInputConnections(0) == 0)
  {
    return nullptr;
  }
  return vtkDataSet::GetData(inputVector[0], 0);
}

std::string vtkRiemannFieldAlgorithm::CheckGrid() const
{
  std::ostringstream why;
  double points = 1.0;
  const char* axes = "xyz";
  for (int a = 0; a < 3; ++a)
  {
    const double lo = this->Bounds[2 * a], hi = this->Bounds[2 * a + 1];
    const int n = this->Dimensions[a];
    if (!std::isfinite(lo) || !std::isfinite(hi))
    {
      why << "the " << axes[a] << " bounds are not finite";
      return why.str();
    }
    if (n < 1)
    {
      why << "Dimensions[" << a << "] = " << n << " (at least 1 point per axis)";
      return why.str();
    }
    if (!(lo < hi) && !(lo == hi && n == 1))
    {
      why << "the " << axes[a] << " bounds " << lo << ", " << hi
          << " need min < max (or min == max with one point)";
      return why.str();
    }
    points *= n;
  }
  if (points > MaximumGridPoints)
  {
    why << "the grid has " << points << " points (at most " << MaximumGridPoints << ")";
    return why.str();
  }
  return {};
}

void vtkRiemannFieldAlgorithm::GridGeometry(double origin[3], double spacing[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    const double lo = this->Bounds[2 * a], hi = this->Bounds[2 * a + 1];
    const int n = this->Dimensions[a];
    if (n == 1)
    {
      origin[a] = 0.5 * (lo + hi);
      spacing[a] = hi > lo ? hi - lo : 1.0;
    }
    else
    {
      origin[a] = lo;
      spacing[a] = (hi - lo) / (n - 1);
    }
  }
}

int vtkRiemannFieldAlgorithm::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // With an input the pipeline copies its information; alone, describe the grid.
  if ((this->SamplesInputPoints() && this->GetNumberOfInputConnections(0) > 0) ||
    !this->CheckGrid().empty())
  {
    return 1;
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  double origin[3], spacing[3];
  this->GridGeometry(origin, spacing);
  const int extent[6] = { 0, this->Dimensions[0] - 1, 0, this->Dimensions[1] - 1, 0,
    this->Dimensions[2] - 1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  // Any sub-extent can be computed alone (every point's value depends on its
  // coordinates only): the executive turns a request for piece p of N, with
  // ghost levels, into UPDATE_EXTENT with vtkExtentTranslator.
  outInfo->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  return 1;
}

namespace
{
/// The extent this request asks for (the whole grid without a request).
void RequestedExtent(vtkInformation* outInfo, const int whole[6], int extent[6])
{
  std::copy(whole, whole + 6, extent);
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    // Never beyond the grid, whatever was asked.
    extent[2 * axis] = std::max(extent[2 * axis], whole[2 * axis]);
    extent[2 * axis + 1] = std::min(extent[2 * axis + 1], whole[2 * axis + 1]);
  }
}

/**
 * Points of `image` outside the piece's own extent (the one without ghost
 * levels) marked as duplicated in vtkGhostType, so that ParaView and the
 * parallel writers know which piece owns them. Nothing without ghost levels.
 */
void MarkGhostPoints(vtkInformation* outInfo, const int whole[6], vtkImageData* image)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  const int ghosts = outInfo->Has(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS())
    ? outInfo->Get(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS())
    : 0;
  if (ghosts <= 0 || !outInfo->Has(SDDP::UPDATE_PIECE_NUMBER()))
  {
    return;
  }
  int own[6];
  vtkNew<vtkExtentTranslator> translator;
  translator->PieceToExtentThreadSafe(outInfo->Get(SDDP::UPDATE_PIECE_NUMBER()),
    outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES()), 0, const_cast<int*>(whole), own,
    translator->GetSplitMode(), 0);
  const int* extent = image->GetExtent();
  vtkNew<vtkUnsignedCharArray> ghost;
  ghost->SetName(vtkDataSetAttributes::GhostArrayName());
  ghost->SetNumberOfTuples(image->GetNumberOfPoints());
  vtkIdType id = 0;
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      for (int i = extent[0]; i <= extent[1]; ++i, ++id)
      {
        const bool inside =
          i >= own[0] && i <= own[1] && j >= own[2] && j <= own[3] && k >= own[4] && k <= own[5];
        ghost->SetValue(id, inside ? 0 : vtkDataSetAttributes::DUPLICATEPOINT);
      }
    }
  }
  image->GetPointData()->AddArray(ghost);
}
} // namespace

int vtkRiemannFieldAlgorithm::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataSet* output = vtkDataSet::GetData(outputVector, 0);
  vtkDataSet* input = this->SampledInput(inputVector);
  output->Initialize();
  this->LastError.clear();
  std::string error;
  vtkRiemannMetric* metricHandle =
    this->MetricInput.Resolve(this, GetMetricPort(), this->Metric, error);
  if (!metricHandle)
  {
    vtkRiemannReportErrorMacro(this->LastError, << error);
    return 1;
  }
  // Hold the metric for the whole computation (SetDefinition may replace it).
  const std::shared_ptr<const riemann::Metric> metric = metricHandle->GetMetric();

  if (input)
  {
    output->ShallowCopy(input);
  }
  else
  {
    const std::string why = this->CheckGrid();
    if (!why.empty())
    {
      vtkRiemannReportErrorMacro(this->LastError, << "Invalid grid: " << why << ".");
      return 1;
    }
    vtkImageData* image = vtkImageData::SafeDownCast(output);
    double origin[3], spacing[3];
    this->GridGeometry(origin, spacing);
    const int whole[6] = { 0, this->Dimensions[0] - 1, 0, this->Dimensions[1] - 1, 0,
      this->Dimensions[2] - 1 };
    int extent[6];
    RequestedExtent(outInfo, whole, extent);
    image->SetExtent(extent);
    image->SetOrigin(origin);
    image->SetSpacing(spacing);
  }
  // vtkDataSet::GetPoint(id, x) is thread-safe once called from one thread.
  if (output->GetNumberOfPoints() > 0)
  {
    double x[3];
    output->GetPoint(0, x);
  }
  if (!this->ComputeFields(*metric, output))
  {
    output->Initialize();
    return 1;
  }
  if (!input)
  {
    const int whole[6] = { 0, this->Dimensions[0] - 1, 0, this->Dimensions[1] - 1, 0,
      this->Dimensions[2] - 1 };
    MarkGhostPoints(outInfo, whole, vtkImageData::SafeDownCast(output));
  }
  return 1;
}

bool vtkRiemannFieldAlgorithm::ForEachPointInBatches(
  vtkIdType count, const std::function<void(vtkIdType, vtkIdType)>& work)
{
  return vtkRiemannForInBatches(this, count, 1024, work) == count && !this->GetAbortExecute();
}

void vtkRiemannFieldAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Metric: " << this->Metric << "\n";
  os << indent << "Bounds: " << this->Bounds[0] << " " << this->Bounds[1] << " " << this->Bounds[2]
     << " " << this->Bounds[3] << " " << this->Bounds[4] << " " << this->Bounds[5] << "\n";
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " "
     << this->Dimensions[2] << "\n";
}
