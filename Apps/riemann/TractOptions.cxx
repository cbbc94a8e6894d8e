#include "TractOptions.h"

#include "CliUtilities.h"
#include "Metric.h"
#include "RiemannScalarImages.h"
#include "RiemannTensorFileChecks.h"
#include "SampledTensorSamples.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRiemannGeodesicTracer.h"
#include "vtkRiemannMetric.h"
#include "vtkNIFTIImageReader.h"
#include "vtkXMLPolyDataReader.h"

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

namespace riemann
{
namespace cli
{
namespace
{
constexpr const char* ImageFormats = ".nii, .nii.gz, .nrrd, .nhdr, .vti, .vtk";

vtkSmartPointer<vtkImageData> ReadRegion(const std::string& option, const std::string& path)
{
  try
  {
    return ReadScalarImageFile(path, "the " + option.substr(2) + " image");
  }
  catch (const std::runtime_error& e)
  {
    throw Failure(option + ": " + e.what());
  }
}

/**
 * A NIfTI file's own voxel order. VTK's reader reverses the slices of a file
 * whose qfac is -1 (so that its matrix is a rotation); a .trk header must
 * name the file's voxels as the file does (DIPY compares the two), so the
 * reversal is undone: the third axis turned back, the origin at the file's
 * first slice. Other files are as read.
 */
void AsTheFileOrdersItsVoxels(const std::string& path, TractReference& reference)
{
  if (!(HasFileEnding(path, ".nii") || HasFileEnding(path, ".nii.gz")))
  {
    return;
  }
  vtkNew<vtkNIFTIImageReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  if (reader->GetQFac() < 0.0)
  {
    reference.Origin += reference.Direction.col(2) * reference.Spacing[2] * (reference.Dimensions[2] - 1);
    reference.Direction.col(2) *= -1.0;
  }
}

/// The "file" of a sampled metric's definition, as a path ("" for another metric).
std::string SampledMetricFile(vtkRiemannMetric* metric)
{
  const nlohmann::json definition = nlohmann::json::parse(metric->GetDefinition(), nullptr, false);
  if (!definition.is_object() || !definition.contains("file") || !definition["file"].is_string())
  {
    return std::string();
  }
  const std::string file = definition["file"].get<std::string>();
  const std::string base = metric->GetDataDirectory();
  return file.empty() || file.front() == '/' || base.empty() ? file : base + "/" + file;
}

} // namespace

TractReference ChooseTrkReference(
  const TractArguments& args, vtkRiemannMetric* metric, vtkImageData* seedMask)
{
  TractReference reference;
  vtkSmartPointer<vtkImageData> image = seedMask;
  if (!args.Reference.empty())
  {
    image = ReadRegion("--reference", args.Reference);
  }
  else if (const SampledTensorField* sampled = SampledFieldOf(*metric->GetMetric()))
  {
    const SampledTensorGrid& grid = sampled->GetGrid();
    reference.Dimensions = grid.Dimensions;
    reference.Spacing = grid.Spacing;
    reference.Origin = grid.Origin;
    reference.Direction = grid.Direction;
    AsTheFileOrdersItsVoxels(SampledMetricFile(metric), reference);
    return reference;
  }
  if (!image)
  {
    throw Failure("-o: a .trk file is written against a reference image (its voxel grid and "
                  "placement): give --reference, or use a sampled metric or --seed-mask",
      2);
  }
  int dimensions[3];
  image->GetDimensions(dimensions);
  for (int a = 0; a < 3; ++a)
  {
    reference.Dimensions[a] = dimensions[a];
    reference.Spacing[a] = image->GetSpacing()[a];
    reference.Origin[a] = image->GetOrigin()[a];
    for (int b = 0; b < 3; ++b)
    {
      reference.Direction(a, b) = image->GetDirectionMatrix()->GetElement(a, b);
    }
  }
  AsTheFileOrdersItsVoxels(args.Reference.empty() ? args.SeedMask : args.Reference, reference);
  return reference;
}

void AddTractOptions(CLI::App* command, TractArguments& args)
{
  const std::string formats = std::string(" (") + ImageFormats + ", placed by its own affine)";
  command
    ->add_option("--stop-mask", args.StopMask,
      "Tractography: stop where this mask is 0, read at the voxel holding each point" + formats)
    ->check(CLI::ExistingFile);
  command
    ->add_option("--include", args.Include,
      "Tractography: keep only the tracts with a point in this region (not 0)" + formats)
    ->check(CLI::ExistingFile);
  command
    ->add_option("--exclude", args.Exclude,
      "Tractography: drop the tracts with a point in this region (not 0)" + formats)
    ->check(CLI::ExistingFile);
  command
    ->add_option("--reference", args.Reference,
      "The image a .trk output is placed against (its grid and affine; default: a sampled "
      "metric's grid, else --seed-mask)" + formats)
    ->check(CLI::ExistingFile);
}

std::vector<NamedPath> TractInputFiles(const TractArguments& args)
{
  return { { "--stop-mask", args.StopMask }, { "--include", args.Include },
    { "--exclude", args.Exclude }, { "--reference", args.Reference } };
}

void ApplyTractOptions(const TractArguments& args, vtkRiemannGeodesicTracer* tracer)
{
  if (!args.StopMask.empty())
  {
    tracer->SetStopMask(ReadRegion("--stop-mask", args.StopMask));
  }
  if (!args.Include.empty())
  {
    tracer->SetIncludeRegion(ReadRegion("--include", args.Include));
  }
  if (!args.Exclude.empty())
  {
    tracer->SetExcludeRegion(ReadRegion("--exclude", args.Exclude));
  }
}

std::string DescribeRejectedTracts(const long long* byRejection)
{
  long long all = 0;
  std::string reasons;
  for (int why = 1; why <= LastTractRejection; ++why)
  {
    if (byRejection[why] > 0)
    {
      all += byRejection[why];
      reasons += (reasons.empty() ? "" : ", ") + std::to_string(byRejection[why]) + " " +
        TractRejectionName(why);
    }
  }
  return all == 0 ? std::string() : std::to_string(all) + " tract(s) dropped: " + reasons;
}

bool IsTractFile(const std::string& path)
{
  const std::string extension = Extension(path);
  return extension == "tck" || extension == "trk";
}

bool WriteTractFile(vtkPolyData* lines, const std::string& path, const std::string& output,
  const TractReference& reference)
{
  std::vector<TractRecord> records;
  const std::vector<Tract> tracts = JoinTracesIntoTracts(lines, &records);
  try
  {
    if (Extension(output) == "trk")
    {
      WriteTrkFile(path, tracts, reference, &records);
    }
    else
    {
      WriteTckFile(path, tracts);
    }
  }
  catch (const std::runtime_error& e)
  {
    throw Failure(e.what());
  }
  return true;
}

vtkSmartPointer<vtkPolyData> SeedsFromTracts(const std::string& path)
{
  // Each streamline's points, and the .vtp's velocity at its first point when it has one.
  std::vector<Tract> tracts;
  std::vector<Vec3> velocities;
  if (Extension(path) == "vtp")
  {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkPolyData* lines = reader->GetOutput();
    if (reader->GetErrorCode() != 0 || lines->GetNumberOfLines() == 0)
    {
      throw Failure("--seeds " + path + ": no polylines to seed from");
    }
    vtkDataArray* velocity = lines->GetPointData()->GetArray("Velocity");
    vtkNew<vtkIdList> ids;
    for (vtkIdType cell = 0; cell < lines->GetNumberOfCells(); ++cell)
    {
      lines->GetCellPoints(cell, ids);
      Tract tract(static_cast<std::size_t>(ids->GetNumberOfIds()));
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        lines->GetPoint(ids->GetId(k), tract[static_cast<std::size_t>(k)].data());
      }
      Vec3 v = Vec3::Zero();
      if (velocity && velocity->GetNumberOfComponents() == 3 && !tract.empty())
      {
        velocity->GetTuple(ids->GetId(0), v.data());
      }
      tracts.push_back(std::move(tract));
      velocities.push_back(v);
    }
  }
  else
  {
    try
    {
      tracts = ReadTractFile(path);
    }
    catch (const std::runtime_error& e)
    {
      throw Failure(std::string("--seeds ") + e.what());
    }
    velocities.assign(tracts.size(), Vec3::Zero());
  }
  std::vector<Vec3> starts, directions;
  for (std::size_t t = 0; t < tracts.size(); ++t)
  {
    const Tract& tract = tracts[t];
    if (tract.size() < 2)
    {
      continue; // a point has no direction
    }
    Vec3 direction = velocities[t];
    if (!(direction.norm() > 0.0))
    {
      // The one-sided difference of the highest order the points allow: on
      // a tract of steps h the third-order one errs by O(h^3) (measured on
      // the phantom's arc bundle, float32 points: 1.5e-6 rad, against
      // 1.6e-4 for the second-order one and 2e-3 for the chord).
      if (tract.size() >= 4)
      {
        direction = -11.0 * tract[0] + 18.0 * tract[1] - 9.0 * tract[2] + 2.0 * tract[3];
      }
      else if (tract.size() == 3)
      {
        direction = -3.0 * tract[0] + 4.0 * tract[1] - tract[2];
      }
      else
      {
        direction = tract[1] - tract[0];
      }
    }
    starts.push_back(tract[0]);
    directions.push_back(direction);
  }
  if (starts.empty())
  {
    throw Failure("--seeds " + path + ": no streamline of two or more points to seed from");
  }
  return SeedsWithDirections(starts, directions);
}

vtkSmartPointer<vtkPolyData> SeedsWithDirections(
  const std::vector<Vec3>& starts, const std::vector<Vec3>& directions)
{
  auto seeds = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> array;
  array->SetName("Direction");
  array->SetNumberOfComponents(3);
  for (std::size_t s = 0; s < starts.size(); ++s)
  {
    points->InsertNextPoint(starts[s].data());
    array->InsertNextTuple(directions[s].data());
  }
  seeds->SetPoints(points);
  seeds->GetPointData()->AddArray(array);
  return seeds;
}
} // namespace cli
} // namespace riemann
