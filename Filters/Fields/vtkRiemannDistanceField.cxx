#include "vtkRiemannDistanceField.h"

#include "RiemannDistanceFieldDeclaration.h"

#include "DistanceField.h"
#include "Metric.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRiemannDistanceImage.h"
#include "vtkRiemannReportError.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkRiemannDistanceField);

vtkRiemannDistanceField::vtkRiemannDistanceField()
  : SeedRadius(riemann::declared::vtkRiemannDistanceField::Default::SeedRadius)
{
}
vtkRiemannDistanceField::~vtkRiemannDistanceField() = default;

void vtkRiemannDistanceField::AddSeed(double x, double y, double z)
{
  this->Seeds.insert(this->Seeds.end(), { x, y, z });
  this->Modified();
}

void vtkRiemannDistanceField::RemoveAllSeeds()
{
  if (!this->Seeds.empty())
  {
    this->Seeds.clear();
    this->Modified();
  }
}

void vtkRiemannDistanceField::GetSeed(int index, double point[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    point[a] = index >= 0 && index < this->GetNumberOfSeeds()
      ? this->Seeds[3 * static_cast<std::size_t>(index) + static_cast<std::size_t>(a)]
      : vtkMath::Nan();
  }
}

int vtkRiemannDistanceField::RequestInformation(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestInformation(request, inputVector, outputVector))
  {
    return 0;
  }
  // The whole grid at once: a point's distance depends on all the grid
  // between it and its seed, so no sub-extent can be computed alone.
  outputVector->GetInformationObject(0)->Remove(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT());
  return 1;
}

int vtkRiemannDistanceField::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  if (vtkInformation* seedsInfo = inputVector[0]->GetInformationObject(0))
  {
    seedsInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    seedsInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    seedsInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
  return 1;
}

int vtkRiemannDistanceField::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->SeedsInput = this->GetNumberOfInputConnections(0) > 0
    ? vtkDataSet::GetData(inputVector[0], 0)
    : nullptr;
  const int result = this->Superclass::RequestData(request, inputVector, outputVector);
  this->SeedsInput = nullptr;
  return result;
}

// ComputeFields as named steps: the checks -> vtkRiemannDistanceGridOf ->
// ComputeDistanceField (in parallel, progress between rounds) -> the point
// arrays.
bool vtkRiemannDistanceField::ComputeFields(const riemann::Metric& metric, vtkDataSet* output)
{
  this->NumberOfUpdates = 0;
  this->NumberOfRounds = 0;
  vtkImageData* image = vtkImageData::SafeDownCast(output);
  if (!image)
  {
    vtkRiemannReportErrorMacro(this->LastError, << "The distance field is computed on an image.");
    return false;
  }
  const int* extent = image->GetExtent();
  if (extent[0] != 0 || extent[2] != 0 || extent[4] != 0 || extent[1] != this->Dimensions[0] - 1 ||
    extent[3] != this->Dimensions[1] - 1 || extent[5] != this->Dimensions[2] - 1)
  {
    vtkRiemannReportErrorMacro(this->LastError,
      << "The distance field is computed on the whole grid at once: it cannot be split into "
         "pieces.");
    return false;
  }
  if (!(this->SeedRadius >= 1.0 && this->SeedRadius <= 20.0))
  {
    vtkRiemannReportErrorMacro(this->LastError,
      << "SeedRadius is " << this->SeedRadius << ": expected a number from 1 to 20 (grid spacings).");
    return false;
  }
  // AddSeed's, then the seeds input's points (SeedId's order).
  std::vector<riemann::Vec3> seeds;
  for (std::size_t s = 0; s + 2 < this->Seeds.size(); s += 3)
  {
    seeds.emplace_back(this->Seeds[s], this->Seeds[s + 1], this->Seeds[s + 2]);
  }
  const vtkIdType inputSeeds = this->SeedsInput ? this->SeedsInput->GetNumberOfPoints() : 0;
  for (vtkIdType n = 0; n < inputSeeds; ++n)
  {
    riemann::Vec3 p;
    this->SeedsInput->GetPoint(n, p.data());
    seeds.push_back(p);
  }
  riemann::DistanceOptions options;
  options.SeedRadius = this->SeedRadius;
  riemann::DistanceFieldResult result;
  bool completed = false;
  try
  {
    completed = riemann::ComputeDistanceField(metric, vtkRiemannDistanceGridOf(image), seeds,
      options, result,
      [](std::size_t count, const std::function<void(std::size_t, std::size_t)>& work)
      {
        vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&work](vtkIdType first, vtkIdType last)
          { work(static_cast<std::size_t>(first), static_cast<std::size_t>(last)); });
      },
      [this](double fraction)
      {
        this->UpdateProgress(fraction);
        return !this->GetAbortExecute();
      });
  }
  catch (const std::invalid_argument& e)
  {
    vtkRiemannReportErrorMacro(this->LastError, << "Cannot compute the distance field: " << e.what() << ".");
    return false;
  }
  if (!completed)
  {
    return false; // aborted: empty output, no error
  }
  this->NumberOfUpdates = static_cast<vtkIdType>(result.Updates);
  this->NumberOfRounds = result.Rounds;

  const vtkIdType count = image->GetNumberOfPoints();
  vtkSmartPointer<vtkDoubleArray> distance = NewPointArray("Distance", 1, count);
  vtkSmartPointer<vtkDoubleArray> direction = NewPointArray("ArrivalDirection", 3, count);
  vtkNew<vtkIntArray> seedId;
  seedId->SetName("SeedId");
  seedId->SetNumberOfTuples(count);
  for (vtkIdType n = 0; n < count; ++n)
  {
    const double u = result.Distance[static_cast<std::size_t>(n)];
    distance->SetValue(n, std::isfinite(u) ? u : vtkMath::Nan());
    direction->SetTuple(n, result.ArrivalDirection.data() + 3 * n);
    seedId->SetValue(n, result.SeedId[static_cast<std::size_t>(n)]);
  }
  // The seeds, for those who walk back to them (vtkRiemannMinimalGeodesics).
  vtkSmartPointer<vtkDoubleArray> seedPoints =
    NewPointArray("Seeds", 3, static_cast<vtkIdType>(seeds.size()));
  for (std::size_t s = 0; s < seeds.size(); ++s)
  {
    seedPoints->SetTuple(static_cast<vtkIdType>(s), seeds[s].data());
  }
  image->GetFieldData()->AddArray(seedPoints);
  vtkPointData* pd = image->GetPointData();
  pd->AddArray(distance);
  pd->AddArray(direction);
  pd->AddArray(seedId);
  pd->SetActiveScalars("Distance");
  return true;
}

void vtkRiemannDistanceField::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSeeds: " << this->GetNumberOfSeeds() << "\n";
  os << indent << "SeedRadius: " << this->SeedRadius << "\n";
  os << indent << "NumberOfUpdates: " << this->NumberOfUpdates << "\n";
  os << indent << "NumberOfRounds: " << this->NumberOfRounds << "\n";
}
