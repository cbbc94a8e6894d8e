// riemann connectivity: how strongly the regions of a label image (an atlas)
// are connected in a metric: for every pair of regions, the geodesic
// distance between them (one distance field per region, seeded at all its
// voxels: Dela Haije's geodesic connectivity), and optionally how many
// tracts seeded in the labelled voxels join them (DIPY's and MRtrix's
// streamline-count connectome). Matrices as CSV, regions in ascending label
// order, named on a leading "#" line, as numpy.loadtxt and MRtrix read them.
#include "CliUtilities.h"
#include "DeclaredOptions.h"
#include "IntegrationOptions.h"
#include "Commands.h"
#include "Distributed.h"
#include "GeodesicTrace.h"
#include "Interrupts.h"
#include "ProgressBar.h"
#include "RiemannScalarImages.h"
#include "TractOptions.h"
#include "TractStops.h"
#include "vtkRiemannGeodesicTracerSettingAccess.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRiemannDistanceField.h"
#include "vtkRiemannGeodesicTracer.h"
#include "vtkRiemannMetric.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace riemann
{
namespace cli
{
namespace
{
/// The most regions a matrix has (a field each: hours beyond).
constexpr int MaximumRegions = 1000;

struct ConnectivityArguments
{
  std::string Metric;
  std::string Labels;
  std::string Output;
  std::string TractCounts;
  double SeedRadius = 2.5;
  /// The tracer's settings that --tract-counts uses (seeds per voxel, the stops).
  std::unique_ptr<DeclaredOptions> Tracer;
  /// The integration options, with the tracer's defaults (IntegrationOptions.h).
  std::unique_ptr<DeclaredOptions> Integration;
  TractArguments Tracts;
};

/// The labelled image and its regions: label per voxel, voxels per label.
struct Atlas
{
  vtkSmartPointer<vtkImageData> Image;
  std::vector<long long> Labels;                    // the regions, ascending
  std::map<long long, std::vector<vtkIdType>> Voxels; // label -> voxel ids
};

Atlas ReadAtlas(const std::string& path)
{
  Atlas atlas;
  try
  {
    atlas.Image = ReadScalarImageFile(path, "the label image");
  }
  catch (const std::runtime_error& e)
  {
    throw Failure(std::string("--labels: ") + e.what());
  }
  vtkDataArray* values = atlas.Image->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    const double value = values->GetTuple1(i);
    if (value != std::floor(value) || !std::isfinite(value))
    {
      throw Failure("--labels " + path + ": voxel " + std::to_string(i) + " holds " +
        std::to_string(value) + ", not a whole number (a label image holds region numbers)");
    }
    if (value != 0.0)
    {
      atlas.Voxels[static_cast<long long>(value)].push_back(i);
    }
  }
  for (const auto& region : atlas.Voxels)
  {
    atlas.Labels.push_back(region.first);
  }
  if (atlas.Labels.size() < 2)
  {
    throw Failure("--labels " + path + ": " + std::to_string(atlas.Labels.size()) +
      " region(s) (labels other than 0); a connectivity matrix needs at least 2");
  }
  if (atlas.Labels.size() > static_cast<std::size_t>(MaximumRegions))
  {
    throw Failure("--labels " + path + ": " + std::to_string(atlas.Labels.size()) +
      " regions, more than the " + std::to_string(MaximumRegions) + " riemann connects");
  }
  return atlas;
}

/// The label of the voxel that holds world point x (0 outside the image).
long long LabelAt(vtkImageData* image, const double x[3])
{
  double ijk[3];
  image->TransformPhysicalPointToContinuousIndex(x, ijk);
  int dims[3];
  image->GetDimensions(dims);
  int index[3];
  for (int a = 0; a < 3; ++a)
  {
    index[a] = VoxelOnAxis(ijk[a], dims[a]);
    if (index[a] < 0)
    {
      return 0;
    }
  }
  return static_cast<long long>(
    image->GetPointData()->GetScalars()->GetTuple1(image->ComputePointId(index)));
}

/// The distance grid: the box of the labelled image's voxel centres (in
/// world axes), at its smallest spacing.
void DistanceGridOf(vtkImageData* image, double bounds[6], int dims[3])
{
  image->GetBounds(bounds); // of the voxel centres, placed by the direction
  const double* spacing = image->GetSpacing();
  const double h = std::min({ spacing[0], spacing[1], spacing[2] });
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = std::max(2, static_cast<int>(std::lround((bounds[2 * a + 1] - bounds[2 * a]) / h)) + 1);
  }
}

/// Write a matrix whole or not at all: "# labels: ..." then one row per region.
template <typename T>
void WriteMatrix(const std::string& path, const std::vector<long long>& labels,
  const std::vector<std::vector<T>>& matrix, const std::string& what)
{
  WriteAtomically(path,
    [&](const std::string& temporary)
    {
      std::ofstream out(temporary);
      out << "# " << what << "; labels:";
      for (long long label : labels)
      {
        out << ' ' << label;
      }
      out << '\n' << std::setprecision(10);
      for (const auto& row : matrix)
      {
        for (std::size_t c = 0; c < row.size(); ++c)
        {
          out << (c ? "," : "") << row[c];
        }
        out << '\n';
      }
      out.close();
      return static_cast<bool>(out);
    });
}

/// The geodesic distance between every two regions: a field per region.
std::vector<std::vector<double>> RegionDistances(
  const ConnectivityArguments& args, vtkRiemannMetric* metric, const Atlas& atlas)
{
  double bounds[6];
  int dims[3];
  DistanceGridOf(atlas.Image, bounds, dims);
  vtkNew<vtkRiemannDistanceField> field;
  vtkNew<ErrorCollector> errors;
  errors->Observe(field);
  field->SetMetric(metric);
  field->SetBounds(bounds);
  field->SetDimensions(dims);
  field->SetSeedRadius(args.SeedRadius);
  const std::size_t n = atlas.Labels.size();
  std::map<long long, std::size_t> row;
  for (std::size_t r = 0; r < n; ++r)
  {
    row[atlas.Labels[r]] = r;
  }
  // The label of each grid point, once (the grid is axis-aligned, the atlas may not be).
  std::vector<long long> gridLabels(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]);
  for (std::size_t p = 0; p < gridLabels.size(); ++p)
  {
    const std::size_t i = p % dims[0], j = (p / dims[0]) % dims[1], k = p / (dims[0] * dims[1]);
    const double x[3] = { bounds[0] + i * (bounds[1] - bounds[0]) / (dims[0] - 1),
      bounds[2] + j * (bounds[3] - bounds[2]) / (dims[1] - 1),
      bounds[4] + k * (bounds[5] - bounds[4]) / (dims[2] - 1) };
    gridLabels[p] = LabelAt(atlas.Image, x);
  }
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<std::vector<double>> oneWay(n, std::vector<double>(n, infinity));
  for (std::size_t r = 0; r < n; ++r)
  {
    field->RemoveAllSeeds();
    for (vtkIdType voxel : atlas.Voxels.at(atlas.Labels[r]))
    {
      field->AddSeed(atlas.Image->GetPoint(voxel));
    }
    vtkNew<ProgressBar> progress;
    progress->Observe(field,
      "riemann connectivity: region " + std::to_string(atlas.Labels[r]) + " (" +
        std::to_string(r + 1) + " of " + std::to_string(n) + ")",
      ProgressBar::StderrIsTerminal());
    field->Update();
    progress->Finish();
    errors->ThrowIfAny("the distance field of region " + std::to_string(atlas.Labels[r]) + " failed:");
    vtkDataArray* distance =
      vtkImageData::SafeDownCast(field->GetOutput())->GetPointData()->GetArray("Distance");
    for (std::size_t p = 0; p < gridLabels.size(); ++p)
    {
      const double d = distance->GetTuple1(static_cast<vtkIdType>(p));
      if (gridLabels[p] != 0 && std::isfinite(d))
      {
        double& entry = oneWay[r][row.at(gridLabels[p])];
        entry = std::min(entry, d);
      }
    }
    oneWay[r][r] = 0.0;
    if (InterruptHandling::Interrupted())
    {
      throw Interrupted();
    }
  }
  // d(A, B) and d(B, A) are the same number up to the grid's error: their mean.
  std::vector<std::vector<double>> distances(n, std::vector<double>(n, 0.0));
  for (std::size_t a = 0; a < n; ++a)
  {
    for (std::size_t b = 0; b < n; ++b)
    {
      const double ab = oneWay[a][b], ba = oneWay[b][a];
      distances[a][b] = std::isfinite(ab) && std::isfinite(ba) ? 0.5 * (ab + ba) : std::min(ab, ba);
    }
  }
  return distances;
}

