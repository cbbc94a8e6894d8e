// The packet curvature kernels (PacketCurvature.h), written once with Google
// Highway and dispatched at run time like PacketKernels.cxx (whose file
// comment explains the mechanism). Each kernel walks a packet in vectors of
// N = Lanes(D) doubles; matrices are arrays of vectors indexed as in
// Curvature.cxx, so each formula reads as its scalar form.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "PacketCurvature.cxx"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include "PacketCurvature.h"
#include "PacketLanes-inl.h" // D, V, M, BitsAt

#include <cmath>

HWY_BEFORE_NAMESPACE();
namespace riemann
{
namespace HWY_NAMESPACE
{
/// A symmetric 3x3 matrix of lanes [o, o + N), as a full array (m[i][j] = m[j][i]).
struct Matrix
{
  V m[3][3];
};

HWY_INLINE Matrix LoadSymmetric(const PacketSym3& a, int o)
{
  const D d;
  Matrix r;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      r.m[i][j] = hn::Load(d, a.C[SymmetricEntryOf[i][j]] + o);
    }
  }
  return r;
}

HWY_INLINE void StoreSymmetric(const Matrix& a, PacketSym3& out, int o)
{
  const D d;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = i; j < 3; ++j)
    {
      hn::Store(a.m[i][j], d, out.C[SymmetricEntryOf[i][j]] + o);
    }
  }
}

/// The Cholesky factor L (g = L L^T) and L^-1, both lower triangular, and
/// the mask of lanes where g is positive definite.
struct Cholesky
{
  V L[3][3];
  V Inverse[3][3];
  M Positive;
};

HWY_INLINE Cholesky Factor(const Matrix& g)
{
  const D d;
  const V zero = hn::Zero(d);
  const V one = hn::Set(d, 1.0);
  Cholesky c;
  const V p0 = g.m[0][0];
  c.L[0][0] = hn::Sqrt(p0);
  c.L[1][0] = hn::Div(g.m[1][0], c.L[0][0]);
  c.L[2][0] = hn::Div(g.m[2][0], c.L[0][0]);
  const V p1 = hn::NegMulAdd(c.L[1][0], c.L[1][0], g.m[1][1]);
  c.L[1][1] = hn::Sqrt(p1);
  c.L[2][1] = hn::Div(hn::NegMulAdd(c.L[2][0], c.L[1][0], g.m[2][1]), c.L[1][1]);
  const V p2 = hn::NegMulAdd(c.L[2][1], c.L[2][1], hn::NegMulAdd(c.L[2][0], c.L[2][0], g.m[2][2]));
  c.L[2][2] = hn::Sqrt(p2);
  c.L[0][1] = c.L[0][2] = c.L[1][2] = zero;
  c.Positive = hn::And(hn::Gt(p0, zero), hn::And(hn::Gt(p1, zero), hn::Gt(p2, zero)));
  // L^-1 by forward substitution.
  c.Inverse[0][0] = hn::Div(one, c.L[0][0]);
  c.Inverse[1][1] = hn::Div(one, c.L[1][1]);
  c.Inverse[2][2] = hn::Div(one, c.L[2][2]);
  c.Inverse[1][0] = hn::Neg(hn::Mul(hn::Mul(c.L[1][0], c.Inverse[0][0]), c.Inverse[1][1]));
  c.Inverse[2][1] = hn::Neg(hn::Mul(hn::Mul(c.L[2][1], c.Inverse[1][1]), c.Inverse[2][2]));
  c.Inverse[2][0] = hn::Neg(hn::Mul(
    hn::MulAdd(c.L[2][1], c.Inverse[1][0], hn::Mul(c.L[2][0], c.Inverse[0][0])), c.Inverse[2][2]));
  c.Inverse[0][1] = c.Inverse[0][2] = c.Inverse[1][2] = zero;
  return c;
}

