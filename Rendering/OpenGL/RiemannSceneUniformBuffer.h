/**
 * @file RiemannSceneUniformBuffer.h
 * @brief Private to Rendering/OpenGL: the scene's uniform block
 * (riemann::SceneUniformBlock) as an OpenGL uniform buffer, uploaded when
 * the scene changes and bound to each frame's program.
 */
#ifndef RiemannSceneUniformBuffer_h
#define RiemannSceneUniformBuffer_h

#include <string>
#include <vector>

namespace riemann
{
class SceneUniformBuffer
{
public:
  SceneUniformBuffer() = default;
  SceneUniformBuffer(const SceneUniformBuffer&) = delete;
  SceneUniformBuffer& operator=(const SceneUniformBuffer&) = delete;

  /**
   * Hold `block` (uploaded only when it differs from the last one) and bind
   * it to the block `rt_scene_objects` of `programHandle`. False with
   * `error` when the program has no such block or the buffer cannot be made.
   * Needs the program's context current.
   */
  bool Bind(const std::vector<float>& block, unsigned int programHandle, std::string& error);

  /**
   * Forget the buffer; delete it when `contextIsCurrent` (the context that
   * made it is current). Without its context the name is dropped, never
   * deleted: in another context it could name someone else's buffer.
   */
  void Release(bool contextIsCurrent);

  /// Uploads so far (a new scene: one more; a moved camera: none).
  int GetNumberOfUploads() const { return this->Uploads; }

private:
  unsigned int Buffer = 0;
  std::vector<float> Uploaded;
  int Uploads = 0;
};
} // namespace riemann

#endif
