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

/**
 * Run `work(first, last)` over the ids [0, count) in parallel, in batches of
 * max(minimumBatch, count / 50) ids; `algorithm` reports progress after each
 * batch, and the loop stops between batches when its AbortExecute is set.
 * Returns how many ids were done (count unless aborted).
 *
 * `grain` (0: the SMP backend decides) is the smallest range handed to one
 * call of `work`: the packet engine needs ranges of many seeds, and TBB's
 * automatic partitioner splits down to single ids.
 */
template <class Work>
vtkIdType vtkRiemannForInBatches(vtkAlgorithm* algorithm, vtkIdType count, vtkIdType minimumBatch,
  const Work& work, vtkIdType grain = 0)
{
  const vtkIdType batch = std::max<vtkIdType>(std::max<vtkIdType>(minimumBatch, 1), count / 50);
  vtkIdType done = 0;
  algorithm->UpdateProgress(0.0);
  while (done < count && !algorithm->GetAbortExecute())
  {
    const vtkIdType end = std::min(count, done + batch);
    vtkSMPTools::For(done, end, grain, [&](vtkIdType first, vtkIdType last) { work(first, last); });
    done = end;
    algorithm->UpdateProgress(static_cast<double>(done) / count);
  }
  return done;
}

#endif
