#include "RiemannStlCheck.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

namespace riemann
{
std::string CheckStlFile(const std::string& path)
{
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file)
  {
    return "cannot open the file";
  }
  const std::uint64_t size = static_cast<std::uint64_t>(file.tellg());
  file.seekg(0);
  char start[84] = {};
  file.read(start, sizeof(start));
  const std::uint64_t read = static_cast<std::uint64_t>(file.gcount());
  // ASCII: "solid" and then text. A binary header may start with "solid"
  // too (some exporters write it), so the binary size is tried first.
  std::uint32_t triangles = 0;
  if (read == sizeof(start))
  {
    const unsigned char* count = reinterpret_cast<const unsigned char*>(start + 80);
    triangles = static_cast<std::uint32_t>(count[0]) | (static_cast<std::uint32_t>(count[1]) << 8) |
      (static_cast<std::uint32_t>(count[2]) << 16) | (static_cast<std::uint32_t>(count[3]) << 24);
    if (size == 84 + 50 * static_cast<std::uint64_t>(triangles))
    {
      return std::string();
    }
  }
  if (read >= 5 && std::strncmp(start, "solid", 5) == 0)
  {
    return std::string(); // ASCII (vtkSTLReader checks it as it reads)
  }
  if (read < sizeof(start))
  {
    return "the file has " + std::to_string(size) +
      " bytes, fewer than a binary STL's 84-byte header and count";
  }
  return "a binary STL of " + std::to_string(triangles) + " triangles takes " +
    std::to_string(84 + 50 * static_cast<std::uint64_t>(triangles)) + " bytes, the file has " +
    std::to_string(size) + (size < 84 + 50 * static_cast<std::uint64_t>(triangles) ? " (cut short?)" : "");
}
} // namespace riemann
