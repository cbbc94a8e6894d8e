/**
 * @file ColorMaps.h
 * @brief The colour maps offered for colouring items, and the one place
 * that sets up a mapper's colouring (array, map, range, opacity).
 */
#ifndef RiemannStudio_ColorMaps_h
#define RiemannStudio_ColorMaps_h

#include <QStringList>

#include <string>

class vtkActor;
class vtkDataArray;
class vtkDataSet;
class vtkMapper;
class vtkScalarBarActor;

namespace riemann
{
namespace studio
{
/**
 * The colour maps: "viridis" (the default: perceptual, colour-blind safe),
 * "cividis" (for deuteranopia and protanopia too), "magma", "cool-to-warm"
 * (Moreland's diverging map, ParaView's; centred on zero when the values
 * change sign), "grayscale", "vtk-rainbow" (vtkLookupTable's default hue
 * ramp, VTK's own) and "rainbow" (kept for old projects; not perceptual).
 */
QStringList ColorMapNames();

/// The picked ray's colour (magenta), and what is drawn like it (connections).
constexpr double PickedRayColor[3] = { 1.0, 0.25, 0.9 };

/// How an item is coloured: its display settings (PipelineItem::Coloring).
struct ColorScale
{
  /// A point or cell array; "Solid" or a missing array: one colour.
  std::string Array = "Solid";
  std::string Map = "viridis";
  double Opacity = 1.0;
  /// The range: the array's own (first component, or magnitude for
  /// vectors) unless CustomRange, then [Minimum, Maximum].
  bool CustomRange = false;
  double Minimum = 0.0;
  double Maximum = 1.0;
  /// 0: continuous; N >= 2: N discrete colours.
  int Steps = 0;
  /// Show a scalar bar (legend) of the map in the outside view.
  bool ScalarBar = false;
};

/**
 * Colour `actor` (whose mapper draws `data`) as `scale` says, `solid` RGB
 * without an array. With a `bar`, it shows this colouring (titled by the
 * array) when scale.ScalarBar and an array colours the actor, else it hides.
 */
/// The array that colours `data` by `name`: its point array, else its cell
/// array; null for "Solid" or an array it lacks. `onPoints` says which.
vtkDataArray* ColoringArray(vtkDataSet* data, const std::string& name, bool* onPoints = nullptr);
/// The range a colouring reads from `values`: the first component's, or the
/// magnitude's for vectors.
void ColoringRange(vtkDataArray* values, double range[2]);

void ApplyColoring(vtkActor* actor, vtkDataSet* data, const ColorScale& scale, const double solid[3],
  vtkScalarBarActor* bar = nullptr);
}
}

#endif
