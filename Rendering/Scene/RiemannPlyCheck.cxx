#include "RiemannPlyCheck.h"

#include "InputFiles.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <vector>

namespace riemann
{
namespace
{
/// Text of the file in a message (PrintableFileText): at most 40 characters.
std::string Printable(const std::string& text)
{
  return PrintableFileText(text, 40);
}

/// Printable(text) in quotes.
std::string Quoted(const std::string& text)
{
  return "\"" + Printable(text) + "\"";
}

/// A PLY scalar type: its size in bytes and how its bytes read.
struct PlyType
{
  int Size = 0; // 0: not a PLY type
  bool Signed = false;
  bool Float = false;
};

PlyType TypeNamed(const std::string& name)
{
  if (name == "char" || name == "int8")
    return { 1, true, false };
  if (name == "uchar" || name == "uint8")
    return { 1, false, false };
  if (name == "short" || name == "int16")
    return { 2, true, false };
  if (name == "ushort" || name == "uint16")
    return { 2, false, false };
  if (name == "int" || name == "int32")
    return { 4, true, false };
  if (name == "uint" || name == "uint32")
    return { 4, false, false };
  if (name == "float" || name == "float32")
    return { 4, true, true };
  if (name == "double" || name == "float64")
    return { 8, true, true };
  return {};
}

struct PlyProperty
{
  std::string Name;
  PlyType Value;
  /// A list: Count is the type of its length, Value of its items.
  bool List = false;
  PlyType Count;
};

struct PlyElement
{
  std::string Name;
  unsigned long long Rows = 0;
  std::vector<PlyProperty> Properties;
};

enum class PlyFormat
{
  Ascii,
  LittleEndian,
  BigEndian
};

/// A problem found in the file: its description.
struct PlyProblem
{
  std::string What;
};

/// The header's elements and format; `body` is set to the first byte after "end_header".
std::vector<PlyElement> ParseHeader(const std::string& file, PlyFormat& format, std::size_t& body)
{
  std::vector<PlyElement> elements;
  bool formatSeen = false;
  std::size_t at = 0;
  int lineNumber = 0;
  while (true)
  {
    const std::size_t end = file.find('\n', at);
    if (end == std::string::npos)
    {
      throw PlyProblem{ "the header has no end_header line" };
    }
    std::string line = file.substr(at, end - at);
    at = end + 1;
    ++lineNumber;
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    const auto bad = [&](const std::string& why)
    { return PlyProblem{ "header line " + std::to_string(lineNumber) + ": " + why }; };
    if (lineNumber == 1)
    {
      if (keyword != "ply")
      {
        throw bad("not a PLY file (it does not start with \"ply\")");
      }
      continue;
    }
    if (keyword == "end_header")
    {
      break;
    }
    if (keyword == "format")
    {
      std::string name;
      words >> name;
      format = name == "ascii" ? PlyFormat::Ascii
        : name == "binary_little_endian" ? PlyFormat::LittleEndian
        : name == "binary_big_endian"    ? PlyFormat::BigEndian
                                         : throw bad("unknown format " + Quoted(name));
      formatSeen = true;
    }
    else if (keyword == "element")
    {
      PlyElement element;
      std::string rows;
      words >> element.Name >> rows;
      char* stop = nullptr;
      errno = 0;
      const unsigned long long count = std::strtoull(rows.c_str(), &stop, 10);
      // The whole word (a NUL byte would end strtoull early), in range.
      if (element.Name.empty() || rows.empty() || stop != rows.c_str() + rows.size() ||
        errno == ERANGE || rows[0] == '-')
      {
        throw bad("an element needs a name and a count of rows");
      }
      element.Rows = count;
      elements.push_back(element);
    }
    else if (keyword == "property")
    {
      if (elements.empty())
      {
        throw bad("a property before any element");
      }
      PlyProperty property;
      std::string type;
      words >> type;
      if (type == "list")
      {
        std::string countType, itemType;
        words >> countType >> itemType >> property.Name;
        property.List = true;
        property.Count = TypeNamed(countType);
        property.Value = TypeNamed(itemType);
        if (property.Count.Size == 0 || property.Count.Float || property.Value.Size == 0)
        {
          throw bad("a list property needs an integer count type and an item type");
        }
      }
      else
      {
        words >> property.Name;
        property.Value = TypeNamed(type);
        if (property.Value.Size == 0)
        {
          throw bad("unknown property type " + Quoted(type));
        }
      }
      elements.back().Properties.push_back(property);
    }
    else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty())
    {
      throw bad("unknown keyword " + Quoted(keyword));
    }
  }
  if (!formatSeen)
  {
    throw PlyProblem{ "the header has no format line" };
  }
  body = at;
  return elements;
}

/// Reads the body's values one by one, in either encoding; throws PlyProblem at its end.
class BodyReader
{
public:
  BodyReader(const std::string& file, std::size_t body, PlyFormat format)
    : File(file)
    , At(body)
    , Format(format)
  {
  }

