/**
 * @file GridOptions.h
 * @brief The grid options of the commands that sample a metric on a grid
 * (`riemann fields`, `riemann distance`): --bounds X0,X1,Y0,Y1,Z0,Z1 and
 * --dims NX,NY,NZ, their checks and their limits.
 */
#ifndef RiemannCliGridOptions_h
#define RiemannCliGridOptions_h

#include <CLI/CLI.hpp>

#include <string>

namespace riemann
{
namespace cli
{
/// Points per axis at most.
constexpr long long MaximumPerAxis = 512;
/// Points one process holds at most (about 4 GB of arrays): the whole grid
/// in one process or gathered on rank 0; under mpirun each rank's piece, so
/// that N ranks may sample N times as many (512^3 on 7 ranks).
constexpr long long MaximumPointsPerProcess = 20000000;

/// What is wrong with `text` as a grid box, or "" (then `bounds` holds it).
std::string CheckBounds(const std::string& text, double bounds[6]);

/// What is wrong with `text` as point counts per axis, or "" (then `dims`
/// holds them). `perProcess`: the total is per rank under mpirun (a grid
/// split into pieces), else for the whole grid.
std::string CheckDimensions(const std::string& text, int dims[3], bool perProcess = true);

/// --bounds and --dims, checked as they are parsed.
void AddGridOptions(CLI::App* command, std::string& bounds, std::string& dimensions,
  bool perProcess = true);

/// Both parsed (they were checked while parsing; a Failure, status 2, if not).
void ParseGridOptions(
  const std::string& bounds, const std::string& dimensions, double box[6], int dims[3],
  bool perProcess = true);
} // namespace cli
} // namespace riemann

#endif
