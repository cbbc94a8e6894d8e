// riemann fields: curvature, volume form and metric tensor of a metric on a
// regular grid, written as .vti (VTK XML image) or .csv (x,y,z, then one
// column per point-data component, one row per grid point).
#include "CliUtilities.h"
#include "Commands.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRiemannCurvatureField.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannMetricTensorField.h"
#include "vtkRiemannVolumeForm.h"
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
  std::string Bounds = "-2,2,-2,2,-2,2";
  std::string Dimensions = "33,33,33";
  std::string Output;
};

constexpr long long MaximumPerAxis = 512;
constexpr long long MaximumPoints = 20000000;

/// "a,b,..." -> exactly `count` finite numbers; throws Failure (status 2) naming `option`.
std::vector<double> ParseNumbers(
  const std::string& text, const std::string& option, size_t count, const std::string& form)
{
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    const bool empty = item.find_first_not_of(" \t") == std::string::npos;
    if (empty || *end != '\0')
    {
      throw Failure(option + ": \"" + item + "\" is not a number (expected " + form + ")", 2);
    }
    if (!std::isfinite(value))
    {
      throw Failure(option + ": \"" + item + "\" is not finite (expected " + form + ")", 2);
    }
    values.push_back(value);
  }
  if (values.size() != count || (!text.empty() && text.back() == ','))
  {
    throw Failure(option + ": expected " + std::to_string(count) + " comma-separated numbers " +
        form + ", got \"" + text + "\"",
      2);
  }
  return values;
}

void ParseBounds(const std::string& text, double bounds[6])
{
  const std::vector<double> b = ParseNumbers(text, "--bounds", 6, "X0,X1,Y0,Y1,Z0,Z1");
  const char* axes = "xyz";
  for (int a = 0; a < 3; ++a)
  {
    if (!(b[2 * a] < b[2 * a + 1]))
    {
      std::ostringstream message;
      message << "--bounds: the " << axes[a] << " range needs " << axes[a] << "0 < " << axes[a]
              << "1, got " << b[2 * a] << " >= " << b[2 * a + 1];
      throw Failure(message.str(), 2);
    }
    bounds[2 * a] = b[2 * a];
    bounds[2 * a + 1] = b[2 * a + 1];
  }
}

void ParseDimensions(const std::string& text, int dims[3])
{
  const std::vector<double> d = ParseNumbers(text, "--dims", 3, "NX,NY,NZ");
  double total = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    if (d[a] != std::floor(d[a]))
    {
      throw Failure("--dims: \"" + text + "\": point counts must be whole numbers", 2);
    }
    if (d[a] < 1 || d[a] > MaximumPerAxis)
    {
      std::ostringstream message;
      message << "--dims: " << d[a] << " points on an axis; each must be between 1 and "
              << MaximumPerAxis;
      throw Failure(message.str(), 2);
    }
    dims[a] = static_cast<int>(d[a]);
    total *= d[a];
  }
  if (total > MaximumPoints)
  {
    std::ostringstream message;
    message << "--dims: " << static_cast<long long>(total) << " grid points; at most "
            << MaximumPoints;
    throw Failure(message.str(), 2);
  }
}

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
  out << '\n' << std::setprecision(17);
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    out << x[0] << ',' << x[1] << ',' << x[2];
    for (vtkDataArray* array : arrays)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        out << ',' << array->GetComponent(i, c);
      }
    }
    out << '\n';
  }
  out.flush();
  return static_cast<bool>(out);
}

void RunFields(const FieldsArguments& args)
{
  const std::string extension = Extension(args.Output);
  if (extension != "vti" && extension != "csv")
  {
    throw Failure("-o " + args.Output + ": the output must end in .vti or .csv", 2);
  }
  double bounds[6];
  int dims[3];
  ParseBounds(args.Bounds, bounds);
  ParseDimensions(args.Dimensions, dims);
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
  tensor->Update();
  errors->ThrowIfAny("computing the fields failed:");
  vtkImageData* image = vtkImageData::SafeDownCast(tensor->GetOutput());
  if (!image || image->GetNumberOfPoints() == 0)
  {
    throw Failure("no fields were computed");
  }

  WriteAtomically(args.Output,
    [&](const std::string& temporary)
    {
      if (extension == "csv")
      {
        return WriteCsv(image, temporary);
      }
      vtkNew<vtkXMLImageDataWriter> writer;
      writer->SetFileName(temporary.c_str());
      writer->SetInputData(image);
      writer->SetDataModeToAppended();
      return writer->Write() == 1 && writer->GetErrorCode() == 0;
    });

  std::cerr << "riemann fields: " << dims[0] << "x" << dims[1] << "x" << dims[2] << " points -> "
            << args.Output << " (VolumeIntegral " << std::setprecision(10)
            << volume->GetVolumeIntegral() << ", trapezoid rule";
  if (volume->GetNumberOfExcludedPoints() > 0)
  {
    std::cerr << ", " << volume->GetNumberOfExcludedPoints() << " degenerate points left out";
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
  command->add_option(
    "--bounds", args->Bounds, "Grid box X0,X1,Y0,Y1,Z0,Z1 (default -2,2,-2,2,-2,2)");
  command->add_option("--dims", args->Dimensions,
    "Grid points per axis NX,NY,NZ (default 33,33,33; at most 512 each, 2e7 in all)");
  command->add_option("--output,-o", args->Output, "Output file: .vti or .csv")->required();
  command->callback([args]() { RunFields(*args); });
}
} // namespace cli
} // namespace riemann
