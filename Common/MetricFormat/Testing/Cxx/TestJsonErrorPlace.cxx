// Where a JSON document is wrong, as data (JsonInputError.h): the metric
// parser's errors carry the failing path, key, expression column or syntax
// offset, located in the text as line, column and byte offset. The texts
// below are refused by ParseMetricDefinition itself wherever it can refuse
// them; LocateJsonError is also driven with places of every value of the
// shipped metrics, checked against nlohmann's reading of the same text.
#include "CameraPathFile.h"
#include "JsonInputError.h"
#include "JsonTextScan.h"
#include "MetricDefinition.h"
#include "ShippedMetricTexts.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <random>
#include <sstream>

namespace riemann
{
namespace
{
using Json = nlohmann::json;

using testing::ShippedMetrics;

std::string ReadMetric(const std::string& name)
{
  return testing::ReadShippedMetric(RIEMANN_TEST_DATA_DIR, name);
}

/// The error of parsing `text`; fails the test when it parses.
MetricDefinitionError ErrorOf(const std::string& text)
{
  try
  {
    ParseMetricDefinition(text);
  }
  catch (const MetricDefinitionError& e)
  {
    return e;
  }
  ADD_FAILURE() << "parsed: " << text;
  return MetricDefinitionError("parsed");
}

/// `path`, or expression `column` of the string there, located in `text`.
TextPlace Locate(const std::string& text, const std::string& path, int column = 0)
{
  JsonErrorPlace place;
  place.Path = path;
  place.ExpressionColumn = column;
  LocateJsonError(text, place);
  return place.Text;
}

/// The key `key` of the object at `path`, located in `text`.
TextPlace LocateKey(const std::string& text, const std::string& path, const std::string& key)
{
  JsonErrorPlace place;
  place.Path = path;
  place.AtKey = true;
  place.Key = key;
  LocateJsonError(text, place);
  return place.Text;
}

void ExpectAt(const TextPlace& place, int line, int column, int offset)
{
  EXPECT_TRUE(place.Known);
  EXPECT_EQ(place.Line, line);
  EXPECT_EQ(place.Column, column);
  EXPECT_EQ(place.Offset, offset);
}

// --- JSON syntax: nlohmann's place, as data ------------------------------------

TEST(JsonErrorPlace, SyntaxErrorAtTheOffendingCharacter)
{
  const std::string text = "{\n  \"type\": \"graph\",\n  \"f\": x\n}";
  const MetricDefinitionError error = ErrorOf(text);
  EXPECT_EQ(std::string(error.what()),
    "invalid JSON: parse error at line 3, column 8: syntax error while parsing value - invalid "
    "literal; last read: '\"f\": x'");
  ExpectAt(error.Place.Text, 3, 8, 28);
  EXPECT_EQ(text[error.Place.Text.Offset], 'x');
  EXPECT_EQ(DescribeTextPlace(error.Place.Text), "line 3, column 8");
  EXPECT_EQ(DescribeTextPlace(TextPlace()), "");
}

TEST(JsonErrorPlace, SyntaxErrorColumnCountsCharactersNotBytes)
{
  // nlohmann says column 21 (bytes); an editor shows column 20.
  ExpectAt(ErrorOf("{\"name\": \"\xc3\xa9\", \"f\": x}").Place.Text, 1, 20, 20);
}

TEST(JsonErrorPlace, SyntaxErrorOnANewlineIsTheEndOfThePreviousLine)
{
  ExpectAt(ErrorOf("[1.\n]").Place.Text, 1, 4, 3);
}

TEST(JsonErrorPlace, SyntaxErrorAtTheEndOfTheText)
{
  ExpectAt(ErrorOf("{\"type\": \"graph\"").Place.Text, 1, 17, 16);
  ExpectAt(ErrorOf("").Place.Text, 1, 1, 0);
}

TEST(JsonErrorPlace, NumberOverflowIsTheNumber)
{
  const std::string text = "{\"type\": \"graph\",\n \"constant\": 1e999}";
  const MetricDefinitionError error = ErrorOf(text);
  EXPECT_EQ(std::string(error.what()), "invalid JSON: number overflow parsing '1e999'");
  ExpectAt(error.Place.Text, 2, 14, 31);
}

/// Every prefix of every shipped metric is refused by nlohmann at a place
/// (its byte count, one-based) that the error's offset must equal.
TEST(JsonErrorPlace, SyntaxErrorsOfTruncatedMetricsMatchNlohmannsByte)
{
  for (const char* name : ShippedMetrics)
  {
    const std::string text = ReadMetric(name);
    for (std::size_t length = 0; length + 1 < text.size(); ++length)
    {
      const std::string truncated = text.substr(0, length);
      int byte = -1;
      try
      {
        (void)Json::parse(truncated);
      }
      catch (const Json::parse_error& e)
      {
        byte = static_cast<int>(e.byte);
      }
      ASSERT_GE(byte, 1) << name << " cut at " << length;
      EXPECT_EQ(ErrorOf(truncated).Place.Text.Offset, byte - 1) << name << " cut at " << length;
    }
  }
}

// --- values, keys and expressions: the parser's own errors --------------------

TEST(JsonErrorPlace, ExpressionColumnInAShippedMetric)
{
  std::string text = ReadMetric("gaussian-bump-typed.json");
  const std::size_t s = text.find("2 * s^2");
  ASSERT_NE(s, std::string::npos);
  text[s + 4] = 'q';
  const MetricDefinitionError error = ErrorOf(text);
  EXPECT_EQ(error.Place.Path, "metric.f");
  EXPECT_EQ(error.Place.Pointer, "/f");
  EXPECT_EQ(error.Place.ExpressionColumn, 35);
  ExpectAt(error.Place.Text, 6, 43, static_cast<int>(s + 4));
}

TEST(JsonErrorPlace, ExpressionColumnCountsEscapesAsOneCharacter)
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
  const MetricDefinitionError error = ErrorOf(text);
  EXPECT_EQ(error.Place.Pointer, "/compose/1/phi/1");
  EXPECT_EQ(error.Place.Text.Line, 6);
  EXPECT_EQ(error.Place.Text.Column, 31);
  EXPECT_EQ(text.substr(error.Place.Text.Offset, 6), "\\u0071");
}

TEST(JsonErrorPlace, ExpressionColumnAfterUtf8AndSurrogatePairs)
{
  const std::string raw = "{\"phi\": [\"x\", \"y\", \"z + \xc3\xa9\"]}";
  const TextPlace e = Locate(raw, "metric.phi[2]", 5);
  ExpectAt(e, 1, 25, 24);
  EXPECT_EQ(raw.substr(e.Offset, 2), "\xc3\xa9");

  const std::string pair = "{\"type\": \"graph\", \"f\": \"x + \\ud83d\\ude00\"}";
  const TextPlace emoji = ErrorOf(pair).Place.Text;
  ExpectAt(emoji, 1, 29, 28);
  EXPECT_EQ(pair.substr(emoji.Offset, 12), "\\ud83d\\ude00");

  const std::string after = "{\"f\": \"\\ud83d\\ude00x\"}";
  const TextPlace x = Locate(after, "metric.f", 2);
  ExpectAt(x, 1, 20, 19);
  EXPECT_EQ(after[x.Offset], 'x');
}

TEST(JsonErrorPlace, ExpressionColumnPastTheEndIsTheClosingQuote)
{
  const std::string text = "{\"type\": \"diffeo\", \"phi\": [\"x\", \"y +\", \"z\"]}";
  EXPECT_EQ(Locate(text, "metric.phi[1]", 3).Offset, static_cast<int>(text.find('+')));
  const TextPlace end = Locate(text, "metric.phi[1]", 4);
  EXPECT_EQ(end.Offset, static_cast<int>(text.find('+') + 1));
  EXPECT_EQ(text[end.Offset], '"');
}

TEST(JsonErrorPlace, ValueAtANestedPath)
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
  const MetricDefinitionError error = ErrorOf(text);
  EXPECT_EQ(error.Place.Path, "metric.gaussians[1].center");
  EXPECT_EQ(error.Place.Pointer, "/gaussians/1/center");
  ExpectAt(error.Place.Text, 6, 16, static_cast<int>(text.find("[0, 0]")));
  // A text edited since: no such element.
  EXPECT_FALSE(Locate(text, "metric.gaussians[2].center").Known);
  EXPECT_FALSE(Locate(text, "metric.gaussians[01]").Known);
  EXPECT_FALSE(Locate(text, "metric.quadratic").Known);
}

