#include "RiemannImageIO.h"

#include "InputFiles.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <unistd.h>

namespace riemann
{
namespace
{
/**
 * The process's stderr (file descriptor 2) sent to a temporary file while
 * this lives. libpng, under OpenImageIO 2.4, prints "libpng error: ..." on
 * stderr itself before OpenImageIO reports the same error: that raw line
 * would come before the tool's own message. What was caught is dropped;
 * the error is told once, by OpenImageIO's text.
 */
class QuietStderr
{
public:
  QuietStderr()
  {
    std::fflush(stderr);
    this->Saved = ::dup(2);
    this->Sink = std::tmpfile();
    if (this->Saved < 0 || !this->Sink || ::dup2(::fileno(this->Sink), 2) < 0)
    {
      this->Restore();
    }
  }
  ~QuietStderr() { this->Restore(); }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

private:
  void Restore()
  {
    std::fflush(stderr);
    if (this->Saved >= 0)
    {
      ::dup2(this->Saved, 2);
      ::close(this->Saved);
      this->Saved = -1;
    }
    if (this->Sink)
    {
      std::fclose(this->Sink);
      this->Sink = nullptr;
    }
  }
  int Saved = -1;
  std::FILE* Sink = nullptr;
};

/// OpenImageIO's error text on one line: its lines joined by "; ".
std::string OneLine(std::string text)
{
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  std::string line;
  for (char c : text)
  {
    if (c == '\n')
    {
      line += "; ";
    }
    else
    {
      line += c;
    }
  }
  return line;
}

std::string Extension(const std::string& path)
{
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return {};
  }
  std::string e = path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}
}

void WriteImage(const std::string& path, const Image& image)
{
  if (image.Width <= 0 || image.Height <= 0 || image.Channels <= 0 ||
    image.Pixels.size() != static_cast<size_t>(image.Width) * image.Height * image.Channels)
  {
    throw ImageFileError(path + ": empty or inconsistent image");
  }
  const std::string extension = Extension(path);
  const bool exr = extension == "exr";
  if (!exr && extension != "png")
  {
    throw ImageFileError(
      path + ": unsupported image format \"." + extension + "\" (use .png or .exr)");
  }
  // OpenImageIO picks the format from the file name, so the temporary file
  // keeps the extension: "out.png" -> "out.partial-<pid>.png".
  const std::string temporary = path.substr(0, path.size() - extension.size() - 1) + ".partial-" +
    std::to_string(::getpid()) + "." + extension;
  std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(temporary);
  if (!output)
  {
    throw ImageFileError("OpenImageIO cannot write " + path + ": " + OneLine(OIIO::geterror()));
  }
  OIIO::ImageSpec spec(
    image.Width, image.Height, image.Channels, exr ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (!image.ChannelNames.empty() && static_cast<int>(image.ChannelNames.size()) == image.Channels)
  {
    spec.channelnames = image.ChannelNames;
  }
  spec.attribute("Software", "RiemannVTK");
  bool ok = output->open(temporary, spec);
  // OIIO converts float to the file's type (clamping to [0, 1] for 8 bits).
  ok = ok && output->write_image(OIIO::TypeDesc::FLOAT, image.Pixels.data());
  const std::string error = output->geterror();
  ok = output->close() && ok;
  if (!ok || std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    throw ImageFileError("could not write " + path + (error.empty() ? "" : ": " + OneLine(error)) +
      " (check that its folder exists and is writable)");
  }
}

Image ReadImage(const std::string& path)
{
  // OpenImageIO opens whatever it is given: a FIFO would block it.
  const std::string notAFile = InputFileProblem(path, "the image");
  if (!notAFile.empty())
  {
    throw ImageFileError(notAFile);
  }
  QuietStderr quiet;
  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(path);
  if (!input)
  {
    throw ImageFileError("cannot read image " + path + ": " + OneLine(OIIO::geterror()));
  }
  const OIIO::ImageSpec& spec = input->spec();
  constexpr long long maximumPixels = 1LL << 28;
  if (static_cast<long long>(spec.width) * spec.height > maximumPixels || spec.nchannels <= 0)
  {
    throw ImageFileError(path + ": image too large or without channels");
  }
  Image image;
  image.Width = spec.width;
  image.Height = spec.height;
  image.Channels = spec.nchannels;
  image.ChannelNames = spec.channelnames;
  image.Pixels.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.Pixels.data()))
  {
    throw ImageFileError("cannot read image " + path + ": " + OneLine(input->geterror()));
  }
  input->close();
  return image;
}

EnvironmentMap ReadEnvironmentMap(const std::string& path)
{
  EnvironmentMap map;
  map.SetImage(ReadImage(path));
  return map;
}
} // namespace riemann
