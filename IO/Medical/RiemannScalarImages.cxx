#include "RiemannScalarImages.h"

#include "InputFiles.h"
#include "RiemannMedicalTensorImages.h"
#include "RiemannTensorFileChecks.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStructuredPoints.h" // GetOutput()'s type (VTK 9.2 only declares it)
#include "vtkStructuredPointsReader.h"
#include "vtkXMLImageDataReader.h"

#include <random>
#include <stdexcept>

namespace riemann
{
namespace
{
/// A VTK image's one-component array (the active scalars, else the only
/// one) as the double array "Scalars".
void KeepScalars(vtkImageData* image)
{
  vtkPointData* pd = image->GetPointData();
  vtkDataArray* values = pd->GetScalars();
  for (int i = 0; !values && i < pd->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = pd->GetArray(i);
    if (array && array->GetNumberOfComponents() == 1)
    {
      values = array;
    }
  }
  if (!values || values->GetNumberOfComponents() != 1)
  {
    throw std::runtime_error("no point array of one value per voxel");
  }
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("Scalars");
  scalars->DeepCopy(values);
  scalars->SetName("Scalars");
  pd->Initialize();
  pd->SetScalars(scalars);
}
} // namespace

vtkSmartPointer<vtkImageData> ReadScalarImageFile(const std::string& path, const std::string& what)
{
  const std::string notAFile = InputFileProblem(path, what);
  if (!notAFile.empty())
  {
    throw std::runtime_error(notAFile);
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  try
  {
    if (HasFileEnding(path, ".nii") || HasFileEnding(path, ".nii.gz"))
    {
      image = ReadNiftiScalarImage(path);
    }
    else if (HasFileEnding(path, ".nrrd") || HasFileEnding(path, ".nhdr"))
    {
      image = ReadNrrdScalarImage(path);
    }
    else if (HasFileEnding(path, ".vti"))
    {
      const std::string problem = CheckVtiFile(path);
      if (!problem.empty())
      {
        throw std::runtime_error(problem);
      }
      vtkNew<vtkXMLImageDataReader> reader;
      reader->SetFileName(path.c_str());
      reader->Update();
      image->ShallowCopy(reader->GetOutput());
      KeepScalars(image);
    }
    else if (HasFileEnding(path, ".vtk"))
    {
      vtkNew<vtkStructuredPointsReader> reader;
      reader->SetFileName(path.c_str());
      if (!reader->IsFileStructuredPoints())
      {
        throw std::runtime_error("not a legacy VTK file of structured points");
      }
      reader->Update();
      image->ShallowCopy(reader->GetOutput());
      KeepScalars(image);
    }
    else
    {
      throw std::runtime_error("unknown image format (read: .nii, .nii.gz, .nrrd, .nhdr, .vti, "
                               ".vtk)");
    }
  }
  catch (const std::runtime_error& e)
  {
    throw std::runtime_error(path + ": " + e.what());
  }
  if (image->GetNumberOfPoints() == 0)
  {
    throw std::runtime_error(path + ": no image data could be read");
  }
  return image;
}

std::vector<double> MaskSeedPoints(vtkImageData* mask, int perVoxel, unsigned randomSeed)
{
  std::vector<double> points;
  vtkDataArray* values = mask->GetPointData()->GetScalars();
  if (!values || perVoxel < 1)
  {
    return points;
  }
  std::mt19937 generator(randomSeed);
  std::uniform_real_distribution<double> jitter(-0.5, 0.5);
  int extent[6];
  mask->GetExtent(extent);
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      for (int i = extent[0]; i <= extent[1]; ++i)
      {
        const int ijk[3] = { i, j, k };
        if (values->GetTuple1(mask->ComputePointId(const_cast<int*>(ijk))) == 0.0)
        {
          continue;
        }
        for (int n = 0; n < perVoxel; ++n)
        {
          double index[3] = { static_cast<double>(i), static_cast<double>(j),
            static_cast<double>(k) };
          if (perVoxel > 1)
          {
            for (double& c : index)
            {
              c += jitter(generator);
            }
          }
          double world[3];
          mask->TransformContinuousIndexToPhysicalPoint(index, world);
          points.insert(points.end(), world, world + 3);
        }
      }
    }
  }
  return points;
}
VoxelMask VoxelMaskFromImage(vtkImageData* image)
{
  VoxelMask mask;
  vtkDataArray* values = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!values)
  {
    return mask;
  }
  int dimensions[3];
  image->GetDimensions(dimensions);
  double origin[3], spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  const double* direction = image->GetDirectionMatrix()->GetData();
  for (int a = 0; a < 3; ++a)
  {
    mask.Dimensions[a] = dimensions[a];
    mask.Origin[a] = origin[a];
    mask.Spacing[a] = spacing[a];
    for (int b = 0; b < 3; ++b)
    {
      mask.Direction(a, b) = direction[3 * a + b];
    }
  }
  mask.Set.resize(static_cast<std::size_t>(values->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    mask.Set[static_cast<std::size_t>(i)] = values->GetComponent(i, 0) != 0.0 ? 1 : 0;
  }
  return mask;
}
} // namespace riemann
