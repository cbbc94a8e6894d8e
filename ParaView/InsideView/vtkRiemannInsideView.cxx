#include "vtkRiemannInsideView.h"

#include "vtkDataObject.h"
#include "vtkObjectFactory.h"
#include "vtkPVDataRepresentation.h"
#include "vtkRenderer.h"
#include "vtkRiemannMetric.h"

#include <cstdio>

vtkStandardNewMacro(vtkRiemannInsideView);

vtkRiemannInsideView::vtkRiemannInsideView()
{
  // The data's actors are the scene's meshes; the rest of the scene is ours.
  this->Pass->SetUseRendererProps(true);
  this->Superclass::SetRemoteRenderingThreshold(0.0);
}

vtkRiemannInsideView::~vtkRiemannInsideView() = default;

void vtkRiemannInsideView::SetRemoteRenderingThreshold(double)
{
  this->Superclass::SetRemoteRenderingThreshold(0.0);
}

vtkRiemannRayTracePass* vtkRiemannInsideView::GetRayTracePass()
{
  return this->Pass;
}

vtkRiemannMetric* vtkRiemannInsideView::FindMetric(std::string& error)
{
  error.clear();
  bool anyVisible = false;
  for (int i = 0; i < this->GetNumberOfRepresentations(); ++i)
  {
    auto* representation = vtkPVDataRepresentation::SafeDownCast(this->GetRepresentation(i));
    if (!representation || !representation->GetVisibility() ||
      representation->GetNumberOfInputConnections(0) == 0)
    {
      continue;
    }
    anyVisible = true;
    vtkDataObject* data = representation->GetInputDataObject(0, 0);
    if (vtkRiemannMetricInput::CarriesMetric(data))
    {
      return this->MetricInput.FromData(data, error);
    }
  }
  // An empty view is no error: it draws nothing until data (and a metric) are shown.
  if (anyVisible)
  {
    error = "No metric: show a Riemann Metric in this view (the eye in the Pipeline Browser); "
            "the inside view draws the visible data along its geodesics.";
  }
  return nullptr;
}

void vtkRiemannInsideView::UpdateScene()
{
  // The view's background; the observer's light (what the data's colours look like
  // straight), no objects of the scene's own.
  double background[3];
  this->GetRenderer()->GetBackground(background);
  char text[256];
  std::snprintf(text, sizeof(text),
    "{\"background\": [%.17g, %.17g, %.17g], \"lighting\": \"observer\", \"objects\": []}",
    background[0], background[1], background[2]);
  if (this->SceneText != text && this->Scene->SetDefinition(text))
  {
    this->SceneText = text;
  }
}

void vtkRiemannInsideView::AboutToRenderOnLocalProcess(bool interactive)
{
  this->Superclass::AboutToRenderOnLocalProcess(interactive);
  std::string error;
  vtkRiemannMetric* metric = this->FindMetric(error);
  if (error != this->LastError && !error.empty())
  {
    vtkErrorMacro(<< error);
  }
  this->LastError = error;
  if (!metric && error.empty())
  {
    // Nothing shown yet: the renderer's own (empty) picture.
    this->GetRenderer()->SetPass(nullptr);
    return;
  }
  this->UpdateScene();
  // Without a metric the pass clears the view to red (its error convention).
  this->Pass->SetMetric(metric);
  this->Pass->SetScene(this->Scene);
  this->GetRenderer()->SetPass(this->Pass);
}

void vtkRiemannInsideView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LastError: " << this->LastError << "\n";
  os << indent << "RayTracePass:\n";
  this->Pass->PrintSelf(os, indent.GetNextIndent());
}
