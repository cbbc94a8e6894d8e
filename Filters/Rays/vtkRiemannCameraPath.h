/**
 * @class   vtkRiemannCameraPath
 * @brief   The frames of a flight through curved space: the observer moves
 * along a geodesic or a spline of key positions, its view frame carried by
 * the metric's connection.
 *
 * Along a geodesic (PathType GEODESIC, the default) the observer starts at
 * Position looking at LookAt, flies Length (g-arc length) straight ahead,
 * and its frame is parallel-transported: "straight ahead" stays the
 * geodesic's direction and the horizon does not spin. Along a spline
 * through KeyPositions (SPLINE) it looks along the spline's tangent and its
 * up and right are Fermi-Walker transported (the transport that turns them
 * only as much as the tangent turns). riemann::ComputeCameraPath
 * (CameraPath.h) does the work; its tests check the frames g-orthonormal to
 * 1e-9 and, in a pulled-back flat metric, the pull-back of a constant frame.
 *
 * Output: a polyline of NumberOfFrames points, the observer's positions
 * evenly spaced in g-arc length, with point data `Forward`, `Up`, `Right`
 * (the frame, coordinate vectors) and `ArcLength`. ApplyFrame() sets a
 * vtkCamera to one of them (for vtkRiemannRayTracePass, the CPU tracer or
 * the ray bundle: they rebuild the same g-orthonormal frame from it).
 *
 * Errors (no metric, fewer than 2 keys, a degenerate metric on the path)
 * go through VTK's error mechanism and GetLastError(); the output is then
 * empty. AbortExecute (riemann-studio's Cancel) stops it within a frame.
 */
#ifndef vtkRiemannCameraPath_h
#define vtkRiemannCameraPath_h

#include "RiemannFiltersRaysModule.h" // For export macro
#include "vtkRiemannGeodesicAlgorithm.h"

class vtkCamera;
class vtkPoints;

class RIEMANNFILTERSRAYS_EXPORT vtkRiemannCameraPath : public vtkRiemannGeodesicAlgorithm
{
public:
  static vtkRiemannCameraPath* New();
  vtkTypeMacro(vtkRiemannCameraPath, vtkRiemannGeodesicAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// riemann::CameraPathKind's numbering.
  enum PathTypes
  {
    GEODESIC = 0,
    SPLINE = 1
  };

  ///@{
  /// GEODESIC (default) or SPLINE.
  vtkSetClampMacro(PathType, int, GEODESIC, SPLINE);
  vtkGetMacro(PathType, int);
  void SetPathTypeToGeodesic() { this->SetPathType(GEODESIC); }
  void SetPathTypeToSpline() { this->SetPathType(SPLINE); }
  ///@}

  ///@{
  /// The first frame (GEODESIC): where the observer starts and what it looks
  /// at (by default the inside view's own camera: declared `like`
  /// vtkRiemannPictureSettings's, checked equal by TestCameraPathDefaults).
  /// ViewUp also serves SPLINE.
  vtkSetVector3Macro(Position, double);
  vtkGetVector3Macro(Position, double);
  vtkSetVector3Macro(LookAt, double);
  vtkGetVector3Macro(LookAt, double);
  vtkSetVector3Macro(ViewUp, double);
  vtkGetVector3Macro(ViewUp, double);
  ///@}

  ///@{
  /// GEODESIC: the g-length flown (default 5).
  vtkSetMacro(Length, double);
  vtkGetMacro(Length, double);
  ///@}

  ///@{
  /// SPLINE: the key positions, passed in order (at least 2).
  virtual void SetKeyPositions(vtkPoints* keys);
  vtkGetObjectMacro(KeyPositions, vtkPoints);
  ///@}

  ///@{
  /// Frames of the film, first and last included (default 60; 1 to 10^6).
  vtkSetClampMacro(NumberOfFrames, int, 1, 1000000);
  vtkGetMacro(NumberOfFrames, int);
  ///@}

  ///@{
  /// Largest integration step in g-arc length (default 0.002).
  vtkSetMacro(Step, double);
  vtkGetMacro(Step, double);
  ///@}

  /**
   * Sets `camera` to frame `frame` of a path this filter produced: its
   * position, a focal point one unit along Forward, and Up as view up.
   * False (camera unchanged) when the path has no such frame or lacks the
   * arrays.
   */
  static bool ApplyFrame(vtkPolyData* path, vtkIdType frame, vtkCamera* camera);

  vtkMTimeType GetMTime() override;

protected:
  vtkRiemannCameraPath();
  ~vtkRiemannCameraPath() override;

  int FillDataPortInformation(int port, vtkInformation* info) override;
  bool UsesIntegrationSettings() const override { return false; }
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  // The declared settings (vtkRiemannCameraPath.settings.json): defaults,
  // ranges and help are there.
  int PathType;
  double Position[3];
  double LookAt[3];
  double ViewUp[3];
  double Length;
  vtkPoints* KeyPositions = nullptr;
  int NumberOfFrames;
  double Step;

private:
  vtkRiemannCameraPath(const vtkRiemannCameraPath&) = delete;
  void operator=(const vtkRiemannCameraPath&) = delete;
};

#endif
