#include "JsonTextScan.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <climits>
#include <map>
#include <string>
#include <string_view>

namespace riemann
{
std::string DescribeTextPlace(const TextPlace& place)
{
  if (!place.Known)
  {
    return std::string();
  }
  return "line " + std::to_string(place.Line) + ", column " + std::to_string(place.Column);
}

namespace jsontext
{
namespace
{
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


class JsonScanner
{
public:
  explicit JsonScanner(const std::string& text)
    : Text(text)
  {
  }

  /// The whole text as one value; false where it is not JSON.
  bool Scan(Node& root)
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

  bool Value(Node& node, int depth)
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
      node.Type = Node::Kind::Object;
      scanned = this->Object(node, depth);
    }
    else if (c == '[')
    {
      node.Type = Node::Kind::Array;
      scanned = this->Array(node, depth);
    }
    else if (c == '"')
    {
      node.Type = Node::Kind::String;
      scanned = this->String(nullptr);
    }
    else if (c == '-' || IsDigit(c))
    {
      node.Type = Node::Kind::Number;
      scanned = this->Number();
    }
    else
    {
      node.Type = Node::Kind::Literal;
      scanned = this->Literal();
    }
    node.End = this->Position;
    return scanned;
  }

  bool Object(Node& node, int depth)
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
      Member member;
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

  static void MarkShadowedMembers(Node& object)
  {
    std::map<std::string, Member*> last;
    for (Member& member : object.Members)
    {
      Member*& previous = last[member.Key];
      if (previous)
      {
        previous->Shadowed = true;
      }
      previous = &member;
    }
  }

  bool Array(Node& node, int depth)
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
} // namespace

bool Scan(const std::string& text, Node& root)
{
  return JsonScanner(text).Scan(root);
}

bool ScanValid(const std::string& text, Node& root)
{
  return nlohmann::json::accept(text) && JsonScanner(text).Scan(root);
}

const Member* FindMember(const Node& object, const std::string& key)
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

namespace
{
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

const Node* Child(const Node& node, const std::string& token)
{
  if (node.Type == Node::Kind::Object)
  {
    const Member* member = FindMember(node, token);
    return member ? &member->Value : nullptr;
  }
  const std::size_t index = ArrayIndex(token);
  if (node.Type == Node::Kind::Array && index < node.Items.size())
  {
    return &node.Items[index];
  }
  return nullptr;
}

} // namespace

const Node* FindByPointer(const Node& root, const std::string& pointer)
{
  const Node* node = &root;
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

TextPlace PlaceOfOffset(const std::string& text, std::size_t offset)
{
  TextPlace location;
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

std::size_t CharacterInString(const std::string& text, const Node& string, int column)
{
  const std::size_t closingQuote = string.End - 1;
  std::size_t position = string.Begin + 1;
  for (int c = 1; c < column && position < closingQuote; ++c)
  {
    position = NextStringCharacter(text, position, nullptr);
  }
  return position;
}
} // namespace jsontext
} // namespace riemann
