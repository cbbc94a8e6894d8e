#include "GridOptions.h"

#include "CliUtilities.h"
#include "Distributed.h"

#include <cmath>
#include <sstream>
#include <vector>

namespace riemann
{
namespace cli
{
std::string CheckBounds(const std::string& text, double bounds[6])
{
  std::vector<double> b;
  const std::string problem = CheckNumberList(text, 6, "X0,X1,Y0,Y1,Z0,Z1", b);
  if (!problem.empty())
  {
    return problem;
  }
  const char* axes = "xyz";
  for (int a = 0; a < 3; ++a)
  {
    if (!(b[2 * a] < b[2 * a + 1]))
    {
      std::ostringstream message;
      message << "the " << axes[a] << " range needs " << axes[a] << "0 < " << axes[a] << "1, got "
              << b[2 * a] << " >= " << b[2 * a + 1];
      return message.str();
    }
    bounds[2 * a] = b[2 * a];
    bounds[2 * a + 1] = b[2 * a + 1];
  }
  return {};
}

std::string CheckDimensions(const std::string& text, int dims[3], bool perProcess)
{
  std::vector<double> d;
  const std::string problem = CheckNumberList(text, 3, "NX,NY,NZ", d);
  if (!problem.empty())
  {
    return problem;
  }
  double total = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    if (d[a] != std::floor(d[a]))
    {
      return "\"" + text + "\": point counts must be whole numbers";
    }
    if (d[a] < 1 || d[a] > MaximumPerAxis)
    {
      std::ostringstream message;
      message << d[a] << " points on an axis; each must be between 1 and " << MaximumPerAxis;
      return message.str();
    }
    dims[a] = static_cast<int>(d[a]);
    total *= d[a];
  }
  const long long maximum = MaximumPointsPerProcess * (perProcess ? NumberOfRanks() : 1);
  if (total > maximum)
  {
    std::ostringstream message;
    message << static_cast<long long>(total) << " grid points; at most " << maximum;
    if (maximum == MaximumPointsPerProcess)
    {
      message << " in one process (under mpirun, " << MaximumPointsPerProcess << " per rank)";
    }
    else
    {
      message << " on " << NumberOfRanks() << " ranks (" << MaximumPointsPerProcess << " per rank)";
    }
    return message.str();
  }
  return {};
}

void AddGridOptions(CLI::App* command, std::string& bounds, std::string& dimensions, bool perProcess)
{
  command
    ->add_option("--bounds", bounds, "Grid box X0,X1,Y0,Y1,Z0,Z1 (default -2,2,-2,2,-2,2)")
    ->check(Checked(
      [](const std::string& text)
      {
        double box[6];
        return CheckBounds(text, box);
      },
      "X0,X1,Y0,Y1,Z0,Z1"));
  command
    ->add_option("--dims", dimensions,
      perProcess ? "Grid points per axis NX,NY,NZ (default 33,33,33; at most 512 each, and 2e7 in "
                   "all per process: under mpirun, per rank)"
                 : "Grid points per axis NX,NY,NZ (default 33,33,33; at most 512 each, and 2e7 "
                   "in all)")
    ->check(Checked(
      [perProcess](const std::string& text)
      {
        int dims[3];
        return CheckDimensions(text, dims, perProcess);
      },
      "NX,NY,NZ"));
}

void ParseGridOptions(const std::string& bounds, const std::string& dimensions, double box[6],
  int dims[3], bool perProcess)
{
  std::string problem = CheckBounds(bounds, box);
  if (!problem.empty())
  {
    throw Failure("--bounds: " + problem, 2);
  }
  problem = CheckDimensions(dimensions, dims, perProcess);
  if (!problem.empty())
  {
    throw Failure("--dims: " + problem, 2);
  }
}
} // namespace cli
} // namespace riemann
