#include "RiemannMedicalTensorImages.h"
#include "RiemannGzipNrrd.h"
#include "RiemannTensorFileChecks.h"

#include "vtkCharArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNIFTIImageHeader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <array>
#include <cmath>
#include <fstream>
#include <map>
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
const ComponentPicks MrtrixOrder = { 0, 1, 2, 3, 5, 4 };          // XX YY ZZ XY XZ YZ
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

/**
 * Turn `image`'s "Tensors" from the frame whose axes (in world coordinates)
 * are the columns of `m` to world axes: D -> M D M^T.
 */
void TurnTensors(vtkImageData* image, const double m[3][3])
{
  double mT[3][3];
  vtkMath::Transpose3x3(m, mT);
  vtkDataArray* tensors = image->GetPointData()->GetArray("Tensors");
  const int count = tensors->GetNumberOfComponents();
  // VTK's order of the six: XX, YY, ZZ, XY, YZ, XZ; nine are row-major.
  const int sixRow[6] = { 0, 1, 2, 0, 1, 0 }, sixColumn[6] = { 0, 1, 2, 1, 2, 2 };
  std::vector<double> tuple(static_cast<std::size_t>(count));
  for (vtkIdType i = 0; i < tensors->GetNumberOfTuples(); ++i)
  {
    tensors->GetTuple(i, tuple.data());
    double d[3][3];
    for (int k = 0; k < count; ++k)
    {
      const int r = count == 6 ? sixRow[k] : k / 3, c = count == 6 ? sixColumn[k] : k % 3;
      d[r][c] = tuple[static_cast<std::size_t>(k)];
      if (count == 6)
      {
        d[c][r] = d[r][c]; // nine are kept as written (their symmetry is checked later)
      }
    }
    double md[3][3];
    double world[3][3];
    vtkMath::Multiply3x3(m, d, md);
    vtkMath::Multiply3x3(md, mT, world);
    for (int k = 0; k < count; ++k)
    {
      tuple[static_cast<std::size_t>(k)] =
        count == 6 ? world[sixRow[k]][sixColumn[k]] : world[k / 3][k % 3];
    }
    tensors->SetTuple(i, tuple.data());
  }
}

/**
 * The axes of FSL's frame in world coordinates, as the columns of `axes`:
 * a NIfTI file's voxel axes (the columns of the reader's `matrix`, the third
 * reversed where the reader reversed the slices, qfac -1), the first
 * reversed when they are right-handed (FSL's "neurological" storage; its
 * voxel frame is always left-handed, "radiological").
 */
void FslFrameAxes(vtkMatrix4x4* matrix, double qfac, double axes[3][3])
{
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      axes[r][c] = matrix->GetElement(r, c);
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    const double norm =
      std::sqrt(axes[0][c] * axes[0][c] + axes[1][c] * axes[1][c] + axes[2][c] * axes[2][c]);
    const double sign = c == 2 && qfac < 0.0 ? -1.0 : 1.0;
    for (int r = 0; r < 3; ++r)
    {
      axes[r][c] *= sign / norm; // PlaceByMatrix refused zero columns
    }
  }
  if (vtkMath::Determinant3x3(axes) > 0.0)
  {
    for (int r = 0; r < 3; ++r)
    {
      axes[r][0] = -axes[r][0];
    }
  }
}

/**
 * vtkNrrdReader, blind to the header's "space" and "space dimension" lines:
 * they are made comments of the same length before it parses the header.
 * VTK 9.1 lets either line reset the array's dimension to 3, so a 4D tensor
 * file in the usual order (dimension, space, sizes: Slicer's and Teem's)
 * lost its last axis; a left-handed "space" also flipped the rows. The
 * placement comes from ApplyNrrdSpace instead.
 */
class SpaceBlindNrrdReader : public vtkNrrdReader
{
public:
  static SpaceBlindNrrdReader* New();
  vtkTypeMacro(SpaceBlindNrrdReader, vtkNrrdReader);

protected:
  SpaceBlindNrrdReader() = default;
  ~SpaceBlindNrrdReader() override = default;

