#include "PipelineItems.h"

namespace riemann
{
namespace studio
{
std::vector<std::string> PipelineItemKinds()
{
  return { "geodesics", "ray-bundle", "exponential-map", "conjugate-locus", "field",
    "distance-field", "connect", "camera-path" };
}

QString PipelineItemLabel(const std::string& kind)
{
  if (kind == "geodesics")
  {
    return QStringLiteral("Geodesics");
  }
  if (kind == "ray-bundle")
  {
    return QStringLiteral("Ray Bundle");
  }
  if (kind == "exponential-map")
  {
    return QStringLiteral("Exponential Map");
  }
  if (kind == "conjugate-locus")
  {
    return QStringLiteral("Conjugate Locus");
  }
  if (kind == "field")
  {
    return QStringLiteral("Field");
  }
  if (kind == "distance-field")
  {
    return QStringLiteral("Distance Field");
  }
  if (kind == "connect")
  {
    return QStringLiteral("Connection");
  }
  if (kind == "camera-path")
  {
    return QStringLiteral("Camera Path");
  }
  return QString();
}

QString PipelineItemAction(const std::string& kind)
{
  // The connector is asked for by what it does, as the issue names it.
  return kind == "connect" ? QStringLiteral("Connect Two Points") : "Add " + PipelineItemLabel(kind);
}

std::unique_ptr<PipelineItem> MakePipelineItem(const std::string& kind, const QString& name)
{
  if (kind == "geodesics")
  {
    return std::make_unique<GeodesicsItem>(name);
  }
  if (kind == "ray-bundle")
  {
    return std::make_unique<RayBundleItem>(name);
  }
  if (kind == "exponential-map")
  {
    return std::make_unique<ExponentialMapItem>(name);
  }
  if (kind == "conjugate-locus")
  {
    return std::make_unique<ConjugateLocusItem>(name);
  }
  if (kind == "field")
  {
    return std::make_unique<FieldItem>(name);
  }
  if (kind == "distance-field")
  {
    return std::make_unique<DistanceFieldItem>(name);
  }
  if (kind == "camera-path")
  {
    return std::make_unique<CameraPathItem>(name);
  }
  if (kind == "connect")
  {
    return std::make_unique<ConnectItem>(name);
  }
  return nullptr;
}
}
}
