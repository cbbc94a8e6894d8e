/**
 * @file RiemannScalarImages.h
 * @brief Masks and label images for tractography (issue 31): one value per
 * voxel, in any of the formats the tensor volumes come in (NIfTI, NRRD, VTK
 * XML or legacy image data), placed in world coordinates by the file's own
 * affine, and the seed points a mask gives.
 */
#ifndef RiemannScalarImages_h
#define RiemannScalarImages_h

#include "RiemannIOMedicalModule.h" // For export macro

#include "TractStops.h"      // For VoxelMask
#include "vtkSmartPointer.h" // For the returned images

#include <string>
#include <vector>

class vtkImageData;

namespace riemann
{
/**
 * Read `path` (.nii, .nii.gz, .nrrd, .nhdr, .vti, .vtk) as an image of one
 * value per voxel, named "Scalars", placed in world coordinates (origin,
 * spacing and direction). `what` names the file in messages ("the seed
 * mask"). Throws std::runtime_error naming the file and the problem (not a
 * regular file, unknown format, several values per voxel, ...).
 */
RIEMANNIOMEDICAL_EXPORT vtkSmartPointer<vtkImageData> ReadScalarImageFile(
  const std::string& path, const std::string& what);

/**
 * Seed points of a mask: `perVoxel` points in each voxel whose value is not
 * 0, in world coordinates. One per voxel is its centre; more are spread
 * uniformly over the voxel's box (±half a voxel along its axes), from a
 * generator seeded by `randomSeed`, so the same arguments give the same
 * points. Three coordinates per point.
 */
RIEMANNIOMEDICAL_EXPORT std::vector<double> MaskSeedPoints(
  vtkImageData* mask, int perVoxel, unsigned randomSeed);
/**
 * The image's active scalars as a VoxelMask (set where not 0), with the
 * image's origin, spacing and direction. An image without scalars gives an
 * empty mask.
 */
RIEMANNIOMEDICAL_EXPORT VoxelMask VoxelMaskFromImage(vtkImageData* image);
} // namespace riemann

#endif
