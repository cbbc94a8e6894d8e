#include "RiemannTensorImage.h"

#include "RiemannMedicalTensorImages.h"
#include "RiemannTensorFileChecks.h"

#include "InputFiles.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStructuredPoints.h"
#include "vtkStructuredPointsReader.h"
#include "vtkXMLImageDataReader.h"

#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace riemann
{
namespace
{
/// Points a tensor volume may have: 2^27 (134 M points, 6.4 GB of samples).
constexpr long long MaximumPoints = 1LL << 27;

/// "Tensors (6 components), FA (1 component)", for messages.
std::string ListArrays(vtkPointData* pd)
{
  std::ostringstream list;
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array)
    {
      continue;
    }
    list << (list.tellp() > 0 ? ", " : "") << (array->GetName() ? array->GetName() : "(unnamed)")
         << " (" << array->GetNumberOfComponents() << " component"
         << (array->GetNumberOfComponents() == 1 ? ")" : "s)");
  }
  return list.tellp() > 0 ? list.str() : std::string("none");
}

vtkDataArray* FindTensorArray(vtkPointData* pd, const std::string& name)
{
  if (!name.empty())
  {
    vtkDataArray* array = pd->GetArray(name.c_str());
    if (!array)
    {
      throw std::runtime_error(
        "no point-data array \"" + name + "\"; the arrays are " + ListArrays(pd));
    }
    return array;
  }
  if (pd->GetTensors())
  {
    return pd->GetTensors();
  }
  vtkDataArray* found = nullptr;
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (array && (array->GetNumberOfComponents() == 6 || array->GetNumberOfComponents() == 9))
    {
      if (found)
      {
        throw std::runtime_error("several arrays could hold the tensors; name one with "
                                 "\"array\": " +
          ListArrays(pd));
      }
      found = array;
    }
  }
  if (!found)
  {
    throw std::runtime_error(
      "no tensor array (6 or 9 components) in the point data; the arrays are " + ListArrays(pd));
  }
  return found;
}
} // namespace

SampledTensorGrid TensorGridFromImage(vtkImageData* image, const std::string& arrayName)
{
  if (!image)
  {
    throw std::runtime_error("no image");
  }
  SampledTensorGrid grid;
  int dims[3];
  image->GetDimensions(dims);
  grid.Dimensions = { dims[0], dims[1], dims[2] };
  if (grid.NumberOfPoints() > MaximumPoints)
  {
    std::ostringstream message;
    message << dims[0] << "x" << dims[1] << "x" << dims[2] << " points: more than " << MaximumPoints
            << " (about 6 GB of tensors)";
    throw std::runtime_error(message.str());
  }
  vtkDataArray* array = FindTensorArray(image->GetPointData(), arrayName);
  const int components = array->GetNumberOfComponents();
  if (components != 6 && components != 9)
  {
    std::ostringstream message;
    message << "array \"" << (array->GetName() ? array->GetName() : "") << "\" has " << components
            << " components; a tensor has 6 (XX, YY, ZZ, XY, YZ, XZ) or 9 (row-major)";
    throw std::runtime_error(message.str());
  }
  const double* origin = image->GetOrigin();
  const double* spacing = image->GetSpacing();
  for (int a = 0; a < 3; ++a)
  {
    grid.Origin[a] = origin[a];
    grid.Spacing[a] = spacing[a];
    for (int b = 0; b < 3; ++b)
    {
      grid.Direction(a, b) = image->GetDirectionMatrix()->GetElement(a, b);
    }
  }
  const long long count = grid.NumberOfPoints();
  grid.Components.resize(6 * static_cast<size_t>(count));
  double t[9];
  for (long long p = 0; p < count; ++p)
  {
    array->GetTuple(p, t);
    double* c = grid.Components.data() + 6 * p;
    if (components == 6)
    {
      std::copy(t, t + 6, c);
      continue;
    }
    for (const auto& [i, j] : { std::pair<int, int>(0, 1), { 1, 2 }, { 0, 2 } })
    {
      const double a = t[3 * i + j];
      const double b = t[3 * j + i];
      if (std::isfinite(a) && std::isfinite(b) &&
        std::abs(a - b) > 1e-6 * (std::abs(a) + std::abs(b)) + 1e-300)
      {
        std::ostringstream message;
        message << "the tensor of point " << p << " is not symmetric: component (" << i << ", " << j
                << ") is " << a << " and (" << j << ", " << i << ") is " << b;
        throw std::runtime_error(message.str());
      }
    }
    const double values[6] = { t[0], t[4], t[8], 0.5 * (t[1] + t[3]), 0.5 * (t[5] + t[7]),
      0.5 * (t[2] + t[6]) };
    std::copy(values, values + 6, c);
  }
  const std::string problem = grid.Check();
  if (!problem.empty())
  {
    throw std::runtime_error(problem);
  }
  return grid;
}

