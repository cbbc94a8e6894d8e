// libFuzzer target: arbitrary bytes as a mesh file, through the checks that
// stand before VTK's readers (whose crashes on bad PLY and silent reading of
// cut STL files they exist for): riemann::CheckPlyFile (the body walked as
// its header describes it, RiemannPlyCheck.h) and riemann::CheckStlFile (the
// size against the triangle count, RiemannStlCheck.h). A reason or "" are
// both fine answers; crashes, hangs (libFuzzer's -timeout), leaks and
// sanitizer reports are failures.
#include "RiemannPlyCheck.h"
#include "RiemannStlCheck.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace
{
/// This process's scratch file (the checks read files, as the readers do).
const std::string& ScratchPath()
{
  static const std::string path = (std::filesystem::temp_directory_path() /
    ("riemann-fuzz-mesh-" + std::to_string(::getpid()) + ".ply"))
                                    .string();
  return path;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  {
    std::ofstream file(ScratchPath(), std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  const std::string ply = riemann::CheckPlyFile(ScratchPath());
  const std::string stl = riemann::CheckStlFile(ScratchPath());
  // A reason is one line of text for a message.
  if (ply.find('\0') != std::string::npos || stl.find('\0') != std::string::npos)
  {
    __builtin_trap();
  }
  return 0;
}
