#include "vtkRiemannTractReader.h"

#include "RiemannTractFiles.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <exception>
#include <string>

vtkStandardNewMacro(vtkRiemannTractReader);

vtkRiemannTractReader::vtkRiemannTractReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkRiemannTractReader::~vtkRiemannTractReader() = default;

// RequestData as named steps: ReadTractFile -> the points -> one polyline a tract.
int vtkRiemannTractReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  this->LastError.clear();
  std::vector<riemann::Tract> tracts;
  try
  {
    if (this->FileName.empty())
    {
      throw std::runtime_error("no file name: set FileName to a .trk or .tck file");
    }
    tracts = riemann::ReadTractFile(this->FileName);
  }
  catch (const std::exception& e)
  {
    // ReadTractFile's messages name the file and what is wrong with it.
    this->LastError = std::string("Cannot read the tracts: ") + e.what() + ".";
    vtkErrorMacro(<< this->LastError);
    return 1;
  }

  vtkIdType count = 0;
  for (const riemann::Tract& tract : tracts)
  {
    count += static_cast<vtkIdType>(tract.size());
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  vtkNew<vtkCellArray> lines;
  lines->AllocateExact(static_cast<vtkIdType>(tracts.size()), count);
  vtkNew<vtkIdTypeArray> tractIds;
  tractIds->SetName("TractId");
  tractIds->SetNumberOfTuples(static_cast<vtkIdType>(tracts.size()));
  vtkIdType next = 0;
  for (std::size_t t = 0; t < tracts.size(); ++t)
  {
    lines->InsertNextCell(static_cast<int>(tracts[t].size()));
    for (const riemann::Vec3& x : tracts[t])
    {
      points->SetPoint(next, x.data());
      lines->InsertCellPoint(next++);
    }
    tractIds->SetValue(static_cast<vtkIdType>(t), static_cast<vtkIdType>(t));
    this->UpdateProgress(static_cast<double>(t + 1) / static_cast<double>(tracts.size()));
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetCellData()->AddArray(tractIds);
  return 1;
}

void vtkRiemannTractReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
