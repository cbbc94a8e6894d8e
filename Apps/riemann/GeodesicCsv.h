/**
 * @file GeodesicCsv.h
 * @brief Geodesic polylines as CSV, one row per point: the format of
 * `riemann trace` and `riemann connect` (seed_id,step,t,x,y,z,vx,vy,vz, then
 * TransverseJacobian,SingularValue0,SingularValue1 when the lines carry
 * those arrays).
 */
#ifndef RiemannCliGeodesicCsv_h
#define RiemannCliGeodesicCsv_h

#include <string>

class vtkPolyData;

namespace riemann
{
namespace cli
{
/// Write `lines` (point data ArcLength and Velocity; cell data SeedIds gives
/// seed_id, else the line's number) to `path`; false when the file cannot be
/// written whole or a point array is missing.
bool WriteGeodesicCsv(vtkPolyData* lines, const std::string& path);
} // namespace cli
} // namespace riemann

#endif
