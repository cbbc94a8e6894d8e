// Input files are checked before they are opened (InputFiles.h): a device
// read without end, a FIFO blocked forever, a folder or a file over the
// limit are errors that say what the path names. The FIFO case is the one
// that hung: it must answer at once, without opening the FIFO.
#include "InputFiles.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace
{
namespace fs = std::filesystem;

fs::path Scratch()
{
  const fs::path folder =
    fs::temp_directory_path() / ("riemann-input-files-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  return folder;
}

std::string ReadError(const std::string& path, std::uint64_t limit)
{
  try
  {
    riemann::ReadInputFile(path, "the test file", limit);
  }
  catch (const std::runtime_error& e)
  {
    return e.what();
  }
  return std::string();
}

TEST(InputFiles, WhatEachPathNamesIsSaid)
{
  const fs::path folder = Scratch();
  const fs::path file = folder / "small.json";
  std::ofstream(file) << "{\"type\": \"euclidean\"}";
  const fs::path fifo = folder / "pipe";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);

  EXPECT_EQ(riemann::InputFileProblem(file.string(), "the test file"), "");
  EXPECT_EQ(riemann::ReadInputFile(file.string(), "the test file", 100), "{\"type\": \"euclidean\"}");
  EXPECT_EQ(ReadError("/dev/zero", 1 << 20),
    "/dev/zero: the test file is not a regular file (a device, FIFO or socket); give a file");
  EXPECT_EQ(ReadError(fifo.string(), 1 << 20),
    fifo.string() + ": the test file is not a regular file (a device, FIFO or socket); give a file");
  EXPECT_EQ(ReadError(folder.string(), 1 << 20), folder.string() + ": the test file is a folder, not a file");
  EXPECT_EQ(ReadError((folder / "none.json").string(), 1 << 20),
    (folder / "none.json").string() + ": the test file does not exist");
  EXPECT_EQ(ReadError(file.string(), 10),
    file.string() + ": the test file has 21 bytes; the limit is 10 bytes");
  EXPECT_EQ(riemann::InputFileProblem("", "the test file"), "the test file: no file name given");
  fs::remove_all(folder);
}
} // namespace