  int ReadHeader(vtkCharArray* header) override
  {
    char* text = header->GetPointer(0);
    const std::string copy(text, static_cast<std::size_t>(header->GetNumberOfTuples()));
    for (std::size_t start = 0; start < copy.size();)
    {
      if (copy.compare(start, 7, "space: ") == 0 ||
        copy.compare(start, 17, "space dimension: ") == 0)
      {
        text[start] = '#';
      }
      const std::size_t end = copy.find('\n', start);
      start = end == std::string::npos ? copy.size() : end + 1;
    }
    return this->Superclass::ReadHeader(header);
  }

private:
  SpaceBlindNrrdReader(const SpaceBlindNrrdReader&) = delete;
  void operator=(const SpaceBlindNrrdReader&) = delete;
};
vtkStandardNewMacro(SpaceBlindNrrdReader);

/// The vectors "(a,b,c)" of a NRRD field's value, in order; "none" gives no vector.
std::vector<std::array<double, 3>> NrrdVectors(const std::string& value, const std::string& field)
{
  std::vector<std::array<double, 3>> vectors;
  std::size_t at = 0;
  while ((at = value.find_first_not_of(" \t", at)) != std::string::npos)
  {
    if (value.compare(at, 4, "none") == 0)
    {
      at += 4;
      continue;
    }
    const std::size_t close = value.find(')', at);
    std::array<double, 3> v;
    char open = 0, comma1 = 0, comma2 = 0;
    std::istringstream text(close == std::string::npos ? "" : value.substr(at, close - at));
    text >> open >> v[0] >> comma1 >> v[1] >> comma2 >> v[2];
    // Nothing may follow z before ')' (a missing ')' would swallow the next vector).
    const bool parsed = static_cast<bool>(text);
    std::string rest;
    text.clear();
    text >> rest;
    const bool whole = parsed && rest.empty();
    if (!whole || value[at] != '(' || close == std::string::npos || open != '(' || comma1 != ',' ||
      comma2 != ',' || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    {
      throw std::runtime_error("the NRRD field \"" + field + ": " + value +
        "\" is not a list of 3D vectors (x,y,z) and none");
    }
    vectors.push_back(v);
    at = close + 1;
  }
  return vectors;
}

/**
 * Place a NRRD volume by its "space directions" (the world step along each
 * voxel axis) and "space origin" (the first voxel's centre), as the file
 * says, and turn its tensors from the "measurement frame" (columns: the
 * frame's axes in world coordinates) to world axes: D -> M D M^T.
 */
void ApplyNrrdSpace(vtkImageData* image, const std::string& path)
{
  const std::map<std::string, std::string> fields = ReadNrrdHeader(path).Fields;
  const auto directions = fields.find("space directions");
  if (directions != fields.end())
  {
    const auto axes = NrrdVectors(directions->second, directions->first);
    if (axes.size() != 3)
    {
      throw std::runtime_error("the NRRD field \"space directions\" gives " +
        std::to_string(axes.size()) + " voxel axes; a tensor volume has 3");
    }
    vtkNew<vtkMatrix4x4> voxelToWorld;
    std::array<double, 3> origin = { 0.0, 0.0, 0.0 };
    const auto spaceOrigin = fields.find("space origin");
    if (spaceOrigin != fields.end())
    {
      const auto points = NrrdVectors(spaceOrigin->second, spaceOrigin->first);
      if (points.size() != 1)
      {
        throw std::runtime_error("the NRRD field \"space origin\" is not one point (x,y,z)");
      }
      origin = points[0];
    }
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        voxelToWorld->SetElement(
          r, c, axes[static_cast<std::size_t>(c)][static_cast<std::size_t>(r)]);
      }
      voxelToWorld->SetElement(r, 3, origin[static_cast<std::size_t>(r)]);
    }
    image->SetOrigin(0.0, 0.0, 0.0);
    image->SetSpacing(1.0, 1.0, 1.0);
    PlaceByMatrix(image, voxelToWorld, "\"space directions\"");
  }

  const auto frame = fields.find("measurement frame");
  if (frame == fields.end())
  {
    return;
  }
  const auto columns = NrrdVectors(frame->second, frame->first);
  if (columns.size() != 3)
  {
    throw std::runtime_error("the NRRD field \"measurement frame\" is not three 3D vectors");
  }
  double m[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      m[r][c] = columns[static_cast<std::size_t>(c)][static_cast<std::size_t>(r)];
    }
  }
  TurnTensors(image, m);
}
} // namespace

