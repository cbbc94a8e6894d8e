// Shared by the tests that read the project's Data folder (scenes, metrics,
// meshes): where it is, and where a test writes its own files. VTK-free, for
// the base's tests too.
#ifndef RiemannTestDataDirectory_h
#define RiemannTestDataDirectory_h

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace riemann
{
namespace testing
{
/// $RIEMANN_DATA_DIR when set and not empty (a bundle run elsewhere), else the checkout's
/// Data folder (RIEMANN_TEST_DATA_DIR, defined by cmake/RiemannTesting.cmake).
inline std::filesystem::path DataDirectory()
{
  const char* dir = std::getenv("RIEMANN_DATA_DIR");
  return dir && *dir ? std::filesystem::path(dir) : std::filesystem::path(RIEMANN_TEST_DATA_DIR);
}
/// The checkout's top folder (the Data folder's parent): regression inputs
/// kept next to the code they test are found from it.
inline std::filesystem::path SourceDirectory()
{
  return DataDirectory().parent_path();
}

/// Write `bytes` to `path` as they are (binary), replacing the file.
inline void WriteTestFile(const std::filesystem::path& path, const std::string& bytes)
{
  std::ofstream(path, std::ios::binary) << bytes;
}

/// A folder `name` for a test's own files, created: under $RIEMANN_TEST_OUTPUT_DIR when set,
/// else under the system's temporary folder.
inline std::filesystem::path TestOutputDirectory(const std::string& name)
{
  const char* output = std::getenv("RIEMANN_TEST_OUTPUT_DIR");
  const std::filesystem::path dir =
    (output && *output ? std::filesystem::path(output) : std::filesystem::temp_directory_path()) /
    name;
  std::filesystem::create_directories(dir);
  return dir;
}
} // namespace testing
} // namespace riemann

#endif
