#include "Metric.h"

#include "Christoffel.h"
#include "PacketCurvature.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <sstream>

namespace riemann
{
bool Metric::Acceleration(const Vec3& p, const Vec3& v, Vec3& a) const
{
  Mat3Stack gamma;
  if (!this->Christoffel(p, gamma))
  {
    return false;
  }
  a = ContractChristoffel(gamma, v);
  return a.allFinite();
}

LaneMask Metric::AccelerationPacket(
  const PacketVec3& x, const PacketVec3& v, PacketVec3& a, LaneMask lanes) const
{
  LaneMask defined = 0;
  for (int l = 0; l < PacketWidth; ++l)
  {
    Vec3 lane = Vec3::Zero();
    if (HasLane(lanes, l) && this->Acceleration(x.Lane(l), v.Lane(l), lane))
    {
      defined |= LaneMask{ 1 } << l;
    }
    a.SetLane(l, lane);
  }
  return defined;
}

LaneMask Metric::JacobiAccelerationPacket(
  const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes) const
{
  // g and its derivatives from the family (lane by lane unless it has a
  // packet form), then the connection and the contraction on the packet.
  PacketTensorJet jet;
  const LaneMask derived = this->TensorSecondDerivativesPacket(y.X, jet, lanes);
  return JacobiAccelerationsFromTensorJet(jet, y, dy) & derived & lanes;
}

void Metric::VolumeFormPacket(const PacketVec3& x, double* volume, LaneMask lanes) const
{
  for (int l = 0; l < PacketWidth; ++l)
  {
    if (HasLane(lanes, l))
    {
      volume[l] = this->VolumeForm(x.Lane(l));
    }
  }
}

LaneMask Metric::TensorSecondDerivativesPacket(
  const PacketVec3& x, PacketTensorJet& jet, LaneMask lanes) const
{
  LaneMask defined = 0;
  Mat3 g;
  Mat3Stack dg;
  std::array<Mat3Stack, 3> d2g;
  for (int l = 0; l < PacketWidth; ++l)
  {
    if (HasLane(lanes, l) && this->TensorSecondDerivatives(x.Lane(l), g, dg, d2g))
    {
      defined |= LaneMask{ 1 } << l;
      jet.SetLane(l, g, dg, d2g);
    }
    else
    {
      jet.SetFlatLane(l);
    }
  }
  return defined;
}

LaneMask Metric::TensorPacket(const PacketVec3& x, PacketSym3& g, LaneMask lanes) const
{
  LaneMask defined = 0;
  for (int l = 0; l < PacketWidth; ++l)
  {
    Mat3 lane = Mat3::Identity();
    if (HasLane(lanes, l) && this->Tensor(x.Lane(l), lane))
    {
      defined |= LaneMask{ 1 } << l;
    }
    g.SetLane(l, lane);
  }
  return defined;
}

bool Metric::TensorSecondDerivatives(
  const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const
{
  (void)p;
  (void)g;
  (void)dg;
  (void)d2g;
  return false;
}

bool Metric::InverseTensor(const Vec3& p, Mat3& inverse) const
{
  Mat3 g;
  if (!this->Tensor(p, g))
  {
    return false;
  }
  const Eigen::LLT<Mat3> llt(g);
  if (llt.info() != Eigen::Success)
  {
    return false;
  }
  inverse = llt.solve(Mat3::Identity());
  return inverse.allFinite();
}

double Metric::VolumeForm(const Vec3& p) const
{
  Mat3 g;
  if (!this->Tensor(p, g))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double det = g.determinant();
  return det > 0 ? std::sqrt(det) : std::numeric_limits<double>::quiet_NaN();
}

double Metric::InnerProduct(const Vec3& p, const Vec3& u, const Vec3& w) const
{
  Mat3 g;
  if (!this->Tensor(p, g))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return u.dot(g * w);
}

void Metric::EmitGlsl(GlslBuilder& /*builder*/) const
{
  throw GlslUnsupportedError(
    "the " + this->FamilyName() + " metric " + this->Describe() + " has no GLSL form");
}

std::string Metric::Validate() const
{
  std::vector<Vec3> points;
  constexpr int n = 11;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int k = 0; k < n; ++k)
      {
        points.push_back(Vec3(i, j, k) - Vec3::Constant(5.0));
      }
    }
  }
  this->AppendSamplePoints(points);
  // g at PacketWidth points at a time (the packet engine's TensorPacket: one
  // SIMD evaluation for the bumps' tens of thousands of sample points).
  PacketVec3 packet;
  PacketSym3 tensors;
  for (size_t first = 0; first < points.size(); first += PacketWidth)
  {
    const int count = static_cast<int>(std::min<size_t>(PacketWidth, points.size() - first));
    for (int l = 0; l < PacketWidth; ++l)
    {
      packet.SetLane(l, points[first + static_cast<size_t>(std::min(l, count - 1))]);
    }
    const LaneMask lanes = (LaneMask{ 1 } << count) - 1;
    const LaneMask defined = this->TensorPacket(packet, tensors, lanes);
    for (int l = 0; l < count; ++l)
    {
      const Vec3& p = points[first + static_cast<size_t>(l)];
      const Mat3 g = tensors.Lane(l);
      const Eigen::LLT<Mat3> llt(g);
      if (HasLane(defined, l) && g.allFinite() && llt.info() == Eigen::Success)
      {
        continue;
      }
      std::ostringstream s;
      s << this->FamilyName() << " metric is not positive definite at (" << p.transpose() << ")";
      if (g.allFinite())
      {
        s << ": eigenvalues of g are ("
          << Eigen::SelfAdjointEigenSolver<Mat3>(g, Eigen::EigenvaluesOnly)
               .eigenvalues()
               .transpose()
          << ")";
      }
      return s.str();
    }
  }
  return {};
}
} // namespace riemann