/// Tracts seeded in every labelled voxel, counted by the regions of their two ends.
std::vector<std::vector<long long>> TractCounts(
  const ConnectivityArguments& args, vtkRiemannMetric* metric, const Atlas& atlas, long long& counted)
{
  vtkNew<vtkImageData> mask;
  mask->DeepCopy(atlas.Image);
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  vtkNew<ErrorCollector> errors;
  errors->Observe(tracer);
  tracer->SetMetric(metric);
  tracer->SetInputData(mask);
  riemann::settings::ApplySettings(tracer, args.Tracer->Given());
  tracer->SetIntegrationDirectionToBoth();
  ApplyIntegrationOptions(*args.Integration, tracer->GetIntegrationSettings());
  ApplyTractOptions(args.Tracts, tracer);
  vtkNew<ProgressBar> progress;
  progress->Observe(tracer, "riemann connectivity: tracts", ProgressBar::StderrIsTerminal());
  tracer->Update();
  progress->Finish();
  errors->ThrowIfAny("tracing failed:");
  const std::size_t n = atlas.Labels.size();
  std::map<long long, std::size_t> row;
  for (std::size_t r = 0; r < n; ++r)
  {
    row[atlas.Labels[r]] = r;
  }
  std::vector<std::vector<long long>> counts(n, std::vector<long long>(n, 0));
  counted = 0;
  for (const Tract& tract : JoinTracesIntoTracts(tracer->GetOutput()))
  {
    const long long a = LabelAt(atlas.Image, tract.front().data());
    const long long b = LabelAt(atlas.Image, tract.back().data());
    if (a != 0 && b != 0 && a != b)
    {
      counts[row.at(a)][row.at(b)]++;
      counts[row.at(b)][row.at(a)]++;
      ++counted;
    }
  }
  return counts;
}

