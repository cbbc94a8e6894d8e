/**
 * @file RiemannTensorImage.h
 * @brief Tensor volumes as the metric core's grids (issue 17): a
 * vtkImageData's tensor array, or a file of one, to a SampledTensorGrid.
 * The reader behind {"type": "sampled"} (vtkRiemannMetric installs it) and
 * vtkRiemannMetric::SetTensorData.
 */
#ifndef RiemannTensorImage_h
#define RiemannTensorImage_h

#include "MetricDefinition.h" // For SampledTensorFrame
#include "RiemannIOMedicalModule.h" // For export macro
#include "SampledTensorField.h"

#include <string>

class vtkImageData;

namespace riemann
{
/**
 * The grid of `image`'s point-data tensor array `arrayName` ("": the
 * active tensors, else the one array of 6 or 9 components): its origin,
 * spacing and direction, and its tensors, 6 components in VTK's order (XX,
 * YY, ZZ, XY, YZ, XZ) or 9 (row-major, which must be symmetric). Throws
 * std::runtime_error saying what is missing or wrong.
 */
RIEMANNIOMEDICAL_EXPORT SampledTensorGrid TensorGridFromImage(vtkImageData* image, const std::string& arrayName);

/**
 * Read `path` (VTK XML image data .vti, legacy .vtk structured points,
 * NIfTI .nii/.nii.gz or NRRD .nrrd/.nhdr: RiemannMedicalTensorImages.h)
 * and return TensorGridFromImage of it; errors name the file. The tensors
 * are in `frame` (SampledTensorFrame::Fsl: NIfTI files only), a NIfTI
 * file's six values in the order `components` (given for NIfTI files only).
 */
RIEMANNIOMEDICAL_EXPORT SampledTensorGrid ReadTensorGridFile(const std::string& path,
  const std::string& arrayName, SampledTensorFrame frame,
  SampledTensorComponents components = SampledTensorComponents::FromFile);
}

#endif
