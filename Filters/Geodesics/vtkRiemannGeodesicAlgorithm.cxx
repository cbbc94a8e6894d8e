#include "vtkRiemannGeodesicAlgorithm.h"

#include "GeodesicTrace.h"
#include "Metric.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRiemannDirectionGrid.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <string>

vtkCxxSetObjectMacro(vtkRiemannGeodesicAlgorithm, Metric, vtkRiemannMetric);

vtkRiemannGeodesicAlgorithm::vtkRiemannGeodesicAlgorithm()
  : IntegrationSettings(vtkRiemannIntegrationSettings::New())
{
  this->SetNumberOfDataPorts(1);
}

void vtkRiemannGeodesicAlgorithm::SetNumberOfDataPorts(int count)
{
  this->MetricPort = count;
  this->SetNumberOfInputPorts(count + 1);
}

void vtkRiemannGeodesicAlgorithm::SetMetricConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(this->MetricPort, output);
}

int vtkRiemannGeodesicAlgorithm::FillDataPortInformation(int port, vtkInformation* info)
{
  return this->Superclass::FillInputPortInformation(port, info);
}

int vtkRiemannGeodesicAlgorithm::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == this->MetricPort)
  {
    vtkRiemannMetricInput::FillPortInformation(info);
    return 1;
  }
  return this->FillDataPortInformation(port, info);
}

vtkTypeBool vtkRiemannGeodesicAlgorithm::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const vtkTypeBool result = this->Superclass::ProcessRequest(request, inputVector, outputVector);
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()) &&
    vtkRiemannMetricInput::IsConnected(this, this->MetricPort))
  {
    vtkRiemannMetricInput::CopyTimeSteps(inputVector[this->MetricPort], outputVector);
  }
  return result;
}

vtkRiemannGeodesicAlgorithm::~vtkRiemannGeodesicAlgorithm()
{
  this->SetMetric(nullptr);
  this->IntegrationSettings->Delete();
}

void vtkRiemannGeodesicAlgorithm::SetIntegrationSettings(vtkRiemannIntegrationSettings* settings)
{
  if (vtkRiemannIntegrationSettings::Share(this, this->IntegrationSettings, settings))
  {
    this->Modified();
  }
}

vtkMTimeType vtkRiemannGeodesicAlgorithm::GetMTime()
{
  vtkMTimeType time = std::max(this->Superclass::GetMTime(), this->IntegrationSettings->GetMTime());
  if (this->Metric)
  {
    time = std::max(time, this->Metric->GetMTime());
  }
  return time;
}

void vtkRiemannGeodesicAlgorithm::ReportError(const std::string& message)
{
  this->LastError = message;
  vtkErrorMacro(<< message);
}

bool vtkRiemannGeodesicAlgorithm::CheckObserver(const double observer[3])
{
  if (!std::isfinite(observer[0]) || !std::isfinite(observer[1]) || !std::isfinite(observer[2]))
  {
    this->ReportError("Observer must be finite.");
    return false;
  }
  return true;
}

bool vtkRiemannGeodesicAlgorithm::BuildDirectionGrid(
  int numberOfDirections, const double coneAxis[3], double coneAngle, vtkPolyData* grid)
{
  std::string message;
  if (!vtkRiemannDirectionGrid::Build(numberOfDirections, coneAxis, coneAngle, grid, message, this))
  {
    if (!this->GetAbortExecute()) // a requested stop is not an error
    {
      this->ReportError(message + ".");
    }
    return false;
  }
  return true;
}

std::shared_ptr<const riemann::Metric> vtkRiemannGeodesicAlgorithm::CheckMetricAndSettings()
{
  this->LastError.clear();
  std::string error;
  vtkRiemannMetric* metric =
    this->MetricInput.Resolve(this, this->MetricPort, this->Metric, error);
  if (!metric)
  {
    this->ReportError(error);
    return nullptr;
  }
  const std::string settingsError =
    this->UsesIntegrationSettings() ? this->IntegrationSettings->CheckSettings() : std::string();
  if (!settingsError.empty())
  {
    this->ReportError("Integration settings: " + settingsError + ".");
    return nullptr;
  }
  // Held for the whole computation (SetDefinition may replace it meanwhile).
  return metric->GetMetric();
}

riemann::GeodesicOptions vtkRiemannGeodesicAlgorithm::MakeGeodesicOptions() const
{
  riemann::GeodesicOptions options;
  this->IntegrationSettings->ApplyTo(options);
  return options;
}

void vtkRiemannGeodesicAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Metric: " << this->Metric << "\n";
  os << indent << "MetricPort: " << this->MetricPort
     << (vtkRiemannMetricInput::IsConnected(this, this->MetricPort) ? " (connected)" : "") << "\n";
  os << indent << "IntegrationSettings:\n";
  this->IntegrationSettings->PrintSelf(os, indent.GetNextIndent());
  os << indent << "LastError: " << this->LastError << "\n";
}

bool vtkRiemannGeodesicAlgorithm::PieceShare(vtkInformation* request,
  vtkInformationVector* outputVector, vtkIdType count, vtkIdType& first, vtkIdType& last)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  const int port = request && request->Has(vtkDemandDrivenPipeline::FROM_OUTPUT_PORT())
    ? std::max(0, request->Get(vtkDemandDrivenPipeline::FROM_OUTPUT_PORT()))
    : 0;
  vtkInformation* outInfo = outputVector->GetInformationObject(port);
  first = 0;
  last = count;
  const int pieces = outInfo && outInfo->Has(SDDP::UPDATE_NUMBER_OF_PIECES())
    ? outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES())
    : 1;
  const int piece = outInfo && outInfo->Has(SDDP::UPDATE_PIECE_NUMBER())
    ? outInfo->Get(SDDP::UPDATE_PIECE_NUMBER())
    : 0;
  if (pieces <= 1 || piece < 0 || piece >= pieces)
  {
    return false;
  }
  // In 64 bits: count * piece stays far from overflow for any vtkIdType count of items.
  first = static_cast<vtkIdType>(static_cast<long long>(count) * piece / pieces);
  last = static_cast<vtkIdType>(static_cast<long long>(count) * (piece + 1) / pieces);
  return true;
}
