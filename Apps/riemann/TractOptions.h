// riemann trace's tractography: the masks and regions (--stop-mask,
// --include, --exclude), the .tck and .trk outputs against a reference image
// (--reference), and seeds read back from streamline files. One place for
// what `trace` and `connectivity` share. The stops' numbers (--stop-fa,
// --max-angle, --min-length) are the tracer's declared settings
// (vtkRiemannGeodesicTracer.settings.json, DeclaredOptions.h).
#ifndef RiemannCliTractOptions_h
#define RiemannCliTractOptions_h

#include "CliUtilities.h"
#include "RiemannTractFiles.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

namespace CLI
{
class App;
}
class vtkImageData;
class vtkPolyData;
class vtkRiemannGeodesicTracer;
class vtkRiemannMetric;

namespace riemann
{
namespace cli
{
struct TractArguments
{
  std::string StopMask;
  std::string Include;
  std::string Exclude;
  std::string Reference;
  /// The seed mask's file (a .trk's last choice of reference), set by `trace`.
  std::string SeedMask;
};

/// Register the options above on `command`.
void AddTractOptions(CLI::App* command, TractArguments& args);

/// The files the options name, for CheckFilePaths.
std::vector<NamedPath> TractInputFiles(const TractArguments& args);

/// Read the masks and regions (each placed by its own affine) into the tracer.
void ApplyTractOptions(const TractArguments& args, vtkRiemannGeodesicTracer* tracer);

/// "; 3 tract(s) dropped: 2 entered the exclude region, 1 ..." from the
/// counts by TractRejection, or "".
std::string DescribeRejectedTracts(const long long* byRejection);

/// Whether `path` is a streamline file riemann writes (.tck, .trk).
bool IsTractFile(const std::string& path);

/**
 * The image a .trk is written against: --reference, else the metric's
 * sampled grid, else `seedMask` (read from args.SeedMask), each with the
 * voxel order of its file. Without any: Failure (usage, status 2).
 */
TractReference ChooseTrkReference(
  const TractArguments& args, vtkRiemannMetric* metric, vtkImageData* seedMask);

/**
 * Write the trace `lines` into `path` as the streamline file `output` names
 * (.tck, or .trk against `reference`; `path` may be a temporary file), one
 * streamline per seed (JoinTracesIntoTracts); a .trk's streamlines carry
 * their seed and why each end stopped (properties seed_id, stop_at_start,
 * stop_at_end: ReasonForTermination codes, 0 for a missing half). Returns
 * true (for WriteAtomically).
 */
bool WriteTractFile(vtkPolyData* lines, const std::string& path, const std::string& output,
  const TractReference& reference);

/// Seeds as the tracer reads them: points with the point-data array "Direction".
vtkSmartPointer<vtkPolyData> SeedsWithDirections(
  const std::vector<Vec3>& points, const std::vector<Vec3>& directions);

/**
 * Seeds from a streamline file (.tck, .trk, or a .vtp of polylines): one per
 * streamline, at its first point, along its tangent there (the .vtp's
 * `Velocity` when it has one, else the third-order one-sided difference of
 * its first four points). Point data "Direction".
 */
vtkSmartPointer<vtkPolyData> SeedsFromTracts(const std::string& path);
} // namespace cli
} // namespace riemann

#endif
