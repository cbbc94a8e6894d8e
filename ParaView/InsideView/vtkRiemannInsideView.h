/**
 * @class   vtkRiemannInsideView
 * @brief   ParaView's render view drawn from inside the space with a metric:
 *          what it shows of the visible data, through vtkRiemannRayTracePass.
 *
 * A vtkPVRenderView whose renderer draws with vtkRiemannRayTracePass
 * (UseRendererProps on): the representations' actors are the meshes of the
 * inside view, seen along the metric's geodesics from ParaView's camera
 * (the view's active camera is the observer). The metric is the one a
 * visible Riemann Metric source carries (its output's field data, as
 * vtkRiemannMetricInput reads it): show the metric in the view (its eye in
 * the Pipeline Browser), at the view's time as every source is. Without one
 * the view says so (vtkErrorMacro, once per change) and draws red, as the
 * pass does on any error.
 *
 * The scene around the data: the view's background colour, the observer's
 * light, no objects, and the pass's declared integration (the "Rays"
 * preset: RK4, step 0.02, 1000 steps, length 30).
 *
 * With a server (pvserver), the view always renders where the data are:
 * its remote rendering threshold is 0, whatever ParaView's settings say,
 * so the server draws through the pass and sends the picture (the client
 * holds no data to find the metric in, nor the meshes to trace).
 */
#ifndef vtkRiemannInsideView_h
#define vtkRiemannInsideView_h

#include "RiemannParaViewInsideViewModule.h" // For export macro
#include "vtkNew.h"                          // For vtkNew
#include "vtkPVRenderView.h"
#include "vtkRiemannMetricInput.h"  // For the metric
#include "vtkRiemannRayTracePass.h" // For vtkNew
#include "vtkRiemannScene.h"        // For vtkNew

#include <string> // For std::string

class RIEMANNPARAVIEWINSIDEVIEW_EXPORT vtkRiemannInsideView : public vtkPVRenderView
{
public:
  static vtkRiemannInsideView* New();
  vtkTypeMacro(vtkRiemannInsideView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The pass that draws the view (its integration and projection settings).
  vtkRiemannRayTracePass* GetRayTracePass();

  /// Why the view draws nothing of the metric ("" when it has one).
  const char* GetLastError() const { return this->LastError.c_str(); }

  /// Always 0: the server renders this view (ParaView's settings set the threshold of every render view).
  void SetRemoteRenderingThreshold(double threshold) override;

protected:
  vtkRiemannInsideView();
  ~vtkRiemannInsideView() override;

  /// Before each render: the metric of the visible data, the scene, the pass.
  void AboutToRenderOnLocalProcess(bool interactive) override;

private:
  vtkRiemannInsideView(const vtkRiemannInsideView&) = delete;
  void operator=(const vtkRiemannInsideView&) = delete;

  /// The metric a visible representation's input carries, or null.
  vtkRiemannMetric* FindMetric(std::string& error);
  /// The scene around the data: the renderer's background, the observer's light.
  void UpdateScene();

  vtkNew<vtkRiemannRayTracePass> Pass;
  vtkNew<vtkRiemannScene> Scene;
  vtkRiemannMetricInput MetricInput;
  std::string SceneText;
  std::string LastError;
};

#endif
