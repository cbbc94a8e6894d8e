/**
 * @file ExpressionFields.h
 * @brief Field providers from typed expressions: f (graph), n (conformal),
 * Phi (diffeomorphism) and g_ij (tensor), compiled by CompiledExpressions.
 *
 * The expressions are differentiated symbolically once; evaluation runs the
 * compiled tape (no GiNaC, no allocation, thread-safe). Named parameters and
 * the time t are inputs of the tape on the CPU and uniforms in the GLSL, so
 * new values never change the shader's source.
 */
#ifndef RiemannExpressionFields_h
#define RiemannExpressionFields_h

#include "ScalarField.h"
#include "SpaceMap.h"
#include "TensorMetric.h"
#include "RiemannCommonExpressionsExport.h"

#include <memory>
#include <string>
#include <vector>

namespace riemann
{
class CompiledExpressions;

/// Named parameter values of a definition (in the order the expressions were compiled with).
struct ExpressionInputs
{
  std::vector<std::string> ParameterNames;
  std::vector<double> ParameterValues;
  double Time = 0.0;
};

/// f(x, y, z) typed as an expression; exact derivatives to third order.
class RIEMANNCOMMONEXPRESSIONS_EXPORT ExpressionScalarField : public ScalarField
{
public:
  /// Throws ExpressionError.
  ExpressionScalarField(const std::string& source, const ExpressionInputs& inputs);
  ~ExpressionScalarField() override;

  void Accumulate(const Vec3& p, int order, ScalarJet& jet) const override;
  /// The tape on all lanes at once (CompiledExpressions::EvaluatePacket).
  void AccumulatePacket(
    const PacketVec3& p, int order, PacketScalarJet& jet, LaneMask lanes) const override;
  std::string Describe() const override;
  std::string EmitGlsl(GlslBuilder& builder) const override;
  /// A 9^3 grid over [-4, 4]^3: an expression may vary anywhere.
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

private:
  std::string Source;
  ExpressionInputs Inputs;
  std::shared_ptr<const CompiledExpressions> Compiled;
};

/// Phi = (Phi_x, Phi_y, Phi_z) typed as three expressions.
class RIEMANNCOMMONEXPRESSIONS_EXPORT ExpressionMap : public SpaceMap
{
public:
  /// Throws ExpressionError (the message says which component).
  ExpressionMap(const std::vector<std::string>& sources, const ExpressionInputs& inputs);
  ~ExpressionMap() override;

  void Evaluate(const Vec3& p, int order, VectorJet& jet) const override;
  std::string Describe() const override;
  std::string EmitGlsl(GlslBuilder& builder) const override;
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

private:
  std::vector<std::string> Sources;
  ExpressionInputs Inputs;
  std::shared_ptr<const CompiledExpressions> Compiled;
};

/// g_ij typed as a symmetric 3x3 array of expressions (the six of the upper triangle are compiled).
class RIEMANNCOMMONEXPRESSIONS_EXPORT ExpressionTensorField : public TensorField
{
public:
  /// `components` row-major 3x3; throws ExpressionError. Symmetry is checked by the caller.
  ExpressionTensorField(const std::vector<std::string>& components, const ExpressionInputs& inputs);
  ~ExpressionTensorField() override;

  /// Runs the tape to first order only (the geodesic hot path).
  void Evaluate(const Vec3& p, bool withDerivatives, Mat3& g, Mat3Stack& dg) const override;
  /// The full tape (compiled to second order): g, dg and d2g.
  bool EvaluateSecond(
    const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const override;
  /// The tape on the packet (ExpressionPacketInterpreter.cxx).
  LaneMask EvaluateSecondPacket(
    const PacketVec3& x, PacketTensorJet& jet, LaneMask lanes) const override;
  std::string Describe() const override;
  std::string EmitGlsl(GlslBuilder& builder) const override;
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

private:
  std::vector<std::string> Components;
  ExpressionInputs Inputs;
  std::shared_ptr<const CompiledExpressions> Compiled;
};
} // namespace riemann

#endif
