#include "ExpressionParser.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace riemann
{
const std::vector<ExpressionFunction>& SupportedExpressionFunctions()
{
  static const std::vector<ExpressionFunction> functions = { { "exp", 1 }, { "log", 1 },
    { "sqrt", 1 }, { "sin", 1 }, { "cos", 1 }, { "tan", 1 }, { "sinh", 1 }, { "cosh", 1 },
    { "tanh", 1 }, { "atan2", 2 }, { "abs", 1 }, { "pow", 2 } };
  return functions;
}

namespace
{
const char* const Variables[] = { "x", "y", "z", "t" };
/// Names GiNaC's lexer turns into its constants whatever the symbol table says.
const char* const GinacLiterals[] = { "I", "Pi", "Euler", "Catalan" };

/// Exact powers beyond this many bits could take GiNaC (CLN) very long.
constexpr double MaximumExactBits = 65536.0;
/// Decimal exponents of typed numbers (beyond double's range either way).
constexpr long MaximumDecimalExponent = 400;

const ExpressionFunction* FindFunction(const std::string& name)
{
  for (const ExpressionFunction& f : SupportedExpressionFunctions())
  {
    if (name == f.Name)
    {
      return &f;
    }
  }
  return nullptr;
}

bool IsVariable(const std::string& name)
{
  for (const char* v : Variables)
  {
    if (name == v)
    {
      return true;
    }
  }
  return false;
}

bool IsGinacLiteral(const std::string& name)
{
  for (const char* v : GinacLiterals)
  {
    if (name == v)
    {
      return true;
    }
  }
  return false;
}

std::string FunctionList()
{
  std::string list;
  for (const ExpressionFunction& f : SupportedExpressionFunctions())
  {
    list += std::string(list.empty() ? "" : ", ") + f.Name;
  }
  return list;
}

std::string Lower(std::string s)
{
  for (char& c : s)
  {
    if (c >= 'A' && c <= 'Z')
    {
      c = static_cast<char>(c - 'A' + 'a');
    }
  }
  return s;
}

bool IsAlpha(char c)
{
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

bool IsDigit(char c)
{
  return c >= '0' && c <= '9';
}

bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

enum class Tok
{
  Number,
  Name,
  Plus,
  Minus,
  Star,
  Slash,
  Caret,
  Open,
  Close,
  Comma,
  End
};

struct Token
{
  Tok Kind;
  std::size_t Begin;
  std::size_t End;
};

enum class Kind
{
  Number,
  Name,
  Negate,
  Sum,
  Product,
  Power,
  Call
};

struct Node
{
  Kind Type;
  std::size_t Begin = 0;
  std::size_t End = 0;
  /// Number: the exact rational text; Name, Call: the name.
  std::string Text;
  std::vector<int> Children;
  /// Sum: '+' or '-' before each child (the first one '+'); Product: '*' or '/'.
  std::vector<char> Operators;
  /// Offsets of those operators (for messages).
  std::vector<std::size_t> OperatorOffsets;
  bool IsConstant = false;
  double Value = 0.0;
  /// Upper bound on the bits of the exact number GiNaC may compute for this
  /// node (symbols count as small numbers: x - x + 9 is 9).
  double Bits = 1.0;
};

class Parser
{
public:
  Parser(const std::string& text, const std::vector<std::string>& parameters)
    : Text(text)
    , Parameters(parameters)
  {
  }

  std::string Run()
  {
    if (this->Text.size() > MaximumExpressionLength)
    {
      throw ExpressionError(0,
        "the expression is " + std::to_string(this->Text.size()) + " characters long; at most " +
          std::to_string(MaximumExpressionLength) + " are accepted");
    }
    this->Tokenize();
    if (this->Tokens.size() == 1)
    {
      throw ExpressionError(0, "the expression is empty");
    }
    const int root = this->ParseSum();
    const Token& next = this->Peek();
    if (next.Kind != Tok::End)
    {
      this->FailAfterOperand(next);
    }
    std::string out;
    this->Print(root, out);
    return out;
  }

private:
  const std::string& Text;
  const std::vector<std::string>& Parameters;
  std::vector<Token> Tokens;
  std::size_t Position = 0;
  std::vector<Node> Nodes;
  int Depth = 0;

  // --- positions and messages ------------------------------------------------
  int Column(std::size_t offset) const
  {
    int column = 1;
    for (std::size_t i = 0; i < offset && i < this->Text.size(); ++i)
    {
      // UTF-8 continuation bytes do not start a character.
      if ((static_cast<unsigned char>(this->Text[i]) & 0xC0) != 0x80)
      {
        ++column;
      }
    }
    return column;
  }

  [[noreturn]] void Fail(std::size_t offset, const std::string& cause) const
  {
    throw ExpressionError(this->Column(offset), cause);
  }

  std::string Spelling(const Token& token) const
  {
    if (token.Kind == Tok::End)
    {
      return "the end of the expression";
    }
    return "\"" + this->Text.substr(token.Begin, token.End - token.Begin) + "\"";
  }

  std::string Quote(const Node& node) const
  {
    std::string s = this->Text.substr(node.Begin, node.End - node.Begin);
    if (s.size() > 60)
    {
      s = s.substr(0, 57) + "...";
    }
    return "\"" + s + "\"";
  }

  std::string AllowedNames() const
  {
    std::string s = "x, y, z, t, pi";
    if (this->Parameters.empty())
    {
      return s + " (no parameters are defined)";
    }
    s += " and the parameters ";
    for (std::size_t i = 0; i < this->Parameters.size(); ++i)
    {
      s += (i ? ", " : "") + this->Parameters[i];
    }
    return s;
  }

  // --- tokens ----------------------------------------------------------------
  void Tokenize()
  {
    const std::string& s = this->Text;
    std::size_t i = 0;
    while (true)
    {
      while (i < s.size() && IsSpace(s[i]))
      {
        ++i;
      }
      if (i == s.size())
      {
        this->Tokens.push_back({ Tok::End, i, i });
        return;
      }
      const std::size_t begin = i;
      const char c = s[i];
      if (IsDigit(c) || c == '.')
      {
        while (i < s.size() && (IsDigit(s[i]) || s[i] == '.'))
        {
          ++i;
        }
        if (i < s.size() && (s[i] == 'e' || s[i] == 'E'))
        {
          std::size_t j = i + 1;
          if (j < s.size() && (s[j] == '+' || s[j] == '-'))
          {
            ++j;
          }
          if (j < s.size() && IsDigit(s[j]))
          {
            while (j < s.size() && IsDigit(s[j]))
            {
              ++j;
            }
            i = j;
          }
          else if (j == i + 1 && j < s.size() && (IsAlpha(s[j]) || IsDigit(s[j]) || s[j] == '_'))
          {
            // "2ex", "2exp(x)": the number ends before the "e" (and a
            // missing operator is reported next).
          }
          else
          {
            this->Fail(begin,
              "malformed number \"" + s.substr(begin, j - begin) +
                "\" (an exponent needs digits, e.g. 1e-3)");
          }
        }
        this->Tokens.push_back({ Tok::Number, begin, i });
        continue;
      }
      if (IsAlpha(c) || c == '_')
      {
        while (i < s.size() && (IsAlpha(s[i]) || IsDigit(s[i]) || s[i] == '_'))
        {
          ++i;
        }
        this->Tokens.push_back({ Tok::Name, begin, i });
        continue;
      }
      Tok kind = Tok::End;
      switch (c)
      {
        case '+':
          kind = Tok::Plus;
          break;
        case '-':
          kind = Tok::Minus;
          break;
        case '*':
          kind = Tok::Star;
          break;
        case '/':
          kind = Tok::Slash;
          break;
        case '^':
          kind = Tok::Caret;
          break;
        case '(':
          kind = Tok::Open;
          break;
        case ')':
          kind = Tok::Close;
          break;
        case ',':
          kind = Tok::Comma;
          break;
        default:
          this->FailCharacter(begin);
      }
      this->Tokens.push_back({ kind, begin, begin + 1 });
      ++i;
    }
  }

  [[noreturn]] void FailCharacter(std::size_t offset) const
  {
    const unsigned char c = static_cast<unsigned char>(this->Text[offset]);
    std::string shown;
    if (c >= 0x80)
    {
      std::size_t end = offset + 1;
      while (end < this->Text.size() &&
        (static_cast<unsigned char>(this->Text[end]) & 0xC0) == 0x80 && end - offset < 4)
      {
        ++end;
      }
      shown = "\"" + this->Text.substr(offset, end - offset) + "\"";
    }
    else if (c < 0x20 || c == 0x7F)
    {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\x%02X", static_cast<unsigned>(c));
      shown = buffer;
    }
    else
    {
      shown = std::string("\"") + static_cast<char>(c) + "\"";
    }
    std::string hint;
    switch (c)
    {
      case '[':
      case ']':
      case '{':
      case '}':
        hint = " (group with parentheses)";
        break;
      case '=':
      case '<':
      case '>':
        hint = " (an expression is a formula, not an equation)";
        break;
      case '!':
        hint = " (factorials are not supported)";
        break;
      case '#':
        hint = " (comments are not supported)";
        break;
      default:
        break;
    }
    this->Fail(offset, "unexpected character " + shown + hint);
  }

  const Token& Peek() const { return this->Tokens[this->Position]; }
  const Token& Previous() const { return this->Tokens[this->Position - 1]; }
  const Token& Take() { return this->Tokens[this->Position++]; }

  /// An operand was complete but `next` cannot follow it.
  [[noreturn]] void FailAfterOperand(const Token& next) const
  {
    const Token& last = this->Previous();
    switch (next.Kind)
    {
      case Tok::Close:
        this->Fail(next.Begin, "unmatched \")\"");
      case Tok::Comma:
        this->Fail(next.Begin, "unexpected \",\" outside the arguments of a function");
      case Tok::Open:
        if (last.Kind == Tok::Name)
        {
          const std::string name = this->Text.substr(last.Begin, last.End - last.Begin);
          this->Fail(
            last.Begin, "\"" + name + "\" is not a function; write " + name + "*(...) to multiply");
        }
        this->Fail(next.Begin, "missing operator before \"(\" (write * to multiply)");
      case Tok::Number:
      case Tok::Name:
        this->Fail(next.Begin,
          "missing operator between " + this->Spelling(last) + " and " + this->Spelling(next) +
            " (write * to multiply)");
      default:
        this->Fail(next.Begin, "unexpected " + this->Spelling(next));
    }
  }

  // --- grammar ---------------------------------------------------------------
  int Add(Node node)
  {
    this->Nodes.push_back(std::move(node));
    return static_cast<int>(this->Nodes.size()) - 1;
  }

  int ParseSum()
  {
    const int first = this->ParseProduct();
    if (this->Peek().Kind != Tok::Plus && this->Peek().Kind != Tok::Minus)
    {
      return first;
    }
    Node sum;
    sum.Type = Kind::Sum;
    sum.Children.push_back(first);
    sum.Operators.push_back('+');
    sum.OperatorOffsets.push_back(this->Nodes[first].Begin);
    while (this->Peek().Kind == Tok::Plus || this->Peek().Kind == Tok::Minus)
    {
      const Token& op = this->Take();
      sum.Operators.push_back(op.Kind == Tok::Plus ? '+' : '-');
      sum.OperatorOffsets.push_back(op.Begin);
      sum.Children.push_back(this->ParseProduct());
    }
    return this->Finish(std::move(sum));
  }

  int ParseProduct()
  {
    const int first = this->ParseUnary();
    if (this->Peek().Kind != Tok::Star && this->Peek().Kind != Tok::Slash)
    {
      return first;
    }
    Node product;
    product.Type = Kind::Product;
    product.Children.push_back(first);
    product.Operators.push_back('*');
    product.OperatorOffsets.push_back(this->Nodes[first].Begin);
    while (this->Peek().Kind == Tok::Star || this->Peek().Kind == Tok::Slash)
    {
      const Token& op = this->Take();
      if (op.Kind == Tok::Star && this->Peek().Kind == Tok::Star)
      {
        this->Fail(this->Peek().Begin, "unexpected \"*\" (write ^ for powers: x^2)");
      }
      product.Operators.push_back(op.Kind == Tok::Star ? '*' : '/');
      product.OperatorOffsets.push_back(op.Begin);
      product.Children.push_back(this->ParseUnary());
    }
    return this->Finish(std::move(product));
  }

  int ParseUnary()
  {
    const Token& token = this->Peek();
    if (++this->Depth > MaximumExpressionNesting)
    {
      this->Fail(token.Begin,
        "nested deeper than " + std::to_string(MaximumExpressionNesting) +
          " levels (parentheses, function calls, signs and exponents together)");
    }
    int result;
    if (token.Kind == Tok::Plus || token.Kind == Tok::Minus)
    {
      const Token op = this->Take();
      const int operand = this->ParseUnary();
      if (op.Kind == Tok::Plus)
      {
        result = operand;
        this->Nodes[result].Begin = op.Begin;
      }
      else
      {
        Node negate;
        negate.Type = Kind::Negate;
        negate.Children.push_back(operand);
        negate.Begin = op.Begin;
        result = this->Finish(std::move(negate));
      }
    }
    else
    {
      result = this->ParsePower();
    }
    --this->Depth;
    return result;
  }

  int ParsePower()
  {
    const int base = this->ParsePrimary();
    if (this->Peek().Kind != Tok::Caret)
    {
      return base;
    }
    const Token& op = this->Take();
    Node power;
    power.Type = Kind::Power;
    power.Children = { base, this->ParseUnary() };
    power.OperatorOffsets = { op.Begin };
    return this->Finish(std::move(power));
  }

  [[noreturn]] void FailOperandExpected(const Token& token) const
  {
    if (token.Kind == Tok::End)
    {
      const Token& last = this->Previous();
      if (last.Kind == Tok::Open)
      {
        this->Fail(last.Begin, "\"(\" is not closed");
      }
      this->Fail(last.Begin, "the expression ends after " + this->Spelling(last));
    }
    std::string after;
    if (this->Position > 0)
    {
      after = " after " + this->Spelling(this->Previous());
    }
    this->Fail(token.Begin,
      "expected a number, a name, a function or \"(\"" + after + ", found " +
        this->Spelling(token));
  }

  int ParsePrimary()
  {
    const Token token = this->Take();
    switch (token.Kind)
    {
      case Tok::Number:
        return this->Number(token);
      case Tok::Name:
        return this->Name(token);
      case Tok::Open:
      {
        const int inner = this->ParseSum();
        const Token& close = this->Peek();
        if (close.Kind == Tok::End)
        {
          this->Fail(token.Begin, "\"(\" is not closed");
        }
        if (close.Kind != Tok::Close)
        {
          this->FailAfterOperand(close);
        }
        this->Take();
        // Parentheses only group: the node keeps its own kind.
        this->Nodes[inner].Begin = token.Begin;
        this->Nodes[inner].End = close.End;
        return inner;
      }
      default:
        --this->Position; // report the token itself
        this->FailOperandExpected(token);
    }
  }

  int Number(const Token& token)
  {
    const std::string literal = this->Text.substr(token.Begin, token.End - token.Begin);
    // The literal in quotes, as messages show it: a 310-digit number is not repeated whole.
    const std::string quoted = literal.size() <= 40
      ? "\"" + literal + "\""
      : "\"" + literal.substr(0, 40) + "...\" (" + std::to_string(literal.size()) + " characters)";
    // digits [. digits] [e [+-] digits], or . digits [...]; one dot at most.
    std::string mantissa;
    long fraction = 0;
    bool dot = false;
    bool digits = false;
    std::size_t i = 0;
    for (; i < literal.size() && literal[i] != 'e' && literal[i] != 'E'; ++i)
    {
      if (literal[i] == '.')
      {
        if (dot)
        {
          this->Fail(token.Begin, "malformed number " + quoted + " (more than one \".\")");
        }
        dot = true;
        continue;
      }
      digits = true;
      mantissa += literal[i];
      fraction += dot ? 1 : 0;
    }
    if (!digits)
    {
      this->Fail(token.Begin, "malformed number " + quoted);
    }
    long exponent = 0;
    if (i < literal.size())
    {
      std::size_t j = i + 1;
      const bool negative = literal[j] == '-';
      if (literal[j] == '+' || literal[j] == '-')
      {
        ++j;
      }
      for (; j < literal.size(); ++j)
      {
        exponent = exponent * 10 + (literal[j] - '0');
        if (exponent > MaximumDecimalExponent)
        {
          this->Fail(token.Begin, "number " + quoted + " out of range");
        }
      }
      exponent = negative ? -exponent : exponent;
    }
    Node node;
    node.Type = Kind::Number;
    node.Begin = token.Begin;
    node.End = token.End;
    node.IsConstant = true;
    double value = 0.0;
    const auto parsed = std::from_chars(literal.data(), literal.data() + literal.size(), value);
    if (parsed.ec == std::errc::result_out_of_range)
    {
      // Tiny numbers become 0 in double precision; huge ones are refused.
      // Which one by the place of the first nonzero digit, not by the sign
      // of the written exponent: "1" and 309 zeros has none, and was taken
      // for tiny (then raised 0.5 to it exactly, forever).
      const std::size_t leadingZeros = std::min(mantissa.find_first_not_of('0'), mantissa.size());
      const long integerDigits = static_cast<long>(mantissa.size()) - fraction -
        static_cast<long>(leadingZeros);
      if (integerDigits + exponent > 0)
      {
        this->Fail(token.Begin, "number " + quoted + " too large");
      }
      value = 0.0;
    }
    else if (parsed.ec != std::errc() || !std::isfinite(value))
    {
      this->Fail(token.Begin, "number " + quoted + " out of range");
    }
    node.Value = value;
    // Exact rational text: mantissa * 10^(exponent - fraction).
    mantissa.erase(0, std::min(mantissa.find_first_not_of('0'), mantissa.size() - 1));
    const long scale = exponent - fraction;
    if (scale >= 0 || mantissa == "0")
    {
      node.Text = mantissa == "0"
        ? "0"
        : mantissa + std::string(static_cast<std::size_t>(std::max(0L, scale)), '0');
    }
    else
    {
      node.Text = "(" + mantissa + "/1" + std::string(static_cast<std::size_t>(-scale), '0') + ")";
    }
    // log2 of numerator and denominator.
    node.Bits = 1.0 + 3.33 * static_cast<double>(mantissa.size() + std::abs(scale));
    return this->Add(std::move(node));
  }

  // A name: a symbol (Symbol) or a function call (Call), each refused with a
  // hint where it is not allowed.
  int Name(const Token& token)
  {
    const std::string name = this->Text.substr(token.Begin, token.End - token.Begin);
    const bool call = this->Peek().Kind == Tok::Open;
    const bool known = IsVariable(name) || name == "pi" ||
      std::find(this->Parameters.begin(), this->Parameters.end(), name) != this->Parameters.end();
    const ExpressionFunction* function = FindFunction(name);
    if (!call)
    {
      return this->Symbol(token, name, function, known);
    }
    if (!function)
    {
      this->FailUnknownFunction(token, name, known);
    }
    return this->Call(token, name, *function);
  }

  /// A variable, a parameter or pi (a constant), not followed by "(".
  int Symbol(
    const Token& token, const std::string& name, const ExpressionFunction* function, bool known)
  {
    if (function)
    {
      this->Fail(token.Begin,
        "\"" + name + "\" is a function; write " + name + "(" +
          (function->Arguments == 2 ? "a, b" : "...") + ")");
    }
    if (!known)
    {
      std::string hint;
      if (name != Lower(name) &&
        (IsVariable(Lower(name)) || Lower(name) == "pi" ||
          std::find(this->Parameters.begin(), this->Parameters.end(), Lower(name)) !=
            this->Parameters.end()))
      {
        hint = " (names are case-sensitive: \"" + Lower(name) + "\")";
      }
      else if (name == "e")
      {
        hint = " (write exp(...) for the exponential)";
      }
      this->Fail(
        token.Begin, "unknown symbol \"" + name + "\"; allowed: " + this->AllowedNames() + hint);
    }
    Node node;
    node.Type = Kind::Name;
    node.Begin = token.Begin;
    node.End = token.End;
    node.Text = name;
    if (name == "pi")
    {
      node.IsConstant = true;
      node.Value = 3.14159265358979323846;
      node.Bits = 2.0;
    }
    return this->Add(std::move(node));
  }

  /// A name followed by "(" that is no function: a symbol used as one, or a
  /// misspelt function (with a hint).
  [[noreturn]] void FailUnknownFunction(
    const Token& token, const std::string& name, bool known) const
  {
    if (known)
    {
      this->Fail(
        token.Begin, "\"" + name + "\" is not a function; write " + name + "*(...) to multiply");
    }
    std::string hint;
    if (FindFunction(Lower(name)))
    {
      hint = " (names are case-sensitive: \"" + Lower(name) + "\")";
    }
    else if (name == "ln")
    {
      hint = " (the natural logarithm is log)";
    }
    else if (name == "arctan2" || name == "atan")
    {
      hint = " (use atan2(y, x))";
    }
    this->Fail(
      token.Begin, "unknown function \"" + name + "\"; supported: " + FunctionList() + hint);
  }

  /// A call of `function`: its arguments, sum (',' sum)*, counted against
  /// the function's.
  int Call(const Token& token, const std::string& name, const ExpressionFunction& function)
  {
    const Token open = this->Take();
    Node node;
    node.Type = Kind::Call;
    node.Begin = token.Begin;
    node.Text = name;
    if (this->Peek().Kind != Tok::Close)
    {
      if (++this->Depth > MaximumExpressionNesting)
      {
        this->Fail(open.Begin,
          "nested deeper than " + std::to_string(MaximumExpressionNesting) +
            " levels (parentheses, function calls, signs and exponents together)");
      }
      while (true)
      {
        node.Children.push_back(this->ParseSum());
        const Token& next = this->Peek();
        if (next.Kind == Tok::Close)
        {
          break;
        }
        if (next.Kind == Tok::Comma)
        {
          this->Take();
          continue;
        }
        if (next.Kind == Tok::End)
        {
          this->Fail(open.Begin, "\"(\" of " + name + "(...) is not closed");
        }
        this->FailAfterOperand(next);
      }
      --this->Depth;
    }
    const Token& close = this->Take();
    node.End = close.End;
    const int count = static_cast<int>(node.Children.size());
    if (count != function.Arguments)
    {
      std::string usage = function.Arguments == 1 ? "1 argument" : "2 arguments";
      if (name == "atan2")
      {
        usage += " (y, x)";
      }
      else if (name == "pow")
      {
        usage += " (base, exponent)";
      }
      this->Fail(token.Begin, name + " takes " + usage + ", got " + std::to_string(count));
    }
    return this->Finish(std::move(node));
  }

  // --- constant folding and size bounds ---------------------------------------
  /// Set Begin/End, constant value and bit bound; refuse what GiNaC cannot take.
  int Finish(Node node)
  {
    if (node.Type != Kind::Negate && node.Type != Kind::Call)
    {
      node.Begin = this->Nodes[node.Children.front()].Begin;
    }
    if (node.Type != Kind::Call)
    {
      node.End = this->Nodes[node.Children.back()].End;
    }
    bool constant = true;
    for (int c : node.Children)
    {
      constant = constant && this->Nodes[c].IsConstant;
    }
    auto value = [this](int child) { return this->Nodes[child].Value; };
    auto bits = [this](int child) { return this->Nodes[child].Bits; };
    double result = 0.0;
    switch (node.Type)
    {
      case Kind::Negate:
        result = -value(node.Children[0]);
        node.Bits = bits(node.Children[0]);
        break;
      case Kind::Sum:
        node.Bits = 0.0;
        for (std::size_t i = 0; i < node.Children.size(); ++i)
        {
          const int c = node.Children[i];
          result += node.Operators[i] == '+' ? value(c) : -value(c);
          node.Bits += bits(c) + 1.0;
        }
        break;
      case Kind::Product:
        result = 1.0;
        node.Bits = 0.0;
        for (std::size_t i = 0; i < node.Children.size(); ++i)
        {
          const int c = node.Children[i];
          if (node.Operators[i] == '/')
          {
            if (this->Nodes[c].IsConstant && value(c) == 0.0)
            {
              this->Fail(node.OperatorOffsets[i], "division by zero");
            }
            result /= value(c);
          }
          else
          {
            result *= value(c);
          }
          node.Bits += bits(c);
        }
        break;
      case Kind::Power:
        result =
          this->CheckPower(node, node.Children[0], node.Children[1], node.OperatorOffsets[0]);
        break;
      case Kind::Call:
        result = this->CheckCall(node);
        break;
      default:
        break;
    }
    node.IsConstant = constant;
    if (constant)
    {
      node.Value = result;
      if (std::isnan(result))
      {
        this->Fail(node.Begin, this->Quote(node) + " is not a real number");
      }
      if (std::isinf(result))
      {
        this->Fail(node.Begin, this->Quote(node) + " is infinite or too large");
      }
    }
    node.Bits = std::min(node.Bits, MaximumExactBits);
    return this->Add(std::move(node));
  }

  double CheckPower(Node& node, int base, int exponent, std::size_t opOffset)
  {
    const Node& b = this->Nodes[base];
    const Node& e = this->Nodes[exponent];
    if (b.IsConstant && b.Value == 0.0 && e.IsConstant)
    {
      if (e.Value == 0.0)
      {
        this->Fail(opOffset, "0^0 is undefined");
      }
      if (e.Value < 0.0)
      {
        this->Fail(opOffset, "division by zero (0 to a negative power)");
      }
    }
    // GiNaC computes integer powers of exact numbers exactly: bound the bits
    // (a symbolic exponent may still simplify to a number: x - x + 9).
    const double magnitude =
      e.IsConstant ? std::fabs(e.Value) : std::ldexp(1.0, static_cast<int>(std::min(e.Bits, 60.0)));
    const double bits = b.Bits * std::max(1.0, magnitude);
    // Not "bits > limit": a 310-digit exponent is infinite as a double, and a
    // base of 0 bits times it is NaN, which compares false with anything
    // (GiNaC then raised 1/2 to it exactly, forever).
    if (!(bits <= MaximumExactBits) || !std::isfinite(magnitude))
    {
      this->Fail(opOffset,
        "power too large in " + this->Quote(node) + " (exact powers are limited to " +
          std::to_string(static_cast<long>(MaximumExactBits)) + " bits)");
    }
    node.Bits = bits;
    return std::pow(b.Value, e.Value);
  }

  double CheckCall(Node& node)
  {
    const std::string& f = node.Text;
    const int a = node.Children[0];
    const double u = this->Nodes[a].Value;
    node.Bits = this->Nodes[a].Bits;
    if (f == "pow")
    {
      return this->CheckPower(node, a, node.Children[1], node.Begin);
    }
    if (f == "atan2")
    {
      const int b = node.Children[1];
      node.Bits += this->Nodes[b].Bits;
      if (this->Nodes[a].IsConstant && this->Nodes[b].IsConstant && u == 0.0 &&
        this->Nodes[b].Value == 0.0)
      {
        this->Fail(node.Begin, "atan2(0, 0) is undefined");
      }
      return std::atan2(u, this->Nodes[b].Value);
    }
    if (f == "log" && this->Nodes[a].IsConstant && u == 0.0)
    {
      this->Fail(node.Begin, this->Quote(node) + " is infinite (log(0))");
    }
    if (f == "exp")
    {
      return std::exp(u);
    }
    if (f == "log")
    {
      return std::log(u);
    }
    if (f == "sqrt")
    {
      return std::sqrt(u);
    }
    if (f == "sin")
    {
      return std::sin(u);
    }
    if (f == "cos")
    {
      return std::cos(u);
    }
    if (f == "tan")
    {
      return std::tan(u);
    }
    if (f == "sinh")
    {
      return std::sinh(u);
    }
    if (f == "cosh")
    {
      return std::cosh(u);
    }
    if (f == "tanh")
    {
      return std::tanh(u);
    }
    return std::fabs(u); // abs
  }

  // --- output for GiNaC --------------------------------------------------------
  /// Append node `i` as a primary (an atom or a parenthesised expression).
  void Print(int i, std::string& out) const
  {
    const Node& node = this->Nodes[i];
    switch (node.Type)
    {
      case Kind::Number:
      case Kind::Name:
        out += node.Text;
        return;
      case Kind::Negate:
        out += "(-";
        this->Print(node.Children[0], out);
        out += ")";
        return;
      case Kind::Sum:
      case Kind::Product:
        out += "(";
        for (std::size_t k = 0; k < node.Children.size(); ++k)
        {
          if (k > 0)
          {
            out += node.Operators[k];
          }
          this->Print(node.Children[k], out);
        }
        out += ")";
        return;
      case Kind::Power:
        out += "(";
        this->Print(node.Children[0], out);
        out += "^";
        this->Print(node.Children[1], out);
        out += ")";
        return;
      case Kind::Call:
        out += node.Text + "(";
        for (std::size_t k = 0; k < node.Children.size(); ++k)
        {
          if (k > 0)
          {
            out += ",";
          }
          this->Print(node.Children[k], out);
        }
        out += ")";
        return;
    }
  }
};
} // namespace

void CheckExpressionParameterNames(const std::vector<std::string>& parameterNames)
{
  if (parameterNames.size() > MaximumExpressionParameters)
  {
    throw ExpressionError(0,
      std::to_string(parameterNames.size()) + " parameters; at most " +
        std::to_string(MaximumExpressionParameters) + " are accepted");
  }
  for (std::size_t q = 0; q < parameterNames.size(); ++q)
  {
    const std::string& name = parameterNames[q];
    const int index = static_cast<int>(q);
    auto fail = [&](const std::string& cause) { throw ExpressionError(0, cause, -1, index); };
    bool identifier = !name.empty() && name.size() <= 64 && IsAlpha(name[0]);
    for (char c : name)
    {
      identifier = identifier && (IsAlpha(c) || IsDigit(c) || c == '_');
    }
    if (!identifier)
    {
      fail("parameter name \"" + name +
        "\" is not a name (a letter, then letters, digits or _; at most 64 characters)");
    }
    if (IsVariable(name))
    {
      fail("parameter name \"" + name + "\" is a variable (x, y, z, t); choose another name");
    }
    if (name == "pi")
    {
      fail("parameter name \"pi\" is the constant pi; choose another name");
    }
    if (FindFunction(name))
    {
      fail("parameter name \"" + name + "\" is a function; choose another name");
    }
    if (IsGinacLiteral(name))
    {
      fail(
        "parameter name \"" + name + "\" is reserved (I, Pi, Euler, Catalan); choose another name");
    }
    for (std::size_t r = 0; r < q; ++r)
    {
      if (parameterNames[r] == name)
      {
        fail("parameter \"" + name + "\" is defined twice");
      }
    }
  }
}

std::string CheckExpressionSyntax(
  const std::string& text, const std::vector<std::string>& parameterNames)
{
  return Parser(text, parameterNames).Run();
}
} // namespace riemann
