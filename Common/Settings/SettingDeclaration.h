/**
 * @file SettingDeclaration.h
 * @brief One user-facing setting of a VTK class, as its declaration file
 * (`<Class>.settings.json`, next to the class) states it once: the VTK
 * property's name, type, default, range or choices, unit, label, help, and
 * the old spellings other surfaces must keep accepting.
 *
 * The tables are generated from those files at build time
 * (cmake/RiemannSettings.py writes `<Class>Settings.h` into this library's
 * build folder); every surface is made from them: the VTK classes'
 * defaults, the `riemann` commands' options, riemann-studio's forms, the
 * project keys, the exported Python and the ParaView server-manager XML
 * (Documentation/Settings.md). Nothing here knows of VTK.
 */
#ifndef RiemannSettingDeclaration_h
#define RiemannSettingDeclaration_h

#include "RiemannCommonSettingsExport.h"

#include <cstddef>
#include <string>

namespace riemann
{
struct SettingDeclaration
{
  enum Kind
  {
    Boolean,   ///< true or false
    Integer,   ///< a whole number in the range
    Number,    ///< a real number in the range
    Point,     ///< three real numbers
    Direction, ///< three real numbers, not all zero
    Choice,    ///< one of Choices, stored by name; the VTK property holds its index
    NumberList, ///< zero or more real numbers in the range (Add/Clear commands)
    Bounds,    ///< a box x0,x1,y0,y1,z0,z1 with x0 < x1, y0 < y1, z0 < z1
    Dimensions ///< three whole numbers in the range (a grid's points per axis)
  };
  /// The VTK property (Set<Name>, Get<Name>); the key in projects and scripts.
  const char* Name;
  Kind Type;
  /// The default as JSON text ("400", "[0, 0, 1]", "\"rk4\"", "[]").
  const char* Default;
  /// The valid range of a number (each number of a Point, NumberList or Dimensions):
  /// Minimum < value (MinimumExclusive) or Minimum <= value, and value <= Maximum
  /// (or value < Maximum: MaximumExclusive, the last field).
  double Minimum;
  bool MinimumExclusive;
  double Maximum;
  /// A Choice's names, '|'-separated, in the order of their indices ("euler|rk4|dp45").
  const char* Choices;
  /// What a value is measured in ("" for a pure number or a choice).
  const char* Unit;
  /// The label of forms (riemann-studio, ParaView).
  const char* Label;
  /// One sentence, without the unit, range or default (every surface adds those).
  const char* Help;
  /// Old option names of the `riemann` commands that keep working
  /// (comma-separated, "--directions"); "" when there are none.
  const char* CommandLineAliases;
  /// A NumberList's commands: add one value, remove them all, count and get (by index).
  const char* AddCommand;
  const char* ClearCommand;
  const char* CountCommand;
  const char* GetCommand;
  /// The key of a scene file's block that sets it ("max_length"); "" when none.
  const char* SceneKey = "";
  /// A Choice's old names that keep working, "old=new" comma-separated ("adaptive=dp45").
  const char* ChoiceAliases = "";
  /// Old property names a project or script may still use for it, comma-separated
  /// ("ConeAxis" for the tracer's StartDirection); "" when there are none.
  const char* ProjectAliases = "";
  /// value < Maximum rather than value <= Maximum (an angle below 180 degrees).
  bool MaximumExclusive = false;
};

/// The declared settings of one VTK class, in the order forms list them.
struct SettingTable
{
  const char* ClassName;
  /// The class as menus name it ("Exponential Map").
  const char* Label;
  const SettingDeclaration* Settings;
  std::size_t Count;

  const SettingDeclaration* begin() const { return this->Settings; }
  const SettingDeclaration* end() const { return this->Settings + this->Count; }
  /// The setting named `name`, or null.
  RIEMANNCOMMONSETTINGS_EXPORT const SettingDeclaration* Find(const std::string& name) const;
};

/// The setting's option of the `riemann` commands: "--number-of-directions"
/// for NumberOfDirections (the property's words, lower case, joined by '-').
RIEMANNCOMMONSETTINGS_EXPORT std::string CommandLineName(const SettingDeclaration& setting);

/// The name and the old spellings, as CLI11 takes them:
/// "--number-of-directions,--directions".
RIEMANNCOMMONSETTINGS_EXPORT std::string CommandLineNames(const SettingDeclaration& setting);

/// The range in words ("a whole number from 1 to 1e+06 (directions)"; a
/// choice: "one of euler, rk4, dp45"; a point: "three numbers"; "" for a boolean).
RIEMANNCOMMONSETTINGS_EXPORT std::string DescribeSettingRange(const SettingDeclaration& setting);
} // namespace riemann

#endif
