#include "FilmFrames.h"

#include "CameraPathFile.h"
#include "CliUtilities.h"
#include "RiemannFilmWriter.h"
#include "RiemannImageIO.h"
#include "vtkCamera.h"
#include "vtkRiemannMetric.h"

#include <algorithm>
#include <cmath>

namespace riemann
{
namespace cli
{
namespace
{

/// A picture's first three channels as bytes, rows top first.
std::vector<unsigned char> RgbBytes(const Image& picture)
{
  std::vector<unsigned char> bytes(static_cast<size_t>(picture.Width) * picture.Height * 3);
  for (size_t pixel = 0; pixel < bytes.size() / 3; ++pixel)
  {
    for (int c = 0; c < 3; ++c)
    {
      const float value = picture.Pixels[pixel * picture.Channels + std::min(c, picture.Channels - 1)];
      bytes[pixel * 3 + c] =
        static_cast<unsigned char>(std::lround(255.0f * std::clamp(value, 0.0f, 1.0f)));
    }
  }
  return bytes;
}
} // namespace

FilmPlan::FilmPlan(const std::string& cameraPathFile, int frames, vtkRiemannMetric* metric)
  : Frames(frames)
{
  if (cameraPathFile.empty())
  {
    return;
  }
  CameraPathFile file;
  try
  {
    file = ReadCameraPathFile(cameraPathFile);
  }
  catch (const CameraPathFileError& e)
  {
    throw Failure(std::string("--camera-path: ") + e.what(), 2);
  }
  this->TimeFrom = file.TimeFrom;
  this->TimeTo = file.TimeTo;
  this->ViewAngle = file.ViewAngleGiven ? file.Settings.Start.ViewAngle : 0.0;
  file.Settings.Frames = frames;
  if (!metric->SetTime(this->TimeFrom))
  {
    throw Failure(std::string("bad metric: ") + metric->GetLastError());
  }
  try
  {
    this->Flight = ComputeCameraPath(*metric->GetMetric(), file.Settings);
  }
  catch (const CameraPathError& e)
  {
    throw Failure(std::string("--camera-path ") + cameraPathFile + ": " + e.what());
  }
}

double FilmPlan::TimeAt(int frame) const
{
  if (this->Frames < 2)
  {
    return this->TimeFrom;
  }
  return this->TimeFrom + (this->TimeTo - this->TimeFrom) * frame / (this->Frames - 1);
}

void FilmPlan::PlaceCamera(int frame, vtkCamera* camera) const
{
  if (this->Flight.empty())
  {
    return;
  }
  const CameraFrame& at = this->Flight[static_cast<size_t>(frame)];
  const Vec3 focal = at.Position + at.Forward;
  camera->SetPosition(at.Position.data());
  camera->SetFocalPoint(focal.data());
  camera->SetViewUp(at.Up.data());
  if (this->ViewAngle > 0)
  {
    camera->SetViewAngle(this->ViewAngle);
  }
}

FrameSink::FrameSink(const std::string& output, int frames)
  : Output(output)
  , Frames(frames)
{
}

FrameSink::~FrameSink() = default;

std::string FrameSink::Add(int frame, const Image& picture)
{
  try
  {
    if (!FilmWriter::IsFilmPath(this->Output))
    {
      const std::string path = this->Frames > 1 ? FramePath(this->Output, frame) : this->Output;
      WriteImage(path, picture);
      return path;
    }
    if (!this->Film)
    {
      this->Film.reset(new FilmWriter(this->Output, picture.Width, picture.Height));
    }
    const std::vector<unsigned char> bytes = RgbBytes(picture);
    this->Film->AddFrame(bytes.data(), picture.Width, picture.Height);
    return this->Output;
  }
  catch (const ImageFileError& e)
  {
    throw Failure(e.what());
  }
  catch (const FilmWriterError& e)
  {
    throw Failure(e.what());
  }
}

void FrameSink::Finish()
{
  if (!this->Film)
  {
    return;
  }
  try
  {
    this->Film->Close();
  }
  catch (const FilmWriterError& e)
  {
    throw Failure(e.what());
  }
}
} // namespace cli
} // namespace riemann