/// g^-1 = L^-T L^-1.
HWY_INLINE Matrix InverseOf(const Cholesky& c)
{
  Matrix r;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = i; j < 3; ++j)
    {
      V sum = hn::Mul(c.Inverse[2][i], c.Inverse[2][j]);
      sum = hn::MulAdd(c.Inverse[1][i], c.Inverse[1][j], sum);
      sum = hn::MulAdd(c.Inverse[0][i], c.Inverse[0][j], sum);
      r.m[i][j] = r.m[j][i] = sum;
    }
  }
  return r;
}

/// F = L^-1 A L^-T: A's components in the g-orthonormal frame of the columns of L^-T.
HWY_INLINE Matrix InFrame(const Cholesky& c, const Matrix& a)
{
  V half[3][3]; // L^-1 A
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      V sum = hn::Mul(c.Inverse[i][0], a.m[0][j]);
      sum = hn::MulAdd(c.Inverse[i][1], a.m[1][j], sum);
      half[i][j] = hn::MulAdd(c.Inverse[i][2], a.m[2][j], sum);
    }
  }
  Matrix r;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = i; j < 3; ++j)
    {
      V sum = hn::Mul(half[i][0], c.Inverse[j][0]);
      sum = hn::MulAdd(half[i][1], c.Inverse[j][1], sum);
      r.m[i][j] = r.m[j][i] = hn::MulAdd(half[i][2], c.Inverse[j][2], sum);
    }
  }
  return r;
}

/**
 * The eigenvalues of a symmetric matrix, ascending, by cyclic Jacobi
 * rotations: each zeroes one off-diagonal entry; six sweeps of the three
 * pairs bring a 3x3 matrix to diagonal within rounding (quadratic
 * convergence), the same number on every lane.
 */
HWY_INLINE void Eigenvalues(Matrix a, V (&eigenvalues)[3])
{
  const D d;
  const V zero = hn::Zero(d);
  const V one = hn::Set(d, 1.0);
  const V half = hn::Set(d, 0.5);
  static const int pairs[3][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 2, 0 } }; // p, q, other
  for (int sweep = 0; sweep < 6; ++sweep)
  {
    for (const auto& pair : pairs)
    {
      const int p = pair[0];
      const int q = pair[1];
      const int r = pair[2];
      const V apq = a.m[p][q];
      // theta = (a_qq - a_pp) / (2 a_pq); t = sign(theta) / (|theta| + sqrt(theta^2 + 1)),
      // the smaller rotation; t = 0 where a_pq is already 0 (theta is then not finite).
      const V theta = hn::Div(hn::Mul(half, hn::Sub(a.m[q][q], a.m[p][p])), apq);
      const V magnitude =
        hn::Div(one, hn::Add(hn::Abs(theta), hn::Sqrt(hn::MulAdd(theta, theta, one))));
      const V t = hn::IfThenElse(hn::Eq(apq, zero), zero, hn::CopySign(magnitude, theta));
      const V c = hn::Div(one, hn::Sqrt(hn::MulAdd(t, t, one)));
      const V s = hn::Mul(t, c);
      a.m[p][p] = hn::NegMulAdd(t, apq, a.m[p][p]);
      a.m[q][q] = hn::MulAdd(t, apq, a.m[q][q]);
      a.m[p][q] = a.m[q][p] = zero;
      const V arp = a.m[r][p];
      const V arq = a.m[r][q];
      a.m[r][p] = a.m[p][r] = hn::NegMulAdd(s, arq, hn::Mul(c, arp));
      a.m[r][q] = a.m[q][r] = hn::MulAdd(s, arp, hn::Mul(c, arq));
    }
  }
  const V x = a.m[0][0];
  const V y = a.m[1][1];
  const V z = a.m[2][2];
  eigenvalues[0] = hn::Min(x, hn::Min(y, z));
  eigenvalues[2] = hn::Max(x, hn::Max(y, z));
  // The middle one: the sum minus the extremes would lose precision; the
  // median of three is max(min(x, y), min(max(x, y), z)).
  eigenvalues[1] = hn::Max(hn::Min(x, y), hn::Min(hn::Max(x, y), z));
}

