#include "vtkRiemannDirectionGrid.h"

#include "RiemannDirectionGridDeclaration.h"
#include "vtkRiemannReportError.h"

#include "DirectionLattice.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDelaunay2D.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <array>
#include <cmath>
#include <map>
#include <vector>

vtkStandardNewMacro(vtkRiemannDirectionGrid);

namespace
{
namespace declared = riemann::declared::vtkRiemannDirectionGrid;
/// The most directions a grid has (the filters that shoot them say so by this limit).
constexpr int MaximumNumberOfDirections = static_cast<int>(declared::Maximum::NumberOfDirections);
}

vtkRiemannDirectionGrid::vtkRiemannDirectionGrid()
  : NumberOfDirections(static_cast<int>(declared::Default::NumberOfDirections))
  , ConeAxis{ declared::Default::ConeAxis[0], declared::Default::ConeAxis[1],
    declared::Default::ConeAxis[2] }
  , ConeAngle(declared::Default::ConeAngle)
{
  this->SetNumberOfInputPorts(0);
}

namespace
{
using Vector = std::array<double, 3>;

/// The loop of boundary edges (edges of one triangle only), in order; empty
/// when there is none or it is not one simple loop.
std::vector<vtkIdType> BoundaryLoop(vtkCellArray* triangles)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> edges;
  vtkNew<vtkIdList> ids;
  for (triangles->InitTraversal(); triangles->GetNextCell(ids);)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = ids->GetId(k);
      const vtkIdType b = ids->GetId((k + 1) % 3);
      ++edges[{ std::min(a, b), std::max(a, b) }];
    }
  }
  std::map<vtkIdType, std::vector<vtkIdType>> neighbours;
  for (const auto& [edge, count] : edges)
  {
    if (count == 1)
    {
      neighbours[edge.first].push_back(edge.second);
      neighbours[edge.second].push_back(edge.first);
    }
  }
  std::vector<vtkIdType> loop;
  if (neighbours.empty())
  {
    return loop;
  }
  for (const auto& [vertex, next] : neighbours)
  {
    if (next.size() != 2)
    {
      return {}; // not a simple loop
    }
  }
  vtkIdType previous = -1;
  vtkIdType current = neighbours.begin()->first;
  do
  {
    loop.push_back(current);
    const auto& next = neighbours[current];
    const vtkIdType following = next[0] != previous ? next[0] : next[1];
    previous = current;
    current = following;
  } while (current != loop.front() && loop.size() <= neighbours.size());
  return loop.size() == neighbours.size() ? loop : std::vector<vtkIdType>();
}

// Build's steps for three directions or more: TriangulateStereographic ->
// OrientOutward.

/// While the triangulation runs for `owner` (the filter that builds the
/// grid): its progress is reported as the owner's, so that a stop requested
/// of the owner (riemann::JobStop sets AbortExecute at a progress report)
/// reaches vtkDelaunay2D, which checks its own AbortExecute as it inserts
/// points. A million directions take minutes to triangulate.
struct TriangulationOwner
{
  vtkAlgorithm* Owner;
  vtkAlgorithm* Triangulation;
};

void ForwardTriangulationProgress(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* owned = static_cast<TriangulationOwner*>(clientData);
  // The grid is the prelude of the owner's work: its first thousandth.
  owned->Owner->UpdateProgress(1e-3 * *static_cast<double*>(callData));
  if (owned->Owner->GetAbortExecute())
  {
    owned->Triangulation->SetAbortExecute(1);
  }
}

/// The triangles of the directions' Delaunay triangulation after a
/// stereographic projection from a pole onto the plane orthogonal to it:
/// -axis for a cap (outside it); for the whole sphere the last direction
/// (the one nearest -axis), whose star is added afterwards as the cone over
/// the boundary of the others' triangulation. Returns false when `owner` was
/// stopped (the triangles are then partial).
bool TriangulateStereographic(vtkPoints* directions, const Vector& axis, bool wholeSphere,
  vtkCellArray* triangles, vtkAlgorithm* owner)
{
  const int count = static_cast<int>(directions->GetNumberOfPoints());
  Vector pole = { -axis[0], -axis[1], -axis[2] };
  const int projectedCount = wholeSphere ? count - 1 : count;
  if (wholeSphere)
  {
    directions->GetPoint(count - 1, pole.data());
  }
  Vector p0 = std::abs(pole[0]) < 0.9 ? Vector{ 1.0, 0.0, 0.0 } : Vector{ 0.0, 1.0, 0.0 };
  Vector e0, e1;
  vtkMath::Cross(pole.data(), p0.data(), e0.data());
  vtkMath::Normalize(e0.data());
  vtkMath::Cross(pole.data(), e0.data(), e1.data());
  vtkNew<vtkPoints> projected;
  projected->SetDataTypeToDouble();
  projected->SetNumberOfPoints(projectedCount);
  for (int i = 0; i < projectedCount; ++i)
  {
    double d[3];
    directions->GetPoint(i, d);
    const double scale = 1.0 / (1.0 - vtkMath::Dot(d, pole.data()));
    projected->SetPoint(
      i, scale * vtkMath::Dot(d, e0.data()), scale * vtkMath::Dot(d, e1.data()), 0.0);
  }
  vtkNew<vtkPolyData> plane;
  plane->SetPoints(projected);
  vtkNew<vtkDelaunay2D> delaunay;
  delaunay->SetInputData(plane);
  TriangulationOwner owned{ owner, delaunay };
  if (owner)
  {
    vtkNew<vtkCallbackCommand> forward;
    forward->SetCallback(ForwardTriangulationProgress);
    forward->SetClientData(&owned);
    delaunay->AddObserver(vtkCommand::ProgressEvent, forward);
  }
  delaunay->Update();
  if (owner && owner->GetAbortExecute())
  {
    return false;
  }
  triangles->DeepCopy(delaunay->GetOutput()->GetPolys());
  if (wholeSphere)
  {
    // The pole's neighbours are the boundary of the planar triangulation.
    const std::vector<vtkIdType> loop = BoundaryLoop(triangles);
    for (size_t k = 0; k < loop.size(); ++k)
    {
      const vtkIdType star[3] = { count - 1, loop[k], loop[(k + 1) % loop.size()] };
      triangles->InsertNextCell(3, star);
    }
  }
  return true;
}

