#include "TimeRangeSampler.h"

#include "ColorMaps.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <limits>

namespace riemann
{
namespace studio
{
vtkStandardNewMacro(TimeRangeSampler);

namespace
{
/// Widens `range` by the colouring array `name` of `result`, read as the
/// colouring reads it (ColorMaps.h).
void Widen(vtkDataObject* result, const std::string& name, double range[2], bool& found)
{
  vtkDataArray* values = ColoringArray(vtkDataSet::SafeDownCast(result), name);
  if (!values || values->GetNumberOfTuples() == 0)
  {
    return;
  }
  double own[2];
  ColoringRange(values, own);
  range[0] = std::min(range[0], own[0]);
  range[1] = std::max(range[1], own[1]);
  found = true;
}

/// What one sampled filter's progress means for the sampler, and its Cancel.
struct Forward
{
  TimeRangeSampler* Sampler;
  vtkAlgorithm* Job;
  int Index;
  int Count;
};
} // namespace

TimeRangeSampler::TimeRangeSampler()
{
  this->SetNumberOfInputPorts(0);
}

bool TimeRangeSampler::GetRange(vtkDataObject* output, double range[2])
{
  vtkDataArray* array = output ? output->GetFieldData()->GetArray("Range") : nullptr;
  if (!array || array->GetNumberOfTuples() != 2)
  {
    return false;
  }
  range[0] = array->GetTuple1(0);
  range[1] = array->GetTuple1(1);
  return true;
}

int TimeRangeSampler::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs)
{
  vtkPolyData* output = vtkPolyData::GetData(outputs);
  double range[2] = { std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() };
  bool found = false;
  const int count = static_cast<int>(this->Jobs.size());
  for (int k = 0; k < count && !this->GetAbortExecute(); ++k)
  {
    vtkAlgorithm* job = this->Jobs[static_cast<size_t>(k)];
    // The job's progress is part of ours; our Cancel stops it where it is.
    Forward forward{ this, job, k, count };
    vtkNew<vtkCallbackCommand> progress;
    progress->SetClientData(&forward);
    progress->SetCallback([](vtkObject*, unsigned long, void* client, void* call) {
      auto* f = static_cast<Forward*>(client);
      f->Sampler->UpdateProgress((f->Index + *static_cast<double*>(call)) / f->Count);
      if (f->Sampler->GetAbortExecute())
      {
        f->Job->AbortExecuteOn();
      }
    });
    const unsigned long tag = job->AddObserver(vtkCommand::ProgressEvent, progress);
    job->Update();
    job->RemoveObserver(tag);
    if (this->GetAbortExecute())
    {
      break;
    }
    for (int port = 0; port < job->GetNumberOfOutputPorts(); ++port)
    {
      Widen(job->GetOutputDataObject(port), this->ArrayName, range, found);
    }
    this->UpdateProgress(static_cast<double>(k + 1) / count);
  }
  if (found && !this->GetAbortExecute())
  {
    vtkNew<vtkDoubleArray> values;
    values->SetName("Range");
    values->InsertNextValue(range[0]);
    values->InsertNextValue(range[1]);
    output->GetFieldData()->AddArray(values);
  }
  return 1;
}
}
}