/// g, its Cholesky factor and inverse, the Christoffel symbols and their
/// derivatives on lanes [o, o + N): ChristoffelAndDerivatives of Curvature.h.
struct Connection
{
  Matrix G;
  Cholesky Factors;
  Matrix Inverse;
  /// Gamma[m][i][j] = Gamma^m_ij.
  V Gamma[3][3][3];
  /// DGamma[l][m][i][j] = d_l Gamma^m_ij.
  V DGamma[3][3][3][3];
};

HWY_INLINE void ConnectionAt(const PacketTensorJet& jet, int o, Connection& c)
{
  const D d;
  c.G = LoadSymmetric(jet.G, o);
  Matrix dg[3];
  Matrix d2g[3][3];
  for (int k = 0; k < 3; ++k)
  {
    dg[k] = LoadSymmetric(jet.D[k], o);
    for (int l = 0; l < 3; ++l)
    {
      d2g[k][l] = LoadSymmetric(jet.DD[SymmetricEntryOf[k][l]], o);
    }
  }
  c.Factors = Factor(c.G);
  c.Inverse = InverseOf(c.Factors);
  const Matrix& ginv = c.Inverse;

  // Step 1: Gamma^m_ij = g^mk Gamma_kij, with
  // Gamma_kij = 1/2 (d_i g_jk + d_j g_ik - d_k g_ij).
  V lowered[3][3][3];
  for (int k = 0; k < 3; ++k)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        lowered[k][i][j] =
          hn::Mul(hn::Set(d, 0.5), hn::Sub(hn::Add(dg[i].m[j][k], dg[j].m[i][k]), dg[k].m[i][j]));
      }
    }
  }
  for (int m = 0; m < 3; ++m)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        V sum = hn::Mul(ginv.m[m][0], lowered[0][i][j]);
        sum = hn::MulAdd(ginv.m[m][1], lowered[1][i][j], sum);
        c.Gamma[m][i][j] = hn::MulAdd(ginv.m[m][2], lowered[2][i][j], sum);
      }
    }
  }

  // Step 2: d_l Gamma^m_ij
  //   = -g^ma (d_l g_ab) Gamma^b_ij + g^mb 1/2 (d_l d_i g_jb + d_l d_j g_ib - d_l d_b g_ij).
  for (int l = 0; l < 3; ++l)
  {
    V first[3][3][3];
    for (int b = 0; b < 3; ++b)
    {
      for (int i = 0; i < 3; ++i)
      {
        for (int j = 0; j < 3; ++j)
        {
          first[b][i][j] = hn::Mul(hn::Set(d, 0.5),
            hn::Sub(hn::Add(d2g[l][i].m[j][b], d2g[l][j].m[i][b]), d2g[l][b].m[i][j]));
        }
      }
    }
    V a[3][3]; // g^ma (d_l g_ab)
    for (int m = 0; m < 3; ++m)
    {
      for (int b = 0; b < 3; ++b)
      {
        V sum = hn::Mul(ginv.m[m][0], dg[l].m[0][b]);
        sum = hn::MulAdd(ginv.m[m][1], dg[l].m[1][b], sum);
        a[m][b] = hn::MulAdd(ginv.m[m][2], dg[l].m[2][b], sum);
      }
    }
    for (int m = 0; m < 3; ++m)
    {
      for (int i = 0; i < 3; ++i)
      {
        for (int j = i; j < 3; ++j)
        {
          V value = hn::Zero(d);
          for (int b = 0; b < 3; ++b)
          {
            value = hn::MulAdd(
              ginv.m[m][b], first[b][i][j], hn::NegMulAdd(a[m][b], c.Gamma[b][i][j], value));
          }
          c.DGamma[l][m][i][j] = c.DGamma[l][m][j][i] = value;
        }
      }
    }
  }
}

/**
 * Curvature.cxx's steps on lanes [o, o + N): the connection (ConnectionAt),
 * Ricci (as the contraction R^j_ijk of the Riemann tensor), the coordinate
 * sectional curvatures, then the identities of dimension 3
 * (PacketCurvature.h) for the sectional extremes and |Rm|.
 */
