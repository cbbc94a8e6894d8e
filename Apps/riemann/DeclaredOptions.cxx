#include "DeclaredOptions.h"

#include "SettingValues.h"

#include <sstream>

namespace riemann
{
namespace cli
{
namespace
{
bool IsLeftOut(const std::string& name, const std::string& leftOut)
{
  std::stringstream stream(leftOut);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    if (item == name)
    {
      return true;
    }
  }
  return false;
}

/**
 * CLI11's check of the typed text: its type (ParseSettingText), then its
 * range. CLI11 reports a refusal as "--option: expected a whole number from
 * 1 to 1e+06, got \"0\"" (status 2) before any command runs.
 */
CLI::Validator DeclaredCheck(const SettingDeclaration& setting)
{
  return CLI::Validator(
    [&setting](std::string& text) -> std::string
    {
      if (setting.Type == SettingDeclaration::Boolean && text.empty())
      {
        return std::string(); // given alone: true (BooleanText)
      }
      std::string error;
      const nlohmann::json value = ParseSettingText(setting, text, error);
      const bool vector = setting.Type == SettingDeclaration::Point ||
        setting.Type == SettingDeclaration::Direction || setting.Type == SettingDeclaration::Bounds ||
        setting.Type == SettingDeclaration::Dimensions;
      if (!error.empty())
      {
        return (vector ? error : "expected " + DescribeSettingRange(setting)) + ", got \"" + text + "\"";
      }
      if (CheckSettingValue(setting, value, "").empty())
      {
        return std::string();
      }
      // A direction or a box says why, naming the text: "\"0,0,0\" is the zero vector: ...".
      if (setting.Type == SettingDeclaration::Direction || setting.Type == SettingDeclaration::Bounds)
      {
        return CheckSettingValue(setting, value, "\"" + text + "\"");
      }
      return "expected " + DescribeSettingRange(setting) + ", got \"" + text + "\"";
    },
    "");
}
} // namespace

std::string DeclaredHelp(const SettingDeclaration& setting, const std::string& byDefault)
{
  std::string help = setting.Help;
  const std::string range = DescribeSettingRange(setting);
  // A choice's names are its type (euler|rk4|dp45), not repeated here.
  if (setting.Type != SettingDeclaration::Boolean && setting.Type != SettingDeclaration::Choice &&
    !range.empty())
  {
    help += "; " + range;
  }
  else if (*setting.Unit)
  {
    help += std::string(" (") + setting.Unit + ")";
  }
  // A value ("default 0.01") or words ("default: the scene's").
  const bool words = byDefault.find(' ') != std::string::npos;
  help += (words ? " (default: " : " (default ") +
    (byDefault.empty() ? std::string("none") : byDefault) + ")";
  return help;
}

DeclaredOptions::DeclaredOptions(CLI::App* command, const SettingTable& table,
  const std::string& leftOut, const nlohmann::json& defaults, const std::string& defaultWords)
  : Table(table)
  , Defaults(DefaultValues(table))
{
  this->Defaults.update(defaults);
  for (const SettingDeclaration& setting : table)
  {
    if (IsLeftOut(setting.Name, leftOut))
    {
      continue;
    }
    std::string& text = this->Texts[setting.Name];
    // Words in place of the value, where "{}" stands for it ("the scene's camera, else {}").
    const std::string value = SettingText(setting, this->Defaults.at(setting.Name));
    std::string byDefault = defaultWords.empty() ? value : defaultWords;
    const std::size_t slot = byDefault.find("{}");
    if (!defaultWords.empty() && slot != std::string::npos)
    {
      byDefault.replace(slot, 2, value);
    }
    CLI::Option* option =
      command->add_option(CommandLineNames(setting), text, DeclaredHelp(setting, byDefault));
    option->check(DeclaredCheck(setting));
    // The type as CLI11 names its own (INT, FLOAT), or the form to type.
    if (setting.Type == SettingDeclaration::Integer)
    {
      option->type_name("INT");
    }
    else if (setting.Type == SettingDeclaration::Number)
    {
      option->type_name("FLOAT");
    }
    else if (setting.Type == SettingDeclaration::Boolean)
    {
      // Alone it means true, as a flag: --transverse-jacobian stays a flag.
      option->expected(0, 1);
      option->type_name("[true|false]");
    }
    else if (setting.Type == SettingDeclaration::Choice)
    {
      option->type_name(setting.Choices);
    }
    else if (setting.Type == SettingDeclaration::Point ||
      setting.Type == SettingDeclaration::Direction)
    {
      option->type_name("X,Y,Z");
    }
    else if (setting.Type == SettingDeclaration::Bounds)
    {
      option->type_name("X0,X1,Y0,Y1,Z0,Z1");
    }
    else if (setting.Type == SettingDeclaration::Dimensions)
    {
      option->type_name("NX,NY,NZ");
    }
    else if (setting.Type == SettingDeclaration::NumberList)
    {
      option->type_name("V1,V2,...");
    }
    this->Options[setting.Name] = option;
  }
}

nlohmann::json DeclaredOptions::Given() const
{
  nlohmann::json given = nlohmann::json::object();
  for (const auto& entry : this->Options)
  {
    if (entry.second->count() > 0)
    {
      given[entry.first] = this->GivenValue(entry.first);
    }
  }
  return given;
}

nlohmann::json DeclaredOptions::GivenValue(const std::string& name) const
{
  const SettingDeclaration* setting = this->Table.Find(name);
  const std::string& text = this->Texts.at(name);
  std::string error; // checked while parsing (DeclaredCheck)
  return setting->Type == SettingDeclaration::Boolean && text.empty()
    ? nlohmann::json(true)
    : ParseSettingText(*setting, text, error);
}

nlohmann::json DeclaredOptions::Value(const std::string& name) const
{
  // This option's text alone (not all of Given(): callers may ask in a loop).
  const auto option = this->Options.find(name);
  if (option != this->Options.end() && option->second->count() > 0)
  {
    return this->GivenValue(name);
  }
  return this->Defaults.at(name);
}

std::string DeclaredOptions::OptionOf(const SettingTable& table, const std::string& name)
{
  const SettingDeclaration* setting = table.Find(name);
  return setting ? CommandLineName(*setting) : name;
}
} // namespace cli
} // namespace riemann
