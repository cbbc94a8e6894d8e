#include "PictureSchema.h"

#include <cmath>
#include <sstream>

namespace riemann
{
std::vector<std::string> PictureChoices(const PictureSetting& setting)
{
  std::vector<std::string> names;
  std::istringstream list(setting.Choices);
  for (std::string name; std::getline(list, name, '|');)
  {
    names.push_back(name);
  }
  return names;
}

int PictureChoiceIndex(const PictureSetting& setting, const std::string& name)
{
  const std::vector<std::string> names = PictureChoices(setting);
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    if (names[i] == name)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

std::string PictureDefaultChoice(const PictureSetting& setting)
{
  const std::vector<std::string> names = PictureChoices(setting);
  const auto index = static_cast<std::size_t>(setting.Default[0]);
  return index < names.size() ? names[index] : std::string();
}

std::string DescribePictureValues(const PictureSetting& setting)
{
  switch (setting.Type)
  {
    case PictureSetting::Point:
      return "three finite comma-separated numbers X,Y,Z";
    case PictureSetting::Direction:
      return "three finite comma-separated numbers X,Y,Z, not all 0";
    case PictureSetting::Choice:
    {
      const std::vector<std::string> names = PictureChoices(setting);
      std::string words;
      for (std::size_t i = 0; i < names.size(); ++i)
      {
        words += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
      }
      return words;
    }
    default:
      return DescribeSettingRange(setting.Range);
  }
}

std::string PictureInterval(const PictureSetting& setting)
{
  switch (setting.Type)
  {
    case PictureSetting::Point:
    case PictureSetting::Direction:
      return "X,Y,Z";
    case PictureSetting::Choice:
      return setting.Choices;
    default:
      return SettingInterval(setting.Range);
  }
}

std::string CheckPictureValue(const PictureSetting& setting, double value, const std::string& name)
{
  return CheckSettingValue(setting.Range, value, name);
}

std::string CheckPictureVector(
  const PictureSetting& setting, const double value[3], const std::string& name)
{
  const bool finite =
    std::isfinite(value[0]) && std::isfinite(value[1]) && std::isfinite(value[2]);
  const bool zero = value[0] == 0 && value[1] == 0 && value[2] == 0;
  if (finite && !(setting.Type == PictureSetting::Direction && zero))
  {
    return std::string();
  }
  std::ostringstream s;
  s << name << " is " << value[0] << "," << value[1] << "," << value[2] << ": expected "
    << DescribePictureValues(setting);
  return s.str();
}
} // namespace riemann