HWY_INLINE LaneMask CurvatureAt(const PacketTensorJet& jet, PacketCurvature& out, int o)
{
  const D d;
  Connection connection;
  ConnectionAt(jet, o, connection);
  const Matrix& g = connection.G;
  const Matrix& ginv = connection.Inverse;
  const Cholesky& cholesky = connection.Factors;
  const auto& gamma = connection.Gamma;
  const auto& dGamma = connection.DGamma;

  // Step 3: R^l_ijk = d_j Gamma^l_ik - d_k Gamma^l_ij + Gamma^l_jm Gamma^m_ik
  // - Gamma^l_km Gamma^m_ij, only the components Ricci and the coordinate
  // sectional curvatures read.
  const auto riemannComponent = [&](int l, int i, int j, int k)
  {
    V value = hn::Sub(dGamma[j][l][i][k], dGamma[k][l][i][j]);
    for (int m = 0; m < 3; ++m)
    {
      value = hn::MulAdd(gamma[l][j][m], gamma[m][i][k], value);
      value = hn::NegMulAdd(gamma[l][k][m], gamma[m][i][j], value);
    }
    return value;
  };
  Matrix ricci; // Ric_ik = R^j_ijk
  for (int i = 0; i < 3; ++i)
  {
    for (int k = i; k < 3; ++k)
    {
      const V value = hn::Add(hn::Add(riemannComponent(0, i, 0, k), riemannComponent(1, i, 1, k)),
        riemannComponent(2, i, 2, k));
      ricci.m[i][k] = ricci.m[k][i] = value;
    }
  }
  V scalar = hn::Zero(d); // S = g^ik Ric_ik
  for (int i = 0; i < 3; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      scalar = hn::MulAdd(ginv.m[i][k], ricci.m[i][k], scalar);
    }
  }
  // K(d_a, d_b) = R_abab / (g_aa g_bb - g_ab^2), R_abab = g_al R^l_bab.
  const auto coordinateSectional = [&](int a, int b)
  {
    V lowered = hn::Zero(d);
    for (int l = 0; l < 3; ++l)
    {
      lowered = hn::MulAdd(g.m[a][l], riemannComponent(l, b, a, b), lowered);
    }
    return hn::Div(lowered, hn::NegMulAdd(g.m[a][b], g.m[a][b], hn::Mul(g.m[a][a], g.m[b][b])));
  };
  const V kxy = coordinateSectional(0, 1);
  const V kxz = coordinateSectional(0, 2);
  const V kyz = coordinateSectional(1, 2);

  // Step 4: Ric in a g-orthonormal frame; its eigenvalues mu give the
  // sectional extremes S / 2 - mu, and |Rm|^2 = 4 |Ric|^2 - S^2.
  const Matrix frame = InFrame(cholesky, ricci);
  V mu[3];
  Eigenvalues(frame, mu);
  const V halfScalar = hn::Mul(hn::Set(d, 0.5), scalar);
  V ricciSquared = hn::Zero(d);
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      ricciSquared = hn::MulAdd(frame.m[i][j], frame.m[i][j], ricciSquared);
    }
  }
  const V norm = hn::Sqrt(
    hn::Max(hn::Zero(d), hn::NegMulAdd(scalar, scalar, hn::Mul(hn::Set(d, 4.0), ricciSquared))));
  const V minimum = hn::Sub(halfScalar, mu[2]);
  const V maximum = hn::Sub(halfScalar, mu[0]);
  const V volume =
    hn::Mul(hn::Mul(cholesky.L[0][0], cholesky.L[1][1]), cholesky.L[2][2]); // sqrt(det g)

  hn::Store(scalar, d, out.Scalar + o);
  StoreSymmetric(ricci, out.Ricci, o);
  hn::Store(kxy, d, out.SectionalXY + o);
  hn::Store(kxz, d, out.SectionalXZ + o);
  hn::Store(kyz, d, out.SectionalYZ + o);
  hn::Store(minimum, d, out.SectionalMin + o);
  hn::Store(maximum, d, out.SectionalMax + o);
  hn::Store(norm, d, out.RiemannNorm + o);
  hn::Store(volume, d, out.VolumeForm + o);

  M defined = cholesky.Positive;
  defined = hn::And(defined, hn::IsFinite(scalar));
  defined = hn::And(defined, hn::IsFinite(norm));
  defined = hn::And(defined, hn::And(hn::IsFinite(minimum), hn::IsFinite(maximum)));
  defined = hn::And(defined, hn::IsFinite(volume));
  for (int i = 0; i < 3; ++i)
  {
    for (int k = i; k < 3; ++k)
    {
      defined = hn::And(defined, hn::IsFinite(ricci.m[i][k]));
    }
  }
  return BitsAt(d, defined, o);
}

