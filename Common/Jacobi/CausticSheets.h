/**
 * @file CausticSheets.h
 * @brief The conjugate locus (caustic) of an observer as sheets over a
 * triangulated grid of directions, with the places where a sheet's rank
 * drops (cusp edges) and where two sheets meet.
 *
 * Sheets. Sheet k is, over the directions, the k-th conjugate point counted
 * with multiplicity (ConjugatePoint::Sheet; a point of multiplicity 2 lies on
 * sheets k and k + 1). The k-th conjugate distance t_k is a continuous
 * function of the direction (the k-th eigenvalue crossing of the Maslov
 * phases, ConjugatePoints.h), so a grid triangle whose three directions all
 * reach sheet k is a piece of that sheet: unlike grouping by ConjugateIndex,
 * a triangle never joins two different folds where a neighbour's pair of
 * simple points merges into a double one. Each sheet has its own points.
 *
 * Cusp edges (A3). The sheet is the image of C(xi) = exp_p(t_k(xi) xi) over
 * g-unit directions xi. Its differential dC(eta) = d exp(t eta + dt(eta) xi)
 * vanishes exactly for eta along the kernel direction u of the point
 * (ConjugatePoint::KernelDirection) where dt(u) = 0. KernelSlope is that
 * derivative, dt_k per radian of direction along u, estimated by least
 * squares over the neighbouring directions of the same sheet; a triangle
 * where it changes sign (the three kernel directions oriented alike) is
 * crossed by a cusp edge.
 *
 * Where two sheets meet (umbilics, D4): the points of multiplicity 2.
 */
#ifndef RiemannCausticSheets_h
#define RiemannCausticSheets_h

#include "ConjugatePoints.h"
#include "RiemannCommonJacobiExport.h"

#include <array>
#include <vector>

namespace riemann
{
/// What a sheet triangle contains (CausticSheets::TriangleSingularity).
enum class CausticSingularity : int
{
  None = 0,
  /// A cusp edge crosses the triangle: KernelSlope changes sign.
  Cusp = 1,
  /// A corner is a point of multiplicity 2: two sheets meet there.
  SheetsMeet = 2
};

struct CausticSheets
{
  /// One entry per sheet vertex (a direction's point on one sheet).
  std::vector<Vec3> Points;
  std::vector<int> Direction;
  std::vector<int> Sheet;
  /// The conjugate point's own fields (ConjugatePoint).
  std::vector<double> ArcLength;
  std::vector<int> Multiplicity;
  std::vector<int> Index;
  /// |dt_k / d(angle)| along the kernel direction (file comment): 0 on a cusp
  /// edge; 0 too at points of multiplicity 2 and where too few neighbours
  /// are on the sheet.
  std::vector<double> KernelSlope;
  /// Triangles, as indices into Points.
  std::vector<std::array<int, 3>> Triangles;
  std::vector<int> TriangleSheet;
  /// CausticSingularity values.
  std::vector<int> TriangleSingularity;
};

/**
 * Build the sheets. `directions` are the grid's unit coordinate vectors
 * (vtkRiemannDirectionGrid), `triangles` its triangles, found[i] the
 * conjugate points of direction i (FindConjugatePoints, from `observer`), `g`
 * the metric at the observer (it maps kernel directions to the grid).
 */
RIEMANNCOMMONJACOBI_EXPORT CausticSheets BuildCausticSheets(const std::vector<Vec3>& directions,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<std::vector<ConjugatePoint>>& found, const Mat3& g);
} // namespace riemann

#endif
