/**
 * @file vtkRiemannDistanceImage.h
 * @brief A distance field image (vtkRiemannDistanceField's output) read back
 * as the core's field (riemann::DistanceGrid, DistanceFieldResult), for the
 * filters that use one: vtkRiemannCutLocus and vtkRiemannMinimalGeodesics.
 *
 * A private header of Riemann::CommonCore (not wrapped, not installed), as
 * vtkRiemannParallelBatches.h; its users link Riemann::CommonDistance.
 */
#ifndef vtkRiemannDistanceImage_h
#define vtkRiemannDistanceImage_h

#include "DistanceField.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

#include <cmath>
#include <limits>
#include <vector>

/// The grid of `image` (its extent's first point as the origin), as the core's.
inline riemann::DistanceGrid vtkRiemannDistanceGridOf(vtkImageData* image)
{
  riemann::DistanceGrid grid;
  double origin[3], spacing[3];
  int dims[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  image->GetDimensions(dims);
  const int* extent = image->GetExtent();
  for (int a = 0; a < 3; ++a)
  {
    grid.Origin[a] = origin[a] + extent[2 * a] * spacing[a];
    grid.Spacing[a] = spacing[a];
    grid.Dimensions[static_cast<std::size_t>(a)] = dims[a];
  }
  return grid;
}

/**
 * The grid, the point arrays Distance (NaN: unreached), ArrivalDirection and
 * SeedId, and (when `seeds` is given) the field data Seeds of `image`. False
 * when an array is missing or has the wrong number of components.
 */
inline bool vtkRiemannReadDistanceImage(vtkImageData* image, riemann::DistanceGrid& grid,
  riemann::DistanceFieldResult& field, std::vector<riemann::Vec3>* seeds = nullptr)
{
  vtkPointData* pd = image->GetPointData();
  vtkDataArray* distance = pd->GetArray("Distance");
  vtkDataArray* direction = pd->GetArray("ArrivalDirection");
  vtkDataArray* seed = pd->GetArray("SeedId");
  vtkDataArray* seedPoints = image->GetFieldData()->GetArray("Seeds");
  if (!distance || !direction || !seed || direction->GetNumberOfComponents() != 3 ||
    (seeds && (!seedPoints || seedPoints->GetNumberOfComponents() != 3)))
  {
    return false;
  }
  grid = vtkRiemannDistanceGridOf(image);
  const vtkIdType count = image->GetNumberOfPoints();
  field.Distance.resize(static_cast<std::size_t>(count));
  field.ArrivalDirection.resize(3 * static_cast<std::size_t>(count));
  field.SeedId.resize(static_cast<std::size_t>(count));
  for (vtkIdType n = 0; n < count; ++n)
  {
    const double u = distance->GetTuple1(n);
    field.Distance[static_cast<std::size_t>(n)] =
      std::isfinite(u) ? u : std::numeric_limits<double>::infinity();
    direction->GetTuple(n, field.ArrivalDirection.data() + 3 * n);
    field.SeedId[static_cast<std::size_t>(n)] = static_cast<int>(seed->GetTuple1(n));
  }
  if (seeds)
  {
    seeds->clear();
    for (vtkIdType s = 0; s < seedPoints->GetNumberOfTuples(); ++s)
    {
      double p[3];
      seedPoints->GetTuple(s, p);
      seeds->emplace_back(p[0], p[1], p[2]);
    }
  }
  return true;
}

#endif