/**
 * The Jacobi system's accelerations on lanes [o, o + N) from the
 * connection: a^m = -Gamma^m_ij v^i v^j and, per variation (X, V),
 * A^m = -X^l d_l Gamma^m_ij v^i v^j - 2 Gamma^m_ij v^i V^j (JacobiField.h).
 */
HWY_INLINE LaneMask JacobiAt(
  const PacketTensorJet& jet, const PacketJacobiState& y, PacketJacobiState& dy, int o)
{
  const D d;
  Connection c;
  ConnectionAt(jet, o, c);
  V v[3];
  for (int i = 0; i < 3; ++i)
  {
    v[i] = hn::Load(d, y.V.C[i] + o);
  }
  // contract(t, u, w) = t_ij u^i w^j for a symmetric t.
  const auto contract = [&](const V(&t)[3][3], const V(&u)[3], const V(&w)[3])
  {
    V sum = hn::Zero(d);
    for (int i = 0; i < 3; ++i)
    {
      const V row = hn::MulAdd(t[i][2], w[2], hn::MulAdd(t[i][1], w[1], hn::Mul(t[i][0], w[0])));
      sum = hn::MulAdd(u[i], row, sum);
    }
    return sum;
  };
  M ok = c.Factors.Positive;
  for (int m = 0; m < 3; ++m)
  {
    const V a = hn::Neg(contract(c.Gamma[m], v, v));
    hn::Store(a, d, dy.V.C[m] + o);
    ok = hn::And(ok, hn::IsFinite(a));
  }
  for (int k = 0; k < 2; ++k)
  {
    V x[3];
    V w[3];
    for (int i = 0; i < 3; ++i)
    {
      x[i] = hn::Load(d, y.J[k].C[i] + o);
      w[i] = hn::Load(d, y.DJ[k].C[i] + o);
    }
    for (int m = 0; m < 3; ++m)
    {
      V value = hn::Mul(hn::Set(d, -2.0), contract(c.Gamma[m], v, w));
      for (int l = 0; l < 3; ++l)
      {
        value = hn::NegMulAdd(x[l], contract(c.DGamma[l][m], v, v), value);
      }
      hn::Store(value, d, dy.DJ[k].C[m] + o);
      ok = hn::And(ok, hn::IsFinite(value));
    }
  }
  return BitsAt(d, ok, o);
}

LaneMask JacobiAccelerationsFromTensorJetImpl(
  const PacketTensorJet& jet, const PacketJacobiState& y, PacketJacobiState& dy)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  LaneMask defined = 0;
  for (int o = 0; o < PacketWidth; o += n)
  {
    defined |= JacobiAt(jet, y, dy, o);
  }
  return defined;
}

LaneMask CurvatureFromTensorJetImpl(const PacketTensorJet& jet, PacketCurvature& curvature)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  LaneMask defined = 0;
  for (int o = 0; o < PacketWidth; o += n)
  {
    defined |= CurvatureAt(jet, curvature, o);
  }
  return defined;
}

