#include "vtkRiemannMetric.h"

#include "MetricDefinition.h"
#include "RiemannTensorImage.h"
#include "SampledTensorSamples.h"
#include "vtkObjectFactory.h"

#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <sstream>
#include <stdexcept>

vtkStandardNewMacro(vtkRiemannMetric);

namespace
{
/// The core reads "sampled" definitions' files through VTK's readers: this
/// library installs the reader when it loads.
const bool SampledTensorReaderInstalled = []()
{
  riemann::SetSampledTensorReader(&riemann::ReadTensorGridFile);
  return true;
}();

/// Copy a 3x3 matrix into a row-major double[9] (the wrapped API's layout).
void CopyRowMajor(const riemann::Mat3& m, double* out)
{
  Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> rowMajor(out);
  rowMajor = m;
}
}

vtkRiemannMetric::vtkRiemannMetric() = default;
vtkRiemannMetric::~vtkRiemannMetric() = default;

bool vtkRiemannMetric::SetDefinition(const char* json)
{
  return this->SetDefinitionIn(json, std::string());
}

bool vtkRiemannMetric::SetDefinition(const char* json, const char* dataDirectory)
{
  return this->SetDefinitionIn(json, dataDirectory ? dataDirectory : "");
}

bool vtkRiemannMetric::SetDefinitionIn(const char* json, const std::string& baseDirectory)
{
  if (!json)
  {
    this->LastError = "no definition given (null)";
    this->LastErrorPlace = riemann::JsonErrorPlace();
    return false;
  }
  std::shared_ptr<const riemann::Metric> metric;
  try
  {
    metric = riemann::ParseMetricDefinition(json, this->Time, baseDirectory);
  }
  catch (const riemann::MetricDefinitionError& e)
  {
    this->LastError = e.what();
    this->LastErrorPlace = e.Place;
    return false;
  }
  // Atomic: a filter running on another thread may be copying the pointer.
  std::atomic_store(&this->Metric, metric);
  this->Definition = json;
  this->BaseDirectory = baseDirectory;
  this->FromTensorData = false;
  this->LastError.clear();
  this->LastErrorPlace = riemann::JsonErrorPlace();
  this->Modified();
  return true;
}

bool vtkRiemannMetric::SetTensorData(vtkImageData* image, const char* arrayName, bool inverse,
  double scale, bool repair, const char* outside, const char* christoffel)
{
  std::shared_ptr<const riemann::Metric> metric;
  const std::string outsideName = outside ? outside : "euclidean";
  const std::string reading = christoffel ? christoffel : "voxels";
  try
  {
    if (outsideName != "euclidean" && outsideName != "stop")
    {
      throw std::invalid_argument(
        "outside: expected \"euclidean\" or \"stop\", got \"" + outsideName + "\"");
    }
    if (reading != "voxels" && reading != "spline")
    {
      throw std::invalid_argument(
        "christoffel: expected \"voxels\" or \"spline\", got \"" + reading + "\"");
    }
    riemann::SampledTensorOptions options;
    options.Kind = inverse ? riemann::TensorMetricKind::Inverse : riemann::TensorMetricKind::Tensor;
    options.Scale = scale;
    options.Repair = repair;
    options.StopOutside = outsideName == "stop";
    options.ChristoffelAtVoxels = reading == "voxels";
    metric = riemann::MakeSampledTensorMetric(
      riemann::TensorGridFromImage(image, arrayName ? arrayName : ""), options);
    const std::string invalid = metric->Validate();
    if (!invalid.empty())
    {
      throw std::runtime_error(invalid);
    }
  }
  catch (const std::exception& e)
  {
    this->LastError = std::string("tensor data: ") + e.what();
    this->LastErrorPlace = riemann::JsonErrorPlace();
    return false;
  }
  std::atomic_store(&this->Metric, metric);
  std::ostringstream definition;
  definition << "{\"type\": \"sampled\", \"file\": \"(in memory)\", \"array\": \""
             << (arrayName ? arrayName : "") << "\", \"inverse\": " << (inverse ? "true" : "false")
             << ", \"scale\": " << scale << ", \"repair\": \"" << (repair ? "clamp" : "none")
             << "\", \"outside\": \"" << outsideName << "\", \"christoffel\": \"" << reading
             << "\"}";
  this->Definition = definition.str();
  this->BaseDirectory.clear();
  this->FromTensorData = true;
  this->LastError.clear();
  this->LastErrorPlace = riemann::JsonErrorPlace();
  this->Modified();
  return true;
}

bool vtkRiemannMetric::SetParsedDefinition(const std::string& json,
  std::shared_ptr<const riemann::Metric> metricAtTimeZero, const std::string& baseDirectory)
{
  if (!metricAtTimeZero || this->Time != 0.0)
  {
    return this->SetDefinitionIn(json.c_str(), baseDirectory);
  }
  std::atomic_store(&this->Metric, metricAtTimeZero);
  this->Definition = json;
  this->BaseDirectory = baseDirectory;
  this->FromTensorData = false;
  this->LastError.clear();
  this->LastErrorPlace = riemann::JsonErrorPlace();
  this->Modified();
  return true;
}

