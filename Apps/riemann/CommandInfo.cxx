// riemann info: what a metric is at a point, as text: g, g^-1, its
// eigenvalues, the volume form and the Christoffel symbols.
#include "CliUtilities.h"
#include "Commands.h"

#include "Curvature.h"
#include "GlslSource.h"
#include "MetricGlsl.h"
#include "Metric.h"
#include "vtkRiemannMetric.h"

#include <CLI/CLI.hpp>
#include <Eigen/Eigenvalues>

#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace riemann
{
namespace cli
{
namespace
{
struct InfoArguments
{
  std::string Metric;
  std::string Point = "0,0,0";
  int Precision = 10;
  bool Glsl = false;
};

void PrintMatrix(std::ostream& out, const std::string& title, const Mat3& m)
{
  out << title << "\n";
  for (int r = 0; r < 3; ++r)
  {
    out << "  [";
    for (int c = 0; c < 3; ++c)
    {
      out << std::setw(out.precision() + 8) << m(r, c) << (c < 2 ? "," : "");
    }
    out << " ]\n";
  }
}

void RunInfo(const InfoArguments& args)
{
  vtkSmartPointer<vtkRiemannMetric> handle = LoadMetric(args.Metric);
  const std::shared_ptr<const Metric> metric = handle->GetMetric();
  if (args.Glsl)
  {
    try
    {
      std::cout << EmitMetricGlsl(*metric).Source;
    }
    catch (const GlslUnsupportedError& e)
    {
      throw Failure(std::string("no GLSL for this metric: ") + e.what());
    }
    return;
  }
  double p[3];
  ParseVector3(args.Point, "--point", p);
  const Vec3 point(p[0], p[1], p[2]);

  std::ostringstream out;
  out << std::setprecision(args.Precision);
  out << "metric:  " << metric->Describe() << "\n";
  out << "family:  " << metric->FamilyName() << "\n";
  out << "point:   (" << p[0] << ", " << p[1] << ", " << p[2] << ")\n";
  Mat3 g, inverse;
  Mat3Stack gamma;
  if (!metric->Tensor(point, g) || !metric->InverseTensor(point, inverse) ||
    !metric->Christoffel(point, gamma))
  {
    // Say what is wrong: the values of g when they are finite, else that
    // they are not; geodesics and rays stop at such points.
    std::ostringstream why;
    why << std::setprecision(args.Precision);
    if (g.allFinite())
    {
      PrintMatrix(out, "g_ij:", g);
      const Eigen::SelfAdjointEigenSolver<Mat3> eigen(g, Eigen::EigenvaluesOnly);
      if (eigen.eigenvalues().minCoeff() <= 0)
      {
        why << "the metric is not positive definite at this point (eigenvalues of g: "
            << eigen.eigenvalues().transpose() << ")";
      }
      else
      {
        why << "the metric is degenerate at this point (its family refuses it here: e.g. a "
               "refractive index n <= 0, or det J = 0 for a diffeomorphism)";
      }
    }
    else
    {
      why << "the metric is not defined at this point (g is not finite)";
    }
    why << "; geodesics and rays stop here (ReasonForTermination 8, degenerate metric)";
    std::cout << out.str();
    throw Failure(why.str());
  }
  PrintMatrix(out, "g_ij:", g);
  PrintMatrix(out, "g^ij:", inverse);
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(g, Eigen::EigenvaluesOnly);
  out << "eigenvalues of g: " << eigen.eigenvalues().transpose() << "\n";
  out << "det g:   " << g.determinant() << "\n";
  out << "volume form sqrt(det g): " << metric->VolumeForm(point) << "\n";
  const char* axes = "xyz";
  for (int m = 0; m < 3; ++m)
  {
    PrintMatrix(out, std::string("Gamma^") + axes[m] + "_ij:", gamma[m]);
  }
  // Curvature (Curvature.h's convention: R(d_j, d_k) d_i = R^l_ijk d_l).
  CurvatureSample curvature;
  if (ComputeCurvature(*metric, point, curvature))
  {
    out << "scalar curvature: " << curvature.Scalar << "\n";
    PrintMatrix(out, "Ricci_ij:", curvature.Ricci);
    out << "sectional curvature: xy " << curvature.SectionalXY << ", xz " << curvature.SectionalXZ
        << ", yz " << curvature.SectionalYZ << "\n";
    out << "sectional curvature over all planes: min " << curvature.SectionalMin << ", max "
        << curvature.SectionalMax << "\n";
    out << "|Riemann|: " << curvature.RiemannNorm << "\n";
  }
  else
  {
    out << "curvature: unavailable here (this metric gives no second derivatives of g)\n";
  }
  std::cout << out.str();
}
} // namespace

void RegisterInfoCommand(CLI::App& app)
{
  auto args = std::make_shared<InfoArguments>();
  CLI::App* command = app.add_subcommand("info",
    "Print g, g^-1, the volume form, the Christoffel symbols and the curvature at a point.");
  command->add_option("--metric,-m", args->Metric, "Metric definition (JSON file)")
    ->required()
    ->check(CLI::ExistingFile);
  command->add_option("--point,-p", args->Point, "Point X,Y,Z (default 0,0,0)")->check(Point3());
  command->add_option("--precision", args->Precision, "Significant digits (default 10)")
    ->check(WholeNumber(1, 17));
  command->add_flag(
    "--glsl", args->Glsl, "Print the metric's part of the ray-tracing shader (GLSL) instead");
  command->callback([args]() { RunInfo(*args); });
}
} // namespace cli
} // namespace riemann
