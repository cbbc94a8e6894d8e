/**
 * @file DeclaredJob.h
 * @brief The items' one job factory and one Python exporter: an item is a
 * toolkit filter and its property values (the declared settings, keyed by
 * property, plus the integration settings of a filter that integrates), so
 * what runs and what the exported Python writes are made from those values
 * the same way for every item.
 *
 * An item adds only what is not a declared setting: the distance field's
 * seed, a camera path's key positions, the ray bundle's inside-view inputs.
 */
#ifndef RiemannStudioDeclaredJob_h
#define RiemannStudioDeclaredJob_h

#include "PipelineItem.h" // For JobInputs

#include "IntegrationValues.h"
#include "SettingDeclaration.h"
#include "SettingValues.h" // For DeclaredAccess

#include "vtkNew.h"
#include "vtkRiemannMetric.h"
#include "vtkSmartPointer.h"

#include <nlohmann/json.hpp>

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace riemann
{
namespace studio
{
/// True for a filter that integrates curves (it has GetIntegrationSettings()).
template <class Filter, class = void>
struct FilterIntegrates : std::false_type
{
};
template <class Filter>
struct FilterIntegrates<Filter,
  std::void_t<decltype(std::declval<Filter&>().GetIntegrationSettings())>> : std::true_type
{
};

/**
 * A new `Filter` for an item's `values`, ready to Update() on a worker
 * thread: its own copy of the document's metric (the document may change
 * its metric while the job runs), the integration settings of `values`
 * when the filter integrates, then the settings `Declared` declares (the
 * filter's class, or the base class whose declaration it takes:
 * `<Declared>SettingAccess.h` must be included before the call).
 */
template <class Filter, class Declared = Filter>
vtkSmartPointer<Filter> DeclaredJob(const nlohmann::json& values, const JobInputs& inputs)
{
  auto job = vtkSmartPointer<Filter>::New();
  vtkNew<vtkRiemannMetric> metric;
  metric->ShallowCopy(inputs.Metric);
  job->SetMetric(metric);
  if constexpr (FilterIntegrates<Filter>::value)
  {
    ApplyIntegrationValues(values, job->GetIntegrationSettings());
  }
  riemann::settings::DeclaredAccess<Declared>::Apply(job.Get(), values);
  return job;
}

/**
 * The Python of an item that runs `className` as variable `var`: the filter
 * made, the metric set (`metric` exists in the exported script), the
 * settings of `values` that `table` declares (SettingPythonLines) and, when
 * the filter `integrates`, its integration settings.
 */
std::vector<std::string> DeclaredPythonLines(const std::string& className,
  const riemann::SettingTable& table, const std::string& var, const nlohmann::json& values,
  bool integrates);

/// DeclaredPythonLines for `Filter` (named `className`) and the table `Declared` declares.
template <class Filter, class Declared = Filter>
std::vector<std::string> DeclaredPythonLines(
  const std::string& className, const std::string& var, const nlohmann::json& values)
{
  return DeclaredPythonLines(className, riemann::settings::DeclaredAccess<Declared>::Settings(), var,
    values, FilterIntegrates<Filter>::value);
}
} // namespace studio
} // namespace riemann

#endif
