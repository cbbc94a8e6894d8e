#include "vtkRiemannMetric.h"

#include "MetricDefinition.h"
#include "vtkObjectFactory.h"

#include <cmath>
#include <fstream>
#include <sstream>

vtkStandardNewMacro(vtkRiemannMetric);

namespace
{
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
  if (!json)
  {
    this->LastError = "no definition given (null)";
    return false;
  }
  try
  {
    this->Metric = riemann::ParseMetricDefinition(json);
  }
  catch (const riemann::MetricDefinitionError& e)
  {
    this->LastError = e.what();
    return false;
  }
  this->Definition = json;
  this->LastError.clear();
  this->Modified();
  return true;
}

bool vtkRiemannMetric::SetDefinitionFile(const char* path)
{
  if (!path)
  {
    this->LastError = "no file name given (null)";
    return false;
  }
  std::ifstream file(path, std::ios::binary);
  if (!file)
  {
    this->LastError = std::string(path) + ": cannot open the metric file";
    return false;
  }
  std::ostringstream text;
  text << file.rdbuf();
  if (!this->SetDefinition(text.str().c_str()))
  {
    this->LastError = std::string(path) + ": " + this->LastError;
    return false;
  }
  return true;
}

std::string vtkRiemannMetric::GetFamilyName() const
{
  return this->Metric ? this->Metric->FamilyName() : std::string();
}

std::string vtkRiemannMetric::GetDescription() const
{
  return this->Metric ? this->Metric->Describe() : std::string();
}

bool vtkRiemannMetric::EvaluateMetricTensor(const double p[3], double g[9])
{
  riemann::Mat3 m;
  if (!this->Metric || !this->Metric->Tensor(riemann::Vec3(p[0], p[1], p[2]), m))
  {
    return false;
  }
  CopyRowMajor(m, g);
  return true;
}

bool vtkRiemannMetric::EvaluateInverseMetricTensor(const double p[3], double inverse[9])
{
  riemann::Mat3 m;
  if (!this->Metric || !this->Metric->InverseTensor(riemann::Vec3(p[0], p[1], p[2]), m))
  {
    return false;
  }
  CopyRowMajor(m, inverse);
  return true;
}

bool vtkRiemannMetric::EvaluateChristoffelSymbols(const double p[3], double gamma[27])
{
  riemann::Mat3Stack symbols;
  if (!this->Metric || !this->Metric->Christoffel(riemann::Vec3(p[0], p[1], p[2]), symbols))
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
  return this->Metric ? this->Metric->VolumeForm(riemann::Vec3(p[0], p[1], p[2])) : std::nan("");
}

void vtkRiemannMetric::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Definition: " << (this->Definition.empty() ? "(none)" : this->Definition) << "\n";
  os << indent << "Family: " << this->GetFamilyName() << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
}
