#include "OutputDisplay.h"

#include "ImageDataDisplay.h"
#include "PolyDataDisplay.h"

#include <algorithm>
#include <functional>

namespace riemann
{
namespace studio
{
namespace
{
/// One kind of display: the data type it shows, its own settings, and how to make one.
struct DisplayKind
{
  const char* DataType;
  std::function<std::vector<PropertySpec>()> Properties;
  std::function<std::unique_ptr<OutputDisplay>(vtkAssembly*)> Make;
};

const std::vector<DisplayKind>& DisplayKinds()
{
  static const std::vector<DisplayKind> kinds{
    { "vtkPolyData", PolyDataDisplay::Properties,
      [](vtkAssembly* parts) { return std::make_unique<PolyDataDisplay>(parts); } },
    { "vtkImageData", ImageDataDisplay::Properties,
      [](vtkAssembly* parts) { return std::make_unique<ImageDataDisplay>(parts); } },
  };
  return kinds;
}

/// The colouring every display has: the array, the map and the colour-map editor's settings.
std::vector<PropertySpec> ColoringPropertySpecs(const QStringList& colorArrays, const std::string& colorArray)
{
  PropertySpec array = DisplaySpec("ColorArray", "Colour by", PropertySpec::Choice, "Solid",
    "The point or cell array that colours the item (Solid, or an array the item does not have: "
    "one colour)");
  array.Choices = QStringList{ "Solid" } + colorArrays;
  if (!array.Choices.contains(QString::fromStdString(colorArray)))
  {
    array.Choices << QString::fromStdString(colorArray);
  }
  array.OpenChoice = true;

  // Perceptual and colour-blind safe by default (ColorMaps.h).
  PropertySpec map = DisplaySpec("ColorMap", "Colour map", PropertySpec::Choice, "viridis",
    "The colours the array's values map to");
  map.Choices = ColorMapNames();

  PropertySpec opacity = DisplaySpec("Opacity", "Opacity", PropertySpec::Number, 1.0,
    "0: invisible, 1: opaque");
  opacity.Minimum = 0.0;
  opacity.Maximum = 1.0;

  PropertySpec range = DisplaySpec("ColorRange", "Colour range", PropertySpec::Choice, "data",
    "data: the array's own range (a diverging map centred on zero); custom: the minimum and "
    "maximum below; over time: the array's range over t = 0, 1/8, ..., 1 (the same colours in "
    "every frame of a film)");
  range.Choices = QStringList{ "data", "custom", "over time" };
  PropertySpec minimum = DisplaySpec("ColorRangeMinimum", "Range minimum", PropertySpec::Number,
    0.0, "The value at the map's first colour (custom range)");
  PropertySpec maximum = DisplaySpec("ColorRangeMaximum", "Range maximum", PropertySpec::Number,
    1.0, "The value at the map's last colour (custom range; above the minimum)");
  PropertySpec steps = DisplaySpec("ColorSteps", "Discrete colours", PropertySpec::Integer, 0,
    "0: a continuous map; N (2 to 256): N bands of equal width");
  steps.Minimum = 0;
  steps.Maximum = 256;
  PropertySpec bar = DisplaySpec("ScalarBar", "Scalar bar", PropertySpec::Boolean, false,
    "Show the map's legend in the outside view");
  return { array, map, opacity, range, minimum, maximum, steps, bar };
}
}

PropertySpec DisplaySpec(const char* key, const char* label, PropertySpec::Kind type,
  nlohmann::json value, const char* help)
{
  PropertySpec spec;
  spec.Key = key;
  spec.Label = label;
  spec.Type = type;
  spec.Default = std::move(value);
  spec.Help = help;
  spec.Display = true;
  return spec;
}

std::unique_ptr<OutputDisplay> MakeOutputDisplay(const std::string& dataType, vtkAssembly* parts)
{
  for (const DisplayKind& kind : DisplayKinds())
  {
    if (dataType == kind.DataType)
    {
      return kind.Make(parts);
    }
  }
  return nullptr;
}

std::vector<PropertySpec> DisplayPropertySpecs(const std::vector<std::string>& dataTypes,
  const QStringList& colorArrays, const std::string& colorArray)
{
  std::vector<PropertySpec> specs = ColoringPropertySpecs(colorArrays, colorArray);
  for (const DisplayKind& kind : DisplayKinds())
  {
    if (std::find(dataTypes.begin(), dataTypes.end(), kind.DataType) != dataTypes.end())
    {
      for (const PropertySpec& spec : kind.Properties())
      {
        specs.push_back(spec);
      }
    }
  }
  return specs;
}

nlohmann::json DisplayDefaults(const std::vector<std::string>& dataTypes)
{
  nlohmann::json values = nlohmann::json::object();
  for (const PropertySpec& spec : DisplayPropertySpecs(dataTypes, QStringList(), "Solid"))
  {
    values[spec.Key] = spec.Default;
  }
  return values;
}
}
}
