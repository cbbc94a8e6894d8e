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
class vtkDataSet;
class vtkMapper;

namespace riemann
{
namespace studio
{
/// "cool-to-warm" (the default, as in ParaView), "viridis", "rainbow", "grayscale".
QStringList ColorMapNames();

/// The picked ray's colour (magenta), and what is drawn like it (connections).
constexpr double PickedRayColor[3] = { 1.0, 0.25, 0.9 };

/**
 * Colour `actor` (whose mapper draws `data`) by `array` (a point or cell
 * array; "Solid" or a missing array: `solid` RGB) through `map`, over the
 * array's range (first component, or magnitude for vectors), with `opacity`.
 */
void ApplyColoring(vtkActor* actor, vtkDataSet* data, const std::string& array,
  const std::string& map, double opacity, const double solid[3]);
}
}

#endif
