/**
 * @file JsonInputError.h
 * @brief Where a JSON document given by a user is wrong, as data: the error
 * of every JSON reader of the toolkit (metric definitions, scenes) carries
 * the failing path, the unknown key or the column in an expression, and,
 * once located in the document's text, its line, column and byte offset.
 * A caller underlines from these fields; it never reads them back out of
 * the message.
 */
#ifndef RiemannJsonInputError_h
#define RiemannJsonInputError_h

#include "JsonTextScan.h" // TextPlace
#include "RiemannCommonMetricFormatExport.h"

#include <stdexcept>
#include <string>

namespace riemann
{
/// Where in a JSON document an error is.
struct JsonErrorPlace
{
  /// The value's path as messages write it, from the document's root name:
  /// "metric.compose[1].phi[0]", "scene.objects[2]"; "" when the error is
  /// not about a value (a file that cannot be read). Keys are written raw.
  std::string Path;
  /// For "unknown key": the error is about the key Key (which may be "")
  /// of the object at Path, not about a value.
  bool AtKey = false;
  std::string Key;
  /// For an expression: the 1-based character of the string at Path; 0: none.
  int ExpressionColumn = 0;
  /// For a syntax error: the byte offset of the character the JSON parser
  /// stopped at (the start of an overflowing number); -1: none.
  long long SyntaxOffset = -1;

  /// Set by LocateJsonError. The value's RFC 6901 pointer ("/compose/1/phi/0",
  /// "" for the root), and where it or its key is in the text. Text.Known is
  /// false for errors about the whole document (validation of the metric,
  /// a missing key of the root) and where the text does not hold the path.
  std::string Pointer;
  TextPlace Text;
};

/**
 * A JSON document that cannot be used. what() is the message the tools
 * print ("metric.f: column 7: unknown symbol \"w\"; ..."); Place says where
 * as data.
 */
class RIEMANNCOMMONMETRICFORMAT_EXPORT JsonInputError : public std::runtime_error
{
public:
  /// An error with no place in the document.
  explicit JsonInputError(const std::string& message);
  /// what() is "<Path>: <cause>" ("<cause>" when the path is empty).
  JsonInputError(const JsonErrorPlace& place, const std::string& cause);
  /// what() is `prefix` followed by `error`'s (a file name: "twist.json: "); its place.
  JsonInputError(const std::string& prefix, const JsonInputError& error);

  JsonErrorPlace Place;
};

/**
 * Fill `place`'s Pointer and Text for the document `text` it is an error of.
 * Dotted paths with raw keys are matched against the document's own keys
 * (a key may hold '.' or '['); of duplicate keys the last counts, as for
 * the parser. Never throws: where nothing fits, Text.Known is false.
 */
RIEMANNCOMMONMETRICFORMAT_EXPORT void LocateJsonError(
  const std::string& text, JsonErrorPlace& place);

/**
 * What `parse()` returns; a JsonInputError it throws (of any reader's
 * type, which `throw;` keeps) is first located in `text`, the document it
 * parses. The readers wrap their work in this once.
 */
template <class Parse>
auto LocatingErrorsIn(const std::string& text, Parse&& parse) -> decltype(parse())
{
  try
  {
    return parse();
  }
  catch (JsonInputError& e)
  {
    LocateJsonError(text, e.Place);
    throw;
  }
}

/**
 * The byte offset at which nlohmann's parser refuses `text` (the offending
 * character; for an overflowing number, its first), or -1 when it reads
 * `text` as JSON.
 */
RIEMANNCOMMONMETRICFORMAT_EXPORT long long JsonSyntaxErrorOffset(const std::string& text);
} // namespace riemann

#endif
