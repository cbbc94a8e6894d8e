/**
 * @class riemann::studio::TimeRangeSampler
 * @brief The colour range "over time" of an item (its colour-map editor's
 * Colour range: over time): the range of its colouring array over the
 * item's results at t = 0, 1/8, ..., 1, so that a film's colours mean the
 * same in every frame (ParaView's "rescale over all timesteps").
 *
 * The item's filters, one per t, are made on the GUI thread (each with its
 * own copy of the metric at that t) and run here in order on the job's
 * worker thread; progress is theirs, and Cancel (AbortExecute) reaches the
 * one running. The output holds the range as field data "Range" (two
 * values), absent when no result had the array.
 */
#ifndef RiemannStudio_TimeRangeSampler_h
#define RiemannStudio_TimeRangeSampler_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // For the jobs

#include <string>
#include <vector>

namespace riemann
{
namespace studio
{
class TimeRangeSampler : public vtkPolyDataAlgorithm
{
public:
  static TimeRangeSampler* New();
  vtkTypeMacro(TimeRangeSampler, vtkPolyDataAlgorithm);

  /// How many times t is sampled in [0, 1], ends included.
  static constexpr int NumberOfTimes = 9;

  /// The item's filter at the next t.
  void AddJob(vtkAlgorithm* job) { this->Jobs.emplace_back(job); }
  /// The point or cell array whose range is taken (first component, or
  /// magnitude for vectors: as the colouring's own range).
  void SetArrayName(const std::string& name) { this->ArrayName = name; }

  /// The range a finished sampler found; false when there is none.
  static bool GetRange(vtkDataObject* output, double range[2]);

protected:
  TimeRangeSampler();
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  std::vector<vtkSmartPointer<vtkAlgorithm>> Jobs;
  std::string ArrayName;
};
}
}

#endif
