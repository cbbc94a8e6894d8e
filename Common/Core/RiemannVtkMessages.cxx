#include "RiemannVtkMessages.h"

#include <cctype>

namespace riemann
{
namespace
{
bool StartsWith(const std::string& text, const char* start)
{
  return text.compare(0, std::char_traits<char>::length(start), start) == 0;
}
} // namespace

std::string WithoutAnsiEscapes(const std::string& text)
{
  std::string plain;
  plain.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i)
  {
    if (text[i] == '\033' && i + 1 < text.size() && text[i + 1] == '[')
    {
      i += 2;
      while (i < text.size() && !std::isalpha(static_cast<unsigned char>(text[i])))
      {
        ++i;
      }
      continue;
    }
    plain += text[i];
  }
  return plain;
}

std::string PlainVtkMessage(const std::string& message, const char* className)
{
  std::string text = WithoutAnsiEscapes(message);
  // Step 1: the "ERROR: In FILE, line N" (or "Warning: In ...") line.
  for (const char* location : { "ERROR: In ", "Error: In ", "Warning: In ", "WARNING: In " })
  {
    if (StartsWith(text, location))
    {
      const std::size_t newline = text.find('\n');
      text = newline == std::string::npos ? std::string() : text.substr(newline + 1);
      break;
    }
  }
  // Step 2: "vtkClass (0x1234): " -> "vtkClass: ".
  std::string prefix = className ? std::string(className) + ": " : std::string();
  const std::size_t open = text.find(" (0x");
  const std::size_t close = open == std::string::npos ? open : text.find("): ", open);
  if (close != std::string::npos && text.find('\n') > open)
  {
    prefix = text.substr(0, open) + ": ";
    text = text.substr(close + 3);
  }
  // Step 3: one line, no blanks at the ends.
  std::string line;
  for (char c : text)
  {
    line += (c == '\n' || c == '\r' || c == '\t') ? ' ' : c;
  }
  const std::size_t first = line.find_first_not_of(' ');
  const std::size_t last = line.find_last_not_of(' ');
  line = first == std::string::npos ? std::string() : line.substr(first, last - first + 1);
  return line.empty() ? std::string() : prefix + line;
}
} // namespace riemann
