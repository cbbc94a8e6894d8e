// riemann fields: curvature, volume form and metric tensor of a metric on a
// regular grid, written as .vti (VTK XML image) or .csv (x,y,z, then one
// column per point-data component, one row per grid point).
#include "CliUtilities.h"
#include "Commands.h"
#include "CsvWriter.h"
#include "DeclaredOptions.h"
#include "Distributed.h"
#include "GridOptions.h"
#include "vtkRiemannCurvatureFieldSettingAccess.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRiemannCurvatureField.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannMetricTensorField.h"
#include "vtkRiemannVolumeForm.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLImageDataWriter.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

namespace riemann
{
namespace cli
{
namespace
{
struct FieldsArguments
{
  std::string Metric;
  /// The grid (vtkRiemannFieldAlgorithm.settings.json, as the three field filters take it).
  std::unique_ptr<DeclaredOptions> Grid;
  std::string Compress = "lz4";
  bool Gather = false;
  std::string Output;
};

bool WriteCsv(vtkImageData* image, const std::string& path)
{
  std::ofstream out(path);
  if (!out)
  {
    return false;
  }
  vtkPointData* pd = image->GetPointData();
  std::vector<vtkDataArray*> arrays;
  out << "x,y,z";
  for (int k = 0; k < pd->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* array = pd->GetArray(k);
    if (!array || !array->GetName())
    {
      continue;
    }
    arrays.push_back(array);
    const int components = array->GetNumberOfComponents();
    for (int c = 0; c < components; ++c)
    {
      out << ',' << array->GetName();
      if (components > 1)
      {
        out << '_' << c;
      }
    }
  }
  out << '\n';
  CsvWriter csv(out);
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    csv.Add(x[0]).Add(x[1]).Add(x[2]);
    for (vtkDataArray* array : arrays)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        csv.Add(array->GetComponent(i, c));
      }
    }
    csv.EndRow();
  }
  return csv.Finish();
}

void RunFields(const FieldsArguments& args)
{
  CheckFilePaths({ { "-m", args.Metric } }, { { "-o", args.Output } });
  const std::string extension = Extension(args.Output);
  if (extension != "vti" && extension != "csv" && extension != "pvti")
  {
    throw Failure("-o " + args.Output + ": the output must end in .vti, .pvti or .csv", 2);
  }
  const OutputLayout layout = ChooseOutputLayout("-o", args.Output, args.Gather, "pvti");
  // Checked while parsing (the declared ranges and LimitGridPoints).
  double bounds[6];
  int dims[3];
  GridOf(*args.Grid, bounds, dims);
  if (layout == OutputLayout::Gathered &&
    static_cast<double>(dims[0]) * dims[1] * dims[2] > MaximumPointsPerProcess)
  {
    throw Failure(
      "--gather: " + std::to_string(static_cast<long long>(dims[0]) * dims[1] * dims[2]) +
        " grid points are more than rank 0 holds (" + std::to_string(MaximumPointsPerProcess) +
        "): write .pvti pieces",
      2);
  }
  vtkSmartPointer<vtkRiemannMetric> metric = LoadMetric(args.Metric);

  // One grid, three filters in a chain: each adds its arrays to a shallow copy.
  vtkNew<ErrorCollector> errors;
  vtkNew<vtkRiemannCurvatureField> curvature;
  curvature->SetMetric(metric);
  curvature->SetBounds(bounds);
  curvature->SetDimensions(dims);
  vtkNew<vtkRiemannVolumeForm> volume;
  volume->SetMetric(metric);
  volume->SetInputConnection(curvature->GetOutputPort());
  vtkNew<vtkRiemannMetricTensorField> tensor;
  tensor->SetMetric(metric);
  tensor->SetInputConnection(volume->GetOutputPort());
  errors->Observe(curvature);
  errors->Observe(volume);
  errors->Observe(tensor);
  // This rank's extent of the grid (all of it in a single process).
  UpdateThisRanksPiece(tensor);
  errors->ThrowIfAny("computing the fields failed:");
  vtkImageData* image = vtkImageData::SafeDownCast(tensor->GetOutput());
  AgreeToGoOn();

  // The job's figures: the pieces' trapezoid sums add up to the whole grid's
  // (neighbouring extents share a plane of points, each with half weight).
  const bool empty = !image || image->GetNumberOfPoints() == 0;
  const std::vector<long long> counts = SumOverRanks(
    { empty ? 0 : image->GetNumberOfPoints(), empty ? 0 : volume->GetNumberOfExcludedPoints() });
  const double volumeIntegral = SumOverRanks(empty ? 0.0 : volume->GetVolumeIntegral());
  if (counts[0] == 0)
  {
    throw Failure("no fields were computed");
  }

  if (layout == OutputLayout::Pieces)
  {
    WritePieces(tensor, 0, args.Output, args.Compress);
  }
  else
  {
    int wholeExtent[6];
    tensor->GetOutputInformation(0)->Get(
      vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent);
    vtkSmartPointer<vtkImageData> whole = layout == OutputLayout::Gathered
      ? GatherImage(image, wholeExtent)
      : vtkSmartPointer<vtkImageData>(image);
    if (Rank() == 0)
    {
      if (layout == OutputLayout::Gathered)
      {
        vtkNew<vtkDoubleArray> integral;
        integral->SetName("VolumeIntegral");
        integral->InsertNextValue(volumeIntegral);
        whole->GetFieldData()->AddArray(integral);
      }
      WriteAtomically(args.Output,
        [&](const std::string& temporary)
        {
          if (extension == "csv")
          {
            return WriteCsv(whole, temporary);
          }
          vtkNew<vtkXMLImageDataWriter> writer;
          writer->SetFileName(temporary.c_str());
          writer->SetInputData(whole);
          writer->SetDataModeToAppended();
          SetCompressor(writer, args.Compress);
          return writer->Write() == 1 && writer->GetErrorCode() == 0;
        });
    }
  }
  if (Rank() != 0)
  {
    return;
  }
  std::cerr << "riemann fields: " << dims[0] << "x" << dims[1] << "x" << dims[2] << " points -> "
            << args.Output << " (VolumeIntegral " << std::setprecision(10) << volumeIntegral
            << ", trapezoid rule";
  if (counts[1] > 0)
  {
    std::cerr << ", " << counts[1] << " degenerate points left out";
  }
  if (IsDistributed())
  {
    std::cerr << "; " << NumberOfRanks() << " ranks"
              << (layout == OutputLayout::Pieces ? ", one piece file each" : ", gathered");
  }
  std::cerr << ")\n";
}
} // namespace

void RegisterFieldsCommand(CLI::App& app)
{
  auto args = std::make_shared<FieldsArguments>();
  CLI::App* command = app.add_subcommand(
    "fields", "Sample curvature, volume form and metric tensor of a metric on a grid.");
  command->add_option("--metric,-m", args->Metric, "Metric definition (JSON file)")
    ->required()
    ->check(CLI::ExistingFile);
  args->Grid = std::make_unique<DeclaredOptions>(
    command, riemann::declared::vtkRiemannCurvatureField::Settings);
  LimitGridPoints(*args->Grid);
  AddCompressOption(command, args->Compress);
  AddGatherOption(command, args->Gather);
  command
    ->add_option(
      "--output,-o", args->Output, std::string("Output file: .vti, .csv, or .pvti ") + PiecesHelp)
    ->required();
  command->callback([args]() { RunFields(*args); });
}
} // namespace cli
} // namespace riemann
