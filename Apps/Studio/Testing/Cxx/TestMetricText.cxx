// The metric editor's text logic (MetricText.h). The error messages below are
// the metric parser's own, as `riemann info -m file.json` printed them for the
// texts they go with (prefixes such as "file.json: " kept where they matter).
#include "MetricText.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>

#ifndef RIEMANN_SOURCE_DIR
#define RIEMANN_SOURCE_DIR "."
#endif

namespace riemann
{
namespace studio
{
namespace
{
using Json = nlohmann::json;

std::string ReadMetric(const std::string& name)
{
  const std::string path = std::string(RIEMANN_SOURCE_DIR) + "/Data/metrics/" + name;
  std::ifstream file(path, std::ios::binary);
  EXPECT_TRUE(file) << "cannot open " << path << " (set RIEMANN_SOURCE_DIR)";
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

const char* const ShippedMetrics[] = { "astigmatic-lens.json", "bump-translation.json",
  "constant-tensor.json", "eight-gaussians.json", "euclidean.json", "gaussian-bump-typed.json",
  "gaussian-bump.json", "gaussian-lens.json", "local-twist.json", "nil.json", "paraboloid.json",
  "poincare-ball.json", "round-sphere.json", "saddle.json", "twist.json",
  "two-bump-composition.json", "two-bumps.json", "wavy-diffeo.json" };

/// The message of the metric parser for text nlohmann refuses (MetricDefinition.cxx).
std::string SyntaxMessage(const std::string& text, int* byte = nullptr)
{
  try
  {
    const Json parsed = Json::parse(text);
    (void)parsed;
  }
  catch (const Json::parse_error& e)
  {
    if (byte)
    {
      *byte = static_cast<int>(e.byte);
    }
    const std::string what = e.what();
    return "invalid JSON: " + what.substr(what.find("] ") + 2);
  }
  catch (const Json::exception& e)
  {
    const std::string what = e.what();
    return "invalid JSON: " + what.substr(what.find("] ") + 2);
  }
  return std::string();
}

void ExpectAt(const TextLocation& location, int line, int column, int offset)
{
  EXPECT_TRUE(location.Known);
  EXPECT_EQ(location.Line, line);
  EXPECT_EQ(location.Column, column);
  EXPECT_EQ(location.Offset, offset);
}

// --- LocateMetricError: JSON syntax ------------------------------------------

TEST(LocateMetricError, SyntaxErrorAtNlohmannsLineAndColumn)
{
  const std::string text = "{\n  \"type\": \"graph\",\n  \"f\": x\n}";
  const std::string message = "a.json: invalid JSON: parse error at line 3, column 8: syntax error "
                              "while parsing value - invalid literal; last read: '\"f\": x'";
  EXPECT_EQ(SyntaxMessage(text), message.substr(8));
  const TextLocation location = LocateMetricError(text, message);
  ExpectAt(location, 3, 8, 28);
  EXPECT_EQ(text[location.Offset], 'x');
  EXPECT_EQ(FormatLocation(location), "line 3, column 8");
  // As the command line prints it.
  ExpectAt(LocateMetricError(text, "riemann: error: bad metric: " + message), 3, 8, 28);
}

TEST(LocateMetricError, SyntaxErrorColumnCountsCharactersNotBytes)
{
  const std::string text = "{\"name\": \"\xc3\xa9\", \"f\": x}";
  const std::string message = SyntaxMessage(text);
  ASSERT_NE(message.find("line 1, column 21:"), std::string::npos) << message;
  ExpectAt(LocateMetricError(text, message), 1, 20, 20);
}

TEST(LocateMetricError, SyntaxErrorOnANewlineIsTheEndOfThePreviousLine)
{
  // nlohmann reports "line 2, column 0" for the newline it just read.
  const std::string text = "[1.\n]";
  const std::string message = SyntaxMessage(text);
  ASSERT_NE(message.find("line 2, column 0:"), std::string::npos) << message;
  ExpectAt(LocateMetricError(text, message), 1, 4, 3);
}

TEST(LocateMetricError, SyntaxErrorAtTheEndOfTheText)
{
  const std::string text = "{\"type\": \"graph\"";
  const std::string message = "invalid JSON: parse error at line 1, column 17: syntax error while "
                              "parsing object - unexpected end of input; expected '}'";
  EXPECT_EQ(SyntaxMessage(text), message);
  ExpectAt(LocateMetricError(text, message), 1, 17, 16);
}

TEST(LocateMetricError, NumberOverflowIsTheNumber)
{
  const std::string text = "{\"type\": \"graph\",\n \"constant\": 1e999}";
  const std::string message = "overflow.json: invalid JSON: number overflow parsing '1e999'";
  EXPECT_EQ(SyntaxMessage(text), message.substr(15));
  ExpectAt(LocateMetricError(text, message), 2, 14, 31);
}

TEST(LocateMetricError, SyntaxPositionOutsideTheTextIsUnknown)
{
  const std::string text = "{\n  \"type\": \"graph\",\n  \"f\": x\n}";
  EXPECT_FALSE(LocateMetricError(text, "invalid JSON: parse error at line 9, column 1: x").Known);
  EXPECT_FALSE(LocateMetricError(text, "invalid JSON: parse error at line 1, column 3: x").Known);
  EXPECT_FALSE(LocateMetricError(text, "invalid JSON: number overflow parsing '1e999'").Known);
  EXPECT_EQ(FormatLocation(TextLocation()), "");
}

// --- LocateMetricError: paths in the definition ------------------------------

TEST(LocateMetricError, ExpressionColumnInAShippedMetric)
{
  std::string text = ReadMetric("gaussian-bump-typed.json");
  const std::size_t s = text.find("2 * s^2");
  ASSERT_NE(s, std::string::npos);
  text[s + 4] = 'q';
  const std::string message = "gbq.json: metric.f: column 35: unknown symbol \"q\"; allowed: x, y, "
                              "z, t, pi and the parameters a, s";
  const TextLocation location = LocateMetricError(text, message);
  EXPECT_TRUE(location.Known);
  EXPECT_EQ(location.Line, 6);
  EXPECT_EQ(location.Column, 43);
  EXPECT_EQ(location.Offset, static_cast<int>(s + 4));
}

TEST(LocateMetricError, ExpressionColumnCountsEscapesAsOneCharacter)
{
  const std::string text = "{\n"
                           "  \"type\": \"diffeo\",\n"
                           "  \"compose\": [\n"
                           "    {\"preset\": \"twist\"},\n"
                           "    {\n"
                           "      \"phi\": [\"x\", \"\\t\\n  y + \\u0071\", \"z\"]\n"
                           "    }\n"
                           "  ]\n"
                           "}";
  const TextLocation location = LocateMetricError(text,
    "metric.compose[1].phi[1]: column 9: unknown symbol \"q\"; allowed: x, y, z, t, pi (no "
    "parameters are defined)");
  EXPECT_TRUE(location.Known);
  EXPECT_EQ(location.Line, 6);
  EXPECT_EQ(location.Column, 31);
  EXPECT_EQ(text.substr(location.Offset, 6), "\\u0071");
}

TEST(LocateMetricError, ExpressionColumnAfterUtf8AndSurrogatePairs)
{
  const std::string raw = "{\"phi\": [\"x\", \"y\", \"z + \xc3\xa9\"]}";
  const TextLocation e =
    LocateMetricError(raw, "metric.phi[2]: column 5: unexpected character \"\xc3\xa9\"");
  ExpectAt(e, 1, 25, 24);
  EXPECT_EQ(raw.substr(e.Offset, 2), "\xc3\xa9");

  const std::string pair = "{\"type\": \"graph\", \"f\": \"x + \\ud83d\\ude00\"}";
  const TextLocation emoji =
    LocateMetricError(pair, "metric.f: column 5: unexpected character \"\xf0\x9f\x98\x80\"");
  ExpectAt(emoji, 1, 29, 28);
  EXPECT_EQ(pair.substr(emoji.Offset, 12), "\\ud83d\\ude00");

  const std::string after = "{\"f\": \"\\ud83d\\ude00x\"}";
  const TextLocation x = LocateMetricError(after, "metric.f: column 2: unknown symbol \"x\"");
  ExpectAt(x, 1, 20, 19);
  EXPECT_EQ(after[x.Offset], 'x');
}

TEST(LocateMetricError, ExpressionColumnPastTheEndIsTheClosingQuote)
{
  const std::string text = "{\"type\": \"diffeo\", \"phi\": [\"x\", \"y +\", \"z\"]}";
  const TextLocation plus =
    LocateMetricError(text, "ends.json: metric.phi[1]: column 3: the expression ends after \"+\"");
  EXPECT_EQ(plus.Offset, static_cast<int>(text.find('+')));
  const TextLocation end = LocateMetricError(text, "metric.phi[1]: column 4: the expression ends");
  EXPECT_EQ(end.Offset, static_cast<int>(text.find('+') + 1));
  EXPECT_EQ(text[end.Offset], '"');
}

TEST(LocateMetricError, ValueAtANestedPath)
{
  const std::string text = "{\n"
                           "  \"type\": \"graph\",\n"
                           "  \"gaussians\": [\n"
                           "    {\"amplitude\": 1, \"center\": [0, 0, 0], \"sigma\": 0.5},\n"
                           "    {\"amplitude\": 1,\n"
                           "     \"center\": [0, 0],\n"
                           "     \"sigma\": 0.5}\n"
                           "  ]\n"
                           "}";
  const TextLocation location = LocateMetricError(text,
    "center.json: metric.gaussians[1].center: expected an array of 3 numbers, got an array of 2");
  EXPECT_TRUE(location.Known);
  EXPECT_EQ(location.Line, 6);
  EXPECT_EQ(location.Column, 16);
  EXPECT_EQ(text.substr(location.Offset, 6), "[0, 0]");
  EXPECT_EQ(FormatLocation(location), "line 6, column 16");
  // The text was edited since: no such element.
  EXPECT_FALSE(LocateMetricError(text, "metric.gaussians[2].center: expected an array").Known);
  EXPECT_FALSE(LocateMetricError(text, "metric.gaussians[01]: expected an object").Known);
  EXPECT_FALSE(LocateMetricError(text, "metric.quadratic: expected an array").Known);
}

TEST(LocateMetricError, ValuesInParametersAndCompositions)
{
  const std::string shipped = ReadMetric("gaussian-bump-typed.json");
  ExpectAt(LocateMetricError(shipped,
             "at t = 0.700000: metric.parameters.a: expected a number (or {\"from\": a, \"to\": "
             "b}), got the string \"big\""),
    5, 23, static_cast<int>(shipped.find("1.0")));

  const std::string animated = "{\"type\": \"graph\", \"f\": \"a*x\", \"parameters\": {\"a\": "
                               "{\"from\": 0, \"to\": \"big\"}}}";
  EXPECT_EQ(LocateMetricError(animated, "metric.parameters.a.to: expected a number").Offset,
    static_cast<int>(animated.find("\"big\"")));

  const std::string composed =
    "{\"type\": \"diffeo\", \"compose\": [{\"preset\": \"twist\"}, "
    "{\"phi\": [\"x + s\", \"y\", \"z\"], \"parameters\": {\"s\": \"big\"}}]}";
  EXPECT_EQ(LocateMetricError(composed,
              "composeparam.json: metric.compose[1].parameters.s: expected a number (or "
              "{\"from\": a, \"to\": b}), got the string \"big\"")
              .Offset,
    static_cast<int>(composed.find("\"big\"")));

  const std::string tensor = "{\"type\": \"tensor\", \"g\": [[\"1\", \"0\", \"0\"], [\"0\", \"1\", "
                             "\"x\"], [\"0\", \"0\", \"1\"]]}";
  EXPECT_EQ(LocateMetricError(tensor,
              "metric.g: g must be symmetric: g[1][2] = \"x\" but g[2][1] = \"0\" (0.3 and 0 at ( "
              "0.3 -0.7 0.45))")
              .Offset,
    static_cast<int>(tensor.find("[[")));
}

TEST(LocateMetricError, KeysHoldingDotsAndDuplicateKeys)
{
  const std::string dotted =
    "{\"type\": \"graph\", \"f\": \"x\", \"parameters\": {\"a.b\": \"big\"}}";
  EXPECT_EQ(LocateMetricError(dotted,
              "metric.parameters.a.b: expected a number (or {\"from\": a, \"to\": b}), got the "
              "string \"big\"")
              .Offset,
    static_cast<int>(dotted.find("\"big\"")));

  // The parser keeps the last of duplicate keys; so does the location.
  const std::string duplicate = "{\"type\": \"graph\", \"f\": \"x\", \"f\": \"y + q\"}";
  EXPECT_EQ(LocateMetricError(duplicate,
              "dup.json: metric.f: column 5: unknown symbol \"q\"; allowed: x, y, z, t, pi (no "
              "parameters are defined)")
              .Offset,
    static_cast<int>(duplicate.find('q')));
}

TEST(LocateMetricError, UnknownKeyIsTheKey)
{
  const std::string root = "{\n  \"type\": \"graph\",\n  \"gausians\": []\n}";
  const TextLocation location = LocateMetricError(root,
    "rootkey.json: metric: unknown key \"gausians\"; expected one of \"type\", \"f\", "
    "\"gaussians\", \"quadratic\", \"constant\", \"parameters\", \"name\", \"description\"");
  ExpectAt(location, 3, 3, 23);
  EXPECT_EQ(root.substr(location.Offset, 10), "\"gausians\"");

  const std::string nested = "{\"type\": \"graph\", \"gaussians\": [{\"amplitude\": 1, \"center\": "
                             "[0, 0, 0], \"sigma\": 1, \"x\": 2}]}";
  EXPECT_EQ(LocateMetricError(nested,
              "metric.gaussians[0]: unknown key \"x\"; expected one of \"amplitude\", \"center\", "
              "\"sigma\", \"name\", \"description\"")
              .Offset,
    static_cast<int>(nested.find("\"x\"")));
  EXPECT_FALSE(LocateMetricError(nested, "metric: unknown key \"n\"; expected one of \"f\"").Known);
}

TEST(LocateMetricError, MessagesAboutTheWholeMetricHaveNoPlace)
{
  const std::string conformal = "{\"type\": \"conformal\", \"constant\": -1}";
  EXPECT_FALSE(LocateMetricError(conformal,
    "metric: conformal metric: the refractive index n = -1 at (0 0 0) must be positive "
    "everywhere (g = n^2 I)")
                 .Known);
  EXPECT_FALSE(LocateMetricError("{\"f\": \"x\"}", "metric: missing required key \"type\"").Known);
  EXPECT_FALSE(LocateMetricError(conformal, "/no/such.json: the metric file does not exist").Known);
  EXPECT_FALSE(LocateMetricError(conformal, "").Known);
}

TEST(LocateMetricError, PathsOfTextThatNoLongerParsesAreUnknown)
{
  EXPECT_FALSE(LocateMetricError("{\"f\": \"x + q\"", "metric.f: column 5: unknown symbol").Known);
  EXPECT_FALSE(LocateMetricError("[\"x\"]", "metric.f: column 1: unknown symbol").Known);
}

TEST(LocateMetricError, AFileCalledMetricIsNotAPath)
{
  const std::string text = "{\"type\": \"graph\", \"f\": \"x + q\"}";
  EXPECT_EQ(LocateMetricError(text, "metric.json: metric.f: column 5: unknown symbol \"q\"").Offset,
    static_cast<int>(text.find('q')));
}

// --- LocateMetricError against nlohmann, on many texts ------------------------

/// Every path of `value` as the parser writes it ("metric.a[0].b"), with its value.
void CollectPaths(
  const Json& value, const std::string& path, std::vector<std::pair<std::string, Json>>& paths)
{
  paths.emplace_back(path, value);
  if (value.is_object())
  {
    for (const auto& item : value.items())
    {
      CollectPaths(item.value(), path + "." + item.key(), paths);
    }
  }
  else if (value.is_array())
  {
    for (std::size_t i = 0; i < value.size(); ++i)
    {
      CollectPaths(value[i], path + "[" + std::to_string(i) + "]", paths);
    }
  }
}

/// Whether a JSON value equal to `expected` starts at `offset`.
bool ValueStartsAt(const std::string& text, int offset, const Json& expected)
{
  for (std::size_t length = 1; offset + length <= text.size(); ++length)
  {
    const Json value = Json::parse(text.substr(offset, length), nullptr, false);
    if (!value.is_discarded() && value == expected)
    {
      return true;
    }
  }
  return false;
}

/// Line and column as an editor counts them, for `offset`.
void ExpectConsistent(const std::string& text, const TextLocation& location)
{
  ASSERT_TRUE(location.Known);
  ASSERT_GE(location.Offset, 0);
  ASSERT_LE(location.Offset, static_cast<int>(text.size()));
  int line = 1;
  int column = 1;
  for (int i = 0; i < location.Offset; ++i)
  {
    const bool newline = text[i] == '\n';
    line += newline ? 1 : 0;
    column = newline ? 1 : column + ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80);
  }
  EXPECT_EQ(location.Line, line);
  EXPECT_EQ(location.Column, column);
}

void ExpectEveryPathLocated(const std::string& text)
{
  std::vector<std::pair<std::string, Json>> paths;
  CollectPaths(Json::parse(text), "metric", paths);
  for (const auto& [path, value] : paths)
  {
    const TextLocation location = LocateMetricError(text, path + ": expected something else");
    if (path == "metric")
    {
      EXPECT_FALSE(location.Known);
      continue;
    }
    ExpectConsistent(text, location);
    EXPECT_TRUE(ValueStartsAt(text, location.Offset, value)) << path;
    if (value.is_string())
    {
      // Column k is where the first k - 1 characters of the string end.
      const std::string content = value.get<std::string>();
      const int characters = static_cast<int>(std::count_if(content.begin(), content.end(),
        [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
      for (int k = 1; k <= characters; ++k)
      {
        const int at =
          LocateMetricError(text, path + ": column " + std::to_string(k) + ": cause").Offset;
        const Json before =
          Json::parse(text.substr(location.Offset, at - location.Offset) + "\"", nullptr, false);
        ASSERT_TRUE(before.is_string()) << path << " column " << k;
        const std::string prefix = before.get<std::string>();
        EXPECT_EQ(prefix, content.substr(0, prefix.size())) << path << " column " << k;
        EXPECT_EQ(std::count_if(prefix.begin(), prefix.end(),
                    [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }),
          k - 1)
          << path << " column " << k;
      }
    }
    if (value.is_object())
    {
      for (const auto& item : value.items())
      {
        const TextLocation key = LocateMetricError(
          text, path + ": unknown key \"" + item.key() + "\"; expected one of \"type\"");
        ExpectConsistent(text, key);
        EXPECT_TRUE(ValueStartsAt(text, key.Offset, Json(item.key()))) << path << " " << item.key();
      }
    }
  }
}

TEST(LocateMetricError, EveryPathOfTheShippedMetrics)
{
  for (const char* name : ShippedMetrics)
  {
    SCOPED_TRACE(name);
    ExpectEveryPathLocated(ReadMetric(name));
  }
}

TEST(LocateMetricError, EveryPathOfATextFullOfEscapes)
{
  ExpectEveryPathLocated("{\"type\":\"diffeo\",\"compose\":[{\"phi\":[\"\\u00e9 + \\\"x\\\"\",\r\n"
                         "\t\"y\\\\\\/\\b\\f\\n\\r\\t\", \"\\ud83d\\ude00\xc3\xa9z\"], "
                         "\"parameters\" : {\"a\\u002eb\": [1, {\"\": null}], \"k\": true}}]}");
}

/// Every prefix of every shipped metric is refused by nlohmann at a place
/// (its byte count, one-based) that the location must equal.
TEST(LocateMetricError, SyntaxErrorsOfTruncatedMetricsMatchNlohmannsByte)
{
  for (const char* name : ShippedMetrics)
  {
    const std::string text = ReadMetric(name);
    for (std::size_t length = 0; length + 1 < text.size(); ++length)
    {
      const std::string truncated = text.substr(0, length);
      int byte = -1;
      const std::string message = SyntaxMessage(truncated, &byte);
      ASSERT_FALSE(message.empty()) << name << " cut at " << length;
      const TextLocation location = LocateMetricError(truncated, message);
      ExpectConsistent(truncated, location);
      EXPECT_EQ(location.Offset, byte - 1) << name << " cut at " << length << ": " << message;
    }
  }
}

// --- never crash ---------------------------------------------------------------

void ExpectSpansWellFormed(const std::string& text)
{
  int end = 0;
  for (const TextSpan& span : HighlightJson(text))
  {
    EXPECT_GE(span.Start, end);
    EXPECT_GT(span.Length, 0);
    end = span.Start + span.Length;
  }
  EXPECT_LE(end, static_cast<int>(text.size()));
}

/// Everything on `text` and a few messages: no crash, and locations in the text.
void ExerciseEverything(const std::string& text, std::mt19937& random)
{
  std::uniform_int_distribution<int> small(0, 12);
  const std::string messages[] = { SyntaxMessage(text),
    "invalid JSON: parse error at line " + std::to_string(small(random)) + ", column " +
      std::to_string(small(random)) + ": x",
    "invalid JSON: number overflow parsing '" + std::to_string(small(random)) + "'",
    "metric.gaussians[" + std::to_string(small(random)) + "].center: column 3: x",
    "metric.compose[1].phi[0]: column " + std::to_string(small(random)) + ": x",
    "metric.f: column 99999999999: x", "metric: unknown key \"type\"; expected one of \"f\"",
    "metric.parameters.a: x", "metric.", "metric[", "metric[0",
    "x: metric.: ", "metric.f: column " };
  for (const std::string& message : messages)
  {
    const TextLocation location = LocateMetricError(text, message);
    if (location.Known)
    {
      ExpectConsistent(text, location);
    }
  }
  const std::vector<MetricParameter> parameters = FindMetricParameters(text);
  std::map<std::string, double> values;
  for (const MetricParameter& parameter : parameters)
  {
    values[parameter.Pointer + (parameter.Animated ? "/to" : "")] = 0.5;
  }
  try
  {
    const std::string applied = ApplyParameterValues(text, values);
    EXPECT_TRUE(Json::accept(applied));
    EXPECT_EQ(FindMetricParameters(applied).size(), parameters.size());
  }
  catch (const std::invalid_argument&)
  {
    EXPECT_FALSE(Json::accept(text)); // only text that is not JSON may be refused
  }
  ExpectSpansWellFormed(text);
}

TEST(NeverCrash, RandomTextsAndMutatedMetrics)
{
  std::mt19937 random(20240611);
  const std::string alphabet = "{}[]:,\"\\/ \n\t0123456789.eE+-ufntrlsabxyz~\xc3\xa9\x80\xff";
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
  for (int i = 0; i < 3000; ++i)
  {
    std::string text(i % 64, ' ');
    for (char& c : text)
    {
      c = alphabet[pick(random)];
    }
    ExerciseEverything(text, random);
  }
  for (const char* name : ShippedMetrics)
  {
    const std::string original = ReadMetric(name);
    std::uniform_int_distribution<std::size_t> where(0, original.size() - 1);
    for (int i = 0; i < 150; ++i)
    {
      std::string text = original;
      for (int k = 0; k < 1 + i % 3; ++k)
      {
        text[where(random)] = alphabet[pick(random)];
      }
      ExerciseEverything(text, random);
    }
  }
}

TEST(NeverCrash, DeeplyNestedTextIsRefusedNotOverflowed)
{
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  ASSERT_TRUE(Json::accept(deep));
  EXPECT_TRUE(FindMetricParameters(deep).empty());
  EXPECT_FALSE(LocateMetricError(deep, "metric[0][0]: x").Known);
  EXPECT_THROW(ApplyParameterValues(deep, {}), std::invalid_argument);
  EXPECT_EQ(HighlightJson(deep).size(), 200000u);
  // Shallow nesting is fine.
  const std::string shallow =
    "{\"parameters\": {\"a\": 1}, \"x\": " + std::string(100, '[') + std::string(100, ']') + "}";
  EXPECT_EQ(FindMetricParameters(shallow).size(), 1u);
}

// --- parameters --------------------------------------------------------------

void ExpectParameter(const MetricParameter& parameter, const std::string& name,
  const std::string& pointer, double value, bool animated, double from, double to)
{
  EXPECT_EQ(parameter.Name, name);
  EXPECT_EQ(parameter.Pointer, pointer);
  EXPECT_EQ(parameter.Value, value);
  EXPECT_EQ(parameter.Animated, animated);
  EXPECT_EQ(parameter.From, from);
  EXPECT_EQ(parameter.To, to);
}

TEST(FindMetricParameters, ShippedMetrics)
{
  const std::vector<MetricParameter> bump =
    FindMetricParameters(ReadMetric("gaussian-bump-typed.json"));
  ASSERT_EQ(bump.size(), 2u);
  ExpectParameter(bump[0], "a", "/parameters/a", 1.0, false, 1.0, 1.0);
  ExpectParameter(bump[1], "s", "/parameters/s", 0.5, false, 0.5, 0.5);

  const std::vector<MetricParameter> wavy = FindMetricParameters(ReadMetric("wavy-diffeo.json"));
  ASSERT_EQ(wavy.size(), 2u);
  ExpectParameter(wavy[0], "a", "/parameters/a", 0.0, true, 0.0, 0.4);
  ExpectParameter(wavy[1], "b", "/parameters/b", 0.3, false, 0.3, 0.3);

  EXPECT_TRUE(FindMetricParameters(ReadMetric("twist.json")).empty());
  EXPECT_TRUE(FindMetricParameters(ReadMetric("two-bump-composition.json")).empty());
}

TEST(FindMetricParameters, NestedCompositionsInDocumentOrder)
{
  const std::string text =
    "{\n"
    "  \"type\": \"diffeo\",\n"
    "  \"compose\": [\n"
    "    {\"phi\": [\"x + s\", \"y\", \"z\"],\n"
    "     \"parameters\": {\"s\": 0.25, \"w~/\": -1e-3, \"bad\": \"big\"}},\n"
    "    {\"compose\": [\n"
    "      {\"preset\": \"twist\"},\n"
    "      {\"phi\": [\"x\", \"y\", \"z\"], \"parameters\": {\"u\": {\"from\": "
    "-1, \"to\": 2}}}\n"
    "    ]}\n"
    "  ],\n"
    "  \"parameters\": {\"k\": 2, \"k\": 3},\n"
    "  \"gaussian\": {\"parameters\": {\"not\": 1}}\n"
    "}";
  const std::vector<MetricParameter> parameters = FindMetricParameters(text);
  ASSERT_EQ(parameters.size(), 4u);
  ExpectParameter(parameters[0], "s", "/compose/0/parameters/s", 0.25, false, 0.25, 0.25);
  ExpectParameter(parameters[1], "w~/", "/compose/0/parameters/w~0~1", -1e-3, false, -1e-3, -1e-3);
  ExpectParameter(parameters[2], "u", "/compose/1/compose/1/parameters/u", -1, true, -1, 2);
  ExpectParameter(parameters[3], "k", "/parameters/k", 3, false, 3, 3);
  // The pointers are the ones nlohmann (hence the metric parser) reads.
  const Json json = Json::parse(text);
  for (const MetricParameter& parameter : parameters)
  {
    const Json& value = json.at(Json::json_pointer(parameter.Pointer));
    EXPECT_EQ(
      parameter.Animated ? value.at("from").get<double>() : value.get<double>(), parameter.From)
      << parameter.Pointer;
  }
}

TEST(FindMetricParameters, AnimatedNeedsExactlyFromAndTo)
{
  const std::vector<MetricParameter> parameters = FindMetricParameters(
    "{\"parameters\": {\"a\": {\"from\": 0, \"to\": 1, \"by\": 2}, \"b\": {\"from\": 0}, "
    "\"c\": {\"from\": \"0\", \"to\": 1}, \"d\": [1], \"e\": {\"to\": 5, \"from\": 4}}}");
  ASSERT_EQ(parameters.size(), 1u);
  ExpectParameter(parameters[0], "e", "/parameters/e", 4, true, 4, 5);
}

TEST(FindMetricParameters, InvalidJsonHasNone)
{
  EXPECT_TRUE(FindMetricParameters("{\"parameters\": {\"a\": 1}").empty());
  EXPECT_TRUE(FindMetricParameters("{\"parameters\": {\"a\": 1e999}}").empty());
  EXPECT_TRUE(FindMetricParameters("").empty());
  EXPECT_TRUE(FindMetricParameters("[1, 2]").empty());
}

// --- ApplyParameterValues ----------------------------------------------------

TEST(ApplyParameterValues, OnlyTheNumbersChange)
{
  const std::string text = ReadMetric("gaussian-bump-typed.json");
  std::string expected = text;
  const std::string before = "\"parameters\": {\"a\": 1.0, \"s\": 0.5}";
  ASSERT_NE(expected.find(before), std::string::npos);
  expected.replace(
    expected.find(before), before.size(), "\"parameters\": {\"a\": 2.5, \"s\": 0.125}");
  const std::string applied =
    ApplyParameterValues(text, { { "/parameters/a", 2.5 }, { "/parameters/s", 0.125 } });
  EXPECT_EQ(applied, expected);
  const std::vector<MetricParameter> parameters = FindMetricParameters(applied);
  ASSERT_EQ(parameters.size(), 2u);
  EXPECT_EQ(parameters[0].Value, 2.5);
  EXPECT_EQ(parameters[1].Value, 0.125);
}

TEST(ApplyParameterValues, AnUnchangedValueKeepsItsSpelling)
{
  const std::string text = "{\"parameters\": {\"a\": 1.000, \"b\": 5E-1,\n \"c\": 2}}";
  EXPECT_EQ(
    ApplyParameterValues(text, { { "/parameters/a", 1.0 }, { "/parameters/b", 0.5 } }), text);
  EXPECT_EQ(ApplyParameterValues(text, { { "/parameters/c", -3.0 } }),
    "{\"parameters\": {\"a\": 1.000, \"b\": 5E-1,\n \"c\": -3.0}}");
  EXPECT_EQ(ApplyParameterValues(text, {}), text);
}

TEST(ApplyParameterValues, NumbersReadBackExactly)
{
  const std::string text = "{\"parameters\": {\"a\": 0}}";
  for (const double value : { 0.1 + 0.2, 1e-300, -2.5e20, 1.0 / 3.0, 5e-324, 123456789.0 })
  {
    const std::string applied = ApplyParameterValues(text, { { "/parameters/a", value } });
    EXPECT_EQ(Json::parse(applied).at("parameters").at("a").get<double>(), value) << applied;
    ASSERT_EQ(FindMetricParameters(applied).size(), 1u);
    EXPECT_EQ(FindMetricParameters(applied)[0].Value, value) << applied;
  }
  EXPECT_EQ(ApplyParameterValues(text, { { "/parameters/a", 0.1 + 0.2 } }),
    "{\"parameters\": {\"a\": 0.30000000000000004}}");
}

TEST(ApplyParameterValues, AnimatedEndsAndCompositions)
{
  const std::string wavy = ReadMetric("wavy-diffeo.json");
  const std::string applied = ApplyParameterValues(
    wavy, { { "/parameters/a/from", 0.25 }, { "/parameters/a/to", 0.75 }, { "/parameters/b", 1 } });
  EXPECT_NE(applied.find("\"parameters\": {\"a\": {\"from\": 0.25, \"to\": 0.75}, \"b\": 1.0},"),
    std::string::npos)
    << applied;
  EXPECT_EQ(applied.size(), wavy.size() + 2); // 0.0 -> 0.25, 0.4 -> 0.75, 0.3 -> 1.0

  const std::string composed =
    "{\"compose\": [{\"preset\": \"twist\"}, {\"parameters\": {\"s\": 1, \"a/b\": 2}}]}";
  EXPECT_EQ(ApplyParameterValues(composed,
              { { "/compose/1/parameters/s", 4 }, { "/compose/1/parameters/a~1b", 0.5 } }),
    "{\"compose\": [{\"preset\": \"twist\"}, {\"parameters\": {\"s\": 4.0, \"a/b\": 0.5}}]}");
}

TEST(ApplyParameterValues, OfDuplicateKeysTheLastCounts)
{
  // nlohmann, hence the metric parser, keeps the last of duplicate keys.
  EXPECT_EQ(
    ApplyParameterValues("{\"parameters\": {\"k\": 2, \"k\": 3}}", { { "/parameters/k", 4 } }),
    "{\"parameters\": {\"k\": 2, \"k\": 4.0}}");
}

void ExpectRefused(const std::string& text, const std::map<std::string, double>& values,
  const std::string& expectedWords)
{
  try
  {
    ApplyParameterValues(text, values);
    ADD_FAILURE() << "no exception for " << text;
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find(expectedWords), std::string::npos) << e.what();
  }
}

TEST(ApplyParameterValues, RefusesWhatIsNotAPlainNumber)
{
  const std::string wavy = ReadMetric("wavy-diffeo.json");
  ExpectRefused(wavy, { { "/parameters/a", 1 } }, "\"/parameters/a\"");
  ExpectRefused(wavy, { { "/parameters/q", 1 } }, "\"/parameters/q\"");
  ExpectRefused(wavy, { { "/type", 1 } }, "\"/type\"");
  ExpectRefused(wavy, { { "parameters/b", 1 } }, "\"parameters/b\"");
  ExpectRefused(wavy, { { "/phi/01", 1 } }, "\"/phi/01\"");
  ExpectRefused(wavy, { { "/parameters/b", std::nan("") } }, "\"/parameters/b\"");
  ExpectRefused(wavy, { { "/parameters/b", HUGE_VAL } }, "not a finite number");
  ExpectRefused(wavy.substr(0, wavy.size() - 3), { { "/parameters/b", 1 } }, "not valid JSON");
}

// --- HighlightJson -----------------------------------------------------------

std::string Describe(const std::string& text)
{
  static const char* const names[] = { "Key", "String", "Number", "Keyword", "Punctuation" };
  std::string described;
  for (const TextSpan& span : HighlightJson(text))
  {
    described += std::string(names[span.Type]) + "(" + text.substr(span.Start, span.Length) + ") ";
  }
  return described;
}

TEST(HighlightJson, ClassifiesALine)
{
  EXPECT_EQ(
    Describe("  \"f\": \"a * exp(-x)\", \"n\" :-1.5e3, \"ok\": true, \"z\": null, \"q\": fals"),
    "Key(\"f\") Punctuation(:) String(\"a * exp(-x)\") Punctuation(,) Key(\"n\") Punctuation(:) "
    "Number(-1.5e3) Punctuation(,) Key(\"ok\") Punctuation(:) Keyword(true) Punctuation(,) "
    "Key(\"z\") Punctuation(:) Keyword(null) Punctuation(,) Key(\"q\") Punctuation(:) ");
  EXPECT_EQ(Describe("{\"center\": [0, -0.5, 1E+2]}"),
    "Punctuation({) Key(\"center\") Punctuation(:) Punctuation([) Number(0) Punctuation(,) "
    "Number(-0.5) Punctuation(,) Number(1E+2) Punctuation(]) Punctuation(}) ");
}

TEST(HighlightJson, EscapedQuotesAndUnterminatedStrings)
{
  EXPECT_EQ(Describe("\"a\\\"b\": \"c\\\\\", \"d"),
    "Key(\"a\\\"b\") Punctuation(:) String(\"c\\\\\") Punctuation(,) String(\"d) ");
  // A string ends with its line: the next line is classified on its own.
  EXPECT_EQ(Describe("[\"open\n\"key\": false]"),
    "Punctuation([) String(\"open) Key(\"key\") Punctuation(:) Keyword(false) Punctuation(]) ");
  EXPECT_EQ(Describe("\"trailing\\"), "String(\"trailing\\) ");
}

TEST(HighlightJson, OffsetsAreBytes)
{
  const std::vector<TextSpan> spans = HighlightJson("\"\xc3\xa9\": 1");
  ASSERT_EQ(spans.size(), 3u);
  EXPECT_EQ(spans[0].Start, 0);
  EXPECT_EQ(spans[0].Length, 4);
  EXPECT_EQ(spans[0].Type, TextSpan::Key);
  EXPECT_EQ(spans[1].Start, 4);
  EXPECT_EQ(spans[2].Start, 6);
  EXPECT_EQ(spans[2].Length, 1);
  EXPECT_EQ(spans[2].Type, TextSpan::Number);
  EXPECT_TRUE(HighlightJson("").empty());
  EXPECT_TRUE(HighlightJson("  \t").empty());
}
} // namespace
} // namespace studio
} // namespace riemann
