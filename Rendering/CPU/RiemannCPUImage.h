/**
 * @file RiemannCPUImage.h
 * @brief The CPU tracer's pixels (RiemannCPUTracer.h: row 0 at the bottom, as
 * VTK's images) as pictures and figures (VTK-free): the colour with its
 * arbitrary output variables as named channels, the hit error's summary and
 * its picture. What `riemann render --backend cpu` writes, straight from the
 * tracer's results.
 */
#ifndef RiemannCPUImage_h
#define RiemannCPUImage_h

#include "RiemannCPUTracer.h"
#include "RiemannImage.h"
#include "RiemannRenderingCPUModule.h" // For export macro

#include <vector>

namespace riemann
{
/**
 * The picture, rows top first: R, G, B, and with `aovs` the arbitrary output
 * variables as float channels HitPosition.X/Y/Z, ArcLength, Steps,
 * ReasonForTermination, SpeedDrift, and HitError when `hitError`.
 */
RIEMANNRENDERINGCPU_EXPORT Image PixelImage(
  const std::vector<PixelResult>& pixels, int width, int height, bool aovs, bool hitError);

/// The HitError of the pixels summarised.
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
RIEMANNRENDERINGCPU_EXPORT HitErrorSummary SummarizeHitError(const std::vector<PixelResult>& pixels);

/**
 * A picture of the hit error, rows top first: log10 of the error from 1e-7
 * (black) through blue, green and yellow to 1e-1 and above (white); red where
 * only one ray hits; grey where neither does.
 */
RIEMANNRENDERINGCPU_EXPORT Image HitErrorPicture(
  const std::vector<PixelResult>& pixels, int width, int height);
} // namespace riemann

#endif
