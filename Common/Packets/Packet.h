/**
 * @file Packet.h
 * @brief Packets: PacketWidth geodesics (points, vectors, jets) side by side,
 * as structures of arrays, so that the metric and the integrators process
 * them with one SIMD instruction per operation (PacketKernels.h).
 *
 * A packet always holds PacketWidth lanes: 8 doubles are one AVX-512
 * register, two AVX2 or four SSE registers, so the same layout serves every
 * target that Highway's runtime dispatch picks. A LaneMask says which lanes
 * are in use (bit l = lane l); lanes outside it hold finite values that
 * nobody reads, so SIMD code may compute them without a branch.
 */
#ifndef RiemannPacket_h
#define RiemannPacket_h

#include "Jets.h"

#include <cstdint>

namespace riemann
{
/// Lanes of a packet.
constexpr int PacketWidth = 8;

/// Bit l set = lane l is in use.
using LaneMask = std::uint32_t;
constexpr LaneMask AllLanes = (LaneMask{ 1 } << PacketWidth) - 1;

inline bool HasLane(LaneMask mask, int lane)
{
  return ((mask >> lane) & 1u) != 0;
}

/// W points or vectors: C[i][l] = component i of lane l.
struct alignas(64) PacketVec3
{
  double C[3][PacketWidth];

  Vec3 Lane(int l) const { return Vec3(this->C[0][l], this->C[1][l], this->C[2][l]); }
  void SetLane(int l, const Vec3& value)
  {
    for (int i = 0; i < 3; ++i)
    {
      this->C[i][l] = value[i];
    }
  }
};

/// The 6 distinct entries of a symmetric 3x3 matrix per lane.
enum SymmetricEntry : int
{
  XX = 0,
  YY = 1,
  ZZ = 2,
  XY = 3,
  XZ = 4,
  YZ = 5
};

/// A symmetric 3x3 matrix per lane: C[e][l], e a SymmetricEntry.
struct alignas(64) PacketSym3
{
  double C[6][PacketWidth];

  Mat3 Lane(int l) const
  {
    Mat3 m;
    m << this->C[XX][l], this->C[XY][l], this->C[XZ][l], //
      this->C[XY][l], this->C[YY][l], this->C[YZ][l],    //
      this->C[XZ][l], this->C[YZ][l], this->C[ZZ][l];
    return m;
  }
  void SetLane(int l, const Mat3& m)
  {
    this->C[XX][l] = m(0, 0);
    this->C[YY][l] = m(1, 1);
    this->C[ZZ][l] = m(2, 2);
    this->C[XY][l] = m(0, 1);
    this->C[XZ][l] = m(0, 2);
    this->C[YZ][l] = m(1, 2);
  }
};

/**
 * g and its exact first and second derivatives at W points (what curvature
 * needs): D[k] = d_k g and DD[e] = d_k d_l g for the pair (k, l) of the
 * SymmetricEntry e (XX = (0, 0), XY = (0, 1), ...).
 */
/// The SymmetricEntry of (i, j), any order.
constexpr int SymmetricEntryOf[3][3] = { { XX, XY, XZ }, { XY, YY, YZ }, { XZ, YZ, ZZ } };

struct alignas(64) PacketTensorJet
{
  PacketSym3 G;
  PacketSym3 D[3];
  PacketSym3 DD[6];

  /// Lane l from the scalar form (Metric::TensorSecondDerivatives').
  void SetLane(int l, const Mat3& g, const Mat3Stack& dg, const std::array<Mat3Stack, 3>& d2g)
  {
    this->G.SetLane(l, g);
    for (int k = 0; k < 3; ++k)
    {
      this->D[k].SetLane(l, dg[k]);
      for (int m = k; m < 3; ++m)
      {
        this->DD[SymmetricEntryOf[k][m]].SetLane(l, d2g[k][m]);
      }
    }
  }

