/**
 * @file RiemannFilmWriter.h
 * @brief A film written frame by frame, whole or not at all: Ogg Theora
 * (.ogv) through VTK's vtkOggTheoraWriter, the movie writer Debian's VTK 9.1
 * offers (its FFMPEG writer is not built). `riemann render --frames N -o
 * film.ogv` and riemann-studio's File > Export Animation write through it.
 *
 * The frames go to a hidden file beside the target, renamed into place by
 * Close(): an interrupted or failed film leaves nothing, and never half of
 * an older film.
 */
#ifndef RiemannFilmWriter_h
#define RiemannFilmWriter_h

#include "RiemannIOFilmModule.h" // For export macro

#include <memory>
#include <stdexcept>
#include <string>

namespace riemann
{
/// The numbered pictures written instead of a film: "dir/out.png", 3 ->
/// "dir/out_0003.png" (`riemann render --frames`, riemann-studio's Export
/// Animation).
RIEMANNIOFILM_EXPORT std::string FramePath(const std::string& path, int frame);

class RIEMANNIOFILM_EXPORT FilmWriterError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

class RIEMANNIOFILM_EXPORT FilmWriter
{
public:
  /// Whether `path` names a film this writer writes (.ogv, any case).
  static bool IsFilmPath(const std::string& path);

  /// Starts the film; throws FilmWriterError when it cannot be (a bad
  /// extension, an odd or absurd size, a folder that cannot be written).
  FilmWriter(const std::string& path, int width, int height, int framesPerSecond = 24);
  /// Removes the unfinished film unless Close() succeeded.
  ~FilmWriter();
  FilmWriter(const FilmWriter&) = delete;
  FilmWriter& operator=(const FilmWriter&) = delete;

  /// One frame: width x height RGB bytes, row 0 at the top (as image files
  /// and QImage); the size must be the film's.
  void AddFrame(const unsigned char* rgb, int width, int height);
  /// Frames added so far.
  int GetNumberOfFrames() const { return this->Frames; }
  /// Finishes the film and moves it into place; throws if that fails.
  void Close();

private:
  struct Internals;
  std::unique_ptr<Internals> Internal;
  std::string Path;
  std::string PartialPath;
  int Width = 0;
  int Height = 0;
  int Frames = 0;
  bool Closed = false;
};
} // namespace riemann

#endif
