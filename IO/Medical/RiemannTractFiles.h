/**
 * @file RiemannTractFiles.h
 * @brief Streamline files of the tractography tools (issue 31): MRtrix's
 * .tck and TrackVis's .trk, written from a trace and read back (as seeds).
 *
 * Points are in world coordinates, which for a NIfTI scan are its RAS+ mm
 * (the placement by its q-form or s-form): .tck stores them as they are
 * (MRtrix's "scanner" coordinates), .trk in its "voxmm" frame of a
 * reference image (voxel coordinates, whose corner is the first voxel's
 * corner, times the voxel sizes), with the reference's voxel-to-RAS affine
 * and voxel order in the header so that nibabel, DIPY and TrackVis put them
 * back where they were. Both in little-endian float32.
 */
#ifndef RiemannTractFiles_h
#define RiemannTractFiles_h

#include "RiemannIOMedicalModule.h" // For export macro
#include "TractStops.h"              // For Vec3, Mat3

#include <array>
#include <string>
#include <vector>

class vtkPolyData;

namespace riemann
{
/// One streamline: its points in world coordinates.
using Tract = std::vector<Vec3>;

/// Where a tract comes from and why its ends stopped (ReasonForTermination codes).
struct RIEMANNIOMEDICAL_EXPORT TractRecord
{
  long long SeedId = -1;
  /// The backward line's reason (the tract's first point), 0 without one.
  int StopAtStart = 0;
  /// The forward line's reason (its last point), 0 without one.
  int StopAtEnd = 0;
};

/// The image a .trk file is written against (its voxel grid and placement).
struct RIEMANNIOMEDICAL_EXPORT TractReference
{
  std::array<int, 3> Dimensions = { 1, 1, 1 };
  Vec3 Spacing = Vec3::Ones();
  Vec3 Origin = Vec3::Zero();
  /// Voxel axes in world axes (orthonormal, possibly a reflection).
  Mat3 Direction = Mat3::Identity();
};

/**
 * A trace's lines (vtkRiemannGeodesicTracer's output: cell data SeedIds,
 * point data ArcLength) as tracts: each seed's backward line reversed, then
 * its forward line, the seed point once. Lines of one seed follow each
 * other, as the tracer writes them. `records` (optional) gets each tract's
 * seed and why its ends stopped.
 */
RIEMANNIOMEDICAL_EXPORT std::vector<Tract> JoinTracesIntoTracts(
  vtkPolyData* lines, std::vector<TractRecord>* records = nullptr);

/// Write .tck (MRtrix). Throws std::runtime_error naming the file.
RIEMANNIOMEDICAL_EXPORT void WriteTckFile(const std::string& path, const std::vector<Tract>& tracts);

/**
 * Write .trk (TrackVis v2) against `reference`. With `records` (one a
 * tract), each streamline carries them as its three properties, "seed_id",
 * "stop_at_start" and "stop_at_end" (nibabel's data_per_streamline).
 * Throws std::runtime_error naming the file.
 */
RIEMANNIOMEDICAL_EXPORT void WriteTrkFile(const std::string& path,
  const std::vector<Tract>& tracts, const TractReference& reference,
  const std::vector<TractRecord>* records = nullptr);

/**
 * Read a .tck or .trk file's streamlines in world coordinates (.trk: through
 * its header's voxel-to-RAS affine and voxel order, as nibabel reads it).
 * Throws std::runtime_error naming the file and what is wrong (not a
 * streamline file, truncated, counts that disagree, absurd sizes).
 */
RIEMANNIOMEDICAL_EXPORT std::vector<Tract> ReadTractFile(const std::string& path);
} // namespace riemann

#endif