  /// Lane l as flat space (g = I, no derivatives): finite filler for lanes not in use.
  void SetFlatLane(int l)
  {
    const Mat3 zero = Mat3::Zero();
    this->SetLane(l, Mat3::Identity(), { zero, zero, zero },
      { Mat3Stack{ zero, zero, zero }, Mat3Stack{ zero, zero, zero },
        Mat3Stack{ zero, zero, zero } });
  }
};

/// The 10 distinct third derivatives d_i d_j d_k f, indices sorted.
enum ThirdEntry : int
{
  XXX = 0,
  YYY = 1,
  ZZZ = 2,
  XXY = 3,
  XXZ = 4,
  XYY = 5,
  XYZ = 6,
  XZZ = 7,
  YYZ = 8,
  YZZ = 9
};

/**
 * Value and derivatives of a scalar field at W points. The geodesic flow
 * reads up to the Hessian; the Jacobi system of the graph family also reads
 * the third derivatives (Third[e][l], e a ThirdEntry), which are filled only
 * when ThirdDerivatives is asked for.
 */
struct alignas(64) PacketScalarJet
{
  double Value[PacketWidth];
  double Gradient[3][PacketWidth];
  PacketSym3 Hessian;
  double Third[10][PacketWidth];

  /// Zero every entry up to and including `order`.
  void SetZero(int order);
};

/// The indices (i, j, k) of each ThirdEntry, i <= j <= k.
constexpr int ThirdEntryIndices[10][3] = { { 0, 0, 0 }, { 1, 1, 1 }, { 2, 2, 2 }, { 0, 0, 1 },
  { 0, 0, 2 }, { 0, 1, 1 }, { 0, 1, 2 }, { 0, 2, 2 }, { 1, 1, 2 }, { 1, 2, 2 } };

/// The geodesic flow's state (x, v) of W geodesics.
struct alignas(64) PacketState
{
  /// Components per lane.
  static constexpr int Size = 6;
  PacketVec3 X;
  PacketVec3 V;

  /// Component i of (x, v), i in [0, 6): the integrators' view.
  double* Component(int i) { return i < 3 ? this->X.C[i] : this->V.C[i - 3]; }
  const double* Component(int i) const { return i < 3 ? this->X.C[i] : this->V.C[i - 3]; }
};

/**
 * The Jacobi system's state of W geodesics (JacobiField.h): x, v and the
 * two variations (J_a, DJ_a), in the order of the scalar 18-vector
 * (x, v, J_0, DJ_0, J_1, DJ_1).
 */
struct alignas(64) PacketJacobiState
{
  static constexpr int Size = 18;
  PacketVec3 X;
  PacketVec3 V;
  PacketVec3 J[2];
  PacketVec3 DJ[2];

  /// Component i in [0, 18) of (x, v, J_0, DJ_0, J_1, DJ_1).
  double* Component(int i) { return this->Vector(i / 3).C[i % 3]; }
  const double* Component(int i) const
  {
    return const_cast<PacketJacobiState*>(this)->Vector(i / 3).C[i % 3];
  }

private:
  PacketVec3& Vector(int block)
  {
    switch (block)
    {
      case 0:
        return this->X;
      case 1:
        return this->V;
      case 2:
        return this->J[0];
      case 3:
        return this->DJ[0];
      case 4:
        return this->J[1];
      default:
        return this->DJ[1];
    }
  }
};

inline void PacketScalarJet::SetZero(int order)
{
  for (double& value : this->Value)
  {
    value = 0.0;
  }
  if (order >= FirstDerivatives)
  {
    for (auto& component : this->Gradient)
    {
      for (double& value : component)
      {
        value = 0.0;
      }
    }
  }
  if (order >= SecondDerivatives)
  {
    for (auto& entry : this->Hessian.C)
    {
      for (double& value : entry)
      {
        value = 0.0;
      }
    }
  }
  if (order >= ThirdDerivatives)
  {
    for (auto& entry : this->Third)
    {
      for (double& value : entry)
      {
        value = 0.0;
      }
    }
  }
}
} // namespace riemann

#endif