TEST(JsonErrorPlace, ValuesInParametersAndCompositions)
{
  std::string typed = ReadMetric("gaussian-bump-typed.json");
  const std::size_t one = typed.find("1.0");
  typed.replace(one, 3, "\"big\"");
  ExpectAt(ErrorOf(typed).Place.Text, 5, 23, static_cast<int>(one));

  const std::string animated = "{\"type\": \"graph\", \"f\": \"a*x\", \"parameters\": {\"a\": "
                               "{\"from\": 0, \"to\": \"big\"}}}";
  EXPECT_EQ(Locate(animated, "metric.parameters.a.to").Offset,
    static_cast<int>(animated.find("\"big\"")));

  const std::string composed =
    "{\"type\": \"diffeo\", \"compose\": [{\"preset\": \"twist\"}, "
    "{\"phi\": [\"x + s\", \"y\", \"z\"], \"parameters\": {\"s\": \"big\"}}]}";
  const MetricDefinitionError error = ErrorOf(composed);
  EXPECT_EQ(error.Place.Pointer, "/compose/1/parameters/s");
  EXPECT_EQ(error.Place.Text.Offset, static_cast<int>(composed.find("\"big\"")));

  const std::string tensor = "{\"type\": \"tensor\", \"g\": [[\"1\", \"0\", \"0\"], [\"0\", \"1\", "
                             "\"x\"], [\"0\", \"0\", \"1\"]]}";
  EXPECT_EQ(ErrorOf(tensor).Place.Text.Offset, static_cast<int>(tensor.find("[[")));
}

