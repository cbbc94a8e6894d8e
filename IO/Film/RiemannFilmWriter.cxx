#include "RiemannFilmWriter.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOggTheoraWriter.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace riemann
{
struct FilmWriter::Internals
{
  vtkNew<vtkImageData> Frame;
  vtkNew<vtkOggTheoraWriter> Writer;
};

namespace
{
std::string LowerExtension(const std::string& path)
{
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

/// "dir/film.ogv" -> "dir/.film.ogv.partial": beside it, so the rename stays
/// on one file system.
std::string PartialPathOf(const std::string& path)
{
  const std::filesystem::path target(path);
  return (target.parent_path() / ("." + target.filename().string() + ".partial")).string();
}
} // namespace

std::string FramePath(const std::string& path, int frame)
{
  const size_t dot = path.find_last_of('.');
  char number[16];
  std::snprintf(number, sizeof(number), "_%04d", frame);
  return path.substr(0, dot) + number + (dot == std::string::npos ? "" : path.substr(dot));
}

bool FilmWriter::IsFilmPath(const std::string& path)
{
  return LowerExtension(path) == ".ogv";
}

FilmWriter::FilmWriter(const std::string& path, int width, int height, int framesPerSecond)
  : Internal(new Internals)
  , Path(path)
  , PartialPath(PartialPathOf(path))
  , Width(width)
  , Height(height)
{
  if (!IsFilmPath(path))
  {
    throw FilmWriterError(path + ": a film is written as Ogg Theora, .ogv");
  }
  // Theora codes 4:2:0 colour on 2 x 2 blocks: even sides.
  if (width < 2 || height < 2 || width > 16384 || height > 16384 || width % 2 || height % 2)
  {
    throw FilmWriterError(path + ": a film's frames must have even sides from 2 to 16384, not " +
      std::to_string(width) + "x" + std::to_string(height));
  }
  if (framesPerSecond < 1 || framesPerSecond > 240)
  {
    throw FilmWriterError(path + ": frames per second must be 1 to 240");
  }
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code exists;
  if (!folder.empty() && !std::filesystem::is_directory(folder, exists))
  {
    throw FilmWriterError(path + ": the folder " + folder.string() + " does not exist");
  }
  vtkImageData* frame = this->Internal->Frame;
  frame->SetDimensions(width, height, 1);
  frame->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::memset(frame->GetScalarPointer(), 0, static_cast<size_t>(width) * height * 3);
  vtkOggTheoraWriter* writer = this->Internal->Writer;
  writer->SetInputData(frame);
  writer->SetFileName(this->PartialPath.c_str());
  writer->SetRate(framesPerSecond);
  writer->SetQuality(2);
  writer->SubsamplingOn();
  writer->Start();
  if (writer->GetError())
  {
    std::error_code ignored;
    std::filesystem::remove(this->PartialPath, ignored);
    throw FilmWriterError(path + ": cannot start the film (" +
      vtkGenericMovieWriter::GetStringFromErrorCode(writer->GetErrorCode()) + ")");
  }
}

FilmWriter::~FilmWriter()
{
  if (!this->Closed)
  {
    this->Internal->Writer->End();
    std::error_code ignored;
    std::filesystem::remove(this->PartialPath, ignored);
  }
}

void FilmWriter::AddFrame(const unsigned char* rgb, int width, int height)
{
  if (width != this->Width || height != this->Height)
  {
    throw FilmWriterError(this->Path + ": frame " + std::to_string(this->Frames + 1) + " is " +
      std::to_string(width) + "x" + std::to_string(height) + ", the film " +
      std::to_string(this->Width) + "x" + std::to_string(this->Height));
  }
  // VTK's rows go up from the bottom.
  auto* target = static_cast<unsigned char*>(this->Internal->Frame->GetScalarPointer());
  const size_t row = static_cast<size_t>(width) * 3;
  for (int r = 0; r < height; ++r)
  {
    std::memcpy(target + (height - 1 - r) * row, rgb + r * row, row);
  }
  this->Internal->Frame->Modified();
  this->Internal->Writer->Write();
  if (this->Internal->Writer->GetError())
  {
    throw FilmWriterError(this->Path + ": frame " + std::to_string(this->Frames + 1) +
      " could not be written");
  }
  ++this->Frames;
}

void FilmWriter::Close()
{
  this->Internal->Writer->End();
  this->Closed = true;
  std::error_code error;
  if (this->Frames == 0 || this->Internal->Writer->GetError())
  {
    std::filesystem::remove(this->PartialPath, error);
    throw FilmWriterError(this->Path + ": the film could not be finished");
  }
  std::filesystem::rename(this->PartialPath, this->Path, error);
  if (error)
  {
    std::filesystem::remove(this->PartialPath, error);
    throw FilmWriterError(this->Path + ": cannot be written (" + error.message() + ")");
  }
}
} // namespace riemann
