#include "RiemannMedicalTensorImages.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNIFTIImageHeader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkPointData.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace riemann
{
namespace
{
/// Which values of a file's tuple become the "Tensors" components: VTK's
/// six (XX, YY, ZZ, XY, YZ, XZ) from the formats' orders, or all nine of a
/// row-major tensor (TensorGridFromImage checks that it is symmetric).
using ComponentPicks = std::vector<int>;
const ComponentPicks NiftiSymmetricMatrix = { 0, 2, 5, 1, 4, 3 }; // XX XY YY XZ YZ ZZ
const ComponentPicks UpperTriangle = { 0, 3, 5, 1, 4, 2 };        // XX XY XZ YY YZ ZZ
const ComponentPicks MaskedUpperTriangle = { 1, 4, 6, 2, 5, 3 };  // confidence, then as above
const ComponentPicks RowMajor = { 0, 1, 2, 3, 4, 5, 6, 7, 8 };

/// Make `image`'s point data the one array "Tensors": the `picks` of each
/// tuple of `source`, times `slope` plus `intercept`.
void SetTensors(vtkImageData* image, vtkDataArray* source, const ComponentPicks& picks,
  double slope, double intercept)
{
  vtkNew<vtkDoubleArray> tensors;
  tensors->SetName("Tensors");
  tensors->SetNumberOfComponents(static_cast<int>(picks.size()));
  tensors->SetNumberOfTuples(source->GetNumberOfTuples());
  std::vector<double> tuple(static_cast<std::size_t>(source->GetNumberOfComponents()));
  std::vector<double> value(picks.size());
  for (vtkIdType i = 0; i < source->GetNumberOfTuples(); ++i)
  {
    source->GetTuple(i, tuple.data());
    for (std::size_t c = 0; c < picks.size(); ++c)
    {
      value[c] = tuple[static_cast<std::size_t>(picks[c])] * slope + intercept;
    }
    tensors->SetTypedTuple(i, value.data());
  }
  image->GetPointData()->Initialize();
  image->GetPointData()->AddArray(tensors);
  image->GetPointData()->SetActiveTensors("Tensors");
}

/// The scalars of a reader's output, or an error naming what was found.
vtkDataArray* OnlyArray(vtkImageData* image, const char* format)
{
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!scalars || image->GetNumberOfPoints() == 0)
  {
    throw std::runtime_error(std::string("no ") + format + " image data could be read");
  }
  return scalars;
}

/// Place `image` (voxel (i, j, k) at origin + spacing * ijk in the reader's
/// frame) by the 4x4 `matrix` from that frame to world axes.
void PlaceByMatrix(vtkImageData* image, vtkMatrix4x4* matrix, const char* which)
{
  double origin[3];
  double spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  vtkNew<vtkMatrix3x3> direction;
  double worldOrigin[3];
  for (int r = 0; r < 3; ++r)
  {
    worldOrigin[r] = matrix->GetElement(r, 3);
    for (int c = 0; c < 3; ++c)
    {
      worldOrigin[r] += matrix->GetElement(r, c) * origin[c];
    }
  }
  double newSpacing[3];
  for (int c = 0; c < 3; ++c)
  {
    const double norm = std::sqrt(std::pow(matrix->GetElement(0, c), 2) +
      std::pow(matrix->GetElement(1, c), 2) + std::pow(matrix->GetElement(2, c), 2));
    if (!(norm > 0.0) || !std::isfinite(norm))
    {
      throw std::runtime_error(std::string("the ") + which + " matrix has a zero column");
    }
    newSpacing[c] = spacing[c] * norm;
    for (int r = 0; r < 3; ++r)
    {
      direction->SetElement(r, c, matrix->GetElement(r, c) / norm);
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    for (int b = a + 1; b < 3; ++b)
    {
      double dot = 0.0;
      for (int r = 0; r < 3; ++r)
      {
        dot += direction->GetElement(r, a) * direction->GetElement(r, b);
      }
      if (std::abs(dot) > 1e-5)
      {
        throw std::runtime_error(std::string("the ") + which +
          " matrix shears the voxel grid (its columns are not orthogonal); sampled metrics "
          "need a rotated grid of boxes");
      }
    }
  }
  image->SetOrigin(worldOrigin);
  image->SetSpacing(newSpacing);
  image->SetDirectionMatrix(direction);
}
} // namespace

vtkSmartPointer<vtkImageData> ReadNiftiTensorImage(const std::string& path)
{
  vtkNew<vtkNIFTIImageReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    throw std::runtime_error("not a NIfTI file");
  }
  // Six volumes (FSL) become six components, as the vector dimension does.
  reader->TimeAsVectorOn();
  reader->SetFileName(path.c_str());
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(reader->GetOutput());
  vtkDataArray* scalars = OnlyArray(image, "NIfTI");

  // Step 1: the components, in VTK's order.
  const int count = scalars->GetNumberOfComponents();
  vtkNIFTIImageHeader* header = reader->GetNIFTIHeader();
  const bool symmatrix = header->GetIntentCode() == vtkNIFTIImageHeader::IntentSymMatrix;
  double slope = reader->GetRescaleSlope();
  double intercept = reader->GetRescaleIntercept();
  if (slope == 0.0 || !std::isfinite(slope) || !std::isfinite(intercept))
  {
    slope = 1.0; // NIfTI: scl_slope 0 means "no scaling"
    intercept = 0.0;
  }
  if (count != 6 && count != 9)
  {
    std::ostringstream message;
    message << "the NIfTI image has " << count
            << " values per voxel; a tensor volume has 6 (a vector dimension or six volumes) "
               "or 9";
    throw std::runtime_error(message.str());
  }
  SetTensors(image, scalars,
    count == 9    ? RowMajor
      : symmatrix ? NiftiSymmetricMatrix
                  : UpperTriangle,
    slope, intercept);

  // Step 2: the placement, q-form first.
  if (header->GetQFormCode() > 0 && reader->GetQFormMatrix())
  {
    PlaceByMatrix(image, reader->GetQFormMatrix(), "q-form");
  }
  else if (header->GetSFormCode() > 0 && reader->GetSFormMatrix())
  {
    PlaceByMatrix(image, reader->GetSFormMatrix(), "s-form");
  }
  return image;
}

vtkSmartPointer<vtkImageData> ReadNrrdTensorImage(const std::string& path)
{
  vtkNew<vtkNrrdReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    throw std::runtime_error("not a NRRD file vtkNrrdReader can read (raw or gzip encoding)");
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(reader->GetOutput());
  vtkDataArray* scalars = OnlyArray(image, "NRRD");
  const int count = scalars->GetNumberOfComponents();
  if (count != 6 && count != 7 && count != 9)
  {
    std::ostringstream message;
    message << "the NRRD image has " << count
            << " values per voxel; a tensor volume has 6 (3D-symmetric-matrix), 7 "
               "(3D-masked-symmetric-matrix) or 9";
    throw std::runtime_error(message.str());
  }
  SetTensors(image, scalars,
    count == 9     ? RowMajor
      : count == 7 ? MaskedUpperTriangle
                   : UpperTriangle,
    1.0, 0.0);
  return image;
}
} // namespace riemann