SampledTensorGrid ReadTensorGridFile(const std::string& path, const std::string& arrayName,
  SampledTensorFrame frame, SampledTensorComponents components)
{
  // A regular file first: a FIFO would block the readers, a device feed them forever.
  const std::string notAFile = InputFileProblem(path, "the tensor file");
  if (!notAFile.empty())
  {
    throw std::runtime_error(notAFile);
  }
  const auto endsWith = [&path](const std::string& end) { return HasFileEnding(path, end); };
  const std::string extension =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  vtkSmartPointer<vtkImageData> image;
  std::string array = arrayName;
  const bool nifti = endsWith(".nii") || endsWith(".nii.gz");
  const bool nrrd = endsWith(".nrrd") || endsWith(".nhdr");
  if (frame == SampledTensorFrame::Fsl && !nifti)
  {
    // NRRD says its frame itself (measurement frame); VTK data is in world axes.
    throw std::runtime_error(path +
      ": \"frame\": \"fsl\" is for NIfTI files (FSL's voxel axes); this file's tensors are "
      "read in world axes");
  }
  if (components != SampledTensorComponents::FromFile && !nifti)
  {
    // VTK's tensors have VTK's order; a NRRD's kind says its own.
    throw std::runtime_error(path +
      ": \"components\" is the order of a NIfTI file's six volumes; this file says its own "
      "order (VTK's, or the NRRD kind's): leave it out");
  }
  if (nifti || nrrd)
  {
    // One tensor per voxel, named by the reader: there is no array to choose.
    if (!array.empty() && array != "Tensors")
    {
      throw std::runtime_error(path + ": a " + (nifti ? "NIfTI" : "NRRD") +
        " file holds one tensor volume; leave \"array\" out (got \"" + array + "\")");
    }
    try
    {
      image = nifti ? ReadNiftiTensorImage(path, frame, components) : ReadNrrdTensorImage(path);
    }
    catch (const std::runtime_error& e)
    {
      throw std::runtime_error(path + ": " + e.what());
    }
    array = "Tensors";
  }
  else if (extension == ".vti")
  {
    const std::string problem = CheckVtiFile(path);
    if (!problem.empty())
    {
      throw std::runtime_error(path + ": " + problem);
    }
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    image = reader->GetOutput();
  }
  else if (extension == ".vtk")
  {
    vtkNew<vtkStructuredPointsReader> reader;
    reader->SetFileName(path.c_str());
    if (!reader->IsFileStructuredPoints())
    {
      throw std::runtime_error(path + ": not a legacy VTK file of structured points");
    }
    reader->Update();
    image = reader->GetOutput();
  }
  else
  {
    throw std::runtime_error(path + ": unknown tensor volume format \"" + extension +
      "\" (read: .vti, .vtk, .nii, .nii.gz, .nrrd, .nhdr)");
  }
  if (!image || image->GetNumberOfPoints() == 0)
  {
    throw std::runtime_error(path + ": no image data could be read");
  }
  try
  {
    return TensorGridFromImage(image, array);
  }
  catch (const std::runtime_error& e)
  {
    throw std::runtime_error(path + ": " + e.what());
  }
}
} // namespace riemann
