// The metric editor's text logic (MetricText.h): parameters, rewriting them
// in place, highlighting. Where errors are is the parser's (the core's
// TestJsonErrorPlace.cxx), not the editor's.
#include "MetricText.h"
#include "ShippedMetricTexts.h"

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

using riemann::testing::ShippedMetrics;

std::string ReadMetric(const std::string& name)
{
  return riemann::testing::ReadShippedMetric(std::string(RIEMANN_SOURCE_DIR) + "/Data", name);
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

/// Everything on `text`: no crash, and parameters that apply.
void ExerciseEverything(const std::string& text)
{
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
    ExerciseEverything(text);
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
      ExerciseEverything(text);
    }
  }
}

TEST(NeverCrash, DeeplyNestedTextIsRefusedNotOverflowed)
{
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  ASSERT_TRUE(Json::accept(deep));
  EXPECT_TRUE(FindMetricParameters(deep).empty());
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
