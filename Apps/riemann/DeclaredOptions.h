/**
 * @file DeclaredOptions.h
 * @brief A command's options made from a VTK class's declared settings
 * (`<Class>.settings.json`, SettingDeclaration.h): one option per setting,
 * named after the property (--number-of-directions for NumberOfDirections)
 * with the declared old spellings (--directions), the declared help with
 * the range, unit and default, checked against the declared range while
 * CLI11 parses. Nothing about a setting is written in the command.
 */
#ifndef RiemannCliDeclaredOptions_h
#define RiemannCliDeclaredOptions_h

#include "SettingDeclaration.h"

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include <map>
#include <string>

namespace riemann
{
namespace cli
{
class DeclaredOptions
{
public:
  /**
   * Add an option to `command` for each setting of `table` but those named
   * in `leftOut` (comma-separated: settings the command decides itself).
   * `defaults` (keyed by property) replaces declared defaults where the
   * command's object has its own (a filter's integration settings: a new
   * filter's SettingValues); `defaultWords`, when given, is what the help
   * says instead of a value ("the scene's"), "{}" in it standing for the
   * value ("the scene's camera, else {}").
   */
  DeclaredOptions(CLI::App* command, const SettingTable& table, const std::string& leftOut = "",
    const nlohmann::json& defaults = nlohmann::json::object(), const std::string& defaultWords = "");

  /// The settings given on the command line, keyed by property, as JSON values.
  nlohmann::json Given() const;

  /// The value of `name`: given, or the default (the command's, else the declared one).
  nlohmann::json Value(const std::string& name) const;
  ///@{
  /// Value() as a number, a whole number, a name (a choice).
  double Number(const std::string& name) const { return this->Value(name).get<double>(); }
  long long Integer(const std::string& name) const { return this->Value(name).get<long long>(); }
  std::string Text(const std::string& name) const { return this->Value(name).get<std::string>(); }
  ///@}

  /// The option of setting `name` (to make it required, say); null when left out.
  CLI::Option* OptionOf(const std::string& name) const
  {
    const auto found = this->Options.find(name);
    return found == this->Options.end() ? nullptr : found->second;
  }

  /// The option that sets `name` ("--radii"), for messages.
  static std::string OptionOf(const SettingTable& table, const std::string& name);

private:
  const SettingTable& Table;
  nlohmann::json Defaults;
  /// The parsed value of the option `name`, which was given.
  nlohmann::json GivenValue(const std::string& name) const;

  /// The text typed for each option (std::map: CLI11 keeps references to its values).
  std::map<std::string, std::string> Texts;
  std::map<std::string, CLI::Option*> Options;
};

/// The option's help: the declared help, unit and range, and the default
/// (`byDefault`: a value, or words such as "the scene's").
std::string DeclaredHelp(const SettingDeclaration& setting, const std::string& byDefault);
} // namespace cli
} // namespace riemann

#endif
