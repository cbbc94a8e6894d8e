// riemann::JobStop (Common/Core/RiemannJobStop.h): the stop the command
// line's SIGINT and riemann-studio's Cancel both request. A request sticks
// across VTK's reset of AbortExecute at the start of an execution, takes
// effect within a batch, and ends with Release().
#include "RiemannJobStop.h"
#include "vtkRiemannExponentialMap.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include "ErrorObserver.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace
{
constexpr int Directions = 4000;

/// An exponential map of Directions geodesics in `metric`.
void SetUpMap(vtkRiemannExponentialMap* map, vtkRiemannMetric* metric)
{
  map->SetMetric(metric);
  map->SetObserver(0.2, 0.1, -0.3);
  map->SetNumberOfDirections(Directions);
  map->GetIntegrationSettings()->SetMaximumPropagation(1.0);
}
} // namespace

TEST(JobStop, ARequestBeforeTheJobStartsStopsItAtOnce)
{
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(R"({"type":"diffeo","preset":"twist"})"));
  vtkNew<vtkRiemannExponentialMap> map;
  SetUpMap(map, metric);

  // Untouched: every direction is traced.
  map->Update();
  const vtkIdType all = map->GetOutput()->GetNumberOfCells();
  ASSERT_EQ(all, Directions);

  // Requested before the update: VTK clears AbortExecute where the execution
  // starts (that lost the GUI's flag before), the watch sets it again at the
  // first progress report, so nothing is traced: the direction grid's
  // triangulation stops at its first check and the filter reports no error
  // (a stop is not a failure).
  {
    riemann::JobStop stop;
    stop.Watch(map);
    stop.Request();
    EXPECT_TRUE(stop.Requested());
    riemann::testing::ErrorObserver errors(map);
    map->Modified();
    map->Update();
    EXPECT_EQ(map->GetOutput()->GetNumberOfCells(), 0);
    EXPECT_TRUE(map->GetAbortExecute());
    EXPECT_TRUE(errors.Messages.empty()) << errors.Messages.front();
    EXPECT_STREQ(map->GetLastError(), "");
    stop.Release();
  }

  // Released: the next job of the same algorithm runs whole.
  map->Modified();
  map->Update();
  EXPECT_EQ(map->GetOutput()->GetNumberOfCells(), all);
}

TEST(JobStop, ARequestDuringTheJobStopsItWithinABatch)
{
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(R"({"type":"diffeo","preset":"twist"})"));
  vtkNew<vtkRiemannExponentialMap> map;
  SetUpMap(map, metric);

  riemann::JobStop stop;
  stop.Watch(map);
  // The request comes at the first progress report after some work (as a
  // user's Cancel or a signal would, from wherever): the job stops at its
  // next check, one batch (1/50 of the directions) later at most, and its
  // output is empty (a partial exponential map is not one).
  struct Watch
  {
    riemann::JobStop* Stop;
    double Furthest = 0.0;
  } watch{ &stop };
  vtkNew<vtkCallbackCommand> requestMidway;
  requestMidway->SetClientData(&watch);
  requestMidway->SetCallback(
    [](vtkObject*, unsigned long, void* clientData, void* callData)
    {
      auto* w = static_cast<Watch*>(clientData);
      const double progress = *static_cast<double*>(callData);
      w->Furthest = std::max(w->Furthest, progress);
      if (progress > 0.0)
      {
        w->Stop->Request();
      }
    });
  map->AddObserver(vtkCommand::ProgressEvent, requestMidway);
  map->Update();
  EXPECT_GT(watch.Furthest, 0.0);
  EXPECT_LE(watch.Furthest, 2.0 / 50 + 1e-9) << "more than a batch after the request";
  EXPECT_TRUE(map->GetAbortExecute());
  EXPECT_EQ(map->GetOutput()->GetNumberOfCells(), 0);
}
