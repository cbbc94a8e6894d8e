#include "InputFiles.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace riemann
{
namespace
{
/// "64.0 MiB", or "21 bytes" under a MiB.
std::string MiB(std::uint64_t bytes)
{
  if (bytes < (1 << 20))
  {
    return std::to_string(bytes) + " bytes";
  }
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(1);
  text << static_cast<double>(bytes) / double(1 << 20) << " MiB";
  return text.str();
}
} // namespace

std::string InputFileProblem(
  const std::string& path, const std::string& what, std::uint64_t maximumBytes)
{
  namespace fs = std::filesystem;
  const std::string named = path + ": " + what;
  if (path.empty())
  {
    return what + ": no file name given";
  }
  std::error_code error;
  const fs::file_status status = fs::status(path, error); // follows links; opens nothing
  if (error || !fs::exists(status))
  {
    return named + " does not exist";
  }
  if (fs::is_directory(status))
  {
    return named + " is a folder, not a file";
  }
  if (!fs::is_regular_file(status))
  {
    return named + " is not a regular file (a device, FIFO or socket); give a file";
  }
  const std::uintmax_t bytes = fs::file_size(path, error);
  if (error)
  {
    return named + ": cannot read its size (" + error.message() + ")";
  }
  if (bytes > maximumBytes)
  {
    return named + " has " + MiB(bytes) + "; the limit is " + MiB(maximumBytes);
  }
  return std::string();
}

std::string ReadInputFile(
  const std::string& path, const std::string& what, std::uint64_t maximumBytes)
{
  const std::string problem = InputFileProblem(path, what, maximumBytes);
  if (!problem.empty())
  {
    throw std::runtime_error(problem);
  }
  std::ifstream file(path, std::ios::binary);
  if (!file)
  {
    throw std::runtime_error(path + ": " + what + " cannot be opened");
  }
  std::string text;
  char buffer[1 << 16];
  while (file.read(buffer, sizeof(buffer)) || file.gcount() > 0)
  {
    text.append(buffer, static_cast<std::size_t>(file.gcount()));
    if (text.size() > maximumBytes)
    {
      throw std::runtime_error(
        path + ": " + what + " grew past " + MiB(maximumBytes) + " while it was read");
    }
  }
  if (file.bad())
  {
    throw std::runtime_error(path + ": " + what + " could not be read");
  }
  return text;
}

std::string PrintableFileText(const std::string& text, std::size_t most)
{
  static const char* digits = "0123456789abcdef";
  std::string shown;
  for (std::size_t i = 0; i < text.size() && i < most; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f)
    {
      shown += static_cast<char>(c);
    }
    else
    {
      shown += "\\x";
      shown += digits[c >> 4];
      shown += digits[c & 15];
    }
  }
  return text.size() > most ? shown + "..." : shown;
}
} // namespace riemann
