/**
 * @file JsonTextScan.h
 * @brief Where the values of a JSON text are: a strict scanner that keeps
 * the byte range of every value and key (nlohmann::json keeps no
 * positions), JSON pointers over the scanned tree, and byte offsets as
 * lines and columns. Used to locate errors (JsonInputError.h) and by
 * riemann-studio's metric editor to rewrite numbers in place.
 *
 * Nesting is limited (512 levels) so that hostile text cannot exhaust the
 * stack; such text is reported as not scanned.
 */
#ifndef RiemannJsonTextScan_h
#define RiemannJsonTextScan_h

#include "RiemannCommonMetricFormatExport.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace riemann
{
/// A place in a text. Line and Column are 1-based; Column counts characters
/// (UTF-8 code points) from the start of the line, as an editor shows them.
struct TextPlace
{
  bool Known = false;
  int Line = 0;
  int Column = 0;
  int Offset = -1; ///< byte offset into the text (may equal its size: the end)
};

/// "line 3, column 7", or "" when the place is not known.
RIEMANNCOMMONMETRICFORMAT_EXPORT std::string DescribeTextPlace(const TextPlace& place);

namespace jsontext
{
constexpr std::size_t Invalid = std::string::npos;

struct Member;

/// A JSON value with the byte range of its text.
struct Node
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
  std::size_t Begin = 0;       ///< its first byte: '{', '[', '"', '-', a digit or a letter
  std::size_t End = 0;         ///< one past its last byte
  std::vector<Member> Members; ///< of an object, in document order
  std::vector<Node> Items;     ///< of an array
};

struct Member
{
  std::string Key;          ///< decoded
  std::size_t KeyBegin = 0; ///< the key's opening quote
  Node Value;
  /// A later member has the same key; parsers (nlohmann included) keep the last.
  bool Shadowed = false;
};

/// The whole of `text` as one value; false where it is not JSON (UTF-8 is not checked).
RIEMANNCOMMONMETRICFORMAT_EXPORT bool Scan(const std::string& text, Node& root);

/// `text` scanned, if nlohmann (hence every reader of the toolkit) reads it as JSON.
RIEMANNCOMMONMETRICFORMAT_EXPORT bool ScanValid(const std::string& text, Node& root);

/// The member named `key` that counts (the last one), or null.
RIEMANNCOMMONMETRICFORMAT_EXPORT const Member* FindMember(const Node& object, const std::string& key);

/// A JSON array index: digits without a leading zero; Invalid otherwise.
RIEMANNCOMMONMETRICFORMAT_EXPORT std::size_t ArrayIndex(std::string_view token);

/// `key` as a token of a JSON pointer ("~" and "/" escaped).
RIEMANNCOMMONMETRICFORMAT_EXPORT std::string EscapePointerToken(const std::string& key);

/// The value at an RFC 6901 pointer ("" is the root), or null.
RIEMANNCOMMONMETRICFORMAT_EXPORT const Node* FindByPointer(
  const Node& root, const std::string& pointer);

/// The line and column of byte `offset` (the end of the text included).
RIEMANNCOMMONMETRICFORMAT_EXPORT TextPlace PlaceOfOffset(
  const std::string& text, std::size_t offset);

/// The offset of character `column` (1-based, escapes counted as one) of a
/// string value's content; past the content, its closing quote.
RIEMANNCOMMONMETRICFORMAT_EXPORT std::size_t CharacterInString(
  const std::string& text, const Node& string, int column);
} // namespace jsontext
} // namespace riemann

#endif