  /// The next value of `type`, as a double (exact for every PLY integer).
  double Next(const PlyType& type)
  {
    if (this->Format == PlyFormat::Ascii)
    {
      return this->NextWord();
    }
    if (this->File.size() - this->At < static_cast<std::size_t>(type.Size))
    {
      throw PlyProblem{ "" }; // the caller says where
    }
    std::uint64_t bits = 0;
    for (int i = 0; i < type.Size; ++i)
    {
      const int byte = this->Format == PlyFormat::LittleEndian ? i : type.Size - 1 - i;
      bits |= static_cast<std::uint64_t>(static_cast<unsigned char>(this->File[this->At + byte]))
        << (8 * i);
    }
    this->At += static_cast<std::size_t>(type.Size);
    if (type.Float)
    {
      if (type.Size == 4)
      {
        const auto narrow = static_cast<std::uint32_t>(bits);
        float value;
        std::memcpy(&value, &narrow, sizeof(value));
        return value;
      }
      double value;
      std::memcpy(&value, &bits, sizeof(value));
      return value;
    }
    if (type.Signed && (bits >> (8 * type.Size - 1)) != 0)
    {
      return static_cast<double>(bits) - std::ldexp(1.0, 8 * type.Size);
    }
    return static_cast<double>(bits);
  }

  /// Skip `count` values of `type` (binary: without reading them).
  void Skip(const PlyType& type, double count)
  {
    if (this->Format == PlyFormat::Ascii)
    {
      for (double i = 0; i < count; ++i)
      {
        this->NextWord();
      }
      return;
    }
    const double bytes = count * type.Size;
    if (bytes > static_cast<double>(this->File.size() - this->At))
    {
      throw PlyProblem{ "" };
    }
    this->At += static_cast<std::size_t>(bytes);
  }

private:
  double NextWord()
  {
    const std::string& f = this->File;
    while (this->At < f.size() && std::isspace(static_cast<unsigned char>(f[this->At])))
    {
      ++this->At;
    }
    if (this->At == f.size())
    {
      throw PlyProblem{ "" };
    }
    const std::size_t start = this->At;
    while (this->At < f.size() && !std::isspace(static_cast<unsigned char>(f[this->At])))
    {
      ++this->At;
    }
    const std::string word = f.substr(start, this->At - start);
    char* stop = nullptr;
    const double value = std::strtod(word.c_str(), &stop);
    // The whole word: a NUL byte would end strtod's reading early and pass.
    if (stop != word.c_str() + word.size())
    {
      throw PlyProblem{ Quoted(word) + " is not a number" };
    }
    return value;
  }

  const std::string& File;
  std::size_t At;
  PlyFormat Format;
};

/// Walk every row of every element; check face lists against the vertex count.
void WalkBody(const std::string& file, std::size_t body, PlyFormat format,
  const std::vector<PlyElement>& elements)
{
  unsigned long long vertices = 0;
  for (const PlyElement& element : elements)
  {
    vertices = element.Name == "vertex" ? element.Rows : vertices;
  }
  BodyReader reader(file, body, format);
  for (const PlyElement& element : elements)
  {
    if (element.Properties.empty())
    {
      continue; // rows of nothing take no bytes
    }
    const bool faces = element.Name == "face";
    for (unsigned long long row = 0; row < element.Rows; ++row)
    {
      const std::string where = "element " + Printable(element.Name) + ", row " + std::to_string(row + 1) +
        " of " + std::to_string(element.Rows);
      try
      {
        for (const PlyProperty& property : element.Properties)
        {
          if (!property.List)
          {
            reader.Skip(property.Value, 1);
            continue;
          }
          const double count = reader.Next(property.Count);
          if (!(count >= 0.0) || count != std::floor(count))
          {
            throw PlyProblem{ where + ": a list of " + std::to_string(count) + " items" };
          }
          const bool indices =
            faces && (property.Name == "vertex_indices" || property.Name == "vertex_index");
          if (!indices)
          {
            reader.Skip(property.Value, count);
            continue;
          }
          for (double i = 0; i < count; ++i)
          {
            const double index = reader.Next(property.Value);
            if (!(index >= 0.0) || index >= static_cast<double>(vertices) ||
              index != std::floor(index))
            {
              std::ostringstream message;
              message << "face " << row + 1 << " refers to vertex " << std::setprecision(17)
                      << index << ", but there are " << vertices << " vertices";
              throw PlyProblem{ message.str() };
            }
          }
        }
      }
      catch (const PlyProblem& problem)
      {
        if (!problem.What.empty() && problem.What.rfind("face ", 0) == 0)
        {
          throw;
        }
        if (!problem.What.empty() && problem.What.rfind("element ", 0) == 0)
        {
          throw;
        }
        throw PlyProblem{ problem.What.empty()
            ? "the file ends in " + where + " (cut short?)"
            : where + ": " + problem.What };
      }
    }
  }
}
} // namespace

std::string CheckPlyFile(const std::string& path)
{
  std::ifstream stream(path, std::ios::binary);
  if (!stream)
  {
    return "cannot open the file";
  }
  const std::string file(
    (std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
  try
  {
    PlyFormat format = PlyFormat::Ascii;
    std::size_t body = 0;
    const std::vector<PlyElement> elements = ParseHeader(file, format, body);
    WalkBody(file, body, format, elements);
  }
  catch (const PlyProblem& problem)
  {
    return problem.What;
  }
  return std::string();
}
} // namespace riemann
