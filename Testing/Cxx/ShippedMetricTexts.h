/**
 * @file ShippedMetricTexts.h
 * @brief The texts of the metric definitions shipped in Data/metrics, for
 * tests that read every one (where errors are, the editor's parameters).
 * Header-only; `dataDirectory` is the source tree's Data folder.
 */
#ifndef RiemannShippedMetricTexts_h
#define RiemannShippedMetricTexts_h

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace riemann
{
namespace testing
{
inline const char* const ShippedMetrics[] = { "astigmatic-lens.json", "bump-translation.json",
  "constant-tensor.json", "eight-gaussians.json", "euclidean.json", "gaussian-bump-typed.json",
  "gaussian-bump.json", "gaussian-lens.json", "local-twist.json", "nil.json", "paraboloid.json",
  "poincare-ball.json", "round-sphere.json", "saddle.json", "twist.json",
  "two-bump-composition.json", "two-bumps.json", "wavy-diffeo.json" };

/// The text of Data/metrics/`name`; fails the test when it cannot be read.
inline std::string ReadShippedMetric(const std::string& dataDirectory, const std::string& name)
{
  const std::string path = dataDirectory + "/metrics/" + name;
  std::ifstream file(path, std::ios::binary);
  EXPECT_TRUE(file) << "cannot open " << path;
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}
} // namespace testing
} // namespace riemann

#endif