/// Every triangle turned to face outward (normal . centroid > 0).
void OrientOutward(vtkPoints* directions, vtkCellArray* triangles)
{
  vtkNew<vtkCellArray> oriented;
  oriented->AllocateExact(triangles->GetNumberOfCells(), 3 * triangles->GetNumberOfCells());
  vtkNew<vtkIdList> cell;
  for (triangles->InitTraversal(); triangles->GetNextCell(cell);)
  {
    double a[3], b[3], c[3], ab[3], ac[3], normal[3];
    directions->GetPoint(cell->GetId(0), a);
    directions->GetPoint(cell->GetId(1), b);
    directions->GetPoint(cell->GetId(2), c);
    vtkMath::Subtract(b, a, ab);
    vtkMath::Subtract(c, a, ac);
    vtkMath::Cross(ab, ac, normal);
    const double centroid[3] = { a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2] };
    vtkIdType t[3] = { cell->GetId(0), cell->GetId(1), cell->GetId(2) };
    if (vtkMath::Dot(normal, centroid) < 0.0)
    {
      std::swap(t[1], t[2]);
    }
    oriented->InsertNextCell(3, t);
  }
  triangles->ShallowCopy(oriented);
}
}

bool vtkRiemannDirectionGrid::Build(int numberOfDirections, const double axisIn[3],
  double coneAngle, vtkPolyData* grid, std::string& message, vtkAlgorithm* owner)
{
  grid->Initialize();
  if (numberOfDirections > MaximumNumberOfDirections)
  {
    // 2^31 - 1 directions once made the grid's vectors throw bad_alloc
    // (uncaught: the process aborted).
    message = "NumberOfDirections: " + std::to_string(numberOfDirections) +
      " directions; at most " + std::to_string(MaximumNumberOfDirections) +
      " are traced (each is a geodesic)";
    return false;
  }
  const bool wholeSphere = coneAngle >= 180.0;
  Vector axis = { 0.0, 0.0, 1.0 };
  if (!wholeSphere)
  {
    const double norm = vtkMath::Norm(axisIn);
    if (!(norm > 0.0) || !std::isfinite(norm))
    {
      message = "ConeAxis: the cone axis must be a finite nonzero vector";
      return false;
    }
    axis = { axisIn[0] / norm, axisIn[1] / norm, axisIn[2] / norm };
  }
  const int count = std::max(numberOfDirections, 0);
  const std::vector<riemann::Vec3> lattice =
    riemann::FibonacciDirections(count, riemann::Vec3(axis[0], axis[1], axis[2]), coneAngle);

  vtkNew<vtkPoints> directions;
  directions->SetDataTypeToDouble();
  directions->SetNumberOfPoints(count);
  vtkNew<vtkIntArray> ids;
  ids->SetName("DirectionId");
  ids->SetNumberOfTuples(count);
  for (int i = 0; i < count; ++i)
  {
    directions->SetPoint(i, lattice[i].data());
    ids->SetValue(i, i);
  }

  vtkNew<vtkCellArray> triangles;
  if (count >= 3)
  {
    if (!TriangulateStereographic(directions, axis, wholeSphere, triangles, owner))
    {
      message = "stopped";
      return false;
    }
    OrientOutward(directions, triangles);
  }
  grid->SetPoints(directions);
  grid->SetPolys(triangles);
  grid->GetPointData()->AddArray(ids);
  return true;
}

vtkIdType vtkRiemannDirectionGrid::AppendTriangles(
  vtkPolyData* grid, const std::vector<vtkIdType>& surfacePointIds, vtkCellArray* triangles)
{
  vtkIdType appended = 0;
  vtkCellArray* gridTriangles = grid->GetPolys();
  vtkNew<vtkIdList> cell;
  for (gridTriangles->InitTraversal(); gridTriangles->GetNextCell(cell);)
  {
    const vtkIdType t[3] = { surfacePointIds[cell->GetId(0)], surfacePointIds[cell->GetId(1)],
      surfacePointIds[cell->GetId(2)] };
    if (t[0] >= 0 && t[1] >= 0 && t[2] >= 0)
    {
      triangles->InsertNextCell(3, t);
      ++appended;
    }
  }
  return appended;
}

int vtkRiemannDirectionGrid::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->LastError.clear();
  std::string message;
  if (!Build(this->NumberOfDirections, this->ConeAxis, this->ConeAngle, output, message))
  {
    output->Initialize();
    vtkRiemannReportErrorMacro(this->LastError, << message << ".");
  }
  return 1;
}

void vtkRiemannDirectionGrid::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "ConeAxis: " << this->ConeAxis[0] << " " << this->ConeAxis[1] << " "
     << this->ConeAxis[2] << "\n";
  os << indent << "ConeAngle: " << this->ConeAngle << "\n";
}
