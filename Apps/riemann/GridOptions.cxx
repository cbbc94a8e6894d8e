#include "GridOptions.h"

#include "CliUtilities.h"
#include "DeclaredOptions.h"
#include "Distributed.h"

#include <sstream>
#include <vector>

namespace riemann
{
namespace cli
{
namespace
{
/// What is wrong with the grid of `text` (three counts, each already in range) in all, or "".
std::string CheckGridPoints(const std::string& text, bool perProcess)
{
  std::vector<double> d;
  if (!CheckNumberList(text, 3, "NX,NY,NZ", d).empty())
  {
    return {}; // the declared check says what is wrong with the text
  }
  const double total = d[0] * d[1] * d[2];
  const long long maximum = MaximumPointsPerProcess * (perProcess ? NumberOfRanks() : 1);
  if (total <= maximum)
  {
    return {};
  }
  std::ostringstream message;
  message << static_cast<long long>(total) << " grid points; at most " << maximum;
  if (maximum == MaximumPointsPerProcess)
  {
    message << " in one process" << (perProcess ? " (under mpirun, " : "")
            << (perProcess ? std::to_string(MaximumPointsPerProcess) + " per rank)" : "");
  }
  else
  {
    message << " on " << NumberOfRanks() << " ranks (" << MaximumPointsPerProcess << " per rank)";
  }
  return message.str();
}
} // namespace

void LimitGridPoints(const DeclaredOptions& grid, bool perProcess)
{
  grid.OptionOf("Dimensions")
    ->check(Checked([perProcess](const std::string& text)
      { return CheckGridPoints(text, perProcess); },
      ""));
}

void GridOf(const DeclaredOptions& grid, double box[6], int dims[3])
{
  const nlohmann::json bounds = grid.Value("Bounds");
  const nlohmann::json counts = grid.Value("Dimensions");
  for (int i = 0; i < 6; ++i)
  {
    box[i] = bounds.at(i).get<double>();
  }
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = counts.at(a).get<int>();
  }
}
} // namespace cli
} // namespace riemann