TEST(JsonErrorPlace, KeysHoldingDotsAndDuplicateKeys)
{
  const std::string dotted =
    "{\"type\": \"graph\", \"f\": \"x\", \"parameters\": {\"a.b\": \"big\"}}";
  const TextPlace inDotted = Locate(dotted, "metric.parameters.a.b");
  EXPECT_EQ(inDotted.Offset, static_cast<int>(dotted.find("\"big\"")));

  // The parser keeps the last of duplicate keys; so does the place.
  const std::string duplicate = "{\"type\": \"graph\", \"f\": \"x\", \"f\": \"y + q\"}";
  EXPECT_EQ(ErrorOf(duplicate).Place.Text.Offset, static_cast<int>(duplicate.find('q')));
}

TEST(JsonErrorPlace, UnknownKeyIsTheKey)
{
  const std::string root = "{\n  \"type\": \"graph\",\n  \"gausians\": []\n}";
  const MetricDefinitionError error = ErrorOf(root);
  EXPECT_TRUE(error.Place.AtKey);
  EXPECT_EQ(error.Place.Key, "gausians");
  EXPECT_EQ(error.Place.Pointer, "");
  ExpectAt(error.Place.Text, 3, 3, 23);
  EXPECT_EQ(root.substr(error.Place.Text.Offset, 10), "\"gausians\"");

  const std::string nested = "{\"type\": \"graph\", \"gaussians\": [{\"amplitude\": 1, \"center\": "
                             "[0, 0, 0], \"sigma\": 1, \"x\": 2}]}";
  EXPECT_EQ(ErrorOf(nested).Place.Text.Offset, static_cast<int>(nested.find("\"x\"")));
  EXPECT_FALSE(LocateKey(nested, "metric", "n").Known);
}

TEST(JsonErrorPlace, ErrorsAboutTheWholeMetricHaveNoPlace)
{
  const MetricDefinitionError negative = ErrorOf("{\"type\": \"conformal\", \"constant\": -1}");
  EXPECT_EQ(negative.Place.Path, "metric");
  EXPECT_FALSE(negative.Place.Text.Known);
  EXPECT_FALSE(ErrorOf("{\"f\": \"x\"}").Place.Text.Known); // missing "type"
  try
  {
    LoadMetricDefinitionFile("/no/such.json");
    ADD_FAILURE();
  }
  catch (const MetricDefinitionError& e)
  {
    EXPECT_FALSE(e.Place.Text.Known);
    EXPECT_EQ(e.Place.Path, "");
  }
}

TEST(JsonErrorPlace, PathsOfTextThatNoLongerParsesAreUnknown)
{
  EXPECT_FALSE(Locate("{\"f\": \"x + q\"", "metric.f", 5).Known);
  EXPECT_FALSE(Locate("[\"x\"]", "metric.f", 1).Known);
}

TEST(JsonErrorPlace, AFileNamePrefixKeepsThePlace)
{
  const std::string file = ::testing::TempDir() + "metric.json";
  const std::string text = "{\"type\": \"graph\", \"f\": \"x + q\"}";
  std::ofstream(file, std::ios::binary) << text;
  try
  {
    LoadMetricDefinitionFile(file);
    ADD_FAILURE();
  }
  catch (const MetricDefinitionError& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind(file + ": metric.f: column 5: ", 0), 0u) << e.what();
    EXPECT_EQ(e.Place.Text.Offset, static_cast<int>(text.find('q')));
  }
  std::remove(file.c_str());
}

TEST(JsonErrorPlace, CameraPathFilesAreLocatedToo)
{
  const std::string text = "{\n  \"path\": \"spline\",\n  \"keys\": [[0, 0, 5], [0, 0]]\n}";
  try
  {
    ParseCameraPathFile(text, "fly.json");
    ADD_FAILURE();
  }
  catch (const CameraPathFileError& e)
  {
    EXPECT_EQ(e.Place.Pointer, "/keys/1");
    ExpectAt(e.Place.Text, 3, 23, static_cast<int>(text.find("[0, 0]]")));
  }
}

