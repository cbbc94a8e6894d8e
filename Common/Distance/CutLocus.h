/**
 * @file CutLocus.h
 * @brief The cut locus of a distance field: where the minimal geodesics
 * from the seeds stop being unique, found as the surface across which the
 * field's arrival direction jumps (the ridge of the distance), or across
 * which the closest seed changes (the boundary of Voronoi regions).
 *
 * Along a grid edge between neighbouring points x and y, the arrival
 * directions of a smooth field turn by at most about |x - y|_g / u (the
 * angle a point source's rays spread by over that step, u the distance):
 * a turn both above MinimumAngle and SmoothFactor times that is a jump, and
 * the cut locus crosses the edge. Each such edge gives the square of the
 * dual grid that it pierces (corners at the centres of the four cells
 * around it), so the squares of neighbouring edges share corners and make
 * one surface; edges on the grid's boundary have fewer cells and give none.
 * A cut locus of lower dimension (a curve behind an obstacle, the single
 * antipode on a round sphere) comes out as a thin tube or a small closed
 * surface around it.
 */
#ifndef RiemannCutLocus_h
#define RiemannCutLocus_h

#include "DistanceField.h"
#include "RiemannCommonDistanceExport.h"

#include <array>
#include <vector>

namespace riemann
{
struct CutLocusOptions
{
  /// Turns of the arrival direction below this (radians) are never jumps.
  double MinimumAngle = 20.0 * 3.14159265358979323846 / 180.0;
  /// A turn must also exceed this times |x - y|_g / u.
  double SmoothFactor = 3.0;
};

struct CutLocusSurface
{
  /// The dual grid's points the squares use (cell centres).
  std::vector<Vec3> Points;
  /// Corners of each square, in order around it.
  std::vector<std::array<int, 4>> Quads;
  /// Per square: the turn of the arrival direction across its edge (radians).
  std::vector<double> Angle;
  /// Per square: 1 where the arrival direction jumps, 2 where the seed changes.
  std::vector<int> Kind;
  /// Per square: the distance at its centre (the mean of the edge's ends).
  std::vector<double> Distance;
  /// Per square: where the cut locus crosses its edge (the two fronts, each
  /// extrapolated along its arrival direction, meet there; the middle of
  /// the edge when they do not meet on it).
  std::vector<Vec3> Centres;
};

/// The cut locus of a distance field computed on `grid`.
RIEMANNCOMMONDISTANCE_EXPORT CutLocusSurface ExtractCutLocus(const Metric& metric,
  const DistanceGrid& grid, const DistanceFieldResult& field, const CutLocusOptions& options = {});
} // namespace riemann

#endif
