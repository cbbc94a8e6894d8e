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
 * Value, gradient and Hessian of a scalar field at W points (what the
 * geodesic flow needs: no third derivatives, which only curvature reads and
 * the scalar ScalarJet keeps).
 */
struct alignas(64) PacketScalarJet
{
  double Value[PacketWidth];
  double Gradient[3][PacketWidth];
  PacketSym3 Hessian;

  /// Zero every entry up to and including `order` (at most SecondDerivatives).
  void SetZero(int order);
};

/// The geodesic flow's state (x, v) of W geodesics.
struct alignas(64) PacketState
{
  PacketVec3 X;
  PacketVec3 V;

  /// Component i of (x, v), i in [0, 6): the integrators' view.
  double* Component(int i) { return i < 3 ? this->X.C[i] : this->V.C[i - 3]; }
  const double* Component(int i) const { return i < 3 ? this->X.C[i] : this->V.C[i - 3]; }
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
}
} // namespace riemann

#endif
