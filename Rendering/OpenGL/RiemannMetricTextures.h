/**
 * @file RiemannMetricTextures.h
 * @brief Private to Rendering/OpenGL: the 3D float textures a metric's GLSL
 * reads (GlslTexture3D: a sampled metric's tensor components), uploaded when
 * their data change and bound for each frame.
 */
#ifndef RiemannMetricTextures_h
#define RiemannMetricTextures_h

#include "GlslSource.h" // For GlslTexture3D

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace riemann
{
class MetricTextures
{
public:
  /**
   * Make the textures hold `textures`: a texture whose data (the shared
   * values) was uploaded before is kept, a new one is uploaded, and those no
   * longer named are released. False with `error` when a volume exceeds the
   * context's 3D texture size or the upload fails.
   */
  bool Update(
    const std::vector<GlslTexture3D>& textures, vtkOpenGLRenderWindow* window, std::string& error);

  /// Bind the textures to free units and point their samplers at them.
  void Activate(vtkShaderProgram* program);
  void Deactivate();

  void Release(vtkWindow* window);

  /// Uploads so far (a new volume: one per texture; a moved camera: none).
  int GetNumberOfUploads() const { return this->Uploads; }

private:
  struct Uploaded
  {
    std::string Uniform;
    std::shared_ptr<const std::vector<float>> Values;
    vtkSmartPointer<vtkTextureObject> Texture;
  };
  std::vector<Uploaded> Textures;
  int Uploads = 0;
};
} // namespace riemann

#endif