void SymmetricEigenvaluesImpl(const PacketSym3& a, double (&eigenvalues)[3][PacketWidth])
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  for (int o = 0; o < PacketWidth; o += n)
  {
    V values[3];
    Eigenvalues(LoadSymmetric(a, o), values);
    for (int i = 0; i < 3; ++i)
    {
      hn::StoreU(values[i], d, eigenvalues[i] + o); // any alignment
    }
  }
}

LaneMask InverseTensorImpl(const PacketSym3& g, PacketSym3& inverse)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  LaneMask defined = 0;
  for (int o = 0; o < PacketWidth; o += n)
  {
    const Cholesky cholesky = Factor(LoadSymmetric(g, o));
    Matrix r = InverseOf(cholesky);
    M ok = cholesky.Positive;
    for (int i = 0; i < 3; ++i)
    {
      for (int j = i; j < 3; ++j)
      {
        ok = hn::And(ok, hn::IsFinite(r.m[i][j]));
      }
    }
    const V nan = hn::Set(d, std::nan(""));
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        r.m[i][j] = hn::IfThenElse(ok, r.m[i][j], nan);
      }
    }
    StoreSymmetric(r, inverse, o);
    defined |= BitsAt(d, ok, o);
  }
  return defined;
}

LaneMask GraphTensorJetFromJetImpl(const PacketScalarJet& f, PacketTensorJet& jet)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  LaneMask finite = 0;
  for (int o = 0; o < PacketWidth; o += n)
  {
    V grad[3];
    V hess[3][3];
    V third[3][3][3];
    for (int i = 0; i < 3; ++i)
    {
      grad[i] = hn::Load(d, f.Gradient[i] + o);
      for (int j = 0; j < 3; ++j)
      {
        hess[i][j] = hn::Load(d, f.Hessian.C[SymmetricEntryOf[i][j]] + o);
      }
    }
    for (int e = 0; e < 10; ++e)
    {
      const int(&t)[3] = ThirdEntryIndices[e];
      const V value = hn::Load(d, f.Third[e] + o);
      // All six permutations of (i, j, k) hold the same derivative.
      const int perm[6][3] = { { t[0], t[1], t[2] }, { t[0], t[2], t[1] }, { t[1], t[0], t[2] },
        { t[1], t[2], t[0] }, { t[2], t[0], t[1] }, { t[2], t[1], t[0] } };
      for (const auto& p : perm)
      {
        third[p[0]][p[1]][p[2]] = value;
      }
    }
    M ok = hn::FirstN(d, static_cast<size_t>(n)); // all true
    const V one = hn::Set(d, 1.0);
    const V zero = hn::Zero(d);
    for (int i = 0; i < 3; ++i)
    {
      for (int j = i; j < 3; ++j)
      {
        const int e = SymmetricEntryOf[i][j];
        const V gij = hn::MulAdd(grad[i], grad[j], i == j ? one : zero);
        hn::Store(gij, d, jet.G.C[e] + o);
        ok = hn::And(ok, hn::IsFinite(gij));
        for (int k = 0; k < 3; ++k)
        {
          // d_k g_ij = f_ik f_j + f_i f_jk.
          const V dk = hn::MulAdd(hess[i][k], grad[j], hn::Mul(grad[i], hess[j][k]));
          hn::Store(dk, d, jet.D[k].C[e] + o);
          ok = hn::And(ok, hn::IsFinite(dk));
          for (int l = k; l < 3; ++l)
          {
            // d_k d_l g_ij = f_ikl f_j + f_ik f_jl + f_il f_jk + f_i f_jkl.
            V dkl = hn::Mul(third[i][k][l], grad[j]);
            dkl = hn::MulAdd(hess[i][k], hess[j][l], dkl);
            dkl = hn::MulAdd(hess[i][l], hess[j][k], dkl);
            dkl = hn::MulAdd(grad[i], third[j][k][l], dkl);
            hn::Store(dkl, d, jet.DD[SymmetricEntryOf[k][l]].C[e] + o);
            ok = hn::And(ok, hn::IsFinite(dkl));
          }
        }
      }
    }
    finite |= BitsAt(d, ok, o);
  }
  return finite;
}