namespace
{
/// A NIfTI file read by `reader` (checked first: VTK's reader trusts the
/// header), every volume a component (six FSL volumes become six
/// components, as a vector dimension does).
vtkSmartPointer<vtkImageData> ReadNifti(vtkNIFTIImageReader* reader, const std::string& path)
{
  if (!reader->CanReadFile(path.c_str()))
  {
    throw std::runtime_error("not a NIfTI file");
  }
  const std::string problem = CheckNiftiFile(path);
  if (!problem.empty())
  {
    throw std::runtime_error(problem);
  }
  reader->TimeAsVectorOn();
  reader->SetFileName(path.c_str());
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(reader->GetOutput());
  return image;
}

/// Place a NIfTI image by its q-form, else its s-form (voxel grid at the
/// origin without either); the matrix used, or null.
vtkMatrix4x4* PlaceNifti(vtkImageData* image, vtkNIFTIImageReader* reader)
{
  vtkNIFTIImageHeader* header = reader->GetNIFTIHeader();
  if (header->GetQFormCode() > 0 && reader->GetQFormMatrix())
  {
    PlaceByMatrix(image, reader->GetQFormMatrix(), "q-form");
    return reader->GetQFormMatrix();
  }
  if (header->GetSFormCode() > 0 && reader->GetSFormMatrix())
  {
    PlaceByMatrix(image, reader->GetSFormMatrix(), "s-form");
    return reader->GetSFormMatrix();
  }
  return nullptr;
}

/// A NRRD file's image (checked first; gzip bodies read by our reader),
/// placed by its "space directions" and "space origin".
vtkSmartPointer<vtkImageData> ReadNrrd(const std::string& path)
{
  const std::string problem = CheckNrrdFile(path);
  if (!problem.empty())
  {
    throw std::runtime_error(problem);
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  if (IsGzipNrrd(path))
  {
    // vtkNrrdReader (VTK 9.1) misreads gzip bodies without an error.
    image = ReadGzipNrrdImage(path);
  }
  else
  {
    vtkNew<SpaceBlindNrrdReader> reader;
    if (!reader->CanReadFile(path.c_str()))
    {
      throw std::runtime_error("not a NRRD file vtkNrrdReader can read (raw or gzip encoding)");
    }
    reader->SetFileName(path.c_str());
    reader->Update();
    image->ShallowCopy(reader->GetOutput());
  }
  return image;
}

/// A one-component image's values, as doubles, named "Scalars".
void KeepOneComponent(vtkImageData* image, const char* format, double slope, double intercept)
{
  vtkDataArray* scalars = OnlyArray(image, format);
  if (scalars->GetNumberOfComponents() != 1)
  {
    std::ostringstream message;
    message << "the " << format << " image has " << scalars->GetNumberOfComponents()
            << " values per voxel; a mask or label image has 1";
    throw std::runtime_error(message.str());
  }
  vtkNew<vtkDoubleArray> values;
  values->SetName("Scalars");
  values->SetNumberOfTuples(scalars->GetNumberOfTuples());
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    values->SetValue(i, slope * scalars->GetTuple1(i) + intercept);
  }
  image->GetPointData()->Initialize();
  image->GetPointData()->SetScalars(values);
}
} // namespace

