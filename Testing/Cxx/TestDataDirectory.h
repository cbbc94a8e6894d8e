// Shared by the tests that read the project's Data folder (scenes, metrics,
// meshes): where it is. VTK-free, for the base's tests too.
#ifndef RiemannTestDataDirectory_h
#define RiemannTestDataDirectory_h

#include <cstdlib>
#include <filesystem>

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
} // namespace testing
} // namespace riemann

#endif
