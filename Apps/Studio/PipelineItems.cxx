#include "PipelineItems.h"

namespace riemann
{
namespace studio
{
std::vector<std::string> PipelineItemKinds()
{
  return { "geodesics", "ray-bundle", "exponential-map", "conjugate-locus", "field" };
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
  return QString();
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
  return nullptr;
}
}
}
