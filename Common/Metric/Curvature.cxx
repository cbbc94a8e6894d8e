#include "Curvature.h"

#include "Christoffel.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>

namespace riemann
{
bool ChristoffelAndDerivatives(const Metric& metric, const Vec3& p, Mat3& g, Mat3& ginv,
  Mat3Stack& gamma, std::array<Mat3Stack, 3>& dGamma)
{
  Mat3Stack dg;
  std::array<Mat3Stack, 3> d2g;
  if (!metric.TensorSecondDerivatives(p, g, dg, d2g))
  {
    return false;
  }
  const Eigen::LLT<Mat3> llt(g);
  if (!g.allFinite() || llt.info() != Eigen::Success)
  {
    return false;
  }
  ginv = llt.solve(Mat3::Identity());

  // gamma[m](i, j) = Gamma^m_ij.
  ChristoffelFromMetricDerivatives(ginv, dg, gamma);

  // dGamma[l][m](i, j) = d_l Gamma^m_ij
  //   = -g^ma (d_l g_ab) Gamma^b_ij + g^mk 1/2 (d_l d_i g_jk + d_l d_j g_ik - d_l d_k g_ij).
  for (int l = 0; l < 3; ++l)
  {
    // first[k](i, j) = 1/2 (d_l d_i g_jk + d_l d_j g_ik - d_l d_k g_ij): d_l Gamma_kij.
    double first[3][3][3];
    for (int k = 0; k < 3; ++k)
    {
      for (int i = 0; i < 3; ++i)
      {
        for (int j = 0; j < 3; ++j)
        {
          first[k][i][j] = 0.5 * (d2g[l][i](j, k) + d2g[l][j](i, k) - d2g[l][k](i, j));
        }
      }
    }
    // a(m, b) = g^ma (d_l g_ab).
    const Mat3 a = ginv * dg[l];
    for (int m = 0; m < 3; ++m)
    {
      for (int i = 0; i < 3; ++i)
      {
        for (int j = 0; j < 3; ++j)
        {
          double value = 0.0;
          for (int b = 0; b < 3; ++b)
          {
            value += -a(m, b) * gamma[b](i, j) + ginv(m, b) * first[b][i][j];
          }
          dGamma[l][m](i, j) = value;
        }
      }
    }
  }
  return true;
}

namespace
{
// ComputeCurvature's steps, one tensor at a time.

/// A rank-4 tensor of a 3-manifold, indexed [a][b][c][d].
using Tensor4 = double[3][3][3][3];

/// R^l_ijk = d_j Gamma^l_ik - d_k Gamma^l_ij + Gamma^l_jm Gamma^m_ik - Gamma^l_km Gamma^m_ij.
void RiemannTensor(const Mat3Stack& gamma, const std::array<Mat3Stack, 3>& dGamma, Tensor4& riemann)
{
  for (int l = 0; l < 3; ++l)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        for (int k = 0; k < 3; ++k)
        {
          double value = dGamma[j][l](i, k) - dGamma[k][l](i, j);
          for (int m = 0; m < 3; ++m)
          {
            value += gamma[l](j, m) * gamma[m](i, k) - gamma[l](k, m) * gamma[m](i, j);
          }
          riemann[l][i][j][k] = value;
        }
      }
    }
  }
}

/// Lowered: lowered[m][i][j][k] = R_mijk = g_ml R^l_ijk = <R(d_j, d_k) d_i, d_m>.
void LowerFirstIndex(const Mat3& g, const Tensor4& riemann, Tensor4& lowered)
{
  for (int m = 0; m < 3; ++m)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        for (int k = 0; k < 3; ++k)
        {
          lowered[m][i][j][k] = g(m, 0) * riemann[0][i][j][k] + g(m, 1) * riemann[1][i][j][k] +
            g(m, 2) * riemann[2][i][j][k];
        }
      }
    }
  }
}

/// The components F_abcd = R_mijk E_ma E_ib E_jc E_kd in a g-orthonormal
/// frame: the columns of E = L^-T (g = L L^T), so E^T g E = I; one index at
/// a time.
void FrameComponents(const Eigen::LLT<Mat3>& llt, const Tensor4& lowered, Tensor4& frame)
{
  const Mat3 lower = llt.matrixL();
  const Mat3 e = lower.transpose().triangularView<Eigen::Upper>().solve(Mat3::Identity());
  Tensor4 work;
  const auto transformIndex = [&e](const Tensor4& in, Tensor4& out, int position)
  {
    for (int a = 0; a < 3; ++a)
    {
      for (int b = 0; b < 3; ++b)
      {
        for (int c = 0; c < 3; ++c)
        {
          for (int d = 0; d < 3; ++d)
          {
            int index[4] = { a, b, c, d };
            const int target = index[position];
            double value = 0.0;
            for (int s = 0; s < 3; ++s)
            {
              index[position] = s;
              value += in[index[0]][index[1]][index[2]][index[3]] * e(s, target);
            }
            out[a][b][c][d] = value;
          }
        }
      }
    }
  };
  transformIndex(lowered, work, 0);
  transformIndex(work, frame, 1);
  transformIndex(frame, work, 2);
  transformIndex(work, frame, 3);
}

