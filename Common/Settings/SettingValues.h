/**
 * @file SettingValues.h
 * @brief Values of declared settings as JSON (the form every surface
 * shares: a project's item settings, a form's field, a parsed option):
 * defaults, checks, reading a typed option, and the Python that sets them.
 *
 * A value is stored as its declaration says: a number, a boolean, three
 * numbers, a choice by name ("rk4"), a list of numbers.
 */
#ifndef RiemannSettingValues_h
#define RiemannSettingValues_h

#include "RiemannCommonSettingsExport.h"
#include "SettingDeclaration.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace riemann
{
/// The declared default of `setting`.
RIEMANNCOMMONSETTINGS_EXPORT nlohmann::json DefaultValue(const SettingDeclaration& setting);

/// Every setting of `table` at its default, keyed by name.
RIEMANNCOMMONSETTINGS_EXPORT nlohmann::json DefaultValues(const SettingTable& table);

/// A Choice's names, in the order of their indices.
RIEMANNCOMMONSETTINGS_EXPORT std::vector<std::string> ChoiceNames(const SettingDeclaration& setting);

/// The index of `name` among a Choice's names (or its old names), or -1.
RIEMANNCOMMONSETTINGS_EXPORT int ChoiceIndex(const SettingDeclaration& setting, const std::string& name);

/// Why `v` cannot be a direction, as the end of a sentence ("is the zero
/// vector: ...", "is too short to normalise (scale it)"), or "" when it can.
RIEMANNCOMMONSETTINGS_EXPORT std::string DirectionProblem(const double v[3]);

/// Why `b` (x0,x1,y0,y1,z0,z1) cannot be a box ("the x range needs x0 < x1,
/// got 1 >= -1"), or "" when it can.
RIEMANNCOMMONSETTINGS_EXPORT std::string BoundsProblem(const double b[6]);

/**
 * "" when `value` has the declared type and range; else why not, naming the
 * setting `name` ("NumberOfDirections is 0: expected a whole number from 1
 * to 1e+06").
 */
RIEMANNCOMMONSETTINGS_EXPORT std::string CheckSettingValue(
  const SettingDeclaration& setting, const nlohmann::json& value, const std::string& name);

/**
 * "" when every setting of `table` has a valid value in `values` (keyed by
 * name, as SettingValues(object) gives them); else CheckSettingValue's
 * sentence for the first that has not, in the table's order.
 */
RIEMANNCOMMONSETTINGS_EXPORT std::string CheckSettingValues(
  const SettingTable& table, const nlohmann::json& values);

/**
 * The value typed as text ("400", "0,0,1", "rk4", "1, 2.5", "true"), as a
 * command's option or a form's field gives it. On bad text returns null and
 * sets `error` ("expected three finite numbers X,Y,Z", without the name or
 * the text); the range is CheckSettingValue's.
 */
RIEMANNCOMMONSETTINGS_EXPORT nlohmann::json ParseSettingText(
  const SettingDeclaration& setting, const std::string& text, std::string& error);

/// The value as such text ("0,0,1", "1, 2.5", "rk4", "true", "400").
RIEMANNCOMMONSETTINGS_EXPORT std::string SettingText(
  const SettingDeclaration& setting, const nlohmann::json& value);

/**
 * Python lines that give `variable` (a VTK object of the table's class) the
 * settings of `values` that the table declares, in the table's order:
 * `v.SetConeAngle(35.0)`, a choice by index, a list as its clear and add
 * commands.
 */
RIEMANNCOMMONSETTINGS_EXPORT std::vector<std::string> SettingPythonLines(
  const SettingTable& table, const std::string& variable, const nlohmann::json& values);

namespace settings
{
/**
 * The declared settings of VTK class `Object` for code that takes the class
 * as a template parameter: specialised in each `<Object>SettingAccess.h`
 * (Settings(), Apply(object, values), Values(object): the header's
 * DeclaredSettings, ApplySettings and SettingValues). A class template,
 * not overloads, because a template's qualified call binds only the
 * overloads declared before it, while a specialisation is found wherever
 * it was declared before the use.
 */
template <class Object>
struct DeclaredAccess;
} // namespace settings
} // namespace riemann

#endif