vtkSmartPointer<vtkImageData> ReadNiftiScalarImage(const std::string& path)
{
  vtkNew<vtkNIFTIImageReader> reader;
  vtkSmartPointer<vtkImageData> image = ReadNifti(reader, path);
  double slope = reader->GetRescaleSlope();
  double intercept = reader->GetRescaleIntercept();
  if (slope == 0.0 || !std::isfinite(slope) || !std::isfinite(intercept))
  {
    slope = 1.0; // NIfTI: scl_slope 0 means "no scaling"
    intercept = 0.0;
  }
  KeepOneComponent(image, "NIfTI", slope, intercept);
  PlaceNifti(image, reader);
  return image;
}

vtkSmartPointer<vtkImageData> ReadNrrdScalarImage(const std::string& path)
{
  vtkSmartPointer<vtkImageData> image = ReadNrrd(path);
  KeepOneComponent(image, "NRRD", 1.0, 0.0);
  // vtkNrrdReader (VTK 9.1) keeps only the lengths of "space directions".
  ApplyNrrdSpace(image, path);
  return image;
}

namespace
{
/// The file's order of a NIfTI file's six values: the one `components`
/// gives, or the one its symmetric-matrix intent says; both must agree, and
/// one must be there.
const ComponentPicks& NiftiSixOrder(bool symmatrix, SampledTensorComponents components)
{
  if (symmatrix && components != SampledTensorComponents::FromFile &&
    components != SampledTensorComponents::Dipy)
  {
    throw std::runtime_error("its intent code (NIFTI_INTENT_SYMMATRIX) says the six values are in "
                             "NIfTI's lower-triangle order (XX XY YY XZ YZ ZZ, \"components\": "
                             "\"dipy\"), but \"components\" says otherwise: remove one of them");
  }
  switch (components)
  {
    case SampledTensorComponents::Fsl:
      return UpperTriangle;
    case SampledTensorComponents::Mrtrix:
      return MrtrixOrder;
    case SampledTensorComponents::Dipy:
      return NiftiSymmetricMatrix;
    case SampledTensorComponents::FromFile:
      break;
  }
  if (symmatrix)
  {
    return NiftiSymmetricMatrix;
  }
  throw std::runtime_error(
    "six values per voxel and no intent code saying their order (the tools that write them "
    "disagree): give the metric \"components\": \"fsl\" (XX XY XZ YY YZ ZZ, FSL's dtifit), "
    "\"mrtrix\" (XX YY ZZ XY XZ YZ, MRtrix's dwi2tensor through mrconvert) or \"dipy\" (XX XY "
    "YY XZ YZ ZZ, DIPY's lower_triangular)");
}
} // namespace

vtkSmartPointer<vtkImageData> ReadNiftiTensorImage(
  const std::string& path, SampledTensorFrame frame, SampledTensorComponents components)
{
  vtkNew<vtkNIFTIImageReader> reader;
  vtkSmartPointer<vtkImageData> image = ReadNifti(reader, path);
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
  if (count == 9 && components != SampledTensorComponents::FromFile)
  {
    throw std::runtime_error("nine values per voxel are read row-major; \"components\" orders six: "
                             "leave it out");
  }
  SetTensors(image, scalars, count == 9 ? RowMajor : NiftiSixOrder(symmatrix, components), slope,
    intercept);

  // Step 2: the placement, q-form first.
  vtkMatrix4x4* placement = PlaceNifti(image, reader);

  // Step 3: tensors in FSL's voxel axes turned to world axes.
  if (frame == SampledTensorFrame::Fsl)
  {
    if (!placement)
    {
      throw std::runtime_error("\"frame\": \"fsl\" needs the file's q-form or s-form (to "
                               "know its voxel axes in the world); this file has neither");
    }
    double axes[3][3];
    FslFrameAxes(placement, reader->GetQFac(), axes);
    TurnTensors(image, axes);
  }
  return image;
}

vtkSmartPointer<vtkImageData> ReadNrrdTensorImage(const std::string& path)
{
  vtkSmartPointer<vtkImageData> image = ReadNrrd(path);
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
  // vtkNrrdReader (VTK 9.1) keeps only the lengths of "space directions".
  ApplyNrrdSpace(image, path);
  return image;
}
} // namespace riemann
