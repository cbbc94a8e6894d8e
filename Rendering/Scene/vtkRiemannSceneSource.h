/**
 * @class   vtkRiemannSceneSource
 * @brief   The scene's objects as ordinary (Euclidean) VTK geometry.
 *
 * For the outside view next to the inside view: the paper's grid of bars as
 * boxes, spheres, planes (as square patches of PlaneSize around their
 * point), boxes and triangle meshes (mesh objects), triangulated, with point
 * data `Colors` (RGB, unsigned
 * char) from each object's material at the vertex (the position
 * pseudo-colour, solid, or checker), so the same colours as in the inside
 * view identify where rays end, and cell data `ObjectIndex` (the object's
 * index in the scene's "objects", to pick or threshold one object).
 */
#ifndef vtkRiemannSceneSource_h
#define vtkRiemannSceneSource_h

#include "RiemannRenderingSceneModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkRiemannScene;

class RIEMANNRENDERINGSCENE_EXPORT vtkRiemannSceneSource : public vtkPolyDataAlgorithm
{
public:
  static vtkRiemannSceneSource* New();
  vtkTypeMacro(vtkRiemannSceneSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scene (default: the built-in default scene).
  virtual void SetScene(vtkRiemannScene* scene);
  vtkGetObjectMacro(Scene, vtkRiemannScene);
  ///@}

  ///@{
  /// Side of the square drawn for each (infinite) plane. Default 10.
  vtkSetClampMacro(PlaneSize, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(PlaneSize, double);
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkRiemannSceneSource();
  ~vtkRiemannSceneSource() override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkRiemannScene* Scene = nullptr;
  double PlaneSize = 10.0;

private:
  vtkRiemannSceneSource(const vtkRiemannSceneSource&) = delete;
  void operator=(const vtkRiemannSceneSource&) = delete;
};

#endif
