/**
 * @file RiemannReducedView.h
 * @brief Private to Rendering/OpenGL: the inside view traced at a lower
 * resolution (one ray per d x d pixels, d the image sample distance) into an
 * offscreen colour and depth target, then magnified into the viewport; and
 * the rule that picks d from the time a frame may take.
 *
 * This is how vtkGPUVolumeRayCastMapper keeps volume rendering interactive
 * (its ImageSampleDistance and AutoAdjustSampleDistances), applied to the
 * geodesic ray tracer, whose cost is per ray.
 *
 * The compute path (vtkRiemannRayTracePass::GPUPath Compute) always traces
 * into images, at any distance, and composes them with the same Magnify():
 * BindImages() instead of Bind().
 */
#ifndef RiemannReducedView_h
#define RiemannReducedView_h

#include "vtkSmartPointer.h"

#include <memory>
#include <string>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace riemann
{
/**
 * The image sample distance for a frame of `budget` seconds, from a frame
 * that took `seconds` at `distance`. A frame traces pixels / d^2 rays, so
 * the time scales as 1 / d^2 and the answer is distance * sqrt(seconds /
 * budget), kept within [minimum, maximum]. Without a usable measurement
 * (seconds or budget not positive and finite) `distance` is kept.
 */
double AdjustedImageSampleDistance(
  double distance, double seconds, double budget, double minimum, double maximum);

/// The number of traced pixels along a side of `pixels` pixels at distance `distance` (>= 1).
int TracedPixels(int pixels, double distance);

class ReducedView
{
public:
  ReducedView();
  ~ReducedView();
  ReducedView(const ReducedView&) = delete;
  ReducedView& operator=(const ReducedView&) = delete;

  /**
   * Push the framebuffer bindings and bind an offscreen target (RGBA8
   * colour, 32-bit float depth) of at least width x height pixels: the view
   * is then traced into its corner (0, 0, width, height). The target is
   * kept while later sizes fit it. False with `error` when the target cannot
   * be made (the bindings are popped again).
   */
  bool Bind(vtkOpenGLRenderWindow* window, int width, int height, std::string& error);

  /**
   * For the compute path: images of at least width x height pixels, the
   * colour (RGBA8) bound to image unit 0 and the window depth (R32F) to
   * unit 1 for writing; Magnify() then composes them. False with `error`
   * when the textures cannot be made.
   */
  bool BindImages(vtkOpenGLRenderWindow* window, int width, int height, std::string& error);

  /// Unbind the image units bound by BindImages().
  void UnbindImages();

  /// Pop the framebuffer bindings pushed by Bind().
  void Unbind(vtkOpenGLRenderWindow* window);

  /**
   * Draw the traced image (of the last Bind() or BindImages()) over
   * `viewport` (x, y, width, height of the current target): colour
   * interpolated bilinearly, depth from the nearest traced pixel (so that props composed over the view never see a depth
   * between a surface and the background). `traced` is the viewport's size
   * in traced pixels (viewport size / d, not rounded). False with `error`
   * when the magnifying shader cannot be built.
   */
  bool Magnify(vtkOpenGLRenderWindow* window, const int viewport[4], const double traced[2],
    std::string& error);

  /**
   * Progressive refinement: draw the images of the last BindImages() over
   * `viewport`, each pixel taking the colour and depth of the traced pixel
   * below and left of it on the finest lattice traced there: `level` (every
   * level-th pixel) for rows below `rowsDone`, 2 * level above (traced
   * earlier). With level 1 and every row done, the images pixel for pixel.
   * False with `error` when the shader cannot be built.
   */
  bool ComposeLattice(vtkOpenGLRenderWindow* window, const int viewport[4], int level,
    int rowsDone, std::string& error);

  void Release(vtkWindow* window);

private:
  void ReleaseTarget(vtkWindow* window);
  /// A colour texture that holds width x height pixels (kept while it fits).
  void ReadyColor(vtkOpenGLRenderWindow* window, int width, int height);
  /// Build `quad` with `shader` once and bind it with the traced colour and depth; null with
  /// `error` when nothing was traced or the shader cannot be built.
  vtkShaderProgram* ReadyComposer(vtkOpenGLRenderWindow* window,
    std::unique_ptr<vtkOpenGLQuadHelper>& quad, const char* shader, std::string& error);
  /// Draw `quad` over `viewport`, then release the traced textures' units.
  void Compose(vtkOpenGLRenderWindow* window, vtkOpenGLQuadHelper* quad, const int viewport[4]);

  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkTextureObject> Color;
  vtkSmartPointer<vtkTextureObject> Depth;
  /// The compute path's depth image (a depth texture cannot be an image).
  vtkSmartPointer<vtkTextureObject> DepthImage;
  /// What Magnify() reads the depth from: Depth or DepthImage.
  vtkTextureObject* TracedDepth = nullptr;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  std::unique_ptr<vtkOpenGLQuadHelper> LatticeQuad;
};
} // namespace riemann

#endif
