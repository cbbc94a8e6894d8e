// libFuzzer target: arbitrary bytes as a tensor volume file, through the
// checks that stand before VTK's NIfTI, NRRD and XML image readers (which
// crashed or hung on the files of Common/Core/Testing/Data/hostile-tensors):
// riemann::CheckNiftiFile, riemann::ReadNrrdHeader and riemann::CheckNrrdFile,
// riemann::CheckVtiFile (RiemannTensorFileChecks.h). The file's kind is
// sniffed as a user's file name would say it: "NRRD" -> .nrrd (.nhdr when it
// names a data file), gzip -> .nii.gz, XML -> .vti, else .nii; so the
// committed hostile files are seeds as they are. A reason or "" are both fine
// answers; crashes, hangs, leaks and sanitizer reports are failures.
#include "RiemannTensorFileChecks.h"

#include "vtkLogger.h"
#include "vtkObject.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace
{
std::string ScratchPath(const char* extension)
{
  return (std::filesystem::temp_directory_path() /
    ("riemann-fuzz-tensor-" + std::to_string(::getpid()) + extension))
    .string();
}

bool StartsWith(const std::uint8_t* data, std::size_t size, const char* start)
{
  const std::size_t length = std::strlen(start);
  return size >= length && std::memcmp(data, start, length) == 0;
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  // VTK's XML parser says what it dislikes on stderr, for most inputs: the
  // reasons returned are what is checked, and printing halved the speed.
  vtkObject::GlobalWarningDisplayOff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const char* extension = ".nii";
  if (StartsWith(data, size, "NRRD"))
  {
    const std::string text(reinterpret_cast<const char*>(data), size);
    extension = text.find("data file") != std::string::npos ? ".nhdr" : ".nrrd";
  }
  else if (StartsWith(data, size, "\x1f\x8b"))
  {
    extension = ".nii.gz";
  }
  else if (StartsWith(data, size, "<?xml") || StartsWith(data, size, "<VTKFile"))
  {
    extension = ".vti";
  }
  const std::string path = ScratchPath(extension);
  {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  std::string reason;
  if (std::strcmp(extension, ".nii") == 0 || std::strcmp(extension, ".nii.gz") == 0)
  {
    reason = riemann::CheckNiftiFile(path);
  }
  else if (std::strcmp(extension, ".vti") == 0)
  {
    reason = riemann::CheckVtiFile(path);
  }
  else
  {
    const riemann::NrrdHeader header = riemann::ReadNrrdHeader(path);
    if (header.Bytes > static_cast<std::uint64_t>(size))
    {
      __builtin_trap(); // the header cannot be longer than the file
    }
    reason = riemann::CheckNrrdFile(path);
  }
  std::remove(path.c_str());
  if (reason.find('\0') != std::string::npos)
  {
    __builtin_trap();
  }
  return 0;
}
