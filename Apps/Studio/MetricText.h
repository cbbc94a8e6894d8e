/**
 * @file MetricText.h
 * @brief What the metric editor of riemann-studio needs to know about the
 * *text* of a metric definition (Documentation/MetricFormat.md): which
 * parameters the text defines, how to rewrite their values without
 * touching anything else, and how to colour it. Where an error is comes
 * from the parser as data (riemann::JsonErrorPlace), not from this file.
 *
 * Qt-free and VTK-free (nlohmann::json and the standard library), so the
 * editor's logic is tested without a display. Byte offsets index the UTF-8
 * text as given; a Qt caller converts them to QString (UTF-16) positions.
 */
#ifndef RiemannStudioMetricText_h
#define RiemannStudioMetricText_h

#include "JsonInputError.h"

#include <map>
#include <string>
#include <vector>

namespace riemann
{
namespace studio
{
/// A place in the metric's text (the core's, JsonInputError.h): errors are
/// located by the parser, as data (vtkRiemannMetric::GetLastErrorPlace).
using TextLocation = riemann::TextPlace;

/// A named number of a "parameters" object (MetricFormat.md, "Parameters").
struct MetricParameter
{
  std::string Name;
  std::string Pointer;   ///< JSON pointer of the value: "/parameters/a", "/compose/1/parameters/s"
  double Value = 0.0;    ///< the number; for an animated parameter, its value at t = 0 (From)
  bool Animated = false; ///< written {"from": a, "to": b}
  double From = 0.0;     ///< equal to Value unless Animated
  double To = 0.0;       ///< equal to Value unless Animated
};

/**
 * Every parameter of the definition: those of the root's "parameters" object
 * and, recursively, those of the objects of "compose" arrays (at any depth),
 * in document order (a "compose" written before the root's "parameters"
 * comes first; of duplicate keys, the last counts, as for the parser).
 * Values that are neither numbers nor {"from": number, "to": number} (errors
 * the metric parser reports) are left out. Empty when `text` is not valid
 * JSON. Never throws.
 */
std::vector<MetricParameter> FindMetricParameters(const std::string& text);

/**
 * `text` with the plain JSON numbers named by the pointers replaced by the
 * given values: only those number tokens change, so the user's formatting
 * is kept byte for byte (a value equal to the number already written keeps
 * its spelling). New numbers are written to read back as the same double.
 * Any plain number may be named, e.g. "/parameters/a" or, for an animated
 * parameter, "/parameters/a/from".
 *
 * Throws std::invalid_argument when `text` is not valid JSON, or naming the
 * pointer that does not lead to a plain number or whose value is not finite.
 */
std::string ApplyParameterValues(
  const std::string& text, const std::map<std::string, double>& valuesByPointer);

/// A classified run of bytes of JSON text, for a syntax highlighter.
struct TextSpan
{
  enum Kind
  {
    Key,        ///< a string followed (after whitespace) by ':'
    String,     ///< any other string, quotes included (unterminated: to the line's end)
    Number,     ///< a run of number characters starting with '-' or a digit
    Keyword,    ///< true, false, null
    Punctuation ///< { } [ ] : ,
  };
  int Start = 0;  ///< byte offset
  int Length = 0; ///< bytes
  Kind Type = Punctuation;
};

/**
 * The lexical classes of `text` (a line or a whole document), in order and
 * without overlap; whitespace and anything else (a misspelled keyword) get
 * no span. Lenient: it classifies text that does not parse, as one types.
 * A string ends at its closing quote or at the end of its line.
 */
std::vector<TextSpan> HighlightJson(const std::string& text);
} // namespace studio
} // namespace riemann

#endif