/// |Rm|: the Frobenius norm of the frame components.
double FrameNorm(const Tensor4& frame)
{
  double squared = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    for (int b = 0; b < 3; ++b)
    {
      for (int c = 0; c < 3; ++c)
      {
        for (int d = 0; d < 3; ++d)
        {
          squared += frame[a][b][c][d] * frame[a][b][c][d];
        }
      }
    }
  }
  return std::sqrt(squared);
}

/// The curvature operator on Lambda^2 in the orthonormal bivector basis
/// e_1^e_2, e_0^e_2, e_0^e_1: Q(e_j^e_k, e_m^e_i) = F_mijk, so that
/// Q(u^w, u^w) = <R(u, w)w, u> = K(u, w) for orthonormal u, w. In 3D every
/// unit bivector is a plane: the eigenvalues are the extremes of K.
bool SectionalExtremes(const Tensor4& frame, double& minimum, double& maximum)
{
  static const int pairs[3][2] = { { 1, 2 }, { 0, 2 }, { 0, 1 } };
  Mat3 q;
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      q(row, column) = frame[pairs[column][0]][pairs[column][1]][pairs[row][0]][pairs[row][1]];
    }
  }
  q = 0.5 * (q + q.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(q, Eigen::EigenvaluesOnly);
  if (eigen.info() != Eigen::Success)
  {
    return false;
  }
  minimum = eigen.eigenvalues()[0];
  maximum = eigen.eigenvalues()[2];
  return true;
}
} // namespace

// ComputeCurvature as named steps: ChristoffelAndDerivatives -> RiemannTensor
// -> Ricci and scalar -> LowerFirstIndex -> coordinate sectional curvatures
// -> FrameComponents -> FrameNorm and SectionalExtremes.
bool ComputeCurvature(const Metric& metric, const Vec3& p, CurvatureSample& sample)
{
  Mat3 g;
  Mat3 ginv;
  Mat3Stack gamma;
  std::array<Mat3Stack, 3> dGamma;
  if (!ChristoffelAndDerivatives(metric, p, g, ginv, gamma, dGamma))
  {
    return false;
  }
  const Eigen::LLT<Mat3> llt(g);
  sample.g = g;
  sample.ginv = ginv;
  RiemannTensor(gamma, dGamma, sample.Riemann);

  // Ric_ik = R^j_ijk, S = g^ik Ric_ik.
  for (int i = 0; i < 3; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      sample.Ricci(i, k) =
        sample.Riemann[0][i][0][k] + sample.Riemann[1][i][1][k] + sample.Riemann[2][i][2][k];
    }
  }
  sample.Scalar = (ginv.cwiseProduct(sample.Ricci)).sum();

  Tensor4 lowered;
  LowerFirstIndex(g, sample.Riemann, lowered);
  // K(d_a, d_b) = <R(d_a, d_b) d_b, d_a> / (g_aa g_bb - g_ab^2) = R_abab / (...).
  const auto coordinateSectional = [&](int a, int b)
  { return lowered[a][b][a][b] / (g(a, a) * g(b, b) - g(a, b) * g(a, b)); };
  sample.SectionalXY = coordinateSectional(0, 1);
  sample.SectionalXZ = coordinateSectional(0, 2);
  sample.SectionalYZ = coordinateSectional(1, 2);

  Tensor4 frame;
  FrameComponents(llt, lowered, frame);
  sample.RiemannNorm = FrameNorm(frame);
  if (!SectionalExtremes(frame, sample.SectionalMin, sample.SectionalMax))
  {
    return false;
  }

  sample.VolumeForm = std::sqrt(g.determinant());
  return std::isfinite(sample.Scalar) && std::isfinite(sample.RiemannNorm) &&
    std::isfinite(sample.SectionalMin) && std::isfinite(sample.SectionalMax) &&
    sample.Ricci.allFinite() && std::isfinite(sample.VolumeForm);
}
LaneMask ComputeCurvature(
  const Metric& metric, const PacketVec3& x, LaneMask lanes, PacketCurvature& curvature)
{
  PacketTensorJet jet;
  const LaneMask derived = metric.TensorSecondDerivativesPacket(x, jet, lanes);
  return CurvatureFromTensorJet(jet, curvature) & derived & lanes;
}
} // namespace riemann
