/**
 * @file GlslSource.h
 * @brief GLSL emission of a metric for the ray-tracing shader.
 *
 * Each provider and family writes its own GLSL (ScalarField::EmitGlsl,
 * SpaceMap::EmitGlsl, Metric::EmitGlsl). The source depends only on the
 * metric's structure (which providers, composed how); every number
 * (amplitudes, centres, spreads, rates, matrices) is a uniform whose value is
 * listed next to the source. Two metrics of the same structure therefore give
 * byte-identical source, so a renderer recompiles only when the structure
 * changes and otherwise just uploads new uniform values (animation in t,
 * interactive edits).
 *
 * The metric part of the shader defines (float precision):
 *
 *   bool rt_metric_tensor(vec3 p, out mat3 g);             // g_ij at p
 *   bool rt_metric_acceleration(vec3 p, vec3 v, out vec3 a); // -Gamma(v, v)
 *
 * both returning false where the metric is degenerate, and
 *
 *   bool rt_metric_inside(vec3 p);                         // Metric::InsideData
 *
 * Sampled metrics also read 3D float textures (GlslTexture3D), listed next to
 * the uniforms: data, like them, so two volumes of the same kind share the
 * program. GLSL mat3 values are column-major: M[j][i] is row i, column j.
 */
#ifndef RiemannGlslSource_h
#define RiemannGlslSource_h

#include "RiemannCommonGlslExport.h"

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace riemann
{
/// A uniform of the generated source and its value.
struct GlslUniform
{
  std::string Name;
  /// "float", "vec3" or "mat3".
  std::string Type;
  /// 1, 3 or 9 values (mat3: column-major, as glUniformMatrix3fv expects).
  std::vector<double> Values;
};

/**
 * A sampler3D uniform of the generated source and the texels it reads: a
 * float texture of Dimensions[0] x [1] x [2] texels of `Components` values
 * each (x fastest), read with texelFetch (edges clamped by the code) or,
 * with GlslEmitOptions::FilteredTextureReads, with texture() (trilinear,
 * clamped to the edges). `Values` is shared with the metric that made it, so emitting the
 * source every frame copies nothing, and a renderer uploads a texture again
 * only when the pointer changes.
 */
struct GlslTexture3D
{
  std::string Name;
  std::array<int, 3> Dimensions = { 0, 0, 0 };
  int Components = 3;
  std::shared_ptr<const std::vector<float>> Values;
};

/// A metric (or provider) that the GLSL backend cannot express; what() says which.
class RIEMANNCOMMONGLSL_EXPORT GlslUnsupportedError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Choices of the emitted source that are the renderer's, not the metric's.
struct GlslEmitOptions
{
  /**
   * Read a sampled metric's spline with the texture unit's trilinear
   * filtering (8 reads per sum) instead of weighting 64 texels in the
   * shader. Fewer reads and far less shader arithmetic, but the
   * interpolation weights are the texture unit's (8-bit fractions on most
   * GPUs; float on Mesa's llvmpipe), so g is no longer the CPU's to float
   * rounding.
   */
  bool FilteredTextureReads = false;
};

/**
 * Collects uniforms and functions while providers emit themselves. Names are
 * numbered in emission order, so the same structure always yields the same text.
 */
class RIEMANNCOMMONGLSL_EXPORT GlslBuilder
{
public:
  GlslBuilder() = default;
  explicit GlslBuilder(const GlslEmitOptions& options)
    : Options(options)
  {
  }
  const GlslEmitOptions& GetOptions() const { return this->Options; }

  /// A fresh identifier "rt_<stem><n>".
  std::string NewName(const std::string& stem);
  /// Declare a uniform (name from NewName) with its value; returns the name.
  std::string AddUniform(
    const std::string& stem, const std::string& type, std::vector<double> values);
  /// Append a function definition (callees must be added before callers).
  void AddFunction(const std::string& code);
  /// Declare a sampler3D uniform (name from NewName) reading `texture`; returns the name.
  std::string AddTexture3D(const std::string& stem, GlslTexture3D texture);
  /**
   * Name the function `bool NAME(vec3 p)` that says where the metric's data
   * holds (Metric::InsideData); without one, rt_metric_inside is true.
   */
  void SetInsideDataFunction(const std::string& name) { this->InsideDataFunction = name; }

  /// Uniform declarations followed by the functions.
  std::string Source() const;
  const std::vector<GlslUniform>& GetUniforms() const { return this->Uniforms; }
  const std::vector<GlslTexture3D>& GetTextures() const { return this->Textures; }
  const std::string& GetInsideDataFunction() const { return this->InsideDataFunction; }

private:
  GlslEmitOptions Options;
  int Counter = 0;
  std::vector<GlslUniform> Uniforms;
  std::vector<GlslTexture3D> Textures;
  std::string InsideDataFunction;
  std::vector<std::string> Functions;
};

} // namespace riemann

#endif
