// vtkActors as meshes of the inside view (RiemannActorMesh.h). MeshFromActor's
// steps: DrawnInput (the mapper's polydata, its pipeline run) -> Moved (the
// actor's matrix) -> VertexColors (as VTK colours it) -> MeshFromPolyData.
#include "RiemannActorMesh.h"

#include "RiemannPolyDataMesh.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkAppendPolyData.h"
#include "vtkCompositeDataSet.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>

namespace riemann
{
namespace
{
/// The surface cells (polygons and strips) of the polydata in `data`: itself,
/// or the leaves of a composite dataset (vtkCompositePolyDataMapper2's
/// input, as ParaView's representations give their mappers).
vtkIdType SurfaceCells(vtkDataObject* data)
{
  vtkIdType cells = 0;
  for (vtkPolyData* leaf : vtkCompositeDataSet::GetDataSets<vtkPolyData>(data))
  {
    cells += leaf->GetNumberOfPolys() + leaf->GetNumberOfStrips();
  }
  if (auto* polyData = vtkPolyData::SafeDownCast(data))
  {
    cells += polyData->GetNumberOfPolys() + polyData->GetNumberOfStrips();
  }
  return cells;
}

/// The data `actor` draws (a polydata or a composite of them), its pipeline
/// brought up to date; null when the actor draws nothing in the inside view.
vtkDataObject* DrawnData(vtkActor* actor)
{
  if (!actor || !actor->GetVisibility() || !actor->GetMapper() ||
    actor->GetProperty()->GetOpacity() <= 0.0)
  {
    return nullptr;
  }
  vtkMapper* mapper = actor->GetMapper();
  mapper->Update();
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  return input && SurfaceCells(input) > 0 ? input : nullptr;
}

/// `data` as one polydata: itself, or a composite's polydata leaves appended in order.
vtkSmartPointer<vtkPolyData> AsOnePolyData(vtkDataObject* data)
{
  if (auto* polyData = vtkPolyData::SafeDownCast(data))
  {
    return polyData;
  }
  vtkNew<vtkAppendPolyData> append;
  for (vtkPolyData* leaf : vtkCompositeDataSet::GetDataSets<vtkPolyData>(data))
  {
    append->AddInputData(leaf);
  }
  append->Update();
  return append->GetOutput();
}

/// `input` moved by the actor's matrix (itself when that is the identity).
vtkSmartPointer<vtkPolyData> Moved(vtkActor* actor, vtkPolyData* input)
{
  vtkMatrix4x4* matrix = actor->GetMatrix();
  if (matrix->IsIdentity())
  {
    return input;
  }
  vtkNew<vtkTransform> transform;
  transform->SetMatrix(matrix);
  vtkNew<vtkTransformPolyDataFilter> move;
  move->SetTransform(transform);
  move->SetInputData(input);
  move->Update();
  return move->GetOutput();
}

/// RGB per point as VTK colours the actor: the mapper's point scalars through
/// its lookup table when scalar colouring is on, else the property's colour.
vtkSmartPointer<vtkUnsignedCharArray> VertexColors(vtkActor* actor, vtkPolyData* data)
{
  vtkMapper* mapper = actor->GetMapper();
  int cellFlag = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(data, mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  vtkSmartPointer<vtkUnsignedCharArray> colors;
  if (mapper->GetScalarVisibility() && scalars && cellFlag == 0)
  {
    vtkScalarsToColors* table = mapper->GetLookupTable();
    // What the mapper does before drawing (a default table is empty until built).
    if (!mapper->GetUseLookupTableScalarRange())
    {
      table->SetRange(mapper->GetScalarRange());
    }
    table->Build();
    colors.TakeReference(
      table->MapScalars(scalars, mapper->GetColorMode(), mapper->GetArrayComponent()));
  }
  if (!colors || colors->GetNumberOfTuples() != data->GetNumberOfPoints())
  {
    double rgb[3];
    actor->GetProperty()->GetColor(rgb);
    colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colors->SetNumberOfComponents(3);
    colors->SetNumberOfTuples(data->GetNumberOfPoints());
    for (int c = 0; c < 3; ++c)
    {
      colors->FillTypedComponent(
        c, static_cast<unsigned char>(std::clamp(rgb[c], 0.0, 1.0) * 255.0 + 0.5));
    }
  }
  colors->SetName("RiemannActorColors");
  return colors;
}
} // namespace

vtkMTimeType ActorMeshTime(vtkActor* actor)
{
  vtkDataObject* input = DrawnData(actor);
  if (!input)
  {
    return 0;
  }
  // The actor's time covers its property and transform; the mapper's its lookup table.
  return std::max({ actor->GetMTime(), actor->GetMapper()->GetMTime(), input->GetMTime() });
}

std::shared_ptr<TriangleMesh> MeshFromActor(vtkActor* actor)
{
  vtkDataObject* drawn = DrawnData(actor);
  vtkSmartPointer<vtkPolyData> input = drawn ? AsOnePolyData(drawn) : nullptr;
  if (!input)
  {
    throw SceneDefinitionError("the actor draws no surface (hidden, opacity 0, no mapper, or "
                               "its mapper's input has no polygons)");
  }
  vtkSmartPointer<vtkPolyData> moved = Moved(actor, input);
  vtkNew<vtkPolyData> coloured;
  coloured->ShallowCopy(moved);
  coloured->GetPointData()->SetScalars(VertexColors(actor, moved));
  return MeshFromPolyData(coloured); // triangles, normals, and the RGB scalars as colours
}

std::shared_ptr<TriangleMesh> AppendMeshes(
  const std::vector<std::shared_ptr<const TriangleMesh>>& meshes)
{
  auto all = std::make_shared<TriangleMesh>();
  const bool normals =
    std::all_of(meshes.begin(), meshes.end(), [](const auto& m) { return !m->Normals.empty(); });
  const bool colors =
    std::all_of(meshes.begin(), meshes.end(), [](const auto& m) { return !m->Colors.empty(); });
  for (const auto& mesh : meshes)
  {
    const auto offset = static_cast<unsigned int>(all->NumberOfPoints());
    all->Points.insert(all->Points.end(), mesh->Points.begin(), mesh->Points.end());
    for (unsigned int index : mesh->Triangles)
    {
      all->Triangles.push_back(offset + index);
    }
    if (normals)
    {
      all->Normals.insert(all->Normals.end(), mesh->Normals.begin(), mesh->Normals.end());
    }
    if (colors)
    {
      all->Colors.insert(all->Colors.end(), mesh->Colors.begin(), mesh->Colors.end());
    }
  }
  return all;
}

std::shared_ptr<const TriangleMesh> RendererActorMeshes::Update(vtkRenderer* renderer)
{
  std::vector<std::pair<vtkActor*, vtkMTimeType>> key;
  vtkActorCollection* actors = renderer ? renderer->GetActors() : nullptr;
  if (actors)
  {
    vtkCollectionSimpleIterator it;
    actors->InitTraversal(it);
    while (vtkActor* actor = actors->GetNextActor(it))
    {
      const vtkMTimeType time = ActorMeshTime(actor);
      if (time > 0)
      {
        key.emplace_back(actor, time);
      }
    }
  }
  if (key == this->Key)
  {
    return this->Mesh;
  }
  std::vector<std::shared_ptr<const TriangleMesh>> meshes;
  for (auto& entry : key)
  {
    meshes.push_back(MeshFromActor(entry.first));
    ++this->Conversions;
    // Converting may touch the lookup table (its range, as the mapper sets
    // it): the time after it, so that the next frame converts nothing.
    entry.second = ActorMeshTime(entry.first);
  }
  this->Key = std::move(key);
  this->Mesh = meshes.empty() ? nullptr : AppendMeshes(meshes);
  return this->Mesh;
}
} // namespace riemann
