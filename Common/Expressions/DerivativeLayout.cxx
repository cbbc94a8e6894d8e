#include "DerivativeLayout.h"

#include <stdexcept>
#include <string>

namespace riemann
{
int DerivativeLayout::OutputsPerSource(int order)
{
  static const int counts[4] = { 1, 4, 10, 20 };
  if (order < 0 || order > 3)
  {
    throw std::out_of_range("derivative order " + std::to_string(order) + " is not in 0..3");
  }
  return counts[order];
}

void DerivativeLayout::FailIndex(int source, int n, int i, int j, int k)
{
  throw std::out_of_range("no output for source " + std::to_string(source) + ", derivative order " +
    std::to_string(n) + ", indices " + std::to_string(i) + " " + std::to_string(j) + " " +
    std::to_string(k));
}
} // namespace riemann
