/**
 * @file vtkRiemannParallelBatches.h
 * @brief The parallel loop of every long RiemannVTK filter: vtkSMPTools over
 * [0, count) in batches, with progress and abort handled between batches on
 * the calling thread (VTK events must not fire from worker threads).
 *
 * A private header of Riemann::CommonCore (not wrapped, not installed): the
 * filters' .cxx files include it.
 */
#ifndef vtkRiemannParallelBatches_h
#define vtkRiemannParallelBatches_h

#include "vtkAlgorithm.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <chrono>

/// How long one batch should take: AbortExecute (riemann-studio's Cancel,
/// the command line's Ctrl+C) is seen between batches, so this bounds how
/// long a cancelled job goes on; 0.1 s of work keeps the threads' start
/// and the progress events a negligible share.
constexpr double vtkRiemannBatchSeconds = 0.1;

/**
 * Run `work(first, last)` over the ids [0, count) in parallel, in batches;
 * `algorithm` reports progress after each batch, and the loop stops between
 * batches when its AbortExecute is set. Returns how many ids were done
 * (count unless aborted).
 *
 * Batches are sized by time: the first has `minimumBatch` ids, each next
 * one as many as the last batch's rate fits in vtkRiemannBatchSeconds (at
 * most 4 times the last, at least `minimumBatch`), so a cancel is seen
 * within about 0.1 s however slow each id is. Batches of count / 50, as
 * before, let a job of T seconds run T / 50 between checks: 1.7 s for an
 * 85 s conjugate search of 200,000 directions to arc length 40.
 * Every id is independent, so the result does not depend on the batches.
 *
 * `grain` (0: the SMP backend decides) is the smallest range handed to one
 * call of `work`: the packet engine needs ranges of many seeds, and TBB's
 * automatic partitioner splits down to single ids.
 */
template <class Work>
vtkIdType vtkRiemannForInBatches(vtkAlgorithm* algorithm, vtkIdType count, vtkIdType minimumBatch,
  const Work& work, vtkIdType grain = 0)
{
  using Clock = std::chrono::steady_clock;
  const vtkIdType smallest = std::max<vtkIdType>(minimumBatch, 1);
  vtkIdType batch = smallest;
  vtkIdType done = 0;
  algorithm->UpdateProgress(0.0);
  while (done < count && !algorithm->GetAbortExecute())
  {
    const vtkIdType end = std::min(count, done + batch);
    const Clock::time_point start = Clock::now();
    vtkSMPTools::For(done, end, grain, [&](vtkIdType first, vtkIdType last) { work(first, last); });
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const double fits = seconds > 0 ? vtkRiemannBatchSeconds / seconds * (end - done) : 4.0 * batch;
    batch = std::max(smallest, std::min<vtkIdType>(4 * batch, static_cast<vtkIdType>(fits)));
    done = end;
    algorithm->UpdateProgress(static_cast<double>(done) / count);
  }
  return done;
}

#endif
