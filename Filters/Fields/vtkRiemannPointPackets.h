/**
 * @file vtkRiemannPointPackets.h
 * @brief The field filters' walk over points in packets of
 * riemann::PacketWidth (the packet engine, Packet.h): the metric is then
 * evaluated at a packet of points at once. Private to Riemann::FiltersFields.
 */
#ifndef vtkRiemannPointPackets_h
#define vtkRiemannPointPackets_h

#include "Packet.h"
#include "vtkDataSet.h"

#include <algorithm>

/**
 * Call `work(start, count, x, lanes)` for the points [first, last) of
 * `points` in packets: points start .. start + count - 1 in lanes
 * 0 .. count - 1 of x (`lanes` marks them); a partial packet's other lanes
 * repeat its last point, so every lane holds a finite point.
 */
template <class Work>
void vtkRiemannForEachPointPacket(
  vtkDataSet* points, vtkIdType first, vtkIdType last, const Work& work)
{
  riemann::PacketVec3 x;
  for (vtkIdType start = first; start < last; start += riemann::PacketWidth)
  {
    const int count = static_cast<int>(std::min<vtkIdType>(riemann::PacketWidth, last - start));
    for (int l = 0; l < riemann::PacketWidth; ++l)
    {
      double p[3];
      points->GetPoint(start + std::min(l, count - 1), p);
      x.SetLane(l, riemann::Vec3(p[0], p[1], p[2]));
    }
    work(start, count, x, (riemann::LaneMask{ 1 } << count) - 1);
  }
}

#endif
