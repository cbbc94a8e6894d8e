#include "JsonInputError.h"

#include "JsonTextScan.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string_view>

namespace riemann
{
namespace
{
using jsontext::Node;

bool StartsWith(const std::string& text, std::size_t position, std::string_view prefix)
{
  return text.compare(position, prefix.size(), prefix.data(), prefix.size()) == 0;
}

/**
 * Follows the dotted `path` from `position` down the tree, writing the
 * pointer of what it reaches. Keys are written raw in paths (they may hold
 * '.' or '['), so each key that fits is tried until the rest fits too.
 */
bool MatchPath(const Node& node, const std::string& path, std::size_t position,
  const Node*& reached, std::string& pointer)
{
  if (position == path.size())
  {
    reached = &node;
    return true;
  }
  const std::size_t pointerSize = pointer.size();
  if (path[position] == '.')
  {
    for (auto member = node.Members.rbegin(); member != node.Members.rend(); ++member)
    {
      pointer.resize(pointerSize);
      pointer += "/" + jsontext::EscapePointerToken(member->Key);
      if (!member->Shadowed && StartsWith(path, position + 1, member->Key) &&
        MatchPath(member->Value, path, position + 1 + member->Key.size(), reached, pointer))
      {
        return true;
      }
    }
  }
  const std::size_t close = path.find(']', position);
  if (path[position] == '[' && close != std::string::npos)
  {
    const std::size_t index =
      jsontext::ArrayIndex(std::string_view(path).substr(position + 1, close - position - 1));
    pointer.resize(pointerSize);
    pointer += "/" + std::to_string(index);
    if (index < node.Items.size() && MatchPath(node.Items[index], path, close + 1, reached, pointer))
    {
      return true;
    }
  }
  pointer.resize(pointerSize);
  return false;
}

/// Records where nlohmann's parser stops; builds nothing.
struct SyntaxErrorRecorder : nlohmann::json_sax<nlohmann::json>
{
  long long Offset = -1;

  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }

  bool parse_error(std::size_t position, const std::string& lastToken,
    const nlohmann::detail::exception& error) override
  {
    // A syntax error's position counts the bytes read, the offending one
    // included; an overflowing number is reported after its last byte.
    const long long read = static_cast<long long>(position);
    const bool overflow = error.id == 406;
    this->Offset = overflow ? read - static_cast<long long>(lastToken.size()) : read - 1;
    if (this->Offset < 0)
    {
      this->Offset = 0;
    }
    return false;
  }
};
} // namespace

JsonInputError::JsonInputError(const std::string& message)
  : std::runtime_error(message)
{
}

JsonInputError::JsonInputError(const JsonErrorPlace& place, const std::string& cause)
  : std::runtime_error(place.Path.empty() ? cause : place.Path + ": " + cause)
  , Place(place)
{
}

JsonInputError::JsonInputError(const std::string& prefix, const JsonInputError& error)
  : std::runtime_error(prefix + error.what())
  , Place(error.Place)
{
}

void LocateJsonError(const std::string& text, JsonErrorPlace& place)
{
  place.Pointer.clear();
  place.Text = TextPlace();
  try
  {
    if (place.SyntaxOffset >= 0)
    {
      place.Text = jsontext::PlaceOfOffset(text, static_cast<std::size_t>(place.SyntaxOffset));
      return;
    }
    Node root;
    if (place.Path.empty() || !jsontext::ScanValid(text, root))
    {
      return;
    }
    // The path starts with the document's name ("metric", "scene", or a
    // file's, which may hold '.'): the first end of it that the rest fits.
    const Node* node = nullptr;
    std::string pointer;
    std::size_t rootEnd = 0;
    do
    {
      rootEnd = std::min(place.Path.find_first_of(".[", rootEnd + 1), place.Path.size());
      pointer.clear();
    } while (!MatchPath(root, place.Path, rootEnd, node, pointer) && rootEnd < place.Path.size());
    if (!node)
    {
      return;
    }
    place.Pointer = pointer;
    if (place.AtKey)
    {
      const jsontext::Member* member = jsontext::FindMember(*node, place.Key);
      if (member)
      {
        place.Text = jsontext::PlaceOfOffset(text, member->KeyBegin);
      }
      return;
    }
    if (node == &root)
    {
      return; // about the whole document (validation): no place in the text
    }
    const std::size_t offset = place.ExpressionColumn > 0 && node->Type == Node::Kind::String
      ? jsontext::CharacterInString(text, *node, place.ExpressionColumn)
      : node->Begin;
    place.Text = jsontext::PlaceOfOffset(text, offset);
  }
  catch (const std::exception&)
  {
    // Out of memory on absurd input: no place rather than a crash.
    place.Text = TextPlace();
  }
}

long long JsonSyntaxErrorOffset(const std::string& text)
{
  SyntaxErrorRecorder recorder;
  nlohmann::json::sax_parse(text, &recorder);
  return recorder.Offset;
}
} // namespace riemann
