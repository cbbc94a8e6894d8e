// riemann render --backend cpu: the CPU tracer's output (vtkRiemannCPURayTracer)
// as pictures and EXR channels, and its hit-error summary.
#ifndef RiemannCpuRender_h
#define RiemannCpuRender_h

#include "RiemannImageIO.h"

class vtkImageData;

namespace riemann
{
namespace cli
{
/**
 * The tracer's image, rows top first: R, G, B, and with `aovs` the
 * arbitrary output variables as named float channels: HitPosition.X/Y/Z,
 * ArcLength, Steps, ReasonForTermination, SpeedDrift, and HitError where
 * the tracer computed it.
 */
Image TracerImage(vtkImageData* data, bool aovs);

/// The "HitError" array of the tracer summarised over the pixels.
struct HitErrorSummary
{
  /// Over pixels where the traced and the exact ray both hit.
  double Maximum = 0.0;
  double Median = 0.0;
  /// The maximum is set by pixels on an object's edge, where the two rays may
  /// hit different objects: the 99th percentile says more about the rest.
  double Percentile99 = 0.0;
  long long Compared = 0;
  /// Pixels where exactly one of the two hits.
  long long Disagreeing = 0;
};
HitErrorSummary SummarizeHitError(vtkImageData* data);

/**
 * A picture of the hit error: log10 of the error from 1e-7 (black) through
 * blue, green and yellow to 1e-1 and above (white); red where only one ray
 * hits; the background grey where neither does. Rows top first.
 */
Image HitErrorPicture(vtkImageData* data);
} // namespace cli
} // namespace riemann

#endif
