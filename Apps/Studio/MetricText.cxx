#include "MetricText.h"

#include <nlohmann/json.hpp>

#include <climits>
#include <cmath>
#include <stdexcept>
#include <string_view>

namespace riemann
{
namespace studio
{
namespace
{
constexpr std::size_t Invalid = std::string::npos;

bool IsDigit(char c)
{
  return c >= '0' && c <= '9';
}

bool IsContinuationByte(char c)
{
  return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

// --- characters of a JSON string ---------------------------------------------

/// The 4 hex digits at `pos`, if there are 4.
bool HexValue(const std::string& text, std::size_t pos, unsigned& value)
{
  if (pos + 4 > text.size())
  {
    return false;
  }
  value = 0;
  for (std::size_t i = pos; i < pos + 4; ++i)
  {
    const char c = text[i];
    const int digit = IsDigit(c) ? c - '0'
      : (c >= 'a' && c <= 'f')   ? c - 'a' + 10
      : (c >= 'A' && c <= 'F')   ? c - 'A' + 10
                                 : -1;
    if (digit < 0)
    {
      return false;
    }
    value = 16 * value + static_cast<unsigned>(digit);
  }
  return true;
}

void AppendUtf8(unsigned codePoint, std::string& out)
{
  if (codePoint < 0x80)
  {
    out += static_cast<char>(codePoint);
    return;
  }
  const int continuations = codePoint < 0x800 ? 1 : codePoint < 0x10000 ? 2 : 3;
  const unsigned leads[] = { 0, 0xC0, 0xE0, 0xF0 };
  out += static_cast<char>(leads[continuations] | (codePoint >> (6 * continuations)));
  for (int k = continuations - 1; k >= 0; --k)
  {
    out += static_cast<char>(0x80 | ((codePoint >> (6 * k)) & 0x3F));
  }
}

/**
 * One character of a JSON string's content starting at byte `pos` (not its
 * closing quote): a UTF-8 sequence or an escape (\n, \", \u00e9, or a
 * surrogate pair \ud83d\ude00, which is one character). Appends it decoded
 * to `decoded` when given. Returns the offset after it, or Invalid where the
 * text is not a valid string there. The metric parser counts expression
 * columns in characters of the decoded string, so an escape is one column.
 */
std::size_t NextStringCharacter(const std::string& text, std::size_t pos, std::string* decoded)
{
  if (static_cast<unsigned char>(text[pos]) < 0x20)
  {
    return Invalid; // control characters must be escaped
  }
  if (text[pos] != '\\')
  {
    std::size_t next = pos + 1;
    while (next < text.size() && IsContinuationByte(text[next]))
    {
      ++next;
    }
    if (decoded)
    {
      decoded->append(text, pos, next - pos);
    }
    return next;
  }
  if (pos + 1 >= text.size())
  {
    return Invalid;
  }
  const std::string_view escapes = "\"\\/bfnrt";
  const std::string_view meanings = "\"\\/\b\f\n\r\t";
  const std::size_t simple = escapes.find(text[pos + 1]);
  if (simple != std::string_view::npos)
  {
    if (decoded)
    {
      *decoded += meanings[simple];
    }
    return pos + 2;
  }
  unsigned unit = 0;
  if (text[pos + 1] != 'u' || !HexValue(text, pos + 2, unit) || (unit >= 0xDC00 && unit <= 0xDFFF))
  {
    return Invalid; // an unknown escape, or a low surrogate alone
  }
  std::size_t next = pos + 6;
  if (unit >= 0xD800 && unit <= 0xDBFF)
  {
    unsigned low = 0;
    if (text.compare(next, 2, "\\u") != 0 || !HexValue(text, next + 2, low) || low < 0xDC00 ||
      low > 0xDFFF)
    {
      return Invalid; // a high surrogate must be followed by a low one
    }
    unit = 0x10000 + ((unit - 0xD800) << 10) + (low - 0xDC00);
    next += 6;
  }
  if (decoded)
  {
    AppendUtf8(unit, *decoded);
  }
  return next;
}

// --- where the values of a JSON text are -------------------------------------

struct JsonMember;

/// A JSON value with the byte range of its text (nlohmann keeps no positions).
struct JsonNode
{
  enum class Kind
  {
    Object,
    Array,
    String,
    Number,
    Literal
  };
  Kind Type = Kind::Literal;
  std::size_t Begin = 0;           ///< its first byte: '{', '[', '"', '-', a digit or a letter
  std::size_t End = 0;             ///< one past its last byte
  std::vector<JsonMember> Members; ///< of an object, in document order
  std::vector<JsonNode> Items;     ///< of an array
};

struct JsonMember
{
  std::string Key;          ///< decoded
  std::size_t KeyBegin = 0; ///< the key's opening quote
  JsonNode Value;
  /// A later member has the same key; parsers (nlohmann included) keep the last.
  bool Shadowed = false;
};

/**
 * A strict recursive scanner of JSON text into JsonNodes. Nesting is limited
 * (MaximumDepth) so that hostile text cannot exhaust the stack; such text is
 * reported as not scanned. It does not check UTF-8; callers that need exactly
 * nlohmann's verdict ask nlohmann::json::accept first.
 */
class JsonScanner
{
public:
  explicit JsonScanner(const std::string& text)
    : Text(text)
  {
  }

  /// The whole text as one value; false where it is not JSON.
  bool Scan(JsonNode& root)
  {
    this->Position = 0;
    this->SkipWhitespace();
    if (!this->Value(root, 0))
    {
      return false;
    }
    this->SkipWhitespace();
    return this->Position == this->Text.size();
  }

private:
  static constexpr int MaximumDepth = 512;
  const std::string& Text;
  std::size_t Position = 0;

  bool Accept(char c)
  {
    if (this->Position < this->Text.size() && this->Text[this->Position] == c)
    {
      ++this->Position;
      return true;
    }
    return false;
  }

  void SkipWhitespace()
  {
    while (this->Accept(' ') || this->Accept('\t') || this->Accept('\n') || this->Accept('\r'))
    {
    }
  }

  bool Value(JsonNode& node, int depth)
  {
    if (this->Position >= this->Text.size() || depth > MaximumDepth)
    {
      return false;
    }
    node.Begin = this->Position;
    const char c = this->Text[this->Position];
    bool scanned = false;
    if (c == '{')
    {
      node.Type = JsonNode::Kind::Object;
      scanned = this->Object(node, depth);
    }
    else if (c == '[')
    {
      node.Type = JsonNode::Kind::Array;
      scanned = this->Array(node, depth);
    }
    else if (c == '"')
    {
      node.Type = JsonNode::Kind::String;
      scanned = this->String(nullptr);
    }
    else if (c == '-' || IsDigit(c))
    {
      node.Type = JsonNode::Kind::Number;
      scanned = this->Number();
    }
    else
    {
      node.Type = JsonNode::Kind::Literal;
      scanned = this->Literal();
    }
    node.End = this->Position;
    return scanned;
  }

  bool Object(JsonNode& node, int depth)
  {
    ++this->Position;
    this->SkipWhitespace();
    if (this->Accept('}'))
    {
      return true;
    }
    do
    {
      this->SkipWhitespace();
      JsonMember member;
      member.KeyBegin = this->Position;
      if (!this->String(&member.Key))
      {
        return false;
      }
      this->SkipWhitespace();
      if (!this->Accept(':'))
      {
        return false;
      }
      this->SkipWhitespace();
      if (!this->Value(member.Value, depth + 1))
      {
        return false;
      }
      node.Members.push_back(std::move(member));
      this->SkipWhitespace();
    } while (this->Accept(','));
    MarkShadowedMembers(node);
    return this->Accept('}');
  }

  static void MarkShadowedMembers(JsonNode& object)
  {
    std::map<std::string, JsonMember*> last;
    for (JsonMember& member : object.Members)
    {
      JsonMember*& previous = last[member.Key];
      if (previous)
      {
        previous->Shadowed = true;
      }
      previous = &member;
    }
  }

  bool Array(JsonNode& node, int depth)
  {
    ++this->Position;
    this->SkipWhitespace();
    if (this->Accept(']'))
    {
      return true;
    }
    do
    {
      this->SkipWhitespace();
      node.Items.emplace_back();
      if (!this->Value(node.Items.back(), depth + 1))
      {
        return false;
      }
      this->SkipWhitespace();
    } while (this->Accept(','));
    return this->Accept(']');
  }

  /// A string token, its content decoded into `decoded` when given.
  bool String(std::string* decoded)
  {
    if (!this->Accept('"'))
    {
      return false;
    }
    while (this->Position < this->Text.size() && this->Text[this->Position] != '"')
    {
      this->Position = NextStringCharacter(this->Text, this->Position, decoded);
      if (this->Position == Invalid)
      {
        return false;
      }
    }
    return this->Accept('"');
  }

  bool Digits()
  {
    const std::size_t start = this->Position;
    while (this->Position < this->Text.size() && IsDigit(this->Text[this->Position]))
    {
      ++this->Position;
    }
    return this->Position > start;
  }

  /// -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
  bool Number()
  {
    this->Accept('-');
    if (!this->Accept('0') && !this->Digits())
    {
      return false;
    }
    if (this->Accept('.') && !this->Digits())
    {
      return false;
    }
    if (this->Accept('e') || this->Accept('E'))
    {
      if (!this->Accept('+'))
      {
        this->Accept('-');
      }
      return this->Digits();
    }
    return true;
  }

  bool Literal()
  {
    for (const char* word : { "true", "false", "null" })
    {
      const std::size_t length = std::char_traits<char>::length(word);
      if (this->Text.compare(this->Position, length, word) == 0)
      {
        this->Position += length;
        return true;
      }
    }
    return false;
  }
};

/// `text` scanned, if nlohmann (hence the metric parser) reads it as JSON.
bool ScanValidJson(const std::string& text, JsonNode& root)
{
  return nlohmann::json::accept(text) && JsonScanner(text).Scan(root);
}

/// The member named `key` that counts (the last one), or null.
const JsonMember* FindMember(const JsonNode& object, const std::string& key)
{
  for (auto member = object.Members.rbegin(); member != object.Members.rend(); ++member)
  {
    if (member->Key == key)
    {
      return &*member;
    }
  }
  return nullptr;
}

/// A JSON array index: digits without a leading zero; Invalid otherwise.
std::size_t ArrayIndex(std::string_view token)
{
  if (token.empty() || token.size() > 9 || (token[0] == '0' && token.size() > 1))
  {
    return Invalid;
  }
  std::size_t index = 0;
  for (const char c : token)
  {
    if (!IsDigit(c))
    {
      return Invalid;
    }
    index = 10 * index + static_cast<std::size_t>(c - '0');
  }
  return index;
}

// --- JSON pointers (RFC 6901) ------------------------------------------------

std::string EscapePointerToken(const std::string& key)
{
  std::string escaped;
  for (const char c : key)
  {
    escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  }
  return escaped;
}

bool UnescapePointerToken(std::string_view token, std::string& key)
{
  key.clear();
  for (std::size_t i = 0; i < token.size(); ++i)
  {
    if (token[i] != '~')
    {
      key += token[i];
    }
    else if (i + 1 < token.size() && (token[i + 1] == '0' || token[i + 1] == '1'))
    {
      key += token[++i] == '0' ? '~' : '/';
    }
    else
    {
      return false;
    }
  }
  return true;
}

const JsonNode* Child(const JsonNode& node, const std::string& token)
{
  if (node.Type == JsonNode::Kind::Object)
  {
    const JsonMember* member = FindMember(node, token);
    return member ? &member->Value : nullptr;
  }
  const std::size_t index = ArrayIndex(token);
  if (node.Type == JsonNode::Kind::Array && index < node.Items.size())
  {
    return &node.Items[index];
  }
  return nullptr;
}

const JsonNode* FindByPointer(const JsonNode& root, const std::string& pointer)
{
  const JsonNode* node = &root;
  std::size_t position = 0;
  std::string key;
  while (node && position < pointer.size())
  {
    if (pointer[position] != '/')
    {
      return nullptr;
    }
    const std::size_t end = std::min(pointer.find('/', position + 1), pointer.size());
    if (!UnescapePointerToken(
          std::string_view(pointer).substr(position + 1, end - position - 1), key))
    {
      return nullptr;
    }
    node = Child(*node, key);
    position = end;
  }
  return node;
}

// --- byte offsets, lines and columns -----------------------------------------

/// The location of byte `offset` (the end of the text included).
TextLocation At(const std::string& text, std::size_t offset)
{
  TextLocation location;
  if (offset > text.size() || offset > static_cast<std::size_t>(INT_MAX))
  {
    return location;
  }
  location.Known = true;
  location.Offset = static_cast<int>(offset);
  location.Line = 1;
  location.Column = 1;
  for (std::size_t i = 0; i < offset; ++i)
  {
    if (text[i] == '\n')
    {
      ++location.Line;
      location.Column = 1;
    }
    else if (!IsContinuationByte(text[i]))
    {
      ++location.Column;
    }
  }
  return location;
}

/**
 * The byte offset of nlohmann's "line L, column C", whose column counts the
 * bytes read on the line, the offending one included. Having just read a
 * newline it reports column 0 of the next line: that newline. Invalid where
 * the text has no such place (it changed since the message).
 */
std::size_t OffsetOfParserPosition(const std::string& text, int line, int column)
{
  if (line < 1 || column < 0)
  {
    return Invalid;
  }
  std::size_t lineStart = 0;
  for (int l = 1; l < line; ++l)
  {
    const std::size_t newline = text.find('\n', lineStart);
    if (newline == Invalid)
    {
      return Invalid;
    }
    lineStart = newline + 1;
  }
  if (column == 0)
  {
    return lineStart == 0 ? 0 : lineStart - 1;
  }
  const std::size_t lineEnd = std::min(text.find('\n', lineStart), text.size());
  const std::size_t offset = lineStart + static_cast<std::size_t>(column) - 1;
  return offset <= lineEnd ? offset : Invalid;
}

/// The offset of character `column` (1-based) of a string token's content;
/// past the content, its closing quote.
std::size_t CharacterInString(const std::string& text, const JsonNode& string, int column)
{
  const std::size_t closingQuote = string.End - 1;
  std::size_t position = string.Begin + 1;
  for (int c = 1; c < column && position < closingQuote; ++c)
  {
    position = NextStringCharacter(text, position, nullptr);
  }
  return position;
}

// --- reading the parser's messages -------------------------------------------

bool StartsWith(const std::string& text, std::size_t position, std::string_view prefix)
{
  return text.compare(position, prefix.size(), prefix.data(), prefix.size()) == 0;
}

/// A non-negative decimal at `position` (advanced past it).
bool ReadInteger(const std::string& text, std::size_t& position, int& value)
{
  const std::size_t start = position;
  value = 0;
  while (position < text.size() && IsDigit(text[position]) && position - start < 9)
  {
    value = 10 * value + (text[position++] - '0');
  }
  return position > start && !(position < text.size() && IsDigit(text[position]));
}

/// "...at line L, column C..." in nlohmann's parse errors.
bool ReadParserPosition(const std::string& cause, int& line, int& column)
{
  const std::size_t at = cause.find("at line ");
  if (at == Invalid)
  {
    return false;
  }
  std::size_t position = at + 8;
  if (!ReadInteger(cause, position, line) || !StartsWith(cause, position, ", column "))
  {
    return false;
  }
  position += 9;
  return ReadInteger(cause, position, column);
}

/// "column N: ..." that expression errors start with.
bool ReadExpressionColumn(const std::string& cause, int& column)
{
  std::size_t position = 7;
  return StartsWith(cause, 0, "column ") && ReadInteger(cause, position, column) && column > 0 &&
    StartsWith(cause, position, ": ");
}

/// The key of "unknown key \"k\"; expected one of ..." (JsonValidation.h).
bool ReadUnknownKey(const std::string& cause, std::string& key)
{
  const std::string_view opening = "unknown key \"";
  const std::size_t closing = cause.find("\"; expected one of ");
  if (!StartsWith(cause, 0, opening) || closing == Invalid || closing < opening.size())
  {
    return false;
  }
  key = cause.substr(opening.size(), closing - opening.size());
  return true;
}

const JsonNode* FirstNumberSpelled(
  const std::string& text, const JsonNode& node, const std::string& spelling)
{
  if (node.Type == JsonNode::Kind::Number)
  {
    return text.compare(node.Begin, node.End - node.Begin, spelling) == 0 ? &node : nullptr;
  }
  for (const JsonNode& item : node.Items)
  {
    if (const JsonNode* found = FirstNumberSpelled(text, item, spelling))
    {
      return found;
    }
  }
  for (const JsonMember& member : node.Members)
  {
    if (const JsonNode* found = FirstNumberSpelled(text, member.Value, spelling))
    {
      return found;
    }
  }
  return nullptr;
}

/// `cause` follows "invalid JSON: ".
TextLocation LocateSyntaxError(const std::string& text, const std::string& cause)
{
  int line = 0;
  int column = 0;
  if (ReadParserPosition(cause, line, column))
  {
    return At(text, OffsetOfParserPosition(text, line, column));
  }
  // nlohmann gives no position for "number overflow parsing '1e999'"; the
  // first number spelled so is the one it stopped at.
  const std::string_view overflow = "number overflow parsing '";
  const std::size_t quote = cause.find('\'', overflow.size());
  JsonNode root;
  if (StartsWith(cause, 0, overflow) && quote != Invalid && JsonScanner(text).Scan(root))
  {
    const std::string spelling = cause.substr(overflow.size(), quote - overflow.size());
    if (const JsonNode* number = FirstNumberSpelled(text, root, spelling))
    {
      return At(text, number->Begin);
    }
  }
  return TextLocation();
}

/// Where a path of a message ("metric.a[1].b: ...") ends.
struct PathMatch
{
  const JsonNode* Node = nullptr;
  std::size_t CauseBegin = 0; ///< after the ": " that ends the path
};

/**
 * Follows `message` from `position` down the tree. Keys are written raw in
 * messages (they may hold '.' or '['), so each key that fits is tried until
 * the rest of the path fits too and reaches ": ".
 */
bool MatchPath(
  const JsonNode& node, const std::string& message, std::size_t position, PathMatch& match)
{
  if (position >= message.size())
  {
    return false;
  }
  if (StartsWith(message, position, ": "))
  {
    match = { &node, position + 2 };
    return true;
  }
  if (message[position] == '.')
  {
    for (auto member = node.Members.rbegin(); member != node.Members.rend(); ++member)
    {
      if (!member->Shadowed && StartsWith(message, position + 1, member->Key) &&
        MatchPath(member->Value, message, position + 1 + member->Key.size(), match))
      {
        return true;
      }
    }
  }
  const std::size_t close = message.find(']', position);
  if (message[position] == '[' && close != Invalid)
  {
    const std::size_t index =
      ArrayIndex(std::string_view(message).substr(position + 1, close - position - 1));
    return index < node.Items.size() && MatchPath(node.Items[index], message, close + 1, match);
  }
  return false;
}

/// `message` starts with "metric".
TextLocation LocateInDefinition(const std::string& text, const std::string& message)
{
  JsonNode root;
  PathMatch match;
  if (!ScanValidJson(text, root) || !MatchPath(root, message, 6, match))
  {
    return TextLocation();
  }
  const std::string cause = message.substr(match.CauseBegin);
  std::string key;
  if (ReadUnknownKey(cause, key))
  {
    const JsonMember* member = FindMember(*match.Node, key);
    return member ? At(text, member->KeyBegin) : TextLocation();
  }
  if (match.Node == &root)
  {
    return TextLocation(); // about the whole metric (validation): no place in the text
  }
  int column = 0;
  if (ReadExpressionColumn(cause, column) && match.Node->Type == JsonNode::Kind::String)
  {
    return At(text, CharacterInString(text, *match.Node, column));
  }
  return At(text, match.Node->Begin);
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
  const JsonMember* from = FindMember(value, "from");
  const JsonMember* to = FindMember(value, "to");
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
          parameter.Pointer = pointer + "/parameters/" + EscapePointerToken(named.Key);
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

TextLocation LocateMetricError(const std::string& text, const std::string& message)
{
  try
  {
    // The parser's own message starts the text or follows the ": " of a
    // prefix ("twist.json: ", "at t = 0.700000: "); a file may itself be
    // called metric.json, so each candidate is tried.
    for (std::size_t start = 0; start < message.size();)
    {
      TextLocation location;
      if (StartsWith(message, start, "invalid JSON: "))
      {
        location = LocateSyntaxError(text, message.substr(start + 14));
      }
      else if (StartsWith(message, start, "metric") && start + 6 < message.size() &&
        std::string_view(".[:").find(message[start + 6]) != std::string_view::npos)
      {
        location = LocateInDefinition(text, message.substr(start));
      }
      if (location.Known)
      {
        return location;
      }
      const std::size_t separator = message.find(": ", start);
      start = separator == Invalid ? Invalid : separator + 2;
    }
  }
  catch (const std::exception&)
  {
    // Out of memory on absurd input: no location rather than a crash.
  }
  return TextLocation();
}

std::string FormatLocation(const TextLocation& location)
{
  if (!location.Known)
  {
    return std::string();
  }
  return "line " + std::to_string(location.Line) + ", column " + std::to_string(location.Column);
}

std::vector<MetricParameter> FindMetricParameters(const std::string& text)
{
  std::vector<MetricParameter> parameters;
  try
  {
    JsonNode root;
    if (ScanValidJson(text, root))
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
  if (!ScanValidJson(text, root))
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
