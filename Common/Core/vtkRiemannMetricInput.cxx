#include "vtkRiemannMetricInput.h"

#include "vtkRiemannMetricSource.h"

#include "vtkAlgorithm.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <cstdio>

namespace
{
/// The one string of field-data array `name`, or false.
bool OneString(vtkFieldData* fieldData, const char* name, std::string& value)
{
  auto* array = vtkStringArray::SafeDownCast(fieldData->GetAbstractArray(name));
  if (!array || array->GetNumberOfValues() != 1)
  {
    return false;
  }
  value = array->GetValue(0);
  return true;
}
}

void vtkRiemannMetricInput::FillPortInformation(vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
}

bool vtkRiemannMetricInput::IsConnected(vtkAlgorithm* algorithm, int port)
{
  return port >= 0 && port < algorithm->GetNumberOfInputPorts() &&
    algorithm->GetNumberOfInputConnections(port) > 0;
}

vtkRiemannMetric* vtkRiemannMetricInput::Resolve(
  vtkAlgorithm* algorithm, int port, vtkRiemannMetric* own, std::string& error)
{
  if (!IsConnected(algorithm, port))
  {
    if (!own || !own->HasDefinition())
    {
      error = "No metric: connect a metric source (SetMetricConnection) or call SetMetric() with "
              "a vtkRiemannMetric that has a valid definition.";
      return nullptr;
    }
    return own;
  }
  return this->FromData(algorithm->GetInputDataObject(port, 0), error);
}

vtkRiemannMetric* vtkRiemannMetricInput::FromData(vtkDataObject* data, std::string& error)
{
  return this->Read(data, error) ? this->Metric.Get() : nullptr;
}

bool vtkRiemannMetricInput::CarriesMetric(vtkDataObject* data)
{
  std::string definition;
  vtkFieldData* fieldData = data ? data->GetFieldData() : nullptr;
  return fieldData && OneString(fieldData, vtkRiemannMetricSource::DefinitionArrayName(), definition);
}

bool vtkRiemannMetricInput::Read(vtkDataObject* data, std::string& error)
{
  std::string definition, directory;
  vtkFieldData* fieldData = data ? data->GetFieldData() : nullptr;
  if (!fieldData || !OneString(fieldData, vtkRiemannMetricSource::DefinitionArrayName(), definition))
  {
    error = "The metric input carries no metric (no RiemannMetricDefinition in its field data): "
            "its source failed, or it is not a metric source.";
    return false;
  }
  OneString(fieldData, vtkRiemannMetricSource::DataDirectoryArrayName(), directory);
  double t = 0.0;
  if (vtkDataArray* time = fieldData->GetArray(vtkRiemannMetricSource::TimeArrayName()))
  {
    t = time->GetNumberOfTuples() == 1 ? time->GetTuple1(0) : 0.0;
  }
  // %a: the time's every bit, so that a new time always parses again.
  char timeText[64];
  std::snprintf(timeText, sizeof(timeText), "%a", t);
  const std::string key = definition + '\n' + directory + '\n' + timeText;
  if (key == this->Parsed)
  {
    return true;
  }
  this->Parsed.clear();
  if (!this->Metric->SetDefinition(definition.c_str(), directory.c_str()) ||
    !this->Metric->SetTime(t))
  {
    error = std::string("The metric input: ") + this->Metric->GetLastError();
    return false;
  }
  this->Parsed = key;
  return true;
}

void vtkRiemannMetricInput::CopyTimeSteps(
  vtkInformationVector* metricInput, vtkInformationVector* outputs)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  vtkInformation* from = metricInput ? metricInput->GetInformationObject(0) : nullptr;
  if (!from)
  {
    return;
  }
  for (int i = 0; i < outputs->GetNumberOfInformationObjects(); ++i)
  {
    vtkInformation* to = outputs->GetInformationObject(i);
    if (from->Has(SDDP::TIME_STEPS()) && !to->Has(SDDP::TIME_STEPS()))
    {
      to->CopyEntry(from, SDDP::TIME_STEPS());
    }
    if (from->Has(SDDP::TIME_RANGE()) && !to->Has(SDDP::TIME_RANGE()))
    {
      to->CopyEntry(from, SDDP::TIME_RANGE());
    }
  }
}
