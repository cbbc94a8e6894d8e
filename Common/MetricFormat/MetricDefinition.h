/**
 * @file MetricDefinition.h
 * @brief Build a Metric from its JSON definition (ARCHITECTURE.md), the same
 * text in the CLI, the app and Python.
 *
 * Built-in providers:
 *
 *   {"type": "euclidean"}
 *   {"type": "graph", <scalar terms>}                      f = sum of the terms
 *   {"type": "conformal", <scalar terms>}                  n = sum of the terms
 *                                                          ("constant" defaults to 1,
 *                                                          or 0 with an "n" expression)
 *   {"type": "diffeo", "preset": "twist", "rate": 1.0}
 *   {"type": "diffeo", "preset": "bump", "gaussian": {...}, "direction": [vx,vy,vz]}
 *   {"type": "diffeo", "preset": "bump", "gaussian": {...},
 *                      "field": {"matrix": [[..],[..],[..]], "center": [..], "offset": [..]}}
 *   {"type": "diffeo", "preset": "identity"}
 *   {"type": "diffeo", "compose": [ {diffeo}, {diffeo}, ... ]}   Phi = Phi_1 o Phi_2 o ...
 *   {"type": "tensor", "matrix": [[..],[..],[..]]}         constant g
 *   {"type": "sampled", "file": "D.vti", "array": "Tensors", "inverse": true,
 *                       "scale": 1.0, "repair": "clamp", "outside": "euclidean",
 *                       "frame": "world"}
 *                        g from a tensor volume (SampledTensorField.h): "file"
 *                        relative to the metric file's folder, read by the
 *                        reader the VTK layer installs (SetSampledTensorReader);
 *                        "array" defaults to the active tensors; "frame":
 *                        "fsl" for NIfTI tensors in FSL's voxel axes
 *
 * where <scalar terms> are any of
 *   "gaussians": [{"amplitude": a, "center": [x,y,z], "sigma": s or [sx,sy,sz]}, ...]
 *   "quadratic": {"matrix": [[..]] or "diagonal": [..], "linear": [..], "constant": c}
 *                (or a list of such objects): f = p^T A p + b . p + c
 *   "constant": c
 * Any number or 3-vector may be animated as {"from": a, "to": b}: its value at
 * time t in [0, 1] is a + t (b - a) (`riemann render --frames`, vtkRiemannMetric::SetTime).
 * The metric's structure never depends on t, so a shader compiled for one
 * frame serves them all with new uniform values.
 *
 * Expressions (x, y, z, t, named "parameters", + - * / ^ and exp, log, sqrt,
 * sin, cos, tan, sinh, cosh, tanh, atan2, abs, pow):
 *   {"type": "graph", "f": "x^2 + y^2 - z^2"}                  (added to any other terms)
 *   {"type": "conformal", "n": "2 / (1 + x^2 + y^2 + z^2)"}
 *   {"type": "diffeo", "phi": ["x + a*exp(-(x^2+y^2+z^2))", "y", "z"], "parameters": {"a": 0.3}}
 *   {"type": "tensor", "g": [["1","0","0"],["0","1+x^2","0"],["0","0","1"]]}
 * "parameters" may appear at the root and in any composed map (inner ones
 * override outer ones); values may be animated. A definition with
 * expressions is not refused for being degenerate somewhere: geodesics and
 * rays stop where it degenerates (ReasonForTermination 8).
 *
 * Every object also accepts "name" and "description" (free text). Unknown keys,
 * wrong sizes and wrong types are errors that name the offending key's path,
 * e.g. `metric.compose[1].gaussian.sigma`.
 */
#ifndef RiemannMetricDefinition_h
#define RiemannMetricDefinition_h

#include "Metric.h"
#include "SampledTensorField.h"
#include "JsonInputError.h"
#include "RiemannCommonMetricFormatExport.h"

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

namespace riemann
{
/// A definition that cannot be turned into a metric; what() says where and why.
class RIEMANNCOMMONMETRICFORMAT_EXPORT MetricDefinitionError : public JsonInputError
{
public:
  using JsonInputError::JsonInputError;
};

/**
 * Parse, build and validate (Metric::Validate) a metric definition at time
 * `time` (animated numbers {"from": a, "to": b} become a + t (b - a)).
 * Throws MetricDefinitionError with a message naming the place and cause.
 */
RIEMANNCOMMONMETRICFORMAT_EXPORT std::shared_ptr<const Metric> ParseMetricDefinition(
  const std::string& json, double time = 0.0);

/**
 * The same, with the folder that relative data files of the definition
 * ("sampled": "file") are read from ("" for the working directory).
 */
RIEMANNCOMMONMETRICFORMAT_EXPORT std::shared_ptr<const Metric> ParseMetricDefinition(
  const std::string& json, double time, const std::string& baseDirectory);

/**
 * The axes a file's tensors are written in ({"type": "sampled"}'s "frame").
 * World: the axes the file places its voxels in (NRRD's measurement frame
 * already turned to them). Fsl: FSL's voxel axes, as dtifit writes them
 * (and DIPY, from FSL-style bvecs): a NIfTI file's voxel axes, the first
 * one reversed when the voxel-to-world matrix has a positive determinant.
 */
enum class SampledTensorFrame
{
  World,
  Fsl
};

/**
 * The order of a NIfTI file's six tensor values ({"type": "sampled"}'s
 * "components"). Six volumes without NIfTI's symmetric-matrix intent do not
 * say their order, and the tools that write them disagree: such a file is
 * refused unless the order is given (never guessed).
 */
enum class SampledTensorComponents
{
  FromFile, ///< not given: the file must say (intent NIFTI_INTENT_SYMMATRIX)
  Fsl,      ///< XX XY XZ YY YZ ZZ: FSL's dtifit
  Mrtrix,   ///< XX YY ZZ XY XZ YZ: MRtrix's dwi2tensor, through mrconvert to NIfTI
  Dipy      ///< XX XY YY XZ YZ ZZ: DIPY's lower_triangular, NIfTI's symmetric-matrix order
};

/**
 * Reads the tensors of a {"type": "sampled"} definition: the grid of array
 * `array` ("": the data's active tensors) of file `path`, its values in the
 * order `components` (NIfTI only), its tensors turned from `frame` to world
 * axes but otherwise as they are stored (PrepareTensorSamples turns them
 * into the metric). Throws std::exception with a message that names the
 * file and what is wrong.
 */
using SampledTensorReader = std::function<SampledTensorGrid(const std::string& path,
  const std::string& array, SampledTensorFrame frame, SampledTensorComponents components)>;

/**
 * Install the reader of "sampled" definitions (the VTK layer installs one
 * for VTK's formats when it loads: vtkRiemannMetric). Without one, such
 * definitions are refused with a message that says so.
 */
RIEMANNCOMMONMETRICFORMAT_EXPORT void SetSampledTensorReader(SampledTensorReader reader);

/// The text of a metric file (refusing unreadable or absurdly large files).
RIEMANNCOMMONMETRICFORMAT_EXPORT std::string ReadMetricDefinitionFile(const std::string& path);

/// Read a file and ParseMetricDefinition() it; the message names the file.
RIEMANNCOMMONMETRICFORMAT_EXPORT std::shared_ptr<const Metric> LoadMetricDefinitionFile(
  const std::string& path, double time = 0.0);
} // namespace riemann

#endif
