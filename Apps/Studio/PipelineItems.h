/**
 * @file PipelineItems.h
 * @brief The kinds of pipeline items, each one toolkit filter:
 *
 * | kind              | filter                                  | shows |
 * |-------------------|-----------------------------------------|-------|
 * | geodesics         | vtkRiemannGeodesicTracer                | polylines from a seed, a cone of directions |
 * | ray-bundle        | vtkRiemannRayBundle                     | the inside view's rays, coloured by where they end |
 * | exponential-map   | vtkRiemannExponentialMap                | rays + geodesic spheres (wavefronts) at chosen radii |
 * | conjugate-locus   | vtkRiemannConjugateLocus                | conjugate points + caustic surfaces |
 * | field             | vtkRiemannCurvatureField / VolumeForm / MetricTensorField | slice, isosurface or tensor glyphs |
 * | distance-field    | vtkRiemannDistanceField (+ vtkRiemannCutLocus) | a slice coloured by distance, its wavefronts, the cut locus |
 * | connect           | vtkRiemannGeodesicConnector             | every geodesic between two points, as the picked ray |
 * | camera-path       | vtkRiemannCameraPath                    | the observer's flight: a tube, cones where it looks |
 */
#ifndef RiemannStudio_PipelineItems_h
#define RiemannStudio_PipelineItems_h

#include "PipelineItem.h"

#include <memory>

class vtkImageData;
class vtkRiemannCameraPath;


namespace riemann
{
namespace studio
{
/// The kinds, in the Add menu's order, and their menu labels.
std::vector<std::string> PipelineItemKinds();
QString PipelineItemLabel(const std::string& kind);
/// The Pipeline menu's and toolbar's text: "Add Distance Field", "Connect Two Points".
QString PipelineItemAction(const std::string& kind);
/// A new item of `kind` with default settings (null for an unknown kind).
std::unique_ptr<PipelineItem> MakePipelineItem(const std::string& kind, const QString& name);

class GeodesicsItem : public PipelineItem
{
  Q_OBJECT
public:
  explicit GeodesicsItem(const QString& name);
  std::string Kind() const override { return "geodesics"; }
  std::string FilterClass() const override { return "vtkRiemannGeodesicTracer"; }
  std::string Preset() const override { return "Fan"; }
  vtkSmartPointer<vtkAlgorithm> MakeJob(const JobInputs& inputs) const override;
  std::vector<std::string> PythonLines(const std::string& var) const override;

protected:
  std::vector<PropertySpec> ItemProperties() const override;
};

class RayBundleItem : public PipelineItem
{
  Q_OBJECT
public:
  explicit RayBundleItem(const QString& name);
  std::string Kind() const override { return "ray-bundle"; }
  std::string FilterClass() const override { return "vtkRiemannRayBundle"; }
  vtkSmartPointer<vtkAlgorithm> MakeJob(const JobInputs& inputs) const override;
  std::vector<std::string> PythonLines(const std::string& var) const override;
  bool FollowsObserver() const override { return true; }
  bool UsesScene() const override { return true; }

protected:
  std::vector<PropertySpec> ItemProperties() const override;
};

class ExponentialMapItem : public PipelineItem
{
  Q_OBJECT
public:
  explicit ExponentialMapItem(const QString& name);
  std::string Kind() const override { return "exponential-map"; }
  std::string FilterClass() const override { return "vtkRiemannExponentialMap"; }
  vtkSmartPointer<vtkAlgorithm> MakeJob(const JobInputs& inputs) const override;
  std::vector<std::string> PythonLines(const std::string& var) const override;
  bool IsLongJob() const override { return true; }

protected:
  std::vector<PropertySpec> ItemProperties() const override;
};

class ConjugateLocusItem : public PipelineItem
{
  Q_OBJECT
public:
  explicit ConjugateLocusItem(const QString& name);
  std::string Kind() const override { return "conjugate-locus"; }
  std::string FilterClass() const override { return "vtkRiemannConjugateLocus"; }
  vtkSmartPointer<vtkAlgorithm> MakeJob(const JobInputs& inputs) const override;
  std::vector<std::string> PythonLines(const std::string& var) const override;
  bool IsLongJob() const override { return true; }

protected:
  std::vector<PropertySpec> ItemProperties() const override;
};

class FieldItem : public PipelineItem
{
  Q_OBJECT
public:
  explicit FieldItem(const QString& name);
  std::string Kind() const override { return "field"; }
  std::string FilterClass() const override;
  vtkSmartPointer<vtkAlgorithm> MakeJob(const JobInputs& inputs) const override;
  std::vector<std::string> PythonLines(const std::string& var) const override;
  bool IsLongJob() const override { return true; }

protected:
  std::vector<PropertySpec> ItemProperties() const override;
};

class DistanceFieldItem : public PipelineItem
{
  Q_OBJECT
public:
  explicit DistanceFieldItem(const QString& name);
  std::string Kind() const override { return "distance-field"; }
  std::string FilterClass() const override { return "vtkRiemannDistanceField"; }
  vtkSmartPointer<vtkAlgorithm> MakeJob(const JobInputs& inputs) const override;
  std::vector<std::string> PythonLines(const std::string& var) const override;
  bool IsLongJob() const override { return true; }
  bool TakePickedPoint(const double point[3]) override;
  /// The grid, its cut locus (when ShowCutLocus) and a marker at the seed.
  std::vector<vtkSmartPointer<vtkDataObject>> ShownData() const override;

protected:
  std::vector<PropertySpec> ItemProperties() const override;

private:
  /// The cut locus of `grid` for the cut-locus settings now (kept: a colour
  /// or slice change redraws without computing it again).
  vtkDataObject* CutLocusOf(vtkImageData* grid) const;
  mutable vtkSmartPointer<vtkDataObject> CutLocus;
  mutable vtkSmartPointer<vtkDataObject> CutLocusGrid;
  mutable nlohmann::json CutLocusSettings;
};

class ConnectItem : public PipelineItem
{
  Q_OBJECT
public:
  explicit ConnectItem(const QString& name);
  std::string Kind() const override { return "connect"; }
  std::string FilterClass() const override { return "vtkRiemannGeodesicConnector"; }
  vtkSmartPointer<vtkAlgorithm> MakeJob(const JobInputs& inputs) const override;
  std::vector<std::string> PythonLines(const std::string& var) const override;
  bool IsLongJob() const override { return true; }
  bool TakePickedPoint(const double point[3]) override;
  /// The geodesics and a marker where they end.
  std::vector<vtkSmartPointer<vtkDataObject>> ShownData() const override;

protected:
  std::vector<PropertySpec> ItemProperties() const override;

private:
  /// The next Ctrl+click sets To (else From).
  bool PickTo = false;
};

class CameraPathItem : public PipelineItem
{
  Q_OBJECT
public:
  explicit CameraPathItem(const QString& name);
  std::string Kind() const override { return "camera-path"; }
  std::string FilterClass() const override { return "vtkRiemannCameraPath"; }
  vtkSmartPointer<vtkAlgorithm> MakeJob(const JobInputs& inputs) const override;
  std::vector<std::string> PythonLines(const std::string& var) const override;
  bool TakePickedPoint(const double point[3]) override;
  /// Sets a vtkRiemannCameraPath's path settings from this item's (all
  /// but the metric): what Export Animation flies along.
  void Configure(vtkRiemannCameraPath* path) const;
  /// The path's key positions (a spline's), from the item's KeyPositions.
  void SetKeyPositions(vtkRiemannCameraPath* path) const;

protected:
  std::vector<PropertySpec> ItemProperties() const override;
};
}
}

#endif
