#include "MetricText.h"

#include "JsonTextScan.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <stdexcept>
#include <string_view>

namespace riemann
{
namespace studio
{
namespace
{
using jsontext::FindByPointer;
using jsontext::Invalid;
using JsonNode = jsontext::Node;
using JsonMember = jsontext::Member;

bool IsDigit(char c)
{
  return c >= '0' && c <= '9';
}

// --- parameters --------------------------------------------------------------

double NumberValue(const std::string& text, const JsonNode& number)
{
  return nlohmann::json::parse(text.begin() + static_cast<std::ptrdiff_t>(number.Begin),
    text.begin() + static_cast<std::ptrdiff_t>(number.End))
    .get<double>();
}

/// A number, or {"from": number, "to": number} (exactly these keys).
bool ReadParameter(const std::string& text, const JsonNode& value, MetricParameter& parameter)
{
  if (value.Type == JsonNode::Kind::Number)
  {
    parameter.Value = parameter.From = parameter.To = NumberValue(text, value);
    return true;
  }
  const JsonMember* from = jsontext::FindMember(value, "from");
  const JsonMember* to = jsontext::FindMember(value, "to");
  std::size_t keys = 0;
  for (const JsonMember& member : value.Members)
  {
    keys += member.Shadowed ? 0 : 1;
  }
  if (value.Type != JsonNode::Kind::Object || keys != 2 || !from || !to ||
    from->Value.Type != JsonNode::Kind::Number || to->Value.Type != JsonNode::Kind::Number)
  {
    return false;
  }
  parameter.Animated = true;
  parameter.Value = parameter.From = NumberValue(text, from->Value);
  parameter.To = NumberValue(text, to->Value);
  return true;
}

/// The parameters of `object` (at `pointer`) and of its "compose" maps, in document order.
void CollectParameters(const std::string& text, const JsonNode& object, const std::string& pointer,
  std::vector<MetricParameter>& parameters)
{
  for (const JsonMember& member : object.Members)
  {
    if (member.Shadowed)
    {
      continue;
    }
    if (member.Key == "parameters")
    {
      for (const JsonMember& named : member.Value.Members)
      {
        MetricParameter parameter;
        if (!named.Shadowed && ReadParameter(text, named.Value, parameter))
        {
          parameter.Name = named.Key;
          parameter.Pointer = pointer + "/parameters/" + jsontext::EscapePointerToken(named.Key);
          parameters.push_back(std::move(parameter));
        }
      }
    }
    else if (member.Key == "compose")
    {
      for (std::size_t i = 0; i < member.Value.Items.size(); ++i)
      {
        CollectParameters(
          text, member.Value.Items[i], pointer + "/compose/" + std::to_string(i), parameters);
      }
    }
  }
}

/// nlohmann writes the shortest text that reads back as the same double, whatever the C locale.
std::string FormatNumber(double value)
{
  return nlohmann::json(value).dump();
}

// --- highlighting ------------------------------------------------------------

/// One past a string's closing quote, or its line's end if it has none.
std::size_t StringEnd(const std::string& text, std::size_t openingQuote)
{
  std::size_t position = openingQuote + 1;
  while (position < text.size() && text[position] != '\n')
  {
    if (text[position] == '"')
    {
      return position + 1;
    }
    const bool escape =
      text[position] == '\\' && position + 1 < text.size() && text[position + 1] != '\n';
    position += escape ? 2 : 1;
  }
  return position;
}

bool IsFollowedByColon(const std::string& text, std::size_t position)
{
  position = text.find_first_not_of(" \t\r\n", position);
  return position != Invalid && text[position] == ':';
}

bool IsWordCharacter(char c)
{
  return IsDigit(c) || c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

std::size_t RunEnd(const std::string& text, std::size_t position, bool (*belongs)(char))
{
  while (position < text.size() && belongs(text[position]))
  {
    ++position;
  }
  return position;
}

bool IsNumberCharacter(char c)
{
  return IsDigit(c) || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}
} // namespace

std::vector<MetricParameter> FindMetricParameters(const std::string& text)
{
  std::vector<MetricParameter> parameters;
  try
  {
    JsonNode root;
    if (jsontext::ScanValid(text, root))
    {
      CollectParameters(text, root, "", parameters);
    }
  }
  catch (const std::exception&)
  {
    parameters.clear();
  }
  return parameters;
}

std::string ApplyParameterValues(
  const std::string& text, const std::map<std::string, double>& valuesByPointer)
{
  JsonNode root;
  if (!jsontext::ScanValid(text, root))
  {
    throw std::invalid_argument("the metric definition is not valid JSON");
  }
  // The new spelling of each number to change, by its first byte.
  std::map<std::size_t, std::pair<const JsonNode*, std::string>> replacements;
  for (const auto& [pointer, value] : valuesByPointer)
  {
    const JsonNode* number = FindByPointer(root, pointer);
    if (!number || number->Type != JsonNode::Kind::Number)
    {
      throw std::invalid_argument("\"" + pointer + "\" does not name a plain number");
    }
    if (!std::isfinite(value))
    {
      throw std::invalid_argument("the value for \"" + pointer + "\" is not a finite number");
    }
    if (NumberValue(text, *number) != value)
    {
      replacements[number->Begin] = { number, FormatNumber(value) };
    }
  }
  std::string result;
  std::size_t copied = 0;
  for (const auto& [begin, replacement] : replacements)
  {
    result.append(text, copied, begin - copied);
    result += replacement.second;
    copied = replacement.first->End;
  }
  result.append(text, copied, std::string::npos);
  return result;
}

std::vector<TextSpan> HighlightJson(const std::string& text)
{
  std::vector<TextSpan> spans;
  if (text.size() > static_cast<std::size_t>(INT_MAX))
  {
    return spans;
  }
  std::size_t position = 0;
  while (position < text.size())
  {
    const char c = text[position];
    std::size_t end = position + 1;
    TextSpan::Kind type = TextSpan::Punctuation;
    if (c == '"')
    {
      end = StringEnd(text, position);
      type = IsFollowedByColon(text, end) ? TextSpan::Key : TextSpan::String;
    }
    else if (c == '-' || IsDigit(c))
    {
      end = RunEnd(text, position, IsNumberCharacter);
      type = TextSpan::Number;
    }
    else if (IsWordCharacter(c))
    {
      end = RunEnd(text, position, IsWordCharacter);
      const std::string_view word = std::string_view(text).substr(position, end - position);
      if (word != "true" && word != "false" && word != "null")
      {
        position = end; // not JSON: left uncoloured
        continue;
      }
      type = TextSpan::Keyword;
    }
    else if (std::string_view("{}[]:,").find(c) == std::string_view::npos)
    {
      position = end; // whitespace or a stray character
      continue;
    }
    spans.push_back({ static_cast<int>(position), static_cast<int>(end - position), type });
    position = end;
  }
  return spans;
}
} // namespace studio
} // namespace riemann
