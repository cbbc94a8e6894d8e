#include "CsvColumns.h"

#include "CliUtilities.h"
#include "InputFiles.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace riemann
{
namespace cli
{
namespace
{
/// "x,y,z,dx,dy,dz".
std::string Joined(const std::vector<std::string>& names)
{
  std::string joined;
  for (const std::string& name : names)
  {
    joined += (joined.empty() ? "" : ",") + name;
  }
  return joined;
}

/// The header's columns by name.
std::map<std::string, int> HeaderColumns(const std::string& line)
{
  std::map<std::string, int> columns;
  std::stringstream header(line);
  std::string name;
  for (int c = 0; std::getline(header, name, ','); ++c)
  {
    name.erase(0, name.find_first_not_of(" \t\r"));
    name.erase(name.find_last_not_of(" \t\r") + 1);
    columns[name] = c;
  }
  return columns;
}

/// The finite numbers of a row; throws naming the first cell that is not one.
std::vector<double> RowValues(const std::string& line, const std::string& where)
{
  std::vector<double> values;
  std::stringstream row(line);
  std::string cell;
  while (std::getline(row, cell, ','))
  {
    char* end = nullptr;
    const double value = std::strtod(cell.c_str(), &end);
    while (end && (*end == ' ' || *end == '\t' || *end == '\r'))
    {
      ++end;
    }
    if (end == cell.c_str() || *end != '\0' || !std::isfinite(value))
    {
      throw Failure(where + ": \"" + cell + "\" is not a finite number");
    }
    values.push_back(value);
  }
  return values;
}
} // namespace

std::vector<std::vector<double>> ReadCsvColumns(const std::string& path,
  const std::vector<std::string>& names, const std::string& rows, long long maximumRows,
  std::vector<long long>* lines)
{
  const std::string what = "the " + rows + " file";
  // A regular file of at most 1 GiB: a FIFO would block, a device read
  // without end.
  const std::string notAFile = InputFileProblem(path, what, std::uint64_t(1) << 30);
  if (!notAFile.empty())
  {
    throw Failure(notAFile);
  }
  std::ifstream file(path);
  if (!file)
  {
    throw Failure(path + ": cannot open " + what);
  }
  std::string line;
  if (!std::getline(file, line))
  {
    throw Failure(path + ": empty " + rows + " file (expected a header " + Joined(names) + ")");
  }
  const std::map<std::string, int> columns = HeaderColumns(line);
  std::vector<int> index;
  for (const std::string& name : names)
  {
    const auto it = columns.find(name);
    if (it == columns.end())
    {
      throw Failure(path + ": line 1: the header lacks column \"" + name + "\" (expected " +
        Joined(names) + ")");
    }
    index.push_back(it->second);
  }
  std::vector<std::vector<double>> read;
  for (long long lineNumber = 2; std::getline(file, line); ++lineNumber)
  {
    if (line.find_first_not_of(" \t\r") == std::string::npos)
    {
      continue;
    }
    const std::string where = path + ": line " + std::to_string(lineNumber);
    const std::vector<double> values = RowValues(line, where);
    std::vector<double> picked;
    for (std::size_t k = 0; k < names.size(); ++k)
    {
      if (index[k] >= static_cast<int>(values.size()))
      {
        throw Failure(where + ": missing column \"" + names[k] + "\"");
      }
      picked.push_back(values[static_cast<std::size_t>(index[k])]);
    }
    if (static_cast<long long>(read.size()) >= maximumRows)
    {
      throw Failure(path + ": more than " + std::to_string(maximumRows) + " " + rows);
    }
    read.push_back(std::move(picked));
    if (lines)
    {
      lines->push_back(lineNumber);
    }
  }
  if (read.empty())
  {
    throw Failure(path + ": no " + rows + " after the header");
  }
  return read;
}
} // namespace cli
} // namespace riemann