void RunConnectivity(const ConnectivityArguments& args)
{
  std::vector<NamedPath> inputs = { { "-m", args.Metric }, { "--labels", args.Labels } };
  for (const auto& input : TractInputFiles(args.Tracts))
  {
    inputs.push_back(input);
  }
  CheckFilePaths(inputs, { { "-o", args.Output }, { "--tract-counts", args.TractCounts } });
  for (const std::string& path : { args.Output, args.TractCounts })
  {
    if (!path.empty() && Extension(path) != "csv")
    {
      throw Failure(path + ": a connectivity matrix is written as .csv", 2);
    }
  }
  if (IsDistributed())
  {
    throw Failure("connectivity runs in one process (each region's distance field uses every "
                  "core): run it without mpirun",
      2);
  }
  const Atlas atlas = ReadAtlas(args.Labels);
  vtkSmartPointer<vtkRiemannMetric> metric = LoadMetric(args.Metric);
  const auto distances = RegionDistances(args, metric, atlas);
  long long counted = 0;
  std::vector<std::vector<long long>> counts;
  if (!args.TractCounts.empty())
  {
    counts = TractCounts(args, metric, atlas, counted);
  }
  WriteMatrix(args.Output, atlas.Labels, distances, "geodesic distance between regions");
  if (!args.TractCounts.empty())
  {
    WriteMatrix(args.TractCounts, atlas.Labels, counts, "tracts joining regions");
  }
  std::cerr << "riemann connectivity: " << atlas.Labels.size() << " regions -> " << args.Output;
  if (!args.TractCounts.empty())
  {
    std::cerr << "; " << counted << " tract(s) join two regions -> " << args.TractCounts;
  }
  std::cerr << "\n";
}
} // namespace

void RegisterConnectivityCommand(CLI::App& app)
{
  auto args = std::make_shared<ConnectivityArguments>();
  CLI::App* command = app.add_subcommand("connectivity",
    "How strongly the regions of a label image are connected: the geodesic distance between "
    "every two regions, and optionally the tracts that join them.");
  command->add_option("--metric,-m", args->Metric, "Metric definition (JSON file)")
    ->required()
    ->check(CLI::ExistingFile);
  command
    ->add_option("--labels", args->Labels,
      "Label image (an atlas: .nii, .nii.gz, .nrrd, .nhdr, .vti, .vtk, placed by its own "
      "affine): each whole number other than 0 is a region")
    ->required()
    ->check(CLI::ExistingFile);
  command
    ->add_option("--seed-radius", args->SeedRadius,
      "Points within this many grid spacings of a region's voxel take the local distance "
      "(default 2.5)")
    ->check(FiniteNumber(1.0, 20.0));
  command->add_option("--tract-counts", args->TractCounts,
    "Also trace tracts from every labelled voxel (e1, both ways, with the stop options) and "
    "write how many join each two regions (by the voxels of their two ends) to this .csv");
  // --tract-counts seeds every labelled voxel along e1, both ways: the tracer's
  // own seed, fan, way and Jacobi fields are not this command's.
  args->Tracer = std::make_unique<DeclaredOptions>(command,
    riemann::declared::vtkRiemannGeodesicTracer::Settings,
    "StartPosition,StartDirection,NumberOfDirections,ConeAngle,IntegrationDirection,SeedDirection,"
    "ComputeTransverseJacobian");
  args->Integration =
    AddIntegrationOptions(command, vtkNew<vtkRiemannGeodesicTracer>()->GetIntegrationSettings());
  AddTractOptions(command, args->Tracts);
  command
    ->add_option("--output,-o", args->Output,
      "The distance matrix (.csv: a \"# ... labels: ...\" line, then one row per region in "
      "ascending label order)")
    ->required();
  command->callback([args]() { RunConnectivity(*args); });
}
} // namespace cli
} // namespace riemann
