/**
 * @file JsonValidation.h
 * @brief Checks shared by the JSON readers (metric and scene definitions):
 * each failure throws `Error` (a JsonInputError) with a message that names
 * the JSON path, e.g. `scene.objects[2]: unknown key "radus"; expected one
 * of ...`, and the path and key as data (JsonErrorPlace).
 *
 * Internal (not installed): it exposes nlohmann::json, which the public API
 * of the toolkit does not.
 */
#ifndef RiemannJsonValidation_h
#define RiemannJsonValidation_h

#include "JsonInputError.h"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>

namespace riemann
{
namespace json
{
using Json = nlohmann::json;

/// A user's text quoted in a message: at most 60 characters (a 2 MB key
/// was once quoted whole), the length said when cut.
inline std::string Quoted(const std::string& text)
{
  constexpr std::size_t most = 60;
  if (text.size() <= most)
  {
    return "\"" + text + "\"";
  }
  return "\"" + text.substr(0, most) + "...\" (" + std::to_string(text.size()) + " characters)";
}

/// A parser's exception text without nlohmann's "[json.exception.parse_error.101] ".
inline std::string WithoutExceptionId(const std::string& message)
{
  const std::size_t bracket = message.find("] ");
  return message.compare(0, 16, "[json.exception.") == 0 && bracket != std::string::npos
    ? message.substr(bracket + 2)
    : message;
}

/// "the string \"x\"", "an array of 2", "an object", ... for messages.
inline std::string Describe(const Json& value)
{
  switch (value.type())
  {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return "a boolean";
    case Json::value_t::string:
      return "the string " + Quoted(value.get<std::string>());
    case Json::value_t::array:
      return "an array of " + std::to_string(value.size());
    case Json::value_t::object:
      return "an object";
    default:
      return value.dump();
  }
}

/**
 * `text` parsed. A syntax error or an overflowing number throws `Error` at
 * `path` with nlohmann's words after `prefix` and the offset it stopped at
 * as data (located in the text by the reader's LocatingErrorsIn).
 */
template <class Error>
Json Parse(const std::string& text, const std::string& path, const std::string& prefix)
{
  try
  {
    return Json::parse(text);
  }
  catch (const Json::exception& e)
  {
    JsonErrorPlace place;
    place.Path = path;
    place.SyntaxOffset = JsonSyntaxErrorOffset(text);
    throw Error(place, prefix + WithoutExceptionId(e.what()));
  }
}

/// Throws `Error` about the value at `path`.
template <class Error>
[[noreturn]] void Fail(const std::string& path, const std::string& message)
{
  JsonErrorPlace place;
  place.Path = path;
  throw Error(place, message);
}

/// Throws `Error` about the key `key` of the object at `path`.
template <class Error>
[[noreturn]] void FailAtKey(const std::string& path, const std::string& key, const std::string& message)
{
  JsonErrorPlace place;
  place.Path = path;
  place.AtKey = true;
  place.Key = key;
  throw Error(place, message);
}

/// Refuse non-objects and keys outside `allowed` (plus "name" and
/// "description", free text on every object). `allowed`: any range of
/// C strings (a braced list, or keys taken from a table).
template <class Error, class Keys = std::initializer_list<const char*>>
void CheckKeys(const Json& object, const std::string& path, const Keys& allowed)
{
  if (!object.is_object())
  {
    Fail<Error>(path, "expected an object, got " + Describe(object));
  }
  for (const auto& item : object.items())
  {
    const std::string& key = item.key();
    if (key == "name" || key == "description")
    {
      if (!item.value().is_string())
      {
        Fail<Error>(path + "." + key, "expected a string, got " + Describe(item.value()));
      }
      continue;
    }
    bool known = false;
    for (const char* a : allowed)
    {
      known = known || key == a;
    }
    if (!known)
    {
      std::string expected;
      for (const char* a : allowed)
      {
        expected += std::string(expected.empty() ? "" : ", ") + "\"" + a + "\"";
      }
      FailAtKey<Error>(path, key,
        "unknown key " + Quoted(key) + "; expected one of " + expected + ", \"name\", \"description\"");
    }
  }
}

template <class Error>
const Json& Required(const Json& object, const char* key, const std::string& path)
{
  if (!object.contains(key))
  {
    Fail<Error>(path, std::string("missing required key \"") + key + "\"");
  }
  return object.at(key);
}
} // namespace json
} // namespace riemann

#endif
