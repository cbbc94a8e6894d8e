/**
 * @file RiemannActorMesh.h
 * @brief A renderer's vtkActors as triangle meshes of the inside view, so
 * that an actor added to a renderer is seen curved by the metric, as VTK
 * would draw it straight: the polydata of its mapper's input (or the polydata
 * leaves of a composite input, as vtkCompositePolyDataMapper2 draws them:
 * ParaView's representations), moved by the
 * actor's matrix (position, orientation, scale, user transform), coloured per
 * vertex as VTK colours it (the mapper's point scalars through its lookup
 * table, else the property's colour).
 *
 * What the inside view does not follow (documented, not silent): opacity is
 * all or nothing (an actor of opacity 0 is not drawn, any other is opaque),
 * cell scalars colour nothing (the property's colour is used), and the
 * representation is always the surface (no wireframe, no points); textures
 * and lighting properties are ignored (the scene's observer lighting
 * applies).
 */
#ifndef RiemannActorMesh_h
#define RiemannActorMesh_h

#include "RiemannRenderingSceneModule.h" // For export macro
#include "RiemannScene.h"

#include "vtkType.h" // For vtkMTimeType

#include <memory>
#include <utility>
#include <vector>

class vtkActor;
class vtkRenderer;

namespace riemann
{
/**
 * Whether the inside view draws `actor` (visible, opacity above 0, a mapper
 * whose input is a vtkPolyData with polygons or strips once its pipeline has
 * run), and the time it last changed (actor, property, transform, mapper,
 * lookup table or data), 0 when it is not drawn. Updates the mapper's input.
 */
RIEMANNRENDERINGSCENE_EXPORT vtkMTimeType ActorMeshTime(vtkActor* actor);

/**
 * The actor's triangles in world coordinates with point normals (the data's
 * moved with it, else computed as MeshFromPolyData does) and a colour per
 * vertex. Throws SceneDefinitionError when the actor has nothing to draw.
 */
RIEMANNRENDERINGSCENE_EXPORT std::shared_ptr<TriangleMesh> MeshFromActor(vtkActor* actor);

/// One mesh holding all of `meshes` (with normals and colours when they all have them).
RIEMANNRENDERINGSCENE_EXPORT std::shared_ptr<TriangleMesh> AppendMeshes(
  const std::vector<std::shared_ptr<const TriangleMesh>>& meshes);

/**
 * The drawn actors of a renderer as one mesh, converted again only when one
 * of them changes (ActorMeshTime) or the set of actors does: between such
 * changes GetMesh() returns the same object, so the GPU pass rebuilds
 * nothing.
 */
class RIEMANNRENDERINGSCENE_EXPORT RendererActorMeshes
{
public:
  /// The renderer's drawn actors now (null when there is none).
  std::shared_ptr<const TriangleMesh> Update(vtkRenderer* renderer);
  /// Actors in the last Update().
  int GetNumberOfActors() const { return static_cast<int>(this->Key.size()); }
  /// Conversions so far (each actor change: one).
  int GetNumberOfConversions() const { return this->Conversions; }

private:
  std::vector<std::pair<vtkActor*, vtkMTimeType>> Key;
  std::shared_ptr<const TriangleMesh> Mesh;
  int Conversions = 0;
};
} // namespace riemann

#endif
