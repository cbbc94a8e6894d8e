#include "MetricDefinition.h"

#include "SampledTensorSamples.h"

#include "BumpTranslationMap.h"
#include "ConformalMetric.h"
#include "DiffeoMetric.h"
#include "EuclideanMetric.h"
#include "Expression.h"
#include "ExpressionFields.h"
#include "GaussianField.h"
#include "GraphMetric.h"
#include "InputFiles.h"
#include "MapComposition.h"
#include "QuadraticField.h"
#include "ScalarFieldSum.h"
#include "TensorMetric.h"
#include "TwistMap.h"

#include "JsonValidation.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

namespace riemann
{
namespace
{
using json::Describe;
using json::Json;

[[noreturn]] void Fail(const std::string& path, const std::string& message)
{
  json::Fail<MetricDefinitionError>(path, message);
}

/// An expression's error at `path`, its column kept as data.
[[noreturn]] void FailInExpression(const std::string& path, const ExpressionError& error)
{
  JsonErrorPlace place;
  place.Path = path;
  place.ExpressionColumn = error.Column;
  throw MetricDefinitionError(place, error.what());
}

void CheckKeys(
  const Json& object, const std::string& path, std::initializer_list<const char*> allowed)
{
  json::CheckKeys<MetricDefinitionError>(object, path, allowed);
}

const Json& Required(const Json& object, const char* key, const std::string& path)
{
  return json::Required<MetricDefinitionError>(object, key, path);
}

/// Guards against absurd inputs (a definition is typed by a person).
constexpr size_t MaximumTerms = 4096;
constexpr size_t MaximumCompositionDepth = 64;
constexpr std::uint64_t MaximumFileSize = 64 << 20;

/**
 * The time t in [0, 1] at which animated numbers are evaluated. A definition
 * is parsed at one time into an immutable metric (a frame of an animation);
 * thread_local keeps concurrent parses at different times apart without
 * threading a context through every helper of this file.
 */
thread_local double ParseTime = 0.0;

/**
 * Set when the definition holds a typed expression. Such metrics are not
 * refused for being degenerate somewhere (a Poincare ball is only defined
 * inside the ball): a geodesic or ray reaching a degenerate point stops
 * there with its own reason, and `riemann info` reports it at a point.
 */
thread_local bool ParseHasExpressions = false;

/// The folder relative data files are read from (ParseMetricDefinition's
/// `baseDirectory`), kept like ParseTime.
thread_local std::string ParseBaseDirectory;

/// The reader of "sampled" definitions (SetSampledTensorReader).
SampledTensorReader& InstalledSampledTensorReader()
{
  static SampledTensorReader reader;
  return reader;
}

double Number(const Json& value, const std::string& path);

/// {"from": a, "to": b}: a + t (b - a), for numbers and 3-vectors alike.
bool IsAnimated(const Json& value)
{
  return value.is_object() && value.contains("from") && value.contains("to") && value.size() == 2;
}

double Number(const Json& value, const std::string& path)
{
  if (IsAnimated(value))
  {
    const double from = Number(value.at("from"), path + ".from");
    const double to = Number(value.at("to"), path + ".to");
    return from + ParseTime * (to - from);
  }
  if (!value.is_number())
  {
    Fail(path, "expected a number (or {\"from\": a, \"to\": b}), got " + Describe(value));
  }
  const double number = value.get<double>();
  if (!std::isfinite(number))
  {
    Fail(path, "expected a finite number");
  }
  return number;
}

double NumberOr(const Json& object, const char* key, const std::string& path, double fallback)
{
  return object.contains(key) ? Number(object.at(key), path + "." + key) : fallback;
}

Vec3 Vector(const Json& value, const std::string& path)
{
  if (IsAnimated(value))
  {
    const Vec3 from = Vector(value.at("from"), path + ".from");
    const Vec3 to = Vector(value.at("to"), path + ".to");
    return from + ParseTime * (to - from);
  }
  if (!value.is_array() || value.size() != 3)
  {
    Fail(path, "expected an array of 3 numbers, got " + Describe(value));
  }
  return Vec3(
    Number(value[0], path + "[0]"), Number(value[1], path + "[1]"), Number(value[2], path + "[2]"));
}

Mat3 Matrix(const Json& value, const std::string& path)
{
  if (!value.is_array() || value.size() != 3)
  {
    Fail(path, "expected a 3x3 matrix (an array of 3 rows of 3 numbers), got " + Describe(value));
  }
  Mat3 m;
  for (int r = 0; r < 3; ++r)
  {
    m.row(r) = Vector(value[r], path + "[" + std::to_string(r) + "]").transpose();
  }
  return m;
}

std::shared_ptr<const ScalarField> Gaussian(const Json& object, const std::string& path)
{
  CheckKeys(object, path, { "amplitude", "center", "sigma" });
  const double amplitude = Number(Required(object, "amplitude", path), path + ".amplitude");
  const Vec3 center = Vector(Required(object, "center", path), path + ".center");
  const Json& sigmaValue = Required(object, "sigma", path);
  const Vec3 sigma = sigmaValue.is_number() ? Vec3::Constant(Number(sigmaValue, path + ".sigma"))
                                            : Vector(sigmaValue, path + ".sigma");
  if (!(sigma.minCoeff() > 0))
  {
    Fail(path + ".sigma", "every spread must be positive");
  }
  return std::make_shared<GaussianField>(amplitude, center, sigma);
}

std::shared_ptr<const ScalarField> Quadratic(const Json& object, const std::string& path)
{
  CheckKeys(object, path, { "matrix", "diagonal", "linear", "constant" });
  Mat3 matrix = Mat3::Zero();
  if (object.contains("matrix") && object.contains("diagonal"))
  {
    Fail(path, "give either \"matrix\" or \"diagonal\", not both");
  }
  if (object.contains("matrix"))
  {
    matrix = Matrix(object.at("matrix"), path + ".matrix");
  }
  else if (object.contains("diagonal"))
  {
    matrix = Vector(object.at("diagonal"), path + ".diagonal").asDiagonal();
  }
  const Vec3 linear =
    object.contains("linear") ? Vector(object.at("linear"), path + ".linear") : Vec3::Zero();
  return std::make_shared<QuadraticField>(matrix, linear, NumberOr(object, "constant", path, 0.0));
}

/**
 * The named parameters visible in `object`: those inherited from enclosing
 * objects, then its own "parameters" (numbers, possibly animated), which
 * override inherited ones of the same name.
 */
ExpressionInputs Parameters(const Json& object, const std::string& path, ExpressionInputs inputs)
{
  if (object.contains("f") || object.contains("n") || object.contains("phi") ||
    object.contains("g"))
  {
    ParseHasExpressions = true;
  }
  inputs.Time = ParseTime;
  if (!object.contains("parameters"))
  {
    return inputs;
  }
  const Json& parameters = object.at("parameters");
  if (!parameters.is_object())
  {
    Fail(path + ".parameters",
      "expected an object of named numbers, e.g. {\"a\": 0.3}, got " + Describe(parameters));
  }
  if (parameters.size() > MaximumTerms)
  {
    Fail(path + ".parameters", "too many parameters");
  }
  for (const auto& item : parameters.items())
  {
    const double value = Number(item.value(), path + ".parameters." + item.key());
    const auto at =
      std::find(inputs.ParameterNames.begin(), inputs.ParameterNames.end(), item.key());
    if (at != inputs.ParameterNames.end())
    {
      inputs.ParameterValues[at - inputs.ParameterNames.begin()] = value;
    }
    else
    {
      inputs.ParameterNames.push_back(item.key());
      inputs.ParameterValues.push_back(value);
    }
  }
  return inputs;
}

/// An expression string at `path` (a number is accepted as its text).
std::string ExpressionText(const Json& value, const std::string& path)
{
  if (value.is_number())
  {
    return value.dump();
  }
  if (!value.is_string())
  {
    Fail(path, "expected an expression (a string such as \"x^2 + y^2\"), got " + Describe(value));
  }
  return value.get<std::string>();
}

/// `count` expressions at `path` (an array of strings); each is checked on
/// its own first so that an error names its component.
std::vector<std::string> ExpressionList(
  const Json& value, const std::string& path, size_t count, const ExpressionInputs& inputs)
{
  if (!value.is_array() || value.size() != count)
  {
    Fail(path,
      "expected an array of " + std::to_string(count) + " expressions, got " + Describe(value));
  }
  std::vector<std::string> sources;
  for (size_t i = 0; i < count; ++i)
  {
    const std::string item = path + "[" + std::to_string(i) + "]";
    sources.push_back(ExpressionText(value[i], item));
    try
    {
      CompiledExpressions(std::vector<std::string>{ sources.back() }, inputs.ParameterNames, 0);
    }
    catch (const ExpressionError& e)
    {
      FailInExpression(item, e);
    }
  }
  return sources;
}

/// The sum of a family's scalar terms ("gaussians", "quadratic", "constant",
/// and the expression under `expressionKey`: "f" or "n").
std::shared_ptr<const ScalarField> ScalarTerms(const Json& object, const std::string& path,
  double defaultConstant, const char* what, const char* expressionKey,
  const ExpressionInputs& inputs)
{
  std::vector<std::shared_ptr<const ScalarField>> terms;
  if (object.contains(expressionKey))
  {
    const std::string expressionPath = path + "." + expressionKey;
    const std::string source = ExpressionText(object.at(expressionKey), expressionPath);
    try
    {
      terms.push_back(std::make_shared<ExpressionScalarField>(source, inputs));
    }
    catch (const ExpressionError& e)
    {
      FailInExpression(expressionPath, e);
    }
    // A typed expression is the whole field unless a constant is added explicitly.
    defaultConstant = 0.0;
  }
  if (object.contains("gaussians"))
  {
    const Json& list = object.at("gaussians");
    if (!list.is_array())
    {
      Fail(path + ".gaussians", "expected an array of Gaussian objects, got " + Describe(list));
    }
    if (list.size() > MaximumTerms)
    {
      Fail(path + ".gaussians",
        "too many terms (" + std::to_string(list.size()) + " > " + std::to_string(MaximumTerms) +
          ")");
    }
    for (size_t i = 0; i < list.size(); ++i)
    {
      terms.push_back(Gaussian(list[i], path + ".gaussians[" + std::to_string(i) + "]"));
    }
  }
  if (object.contains("quadratic"))
  {
    const Json& q = object.at("quadratic");
    if (q.is_array())
    {
      for (size_t i = 0; i < q.size() && i < MaximumTerms; ++i)
      {
        terms.push_back(Quadratic(q[i], path + ".quadratic[" + std::to_string(i) + "]"));
      }
    }
    else
    {
      terms.push_back(Quadratic(q, path + ".quadratic"));
    }
  }
  if (terms.empty() && !object.contains("constant"))
  {
    Fail(path,
      std::string("the ") + what + " needs at least one of \"" + expressionKey +
        "\", \"gaussians\", \"quadratic\" or \"constant\"");
  }
  return std::make_shared<ScalarFieldSum>(
    NumberOr(object, "constant", path, defaultConstant), std::move(terms));
}

std::shared_ptr<const SpaceMap> Diffeomorphism(
  const Json& object, const std::string& path, size_t depth, const ExpressionInputs& inherited)
{
  if (depth > MaximumCompositionDepth)
  {
    Fail(path, "compositions nested deeper than " + std::to_string(MaximumCompositionDepth));
  }
  if (!object.is_object())
  {
    Fail(path, "expected a diffeomorphism object, got " + Describe(object));
  }
  if (object.contains("type") && object.at("type") != "diffeo")
  {
    Fail(path + ".type", "a composition may only hold diffeomorphisms (\"type\": \"diffeo\")");
  }
  const ExpressionInputs inputs = Parameters(object, path, inherited);
  if (object.contains("compose"))
  {
    CheckKeys(object, path, { "type", "compose", "parameters" });
    const Json& list = object.at("compose");
    if (!list.is_array() || list.empty())
    {
      Fail(
        path + ".compose", "expected a non-empty array of diffeomorphisms, got " + Describe(list));
    }
    if (list.size() > MaximumTerms)
    {
      Fail(path + ".compose", "too many maps (" + std::to_string(list.size()) + ")");
    }
    std::vector<std::shared_ptr<const SpaceMap>> maps;
    for (size_t i = 0; i < list.size(); ++i)
    {
      maps.push_back(
        Diffeomorphism(list[i], path + ".compose[" + std::to_string(i) + "]", depth + 1, inputs));
    }
    return std::make_shared<MapComposition>(std::move(maps));
  }
  if (object.contains("phi"))
  {
    CheckKeys(object, path, { "type", "phi", "parameters" });
    const std::vector<std::string> sources =
      ExpressionList(object.at("phi"), path + ".phi", 3, inputs);
    try
    {
      return std::make_shared<ExpressionMap>(sources, inputs);
    }
    catch (const ExpressionError& e)
    {
      FailInExpression(path + ".phi", e);
    }
  }
  if (!object.contains("preset"))
  {
    Fail(path,
      "a diffeomorphism needs \"phi\" (three expressions), \"preset\" (twist, bump, "
      "identity) or \"compose\"");
  }
  const Json& preset = object.at("preset");
  if (preset == "twist")
  {
    CheckKeys(object, path, { "type", "preset", "rate" });
    return std::make_shared<TwistMap>(NumberOr(object, "rate", path, 1.0));
  }
  if (preset == "identity")
  {
    CheckKeys(object, path, { "type", "preset" });
    return std::make_shared<MapComposition>(std::vector<std::shared_ptr<const SpaceMap>>{});
  }
  if (preset == "bump")
  {
    CheckKeys(object, path, { "type", "preset", "gaussian", "direction", "field" });
    auto f = Gaussian(Required(object, "gaussian", path), path + ".gaussian");
    if (object.contains("direction") == object.contains("field"))
    {
      Fail(path,
        "a bump needs exactly one of \"direction\" (p + f(p) v) or \"field\" "
        "(p + f(p) (A (p - c) + b))");
    }
    if (object.contains("direction"))
    {
      return std::make_shared<BumpTranslationMap>(
        f, Vector(object.at("direction"), path + ".direction"));
    }
    const Json& field = object.at("field");
    const std::string fieldPath = path + ".field";
    CheckKeys(field, fieldPath, { "matrix", "center", "offset" });
    const Mat3 matrix = Matrix(Required(field, "matrix", fieldPath), fieldPath + ".matrix");
    const Vec3 center =
      field.contains("center") ? Vector(field.at("center"), fieldPath + ".center") : Vec3::Zero();
    const Vec3 offset =
      field.contains("offset") ? Vector(field.at("offset"), fieldPath + ".offset") : Vec3::Zero();
    return std::make_shared<BumpTranslationMap>(f, matrix, center, offset);
  }
  Fail(path + ".preset",
    "unknown preset " + (preset.is_string() ? preset.dump() : Describe(preset)) +
      "; expected \"twist\", \"bump\" or \"identity\"");
}

/**
 * g_ij as a 3x3 array of expressions. g must be symmetric: g_ji is compared
 * with g_ij at sample points (texts may differ, e.g. "x*y" and "y*x").
 */
std::shared_ptr<const TensorField> TensorExpressions(
  const Json& value, const std::string& path, const ExpressionInputs& inputs)
{
  if (!value.is_array() || value.size() != 3)
  {
    Fail(path, "expected a 3x3 array of expressions, got " + Describe(value));
  }
  std::vector<std::string> components;
  for (int r = 0; r < 3; ++r)
  {
    const std::vector<std::string> row =
      ExpressionList(value[r], path + "[" + std::to_string(r) + "]", 3, inputs);
    components.insert(components.end(), row.begin(), row.end());
  }
  const CompiledExpressions all(components, inputs.ParameterNames, 0);
  std::vector<double> values(9);
  for (const Vec3& p : { Vec3(0.3, -0.7, 0.45), Vec3(-1.3, 0.2, 0.9), Vec3(2.1, 1.7, -0.6) })
  {
    all.Evaluate(p.data(), inputs.Time, inputs.ParameterValues.data(), values.data());
    for (int i = 0; i < 3; ++i)
    {
      for (int j = i + 1; j < 3; ++j)
      {
        const double a = values[3 * i + j];
        const double b = values[3 * j + i];
        if (!(std::abs(a - b) <= 1e-12 * (1.0 + std::abs(a))) &&
          (std::isfinite(a) || std::isfinite(b)))
        {
          std::ostringstream s;
          s << "g must be symmetric: g[" << i << "][" << j << "] = \"" << components[3 * i + j]
            << "\" but g[" << j << "][" << i << "] = \"" << components[3 * j + i] << "\" (" << a
            << " and " << b << " at (" << p.transpose() << "))";
          Fail(path, s.str());
        }
      }
    }
  }
  try
  {
    return std::make_shared<ExpressionTensorField>(components, inputs);
  }
  catch (const ExpressionError& e)
  {
    FailInExpression(path, e);
  }
}

/// A string member, or `fallback` when absent.
std::string StringOr(
  const Json& object, const char* key, const std::string& path, const std::string& fallback)
{
  if (!object.contains(key))
  {
    return fallback;
  }
  const Json& value = object.at(key);
  if (!value.is_string())
  {
    Fail(path + "." + key, "expected a string, got " + Describe(value));
  }
  return value.get<std::string>();
}

/// A string member that must be one of `choices` (each a value and what it
/// means, for the error), or the first choice when absent.
std::string ChoiceOr(const Json& object, const char* key, const std::string& path,
  const std::vector<std::pair<std::string, std::string>>& choices)
{
  const std::string value = StringOr(object, key, path, choices.front().first);
  std::string expected;
  for (const auto& [choice, meaning] : choices)
  {
    if (value == choice)
    {
      return value;
    }
    expected += (expected.empty() ? "expected \"" : " or \"") + choice + "\" (" + meaning + ")";
  }
  Fail(path + "." + key, expected + ", got \"" + value + "\"");
}

/// {"type": "sampled", ...}: a tensor volume read by the installed reader.
std::shared_ptr<const Metric> SampledMetric(const Json& root, const std::string& path)
{
  CheckKeys(
    root, path, { "type", "file", "array", "inverse", "tensor_metric", "sharpening", "scale",
                  "repair", "outside", "frame", "christoffel", "components" });
  const Json& fileValue = Required(root, "file", path);
  if (!fileValue.is_string() || fileValue.get<std::string>().empty())
  {
    Fail(path + ".file", "expected the name of a tensor volume file, got " + Describe(fileValue));
  }
  SampledTensorOptions options;
  if (root.contains("inverse"))
  {
    if (!root.at("inverse").is_boolean())
    {
      Fail(path + ".inverse", "expected true or false, got " + Describe(root.at("inverse")));
    }
    options.Kind =
      root.at("inverse").get<bool>() ? TensorMetricKind::Inverse : TensorMetricKind::Tensor;
  }
  // "tensor_metric": which metric each tensor gives; "inverse": true is its
  // older spelling of "inverse", so the two must agree when both are given.
  if (root.contains("tensor_metric"))
  {
    const std::string kind = ChoiceOr(root, "tensor_metric", path,
      { { "tensor", "g = D" }, { "inverse", "g = D^-1" }, { "adjugate", "g = det(D) D^-1" },
        { "sharpened", "g = det(D)^((p-1)/3) D^-p, p the sharpening" } });
    for (TensorMetricKind k : { TensorMetricKind::Tensor, TensorMetricKind::Inverse,
           TensorMetricKind::Adjugate, TensorMetricKind::Sharpened })
    {
      if (kind == TensorMetricName(k))
      {
        if (root.contains("inverse") && root.at("inverse").get<bool>() != (k == TensorMetricKind::Inverse))
        {
          Fail(path + ".inverse", std::string("\"inverse\": ") +
              (root.at("inverse").get<bool>() ? "true" : "false") +
              " contradicts \"tensor_metric\": \"" + kind + "\" (give only \"tensor_metric\")");
        }
        options.Kind = k;
      }
    }
  }
  if (root.contains("sharpening"))
  {
    if (options.Kind != TensorMetricKind::Sharpened)
    {
      Fail(path + ".sharpening", "only a \"sharpened\" tensor_metric takes a sharpening");
    }
    options.Sharpening = NumberOr(root, "sharpening", path, 2.0);
    if (!(options.Sharpening >= 1.0 && options.Sharpening <= 16.0))
    {
      Fail(path + ".sharpening", "expected a number in [1, 16] (1: the inverse), got " +
          Describe(root.at("sharpening")));
    }
  }
  // "scale": a number, or "mean-diffusivity" (arc length in the voxels' units).
  if (root.contains("scale") && root.at("scale").is_string())
  {
    if (root.at("scale").get<std::string>() != "mean-diffusivity")
    {
      Fail(path + ".scale", "expected a positive number or \"mean-diffusivity\" (the metric "
                            "scaled so that arc length is length where the data is isotropic), "
                            "got " + Describe(root.at("scale")));
    }
    options.ScaleToMeanDiffusivity = true;
  }
  else
  {
    options.Scale = NumberOr(root, "scale", path, 1.0);
  }
  options.Repair = ChoiceOr(root, "repair", path,
                     { { "none", "samples that are not positive definite are an error" },
                       { "clamp", "their eigenvalues are raised to a floor" } }) == "clamp";
  const std::string problem = options.Check();
  if (!problem.empty())
  {
    Fail(path + ".scale", problem);
  }
  options.StopOutside = ChoiceOr(root, "outside", path,
                          { { "euclidean", "g = I outside the volume" },
                            { "stop", "geodesics and rays stop where they leave it" } }) == "stop";
  options.ChristoffelAtVoxels =
    ChoiceOr(root, "christoffel", path,
      { { "voxels", "g and its derivatives sampled at the voxels, trilinear: fast, the default" },
        { "spline", "the spline's own, exact" } }) == "voxels";
  const std::string frame = ChoiceOr(root, "frame", path,
    { { "world", "tensors in the axes the file places its voxels in" },
      { "fsl", "NIfTI tensors in FSL's voxel axes, as dtifit writes them" } });
  // Only when given: without it the file must say its order itself.
  SampledTensorComponents components = SampledTensorComponents::FromFile;
  if (root.contains("components"))
  {
    const std::string order = ChoiceOr(root, "components", path,
      { { "fsl", "XX XY XZ YY YZ ZZ, FSL's dtifit" },
        { "mrtrix", "XX YY ZZ XY XZ YZ, MRtrix's dwi2tensor and mrconvert" },
        { "dipy", "XX XY YY XZ YZ ZZ, DIPY's lower_triangular and NIfTI's symmetric-matrix order" } });
    components = order == "fsl"    ? SampledTensorComponents::Fsl
      : order == "mrtrix"          ? SampledTensorComponents::Mrtrix
                                   : SampledTensorComponents::Dipy;
  }
  const SampledTensorReader& reader = InstalledSampledTensorReader();
  if (!reader)
  {
    Fail(path,
      "sampled metrics are read through VTK (vtkRiemannMetric: the riemann tool, "
      "riemann-studio, Python); this program installed no reader");
  }
  std::string file = fileValue.get<std::string>();
  if (file.front() != '/' && !ParseBaseDirectory.empty())
  {
    file = ParseBaseDirectory + "/" + file;
  }
  SampledTensorGrid grid;
  try
  {
    grid = reader(file, StringOr(root, "array", path, ""),
      frame == "fsl" ? SampledTensorFrame::Fsl : SampledTensorFrame::World, components);
  }
  catch (const std::exception& e)
  {
    Fail(path + ".file", e.what());
  }
  try
  {
    return MakeSampledTensorMetric(std::move(grid), options);
  }
  catch (const std::invalid_argument& e)
  {
    Fail(path + ".file", file + ": " + e.what());
  }
}

std::shared_ptr<const Metric> Build(const Json& root)
{
  const std::string path = "metric";
  if (!root.is_object())
  {
    Fail(path, "expected a JSON object with a \"type\", got " + Describe(root));
  }
  const Json& typeValue = Required(root, "type", path);
  if (!typeValue.is_string())
  {
    Fail(path + ".type", "expected a string, got " + Describe(typeValue));
  }
  const std::string type = typeValue.get<std::string>();
  if (type == "euclidean")
  {
    CheckKeys(root, path, { "type" });
    return std::make_shared<EuclideanMetric>();
  }
  const ExpressionInputs inputs = Parameters(root, path, ExpressionInputs());
  if (type == "graph")
  {
    CheckKeys(root, path, { "type", "f", "gaussians", "quadratic", "constant", "parameters" });
    return std::make_shared<GraphMetric>(
      ScalarTerms(root, path, 0.0, "graph's function f", "f", inputs));
  }
  if (type == "conformal")
  {
    CheckKeys(root, path, { "type", "n", "gaussians", "quadratic", "constant", "parameters" });
    return std::make_shared<ConformalMetric>(
      ScalarTerms(root, path, 1.0, "refractive index n", "n", inputs));
  }
  if (type == "diffeo")
  {
    return std::make_shared<DiffeoMetric>(Diffeomorphism(root, path, 0, ExpressionInputs()));
  }
  if (type == "sampled")
  {
    return SampledMetric(root, path);
  }
  if (type == "tensor" && root.contains("g"))
  {
    CheckKeys(root, path, { "type", "g", "parameters" });
    return std::make_shared<TensorMetric>(TensorExpressions(root.at("g"), path + ".g", inputs));
  }
  if (type == "tensor")
  {
    CheckKeys(root, path, { "type", "matrix", "g", "parameters" });
    const Mat3 matrix = Matrix(Required(root, "matrix", path), path + ".matrix");
    if (!matrix.isApprox(matrix.transpose(), 1e-12))
    {
      Fail(path + ".matrix", "g must be symmetric");
    }
    return std::make_shared<TensorMetric>(std::make_shared<ConstantTensorField>(matrix));
  }
  Fail(path + ".type",
    "unknown metric type \"" + type +
      "\"; expected \"graph\", \"diffeo\", \"conformal\", \"tensor\", \"sampled\" or "
      "\"euclidean\"");
}
} // namespace

void SetSampledTensorReader(SampledTensorReader reader)
{
  InstalledSampledTensorReader() = std::move(reader);
}

std::shared_ptr<const Metric> ParseMetricDefinition(const std::string& json, double time)
{
  return ParseMetricDefinition(json, time, ParseBaseDirectory);
}

std::shared_ptr<const Metric> ParseMetricDefinition(
  const std::string& json, double time, const std::string& baseDirectory)
{
  struct DirectoryScope
  {
    std::string Saved;
    explicit DirectoryScope(const std::string& directory)
      : Saved(ParseBaseDirectory)
    {
      ParseBaseDirectory = directory;
    }
    ~DirectoryScope() { ParseBaseDirectory = this->Saved; }
  } directoryScope(baseDirectory);
  if (!std::isfinite(time))
  {
    throw MetricDefinitionError("the time t must be a finite number");
  }
  struct TimeScope
  {
    double Saved;
    bool SavedExpressions;
    explicit TimeScope(double t)
      : Saved(ParseTime)
      , SavedExpressions(ParseHasExpressions)
    {
      ParseTime = t;
      ParseHasExpressions = false;
    }
    ~TimeScope()
    {
      ParseTime = this->Saved;
      ParseHasExpressions = this->SavedExpressions;
    }
  } scope(time);
  // Syntax errors and number overflows: nlohmann's words, and where it
  // stopped as data.
  std::shared_ptr<const Metric> metric = LocatingErrorsIn(
    json, [&]() { return Build(json::Parse<MetricDefinitionError>(json, "", "invalid JSON: ")); });
  const std::string why = ParseHasExpressions ? std::string() : metric->Validate();
  if (!why.empty())
  {
    JsonErrorPlace wholeMetric;
    wholeMetric.Path = "metric";
    throw MetricDefinitionError(wholeMetric, why);
  }
  return metric;
}

std::string ReadMetricDefinitionFile(const std::string& path)
{
  try
  {
    return ReadInputFile(path, "the metric file", MaximumFileSize);
  }
  catch (const std::runtime_error& e)
  {
    throw MetricDefinitionError(e.what());
  }
}

std::shared_ptr<const Metric> LoadMetricDefinitionFile(const std::string& path, double time)
{
  const std::string text = ReadMetricDefinitionFile(path);
  const size_t slash = path.rfind('/');
  try
  {
    return ParseMetricDefinition(
      text, time, slash == std::string::npos ? std::string() : path.substr(0, slash));
  }
  catch (const MetricDefinitionError& e)
  {
    throw MetricDefinitionError(path + ": ", e);
  }
}
} // namespace riemann
