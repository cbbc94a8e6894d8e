/**
 * @file RiemannMedicalTensorImages.h
 * @brief Diffusion-tensor volumes in the formats medical imaging writes them
 * (issue 17): NIfTI-1 (.nii, .nii.gz, through vtkNIFTIImageReader) and NRRD
 * (.nrrd, .nhdr, through vtkNrrdReader), as a vtkImageData placed in world
 * coordinates with a 6-component "Tensors" array in VTK's order (XX, YY, ZZ,
 * XY, YZ, XZ): what TensorGridFromImage reads.
 */
#ifndef RiemannMedicalTensorImages_h
#define RiemannMedicalTensorImages_h

#include "MetricDefinition.h" // For SampledTensorFrame
#include "vtkSmartPointer.h"  // For the returned images

#include <string>

class vtkImageData;

namespace riemann
{
/**
 * Read a NIfTI tensor volume. Placement: the q-form when the file has one
 * (qform_code > 0), else the s-form, else the voxel grid at the origin
 * (the matrices map voxel centres to the file's world axes, RAS for
 * scanner data). An s-form with shear or unequal column norms beyond the
 * voxel sizes is refused. Components: six per voxel, stored as the vector
 * dimension (dim[5]) or as six volumes (dim[4]), in the order `components`
 * says (FSL's, MRtrix's or DIPY's: SampledTensorComponents); with intent
 * NIFTI_INTENT_SYMMATRIX (1005) the file says NIfTI's lower-triangle order
 * (XX, XY, YY, XZ, YZ, ZZ, DIPY's), and another `components` is refused;
 * without that intent and without `components` the file is refused (the
 * writers disagree: never guessed). Or nine, row-major (no `components`).
 * scl_slope and scl_inter are applied. The tensors are taken in the world
 * axes of the placement (MRtrix writes them so), or with `frame`
 * SampledTensorFrame::Fsl in FSL's voxel axes (dtifit's, and DIPY's from
 * FSL-style bvecs): the file's voxel axes, the first reversed when the
 * placement's matrix, qfac included, has a positive determinant; they are
 * turned to world axes, D -> A D A^T (A: those axes as columns). Throws
 * std::runtime_error saying what is wrong.
 */
vtkSmartPointer<vtkImageData> ReadNiftiTensorImage(const std::string& path,
  SampledTensorFrame frame = SampledTensorFrame::World,
  SampledTensorComponents components = SampledTensorComponents::FromFile);

/**
 * Read a NRRD tensor volume: 6 components per voxel in Teem's order (XX,
 * XY, XZ, YY, YZ, ZZ: kind "3D-symmetric-matrix"), 7 (Teem's
 * "3D-masked-symmetric-matrix": a confidence value first, dropped) or 9
 * (row-major), on the axis that comes first. Placed by the header's "space
 * directions" (world step along each voxel axis; rotated grids included,
 * sheared ones refused) and "space origin", read from the header itself
 * (vtkNrrdReader keeps only the directions' lengths); without them, by the
 * spacings and origin vtkNrrdReader reads. Tensors given in a "measurement
 * frame" M (its vectors are M's columns, the frame's axes in world
 * coordinates) are turned to world axes, D -> M D M^T. vtkNrrdReader
 * misreads ASCII-encoded doubles, so raw or gzip encodings are the ones to
 * use. Throws std::runtime_error.
 */
vtkSmartPointer<vtkImageData> ReadNrrdTensorImage(const std::string& path);

/**
 * Read a NIfTI or NRRD image of one value per voxel (a mask, a label
 * image), placed in world coordinates as the tensor readers place theirs
 * (NIfTI: q-form, else s-form; NRRD: space directions and origin), its
 * values (NIfTI's scl_slope and scl_inter applied) as a double array
 * "Scalars". Throws std::runtime_error saying what is wrong.
 */
vtkSmartPointer<vtkImageData> ReadNiftiScalarImage(const std::string& path);
vtkSmartPointer<vtkImageData> ReadNrrdScalarImage(const std::string& path);
}

#endif