// --- every path of many texts, against nlohmann --------------------------------

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

/// Line and column as an editor counts them, for the place's offset.
void ExpectConsistent(const std::string& text, const TextPlace& place)
{
  ASSERT_TRUE(place.Known);
  ASSERT_GE(place.Offset, 0);
  ASSERT_LE(place.Offset, static_cast<int>(text.size()));
  int line = 1;
  int column = 1;
  for (int i = 0; i < place.Offset; ++i)
  {
    const bool newline = text[i] == '\n';
    line += newline ? 1 : 0;
    column = newline ? 1 : column + ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80);
  }
  EXPECT_EQ(place.Line, line);
  EXPECT_EQ(place.Column, column);
}

int Characters(const std::string& text)
{
  return static_cast<int>(std::count_if(
    text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

void ExpectEveryPathLocated(const std::string& text)
{
  std::vector<std::pair<std::string, Json>> paths;
  CollectPaths(Json::parse(text), "metric", paths);
  for (const auto& [path, value] : paths)
  {
    const TextPlace place = Locate(text, path);
    if (path == "metric")
    {
      EXPECT_FALSE(place.Known);
      continue;
    }
    ExpectConsistent(text, place);
    EXPECT_TRUE(ValueStartsAt(text, place.Offset, value)) << path;
    if (value.is_string())
    {
      // Column k is where the first k - 1 characters of the string end.
      const std::string content = value.get<std::string>();
      for (int k = 1; k <= Characters(content); ++k)
      {
        const int at = Locate(text, path, k).Offset;
        const Json before =
          Json::parse(text.substr(place.Offset, at - place.Offset) + "\"", nullptr, false);
        ASSERT_TRUE(before.is_string()) << path << " column " << k;
        const std::string prefix = before.get<std::string>();
        EXPECT_EQ(prefix, content.substr(0, prefix.size())) << path << " column " << k;
        EXPECT_EQ(Characters(prefix), k - 1) << path << " column " << k;
      }
    }
    if (value.is_object())
    {
      for (const auto& item : value.items())
      {
        const TextPlace key = LocateKey(text, path, item.key());
        ExpectConsistent(text, key);
        EXPECT_TRUE(ValueStartsAt(text, key.Offset, Json(item.key()))) << path << " " << item.key();
      }
    }
  }
}

TEST(JsonErrorPlace, EveryPathOfTheShippedMetrics)
{
  for (const char* name : ShippedMetrics)
  {
    SCOPED_TRACE(name);
    ExpectEveryPathLocated(ReadMetric(name));
  }
}

TEST(JsonErrorPlace, EveryPathOfATextFullOfEscapes)
{
  ExpectEveryPathLocated("{\"type\":\"diffeo\",\"compose\":[{\"phi\":[\"\\u00e9 + \\\"x\\\"\",\r\n"
                         "\t\"y\\\\\\/\\b\\f\\n\\r\\t\", \"\\ud83d\\ude00\xc3\xa9z\"], "
                         "\"parameters\" : {\"a\\u002eb\": [1, {\"\": null}], \"k\": true}}]}");
}

// --- never crash ---------------------------------------------------------------

TEST(JsonErrorPlace, RandomTextsAndPlacesNeverCrash)
{
  std::mt19937 random(20240611);
  const std::string alphabet = "{}[]:,\"\\/ \n\t0123456789.eE+-ufntrlsabxyz~\xc3\xa9\x80\xff";
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
  std::uniform_int_distribution<int> small(0, 12);
  for (int i = 0; i < 3000; ++i)
  {
    std::string text(i % 64, ' ');
    for (char& c : text)
    {
      c = alphabet[pick(random)];
    }
    const std::string paths[] = { "metric.gaussians[" + std::to_string(small(random)) + "]",
      "metric.compose[1].phi[0]", "metric.", "metric[", "metric[0", "x.", "" };
    for (const std::string& path : paths)
    {
      const TextPlace place =
        small(random) > 6 ? LocateKey(text, path, "type") : Locate(text, path, small(random));
      if (place.Known)
      {
        ExpectConsistent(text, place);
      }
    }
    const long long syntax = JsonSyntaxErrorOffset(text);
    EXPECT_EQ(syntax < 0, Json::accept(text)) << text;
    EXPECT_LE(syntax, static_cast<long long>(text.size()));
  }
}

TEST(JsonErrorPlace, DeeplyNestedTextIsRefusedNotOverflowed)
{
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  ASSERT_TRUE(Json::accept(deep));
  jsontext::Node root;
  EXPECT_FALSE(jsontext::Scan(deep, root));
  EXPECT_FALSE(Locate(deep, "metric[0][0]").Known);
}
} // namespace
} // namespace riemann
