// riemann render's films: the frames of `--frames N`, in the metric's time t
// and, with `--camera-path P.json`, along a flight through curved space
// (CameraPath.h), written as numbered pictures or as one .ogv film
// (RiemannFilmWriter.h).
#ifndef RiemannCliFilmFrames_h
#define RiemannCliFilmFrames_h

#include "CameraPath.h"
#include "RiemannImage.h"

#include <memory>
#include <string>
#include <vector>

class vtkCamera;
class vtkRiemannMetric;

namespace riemann
{
class FilmWriter;

namespace cli
{
/// What each frame of a film shows: the metric's time and the observer.
class FilmPlan
{
public:
  /**
   * `frames` frames; t from 0 to 1 and the camera as given, or, with a
   * camera path file, its times and its flight (computed in the metric at
   * its first time). Throws Failure (status 2 for a bad path file, 1 for a
   * flight the metric stops) saying why.
   */
  FilmPlan(const std::string& cameraPathFile, int frames, vtkRiemannMetric* metric);

  /// The metric's time at `frame`.
  double TimeAt(int frame) const;
  /// Puts `camera` at `frame` of the flight; nothing without a camera path.
  void PlaceCamera(int frame, vtkCamera* camera) const;
  bool HasFlight() const { return !this->Flight.empty(); }
  int GetNumberOfFrames() const { return this->Frames; }

private:
  int Frames = 1;
  double TimeFrom = 0.0;
  double TimeTo = 1.0;
  /// The path file's "fov"; 0: the picture's own.
  double ViewAngle = 0.0;
  std::vector<CameraFrame> Flight;
};

/// Where the frames go: `-o out.png` numbered out_0000.png, ... (one frame:
/// out.png), or `-o film.ogv` one film, written whole at Finish().
class FrameSink
{
public:
  FrameSink(const std::string& output, int frames);
  ~FrameSink();
  /// Writes frame `frame`; returns the path it went to (the film's).
  std::string Add(int frame, const Image& picture);
  /// Finishes the film; nothing for pictures.
  void Finish();

private:
  std::string Output;
  int Frames = 1;
  std::unique_ptr<FilmWriter> Film;
};
} // namespace cli
} // namespace riemann

#endif
