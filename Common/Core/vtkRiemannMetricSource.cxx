#include "vtkRiemannMetricSource.h"

#include "MetricDefinition.h"
#include "MetricParameters.h"
#include "vtkRiemannMetric.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkRiemannMetricSource);

vtkRiemannMetricSource::vtkRiemannMetricSource()
{
  this->SetNumberOfInputPorts(0);
}

vtkRiemannMetricSource::~vtkRiemannMetricSource() = default;

void vtkRiemannMetricSource::SetParameter(const char* name, double value)
{
  if (!name)
  {
    return;
  }
  for (auto& parameter : this->Parameters)
  {
    if (parameter.first == name)
    {
      // Bitwise comparison on purpose: the same value must not re-execute the pipeline.
      if (!(parameter.second == value) || std::isnan(value) != std::isnan(parameter.second))
      {
        parameter.second = value;
        this->Modified();
      }
      return;
    }
  }
  this->Parameters.emplace_back(name, value);
  this->Modified();
}

void vtkRiemannMetricSource::RemoveAllParameters()
{
  if (!this->Parameters.empty())
  {
    this->Parameters.clear();
    this->Modified();
  }
}

void vtkRiemannMetricSource::ReportError(const std::string& message)
{
  this->LastError = message;
  vtkErrorMacro(<< message);
}

int vtkRiemannMetricSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // t in [0, 1] is the metric's time whatever the definition: a definition
  // with nothing animated is the same at every step.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int steps = this->NumberOfTimeSteps;
  std::vector<double> times(static_cast<size_t>(steps), 0.0);
  for (int i = 0; i < steps; ++i)
  {
    times[static_cast<size_t>(i)] = steps == 1 ? 0.0 : static_cast<double>(i) / (steps - 1);
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), steps);
  const double range[2] = { 0.0, 1.0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  // Every piece is the whole metric (it is the same everywhere): without
  // this, the executive would hand the ranks other than 0 an empty output.
  outInfo->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

bool vtkRiemannMetricSource::MakeMetric(double t, vtkRiemannMetric* metric)
{
  std::string text = this->Definition;
  std::string directory;
  if (!this->DefinitionFile.empty())
  {
    try
    {
      text = riemann::ReadMetricDefinitionFile(this->DefinitionFile);
    }
    catch (const std::exception& e)
    {
      this->ReportError(e.what());
      return false;
    }
    const size_t slash = this->DefinitionFile.find_last_of('/');
    directory = slash == std::string::npos ? std::string() : this->DefinitionFile.substr(0, slash);
  }
  if (text.empty())
  {
    this->ReportError("No metric: set Definition (JSON text) or DefinitionFile.");
    return false;
  }
  std::vector<riemann::ParameterValue> values;
  for (const auto& parameter : this->Parameters)
  {
    values.push_back({ parameter.first, parameter.second });
  }
  try
  {
    text = riemann::WithParameterValues(text, values);
  }
  catch (const std::exception& e)
  {
    this->ReportError(e.what());
    return false;
  }
  const std::string where = this->DefinitionFile.empty() ? std::string() : this->DefinitionFile + ": ";
  if (!metric->SetDefinition(text.c_str(), directory.c_str()) || !metric->SetTime(t))
  {
    this->ReportError(where + metric->GetLastError());
    return false;
  }
  return true;
}

int vtkRiemannMetricSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  output->Initialize();
  this->LastError.clear();

  double t = 0.0;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    t = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    t = std::isfinite(t) ? std::min(1.0, std::max(0.0, t)) : 0.0;
  }
  vtkNew<vtkRiemannMetric> metric;
  if (!this->MakeMetric(t, metric))
  {
    return 1;
  }
  StoreMetric(metric, output->GetFieldData());
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), t);
  return 1;
}

void vtkRiemannMetricSource::StoreMetric(vtkRiemannMetric* metric, vtkFieldData* fieldData)
{
  const auto addString = [fieldData](const char* name, const std::string& value) {
    vtkNew<vtkStringArray> array;
    array->SetName(name);
    array->InsertNextValue(value);
    fieldData->AddArray(array);
  };
  addString(DefinitionArrayName(), metric->GetDefinition());
  addString(DataDirectoryArrayName(), metric->GetDataDirectory());
  addString(DescriptionArrayName(), metric->GetDescription());
  vtkNew<vtkDoubleArray> time;
  time->SetName(TimeArrayName());
  time->InsertNextValue(metric->GetTime());
  fieldData->AddArray(time);
}

void vtkRiemannMetricSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Definition: " << this->Definition << "\n";
  os << indent << "DefinitionFile: " << this->DefinitionFile << "\n";
  for (const auto& parameter : this->Parameters)
  {
    os << indent << "Parameter " << parameter.first << ": " << parameter.second << "\n";
  }
  os << indent << "NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
}