void vtkRiemannMetric::ShallowCopy(vtkRiemannMetric* other)
{
  if (!other || other == this)
  {
    return;
  }
  std::atomic_store(&this->Metric, other->GetMetric());
  this->Definition = other->Definition;
  this->BaseDirectory = other->BaseDirectory;
  this->FromTensorData = other->FromTensorData;
  this->Time = other->Time;
  this->LastError.clear();
  this->LastErrorPlace = riemann::JsonErrorPlace();
  this->Modified();
}

bool vtkRiemannMetric::SetTime(double t)
{
  if (t == this->Time)
  {
    return true;
  }
  const double previous = this->Time;
  this->Time = t;
  if (this->Definition.empty() || this->FromTensorData)
  {
    this->Modified();
    return true;
  }
  const std::string definition = this->Definition;
  const std::string directory = this->BaseDirectory;
  if (!this->SetDefinitionIn(definition.c_str(), directory))
  {
    this->Time = previous;
    this->LastError = "at t = " + std::to_string(t) + ": " + this->LastError;
    return false;
  }
  return true;
}

bool vtkRiemannMetric::SetDefinitionFile(const char* path)
{
  if (!path)
  {
    this->LastError = "no file name given (null)";
    this->LastErrorPlace = riemann::JsonErrorPlace();
    return false;
  }
  std::string text;
  try
  {
    text = riemann::ReadMetricDefinitionFile(path);
  }
  catch (const riemann::MetricDefinitionError& e)
  {
    this->LastError = e.what();
    this->LastErrorPlace = e.Place;
    return false;
  }
  if (!this->SetDefinitionIn(text.c_str(), vtksys::SystemTools::GetFilenamePath(path)))
  {
    this->LastError = std::string(path) + ": " + this->LastError;
    return false;
  }
  return true;
}

int vtkRiemannMetric::GetLastErrorLine() const
{
  return this->LastErrorPlace.Text.Known ? this->LastErrorPlace.Text.Line : 0;
}

int vtkRiemannMetric::GetLastErrorColumn() const
{
  return this->LastErrorPlace.Text.Known ? this->LastErrorPlace.Text.Column : 0;
}

int vtkRiemannMetric::GetLastErrorOffset() const
{
  return this->LastErrorPlace.Text.Known ? this->LastErrorPlace.Text.Offset : -1;
}

std::shared_ptr<const riemann::Metric> vtkRiemannMetric::GetMetric() const
{
  return std::atomic_load(&this->Metric);
}

bool vtkRiemannMetric::HasDefinition() const
{
  return this->GetMetric() != nullptr;
}

std::string vtkRiemannMetric::GetFamilyName() const
{
  const auto metric = this->GetMetric();
  return metric ? metric->FamilyName() : std::string();
}

std::string vtkRiemannMetric::GetDescription() const
{
  const auto metric = this->GetMetric();
  return metric ? metric->Describe() : std::string();
}

bool vtkRiemannMetric::EvaluateMetricTensor(const double p[3], double g[9])
{
  riemann::Mat3 m;
  const auto metric = this->GetMetric();
  if (!metric || !metric->Tensor(riemann::Vec3(p[0], p[1], p[2]), m))
  {
    return false;
  }
  CopyRowMajor(m, g);
  return true;
}

bool vtkRiemannMetric::EvaluateInverseMetricTensor(const double p[3], double inverse[9])
{
  riemann::Mat3 m;
  const auto metric = this->GetMetric();
  if (!metric || !metric->InverseTensor(riemann::Vec3(p[0], p[1], p[2]), m))
  {
    return false;
  }
  CopyRowMajor(m, inverse);
  return true;
}

bool vtkRiemannMetric::EvaluateChristoffelSymbols(const double p[3], double gamma[27])
{
  riemann::Mat3Stack symbols;
  const auto metric = this->GetMetric();
  if (!metric || !metric->Christoffel(riemann::Vec3(p[0], p[1], p[2]), symbols))
  {
    return false;
  }
  for (int m = 0; m < 3; ++m)
  {
    CopyRowMajor(symbols[m], gamma + 9 * m);
  }
  return true;
}

double vtkRiemannMetric::EvaluateVolumeForm(const double p[3])
{
  const auto metric = this->GetMetric();
  return metric ? metric->VolumeForm(riemann::Vec3(p[0], p[1], p[2])) : std::nan("");
}

void vtkRiemannMetric::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Definition: " << (this->Definition.empty() ? "(none)" : this->Definition)
     << "\n";
  os << indent << "Family: " << this->GetFamilyName() << "\n";
  os << indent << "Time: " << this->Time << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
}
