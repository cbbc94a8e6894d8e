/**
 * @file OutputDisplay.h
 * @brief How the outside view shows one output of an item, chosen by the
 * output's data type, as ParaView's views choose a representation: a
 * vtkPolyData (curves, points, surfaces) by PolyDataDisplay, a vtkImageData
 * (a grid: slice, isosurface, tensor glyphs, level lines) by
 * ImageDataDisplay.
 *
 * Each kind of display declares its settings here, once (key, label, range,
 * default, help): the properties panel shows them for every item with an
 * output of that type, projects store them under those keys, and the item
 * only overrides a default it wants (a distance field's level lines). The
 * colouring settings every display has (ColorArray, ColorMap, Opacity and
 * the colour-map editor's) are declared once for all of them.
 */
#ifndef RiemannStudio_OutputDisplay_h
#define RiemannStudio_OutputDisplay_h

#include "ColorMaps.h" // For ColorScale
#include "PipelineItem.h" // For PropertySpec
#include "ShownOutput.h"

#include "vtkSmartPointer.h"

#include <nlohmann/json.hpp>

#include <QStringList>

#include <memory>
#include <string>
#include <vector>

class vtkAssembly;
class vtkDataObject;
class vtkScalarBarActor;

namespace riemann
{
namespace studio
{
class OutputDisplay
{
public:
  virtual ~OutputDisplay() = default;
  /**
   * Show `data` (null: nothing yet, hidden) as `look` and the item's display
   * `settings` say, coloured by `coloring`; `bar` is the item's legend when
   * this output has it (Legend), else null.
   */
  virtual void Show(vtkDataObject* data, const OutputLook& look, const nlohmann::json& settings,
    ColorScale coloring, vtkScalarBarActor* bar) = 0;

  OutputDisplay(const OutputDisplay&) = delete;
  OutputDisplay& operator=(const OutputDisplay&) = delete;

protected:
  OutputDisplay() = default;
};

/// A display setting as a display declares it: shown in the form, kept in projects, never re-running the job.
PropertySpec DisplaySpec(const char* key, const char* label, PropertySpec::Kind type,
  nlohmann::json value, const char* help);

/// A display for outputs of `dataType`, its actors added to `parts`; null for a type no display shows.
std::unique_ptr<OutputDisplay> MakeOutputDisplay(const std::string& dataType, vtkAssembly* parts);

/**
 * The display settings of an item whose outputs have `dataTypes`: the
 * colouring settings, then each type's own (once). `colorArrays` are the
 * result's arrays (the choices of ColorArray) and `colorArray` the current
 * choice, kept selectable before the first result.
 */
std::vector<PropertySpec> DisplayPropertySpecs(const std::vector<std::string>& dataTypes,
  const QStringList& colorArrays, const std::string& colorArray);

/// The declared defaults of DisplayPropertySpecs, keyed by setting.
nlohmann::json DisplayDefaults(const std::vector<std::string>& dataTypes);
}
}

#endif
