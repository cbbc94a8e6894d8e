// Every way a typed expression can be refused, with the message a person
// reads and the column it points at. The printed table is part of the
// expression issue's note.
#include "Expression.h"
#include "ExpressionParser.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace riemann
{
namespace
{
struct Case
{
  const char* Source;
  const char* Message; // what(), exactly
  int Column;
};

const Case Cases[] = {
  // Syntax.
  { "", "the expression is empty", 0 },
  { "   ", "the expression is empty", 0 },
  { "x +* y", "column 4: expected a number, a name, a function or \"(\" after \"+\", found \"*\"",
    4 },
  { "x**2", "column 3: unexpected \"*\" (write ^ for powers: x^2)", 3 },
  { "x + ", "column 3: the expression ends after \"+\"", 3 },
  { "2*(x + y", "column 3: \"(\" is not closed", 3 },
  { "sin(x", "column 4: \"(\" of sin(...) is not closed", 4 },
  { "x + y)", "column 6: unmatched \")\"", 6 },
  { "()", "column 2: expected a number, a name, a function or \"(\" after \"(\", found \")\"", 2 },
  { "3x", "column 2: missing operator between \"3\" and \"x\" (write * to multiply)", 2 },
  { "x y", "column 3: missing operator between \"x\" and \"y\" (write * to multiply)", 3 },
  { "2(x+1)", "column 2: missing operator before \"(\" (write * to multiply)", 2 },
  { "x, y", "column 2: unexpected \",\" outside the arguments of a function", 2 },
  { "x # comment", "column 3: unexpected character \"#\" (comments are not supported)", 3 },
  { "[x]", "column 1: unexpected character \"[\" (group with parentheses)", 1 },
  { "x = 1", "column 3: unexpected character \"=\" (an expression is a formula, not an equation)",
    3 },
  { "x!", "column 2: unexpected character \"!\" (factorials are not supported)", 2 },
  { "\xc3\xa9 + x", "column 1: unexpected character \"\xc3\xa9\"", 1 },
  { "\xc3\xa9 + $", "column 1: unexpected character \"\xc3\xa9\"", 1 },
  { "x\t+ \x01", "column 5: unexpected character \\x01", 5 },
  // Numbers.
  { "1.2.3*x", "column 1: malformed number \"1.2.3\" (more than one \".\")", 1 },
  { "2e*x", "column 1: malformed number \"2e\" (an exponent needs digits, e.g. 1e-3)", 1 },
  { "1e+x", "column 1: malformed number \"1e+\" (an exponent needs digits, e.g. 1e-3)", 1 },
  { "x + 1e999", "column 5: number \"1e999\" out of range", 5 },
  { "x + 1e400", "column 5: number \"1e400\" too large", 5 },
  // Names.
  { "foo + x", "column 1: unknown symbol \"foo\"; allowed: x, y, z, t, pi and the parameters a, b",
    1 },
  { "X^2",
    "column 1: unknown symbol \"X\"; allowed: x, y, z, t, pi and the parameters a, b "
    "(names are case-sensitive: \"x\")",
    1 },
  { "Pi*x",
    "column 1: unknown symbol \"Pi\"; allowed: x, y, z, t, pi and the parameters a, b "
    "(names are case-sensitive: \"pi\")",
    1 },
  { "I*x", "column 1: unknown symbol \"I\"; allowed: x, y, z, t, pi and the parameters a, b", 1 },
  { "e^x",
    "column 1: unknown symbol \"e\"; allowed: x, y, z, t, pi and the parameters a, b "
    "(write exp(...) for the exponential)",
    1 },
  { "2*sin", "column 3: \"sin\" is a function; write sin(...)", 3 },
  { "atan2 + 1", "column 1: \"atan2\" is a function; write atan2(a, b)", 1 },
  { "a(x + 1)", "column 1: \"a\" is not a function; write a*(...) to multiply", 1 },
  { "foo(x)",
    "column 1: unknown function \"foo\"; supported: exp, log, sqrt, sin, cos, tan, "
    "sinh, cosh, tanh, atan2, abs, pow",
    1 },
  { "1 + Exp(x)",
    "column 5: unknown function \"Exp\"; supported: exp, log, sqrt, sin, cos, tan, "
    "sinh, cosh, tanh, atan2, abs, pow (names are case-sensitive: \"exp\")",
    5 },
  { "ln(x)",
    "column 1: unknown function \"ln\"; supported: exp, log, sqrt, sin, cos, tan, sinh, "
    "cosh, tanh, atan2, abs, pow (the natural logarithm is log)",
    1 },
  { "atan(y/x)",
    "column 1: unknown function \"atan\"; supported: exp, log, sqrt, sin, cos, tan, "
    "sinh, cosh, tanh, atan2, abs, pow (use atan2(y, x))",
    1 },
  // Arguments.
  { "sin(x, y)", "column 1: sin takes 1 argument, got 2", 1 },
  { "x + sin()", "column 5: sin takes 1 argument, got 0", 5 },
  { "atan2(y)", "column 1: atan2 takes 2 arguments (y, x), got 1", 1 },
  { "pow(x)", "column 1: pow takes 2 arguments (base, exponent), got 1", 1 },
  { "exp(x,)", "column 7: expected a number, a name, a function or \"(\" after \",\", found \")\"",
    7 },
  // Constants that are not finite real numbers.
  { "x/0", "column 2: division by zero", 2 },
  { "x/(2 - 2)", "column 2: division by zero", 2 },
  { "0^0 + x", "column 2: 0^0 is undefined", 2 },
  { "x + 0^(-1)", "column 6: division by zero (0 to a negative power)", 6 },
  { "log(0) + x", "column 1: \"log(0)\" is infinite (log(0))", 1 },
  { "x + log(-1)", "column 5: \"log(-1)\" is not a real number", 5 },
  { "sqrt(-4)*x", "column 1: \"sqrt(-4)\" is not a real number", 1 },
  { "(-8)^(1/3)*x", "column 1: \"(-8)^(1/3)\" is not a real number", 1 },
  { "x*exp(1000)", "column 3: \"exp(1000)\" is infinite or too large", 3 },
  { "atan2(0, 0) + x", "column 1: atan2(0, 0) is undefined", 1 },
  // Sizes GiNaC must not be asked to compute.
  { "x^100000",
    "column 2: power too large in \"x^100000\" (exact powers are limited to 65536 bits)", 2 },
  { "(x - x + 9)^(9^9)",
    "column 12: power too large in \"(x - x + 9)^(9^9)\" (exact powers are "
    "limited to 65536 bits)",
    12 },
  // What only GiNaC's simplification reveals (no column).
  { "1/(x - x)",
    "the expression is infinite where it simplifies to a constant (division by zero, "
    "log(0), tan(pi/2), ...): power::eval(): division by zero",
    0 },
  { "log(x - x)",
    "the expression is infinite where it simplifies to a constant (division by zero, "
    "log(0), tan(pi/2), ...): log_eval(): log(0)",
    0 },
  { "tan(pi/2) + x",
    "the expression is infinite where it simplifies to a constant (division by "
    "zero, log(0), tan(pi/2), ...): tan_eval(): simple pole",
    0 },
  { "log(x - x - 1)",
    "the expression takes complex values (it simplifies partly to I; e.g. log or "
    "a fractional power of a negative number)",
    0 },
};

std::string Shown(const std::string& source)
{
  std::string s;
  for (unsigned char c : source)
  {
    if (c < 0x20)
    {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\x%02X", static_cast<unsigned>(c));
      s += buffer;
    }
    else
    {
      s += static_cast<char>(c);
    }
  }
  return s;
}

TEST(ExpressionErrors, EveryMistakeHasItsMessageAndColumn)
{
  std::printf("| input | message |\n|---|---|\n");
  for (const Case& c : Cases)
  {
    try
    {
      // The mistake is in the second of three sources: Source says so.
      CompiledExpressions({ "x", c.Source, "y" }, { "a", "b" }, 2);
      ADD_FAILURE() << "accepted: " << c.Source;
    }
    catch (const ExpressionError& e)
    {
      std::printf("| `%s` | %s |\n", Shown(c.Source).c_str(), e.what());
      EXPECT_EQ(std::string(e.what()), c.Message) << c.Source;
      EXPECT_EQ(e.Column, c.Column) << c.Source;
      EXPECT_EQ(e.Source, 1) << c.Source;
      EXPECT_EQ(e.Parameter, -1) << c.Source;
    }
  }
}

TEST(ExpressionErrors, Limits)
{
  EXPECT_NO_THROW(
    CompiledExpressions({ std::string(90, '(') + "x" + std::string(90, ')') }, {}, 3));
  try
  {
    CompiledExpressions({ "x + " + std::string(200, '(') + "x" + std::string(200, ')') }, {}, 1);
    ADD_FAILURE() << "deep nesting accepted";
  }
  catch (const ExpressionError& e)
  {
    EXPECT_EQ(std::string(e.what()),
      "column 105: nested deeper than 100 levels (parentheses, function calls, signs and "
      "exponents together)");
  }
  EXPECT_THROW(CompiledExpressions({ std::string(10000, '-') + "x" }, {}, 0), ExpressionError);
  EXPECT_THROW(
    CompiledExpressions({ "x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^"
                          "x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^"
                          "x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^"
                          "x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x^x" },
      {}, 0),
    ExpressionError);
  try
  {
    CompiledExpressions({ "x + " + std::string(MaximumExpressionLength, ' ') }, {}, 0);
    ADD_FAILURE() << "long text accepted";
  }
  catch (const ExpressionError& e)
  {
    EXPECT_EQ(
      std::string(e.what()), "the expression is 10004 characters long; at most 10000 are accepted");
  }
  // Expression swell: third derivatives of a product of 40 distinct factors.
  std::string product;
  for (int i = 1; i <= 40; ++i)
  {
    product += (i > 1 ? "*sin(x+" : "sin(x+") + std::to_string(i) + "*y*z)";
  }
  try
  {
    CompiledExpressions({ product }, {}, 3);
    ADD_FAILURE() << "expression swell accepted";
  }
  catch (const ExpressionError& e)
  {
    std::printf("| 40-factor product, order 3 | %s |\n", e.what());
    EXPECT_NE(std::string(e.what()).find("too complex"), std::string::npos) << e.what();
  }
  EXPECT_THROW(CompiledExpressions(std::vector<std::string>(17, "x"), {}, 0), ExpressionError);
  EXPECT_THROW(CompiledExpressions(std::vector<std::string>{}, {}, 0), ExpressionError);
  // A huge literal without an exponent ("1" and 309 zeros) was taken for a
  // tiny one, and GiNaC raised 0.5 to it exactly, forever.
  try
  {
    CompiledExpressions({ "0.5^1" + std::string(309, '0') + "*x" }, {}, 1);
    ADD_FAILURE() << "a 310-digit exponent accepted";
  }
  catch (const ExpressionError& e)
  {
    EXPECT_EQ(std::string(e.what()),
      "column 5: number \"1000000000000000000000000000000000000000...\" (310 characters) too "
      "large");
  }
  EXPECT_NO_THROW(CompiledExpressions({ "x*0." + std::string(400, '0') + "1" }, {}, 1))
    << "a tiny literal is 0 in double precision, as before";
}

TEST(ExpressionErrors, ParameterNames)
{
  struct NameCase
  {
    std::vector<std::string> Names;
    int Parameter;
    const char* Message;
  };
  const NameCase cases[] = {
    { { "a", "x" }, 1, "parameter name \"x\" is a variable (x, y, z, t); choose another name" },
    { { "t" }, 0, "parameter name \"t\" is a variable (x, y, z, t); choose another name" },
    { { "sin" }, 0, "parameter name \"sin\" is a function; choose another name" },
    { { "pi" }, 0, "parameter name \"pi\" is the constant pi; choose another name" },
    { { "Pi" }, 0,
      "parameter name \"Pi\" is reserved (I, Pi, Euler, Catalan); choose another name" },
    { { "a", "b", "a" }, 2, "parameter \"a\" is defined twice" },
    { { "2a" }, 0,
      "parameter name \"2a\" is not a name (a letter, then letters, digits or _; at "
      "most 64 characters)" },
    { { "" }, 0,
      "parameter name \"\" is not a name (a letter, then letters, digits or _; at most "
      "64 characters)" },
    { { "a b" }, 0,
      "parameter name \"a b\" is not a name (a letter, then letters, digits or _; at "
      "most 64 characters)" },
    { { "_a" }, 0,
      "parameter name \"_a\" is not a name (a letter, then letters, digits or _; at "
      "most 64 characters)" },
  };
  for (const NameCase& c : cases)
  {
    try
    {
      CompiledExpressions({ "x" }, c.Names, 1);
      ADD_FAILURE() << "accepted parameter " << c.Names.back();
    }
    catch (const ExpressionError& e)
    {
      std::printf(
        "| parameter `%s` | %s |\n", c.Names[static_cast<size_t>(c.Parameter)].c_str(), e.what());
      EXPECT_EQ(std::string(e.what()), c.Message);
      EXPECT_EQ(e.Parameter, c.Parameter);
      EXPECT_EQ(e.Column, 0);
      EXPECT_EQ(e.Source, -1);
    }
  }
  EXPECT_NO_THROW(CompiledExpressions({ "alpha_1*x + Beta2" }, { "alpha_1", "Beta2" }, 1));
  EXPECT_THROW(CompiledExpressions({ "x" }, std::vector<std::string>(65, "p"), 0), ExpressionError);
}

TEST(ExpressionErrors, ValidTextIsReadConventionally)
{
  // Precedence and associativity GiNaC's own parser gets wrong or refuses.
  auto value = [](const std::string& source, double x, double y = 0.0, double z = 0.0)
  {
    const CompiledExpressions c({ source }, {}, 0);
    const double p[3] = { x, y, z };
    double out = 0.0;
    c.Evaluate(p, 0.0, nullptr, &out);
    return out;
  };
  EXPECT_DOUBLE_EQ(value("-x^2", 3), -9);
  EXPECT_DOUBLE_EQ(value("2^3^2", 0), 512);
  EXPECT_DOUBLE_EQ(value("x^-2*y", 2, 3), 0.75);
  EXPECT_DOUBLE_EQ(value("x - -y + z", 1, 2, 3), 6);
  EXPECT_DOUBLE_EQ(value("2*-x + y", 1, 5), 3);
  EXPECT_DOUBLE_EQ(value("x/y/z", 8, 2, 2), 2);
  EXPECT_DOUBLE_EQ(value("x - y - z", 8, 2, 2), 4);
  EXPECT_DOUBLE_EQ(value("+x", 4), 4);
  EXPECT_DOUBLE_EQ(value("--x", 4), 4);
  EXPECT_DOUBLE_EQ(value(".5e1*x + 1.e-1", 1), 5.1);
  EXPECT_DOUBLE_EQ(value("2E2 + 0.25E+1", 0), 202.5);
  EXPECT_DOUBLE_EQ(value("  x\n+\ty  ", 1, 2), 3);
  EXPECT_THROW(value("2exp(x)", 0), ExpressionError) << "a number, then a name";
}
} // namespace
} // namespace riemann
