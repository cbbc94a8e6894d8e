/**
 * @file RiemannGzipNrrd.h
 * @brief Private to Common/Core: the values of a gzip-encoded NRRD file,
 * inflated with zlib.
 *
 * VTK 9.1's vtkNrrdReader misreads gzip bodies: a 40^3 volume of
 * diag(2, 3, 4) tensors came back with 47,998 of its 64,000 tuples zero,
 * without an error (so "not positive definite", or with "repair": "clamp"
 * a wrong metric). ReadGzipNrrdImage reads such a file itself: the values
 * inflated to exactly the size the header declares (more or fewer is an
 * error), in the file's byte order, as an image with the first axis as
 * components (dimension 4) and "spacings" as its spacing. The placement by
 * "space directions" and "space origin" is applied afterwards, as for raw
 * files (RiemannMedicalTensorImages).
 */
#ifndef RiemannGzipNrrd_h
#define RiemannGzipNrrd_h

#include "vtkImageData.h"
#include "vtkSmartPointer.h"

#include <string>

namespace riemann
{
/// True when the NRRD file's header says "encoding: gzip" (or "gz").
bool IsGzipNrrd(const std::string& path);

/// The image of a gzip-encoded NRRD file (checked by CheckNrrdFile first); throws
/// std::runtime_error naming what is wrong.
vtkSmartPointer<vtkImageData> ReadGzipNrrdImage(const std::string& path);
} // namespace riemann

#endif