LaneMask ConformalTensorJetFromJetImpl(const PacketScalarJet& index, PacketTensorJet& jet)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  LaneMask defined = 0;
  const V zero = hn::Zero(d);
  const V two = hn::Set(d, 2.0);
  for (int o = 0; o < PacketWidth; o += n)
  {
    const V value = hn::Load(d, index.Value + o);
    V grad[3];
    for (int i = 0; i < 3; ++i)
    {
      grad[i] = hn::Load(d, index.Gradient[i] + o);
    }
    // g = m delta with m = n^2, d_k m = 2 n n_k, d_k d_l m = 2 (n_k n_l + n n_kl).
    const V m = hn::Mul(value, value);
    M ok = hn::And(hn::Gt(value, zero), hn::IsFinite(m));
    const auto storeIsotropic = [&](PacketSym3& out, V diagonal)
    {
      hn::Store(diagonal, d, out.C[XX] + o);
      hn::Store(diagonal, d, out.C[YY] + o);
      hn::Store(diagonal, d, out.C[ZZ] + o);
      hn::Store(zero, d, out.C[XY] + o);
      hn::Store(zero, d, out.C[XZ] + o);
      hn::Store(zero, d, out.C[YZ] + o);
      ok = hn::And(ok, hn::IsFinite(diagonal));
    };
    storeIsotropic(jet.G, m);
    for (int k = 0; k < 3; ++k)
    {
      storeIsotropic(jet.D[k], hn::Mul(two, hn::Mul(value, grad[k])));
      for (int l = k; l < 3; ++l)
      {
        const int e = SymmetricEntryOf[k][l];
        const V nkl = hn::Load(d, index.Hessian.C[e] + o);
        storeIsotropic(jet.DD[e], hn::Mul(two, hn::MulAdd(grad[k], grad[l], hn::Mul(value, nkl))));
      }
    }
    defined |= BitsAt(d, ok, o);
  }
  return defined;
}
} // namespace HWY_NAMESPACE
} // namespace riemann
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace riemann
{
HWY_EXPORT(CurvatureFromTensorJetImpl);
HWY_EXPORT(JacobiAccelerationsFromTensorJetImpl);
HWY_EXPORT(SymmetricEigenvaluesImpl);
HWY_EXPORT(InverseTensorImpl);
HWY_EXPORT(GraphTensorJetFromJetImpl);
HWY_EXPORT(ConformalTensorJetFromJetImpl);

LaneMask CurvatureFromTensorJet(const PacketTensorJet& jet, PacketCurvature& curvature)
{
  return HWY_DYNAMIC_DISPATCH(CurvatureFromTensorJetImpl)(jet, curvature);
}

LaneMask JacobiAccelerationsFromTensorJet(
  const PacketTensorJet& jet, const PacketJacobiState& y, PacketJacobiState& dy)
{
  return HWY_DYNAMIC_DISPATCH(JacobiAccelerationsFromTensorJetImpl)(jet, y, dy);
}

void SymmetricEigenvalues(const PacketSym3& a, double (&eigenvalues)[3][PacketWidth])
{
  HWY_DYNAMIC_DISPATCH(SymmetricEigenvaluesImpl)(a, eigenvalues);
}

LaneMask InverseTensor(const PacketSym3& g, PacketSym3& inverse)
{
  return HWY_DYNAMIC_DISPATCH(InverseTensorImpl)(g, inverse);
}

LaneMask GraphTensorJetFromJet(const PacketScalarJet& f, PacketTensorJet& jet)
{
  return HWY_DYNAMIC_DISPATCH(GraphTensorJetFromJetImpl)(f, jet);
}

LaneMask ConformalTensorJetFromJet(const PacketScalarJet& n, PacketTensorJet& jet)
{
  return HWY_DYNAMIC_DISPATCH(ConformalTensorJetFromJetImpl)(n, jet);
}
} // namespace riemann
#endif
