/**
 * @file GridOptions.h
 * @brief What the commands that sample a metric on a grid (`riemann fields`,
 * `riemann distance`) add to the grid's declared options (--bounds,
 * --dimensions: vtkRiemannFieldAlgorithm.settings.json, DeclaredOptions.h):
 * the limit on the grid's points in all, and the grid as numbers.
 */
#ifndef RiemannCliGridOptions_h
#define RiemannCliGridOptions_h

#include <CLI/CLI.hpp>

#include <string>

namespace riemann
{
namespace cli
{
class DeclaredOptions;

/// Points one process holds at most (about 4 GB of arrays): the whole grid
/// in one process or gathered on rank 0; under mpirun each rank's piece, so
/// that N ranks may sample N times as many (512^3 on 7 ranks).
constexpr long long MaximumPointsPerProcess = 20000000;

/**
 * Check the points of the declared Dimensions option of `grid` in all, as it
 * is parsed: at most MaximumPointsPerProcess, per rank under mpirun when
 * `perProcess` (a grid split into pieces), else for the whole grid.
 */
void LimitGridPoints(const DeclaredOptions& grid, bool perProcess = true);

/// The grid's box and points per axis (given, or the declared defaults).
void GridOf(const DeclaredOptions& grid, double box[6], int dims[3]);
} // namespace cli
} // namespace riemann

#endif
