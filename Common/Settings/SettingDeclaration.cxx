#include "SettingDeclaration.h"

#include "SettingRange.h"

#include <cctype>
#include <cstring>

namespace riemann
{
const SettingDeclaration* SettingTable::Find(const std::string& name) const
{
  for (const SettingDeclaration& setting : *this)
  {
    if (name == setting.Name)
    {
      return &setting;
    }
  }
  return nullptr;
}

std::string CommandLineName(const SettingDeclaration& setting)
{
  // A capital starts a word, except inside a run of capitals ("FA" in
  // "MinimumFA" is one word: --minimum-fa), whose last capital starts the
  // next word when a small letter follows ("GPUPath": --gpu-path).
  std::string name = "--";
  const char* text = setting.Name;
  const auto upper = [text](std::size_t i) { return std::isupper(static_cast<unsigned char>(text[i])) != 0; };
  const auto lower = [text](std::size_t i) { return std::islower(static_cast<unsigned char>(text[i])) != 0; };
  for (std::size_t i = 0; text[i]; ++i)
  {
    const bool startsWord = upper(i) && i > 0 && (!upper(i - 1) || (text[i + 1] && lower(i + 1)));
    if (startsWord)
    {
      name += '-';
    }
    name += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
  }
  return name;
}

std::string CommandLineNames(const SettingDeclaration& setting)
{
  std::string names = CommandLineName(setting);
  if (*setting.CommandLineAliases)
  {
    names += std::string(",") + setting.CommandLineAliases;
  }
  return names;
}

std::string DescribeSettingRange(const SettingDeclaration& setting)
{
  const SettingRange range{ setting.Minimum, setting.MinimumExclusive, setting.Maximum,
    setting.Type == SettingDeclaration::Integer || setting.Type == SettingDeclaration::Dimensions,
    setting.Unit, setting.MaximumExclusive };
  switch (setting.Type)
  {
    case SettingDeclaration::Boolean:
      return "true or false";
    case SettingDeclaration::Choice:
    {
      std::string names = setting.Choices;
      for (std::size_t bar = names.find('|'); bar != std::string::npos; bar = names.find('|'))
      {
        names.replace(bar, 1, ", ");
      }
      return "one of " + names;
    }
    case SettingDeclaration::Point:
      return "three numbers" + std::string(*setting.Unit ? " (" + std::string(setting.Unit) + ")" : "");
    case SettingDeclaration::Direction:
      return "three numbers, not all zero";
    case SettingDeclaration::NumberList:
      return "numbers, each " + DescribeSettingRange(range).substr(std::strlen("a number "));
    case SettingDeclaration::Bounds:
      return "six numbers x0,x1,y0,y1,z0,z1 with x0 < x1, y0 < y1, z0 < z1" +
        std::string(*setting.Unit ? " (" + std::string(setting.Unit) + ")" : "");
    case SettingDeclaration::Dimensions:
      return "three whole numbers, each " +
        DescribeSettingRange(range).substr(std::strlen("a whole number "));
    case SettingDeclaration::Integer:
    case SettingDeclaration::Number:
      break;
  }
  return DescribeSettingRange(range);
}
} // namespace riemann
