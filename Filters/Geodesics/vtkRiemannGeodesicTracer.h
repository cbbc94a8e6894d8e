/**
 * @class   vtkRiemannGeodesicTracer
 * @brief   Geodesics of a Riemannian metric as polylines, from seed points.
 *
 * vtkRiemannGeodesicTracer integrates the geodesic equation of a
 * vtkRiemannMetric from each seed, following vtkStreamTracer's conventions:
 *
 * - Seeds are the points of the input dataset (port 0, optional); the initial
 *   direction of each is the point-data vector named DirectionArrayName
 *   ("Direction" by default). Without an input, or without that array, the
 *   StartPosition and/or StartDirection ivars are used; without an input,
 *   NumberOfDirections > 1 fans the seed over a cone around StartDirection.
 * - The user-facing settings and their defaults and ranges are declared in
 *   vtkRiemannGeodesicTracer.settings.json (Documentation/Settings.md).
 * - Directions are coordinate vectors; each is normalised to unit speed in g
 *   at its seed, so every length here is Riemannian arc length.
 * - How each geodesic is integrated is GetIntegrationSettings()'s
 *   (vtkRiemannIntegrationSettings, vtkStreamTracer's words): IntegratorType
 *   EULER (the paper's), RUNGE_KUTTA4 (default) or DORMAND_PRINCE45
 *   (adaptive, with MaximumError as the per-step tolerance and the step
 *   bounded by Minimum/MaximumIntegrationStep); defaults: step 0.01,
 *   MaximumPropagation 10, MaximumNumberOfSteps 10000.
 * - IntegrationDirection FORWARD, BACKWARD or BOTH (two lines per seed; the
 *   backward one has negative ArcLength, as vtkStreamTracer's IntegrationTime).
 * - Each line stops at MaximumPropagation (arc length), after
 *   MaximumNumberOfSteps, on leaving DomainBounds (when UseDomainBounds), or
 *   where the metric degenerates.
 *
 * Tractography (issue 31; riemann/TractStops.h): StopMask ends geodesics
 * where a mask is 0 (STOPPED_BY_MASK), StopFractionalAnisotropy where the
 * diffusion tensor the metric stands for is less anisotropic than it
 * (LOW_ANISOTROPY), MaximumAngle where they turn more than that many degrees
 * per unit of length (SHARP_TURN: the part up to the turn is kept). Then a
 * tract (a seed's lines: both halves with BOTH) is dropped when it enters
 * ExcludeRegion, misses IncludeRegion or is shorter than MinimumLength
 * (GetNumberOfRejectedTracts says how many, by why). Masks and regions are
 * images read at the voxel that holds each point; lengths and angles are
 * Euclidean (mm for a scan), whatever the metric's scale. They are set
 * (SetStopMask, ...) or connected (optional ports StopMaskPort,
 * IncludeRegionPort, ExcludeRegionPort; a connection wins): ParaView's
 * tracer takes them as inputs, whole on every piece.
 *
 * Ports: 0 the seeds (optional), 1 to 3 the masks (optional), 4 the metric
 * (GetMetricPort()).
 *
 * Output: one polyline per seed and direction with point data `ArcLength`,
 * `Velocity` (dx/ds), `SpeedDrift` (g(v,v) - 1 for the unit-speed velocity:
 * exactly 0 for an exact geodesic, so it monitors the integration error)
 * and cell data `SeedIds` and `ReasonForTermination` (vtkStreamTracer's codes
 * plus DEGENERATE_METRIC, HIT_SURFACE, OUT_OF_DATA and tractography's
 * STOPPED_BY_MASK, LOW_ANISOTROPY and SHARP_TURN).
 *
 * With ComputeTransverseJacobian on, each geodesic is integrated together with
 * two Jacobi fields J_a (J_a(0) = 0, J_a'(0) g-orthonormal and g-orthogonal to
 * the direction: riemann::TraceJacobiFields, same integrator and stopping
 * rules) and two more point-data arrays describe the differential of the
 * exponential map at the seed, transverse to the geodesic:
 * `TransverseJacobian` (the signed determinant of the 2x2 matrix g(J_a, e_b)
 * in a g-orthonormal frame e_b orthogonal to the velocity: s^2 in flat space,
 * sin^2 s on the unit sphere; zero at conjugate points) and
 * `TransverseJacobianSingularValues` (its two singular values, largest
 * first: how much a thin pencil of geodesics is stretched in each direction).
 * It costs about four times as much per step (the Jacobi system needs the
 * derivatives of the Christoffel symbols).
 *
 * Seeds are traced in parallel with vtkSMPTools; progress is reported and
 * AbortExecute honoured between batches of seeds.
 *
 * Pieces: asked for piece p of N (UPDATE_PIECE_NUMBER,
 * UPDATE_NUMBER_OF_PIECES, as an MPI job asks), the filter reads all its
 * seeds (it requests the whole input) and traces the p-th contiguous share
 * of them, [n p / N, n (p + 1) / N) of the n seed-direction pairs in output
 * order: the pieces, appended in order, are the one-piece output, with the
 * same SeedIds. Without a valid metric, or
 * with an unusable setting, the filter reports an error (GetLastError) and
 * produces empty output.
 */
#ifndef vtkRiemannGeodesicTracer_h
#define vtkRiemannGeodesicTracer_h

#include "RiemannFiltersGeodesicsModule.h" // For export macro
#include "vtkRiemannGeodesicAlgorithm.h"

#include "vtkImageData.h"    // For the masks' smart pointers
#include "vtkSmartPointer.h" // For the masks

#include <vector> // For UntracedSeeds

class RIEMANNFILTERSGEODESICS_EXPORT vtkRiemannGeodesicTracer : public vtkRiemannGeodesicAlgorithm
{
public:
  static vtkRiemannGeodesicTracer* New();
  vtkTypeMacro(vtkRiemannGeodesicTracer, vtkRiemannGeodesicAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Directions
  {
    FORWARD = 0,
    BACKWARD = 1,
    BOTH = 2
  };

  /// vtkStreamTracer's ReasonForTermination codes (1-6) and ours (8-14).
  enum ReasonForTermination
  {
    OUT_OF_DOMAIN = 1,
    NOT_INITIALIZED = 2,
    UNEXPECTED_VALUE = 3,
    OUT_OF_LENGTH = 4,
    OUT_OF_STEPS = 5,
    STAGNATION = 6,
    DEGENERATE_METRIC = 8,
    HIT_SURFACE = 9,
    /// Left a sampled metric's volume with "outside": "stop".
    OUT_OF_DATA = 10,
    /// Reached a voxel where StopMask is 0 (or left its grid).
    STOPPED_BY_MASK = 11,
    /// Reached fractional anisotropy below StopFractionalAnisotropy.
    LOW_ANISOTROPY = 12,
    /// Turned more than MaximumAngle degrees per unit length between two steps.
    SHARP_TURN = 13,
    /// A step's chord was more than twice its nominal length: refused.
    OUTRAN_STEP = 14
  };

  /// Why GetNumberOfRejectedTracts counts a tract (riemann::TractRejection).
  enum TractRejections
  {
    TOO_SHORT = 1,
    MISSED_INCLUDE = 2,
    CROSSED_EXCLUDE = 3
  };

  ///@{
  /// Seed used when there is no input dataset.
  vtkSetVector3Macro(StartPosition, double);
  vtkGetVector3Macro(StartPosition, double);
  ///@}

  ///@{
  /// Direction used when there is no input, or it lacks DirectionArrayName.
  vtkSetVector3Macro(StartDirection, double);
  vtkGetVector3Macro(StartDirection, double);
  ///@}

  ///@{
  /**
   * Without an input: NumberOfDirections geodesics from StartPosition, 1
   * (default) along StartDirection, more spread over the cone of half-angle
   * ConeAngle degrees (default 15) around it, as vtkRiemannDirectionGrid
   * spreads them (riemann::FibonacciDirections; SeedIds number them in
   * that order). Ignored with an input.
   */
  vtkSetClampMacro(NumberOfDirections, int, 1, 1000000);
  vtkGetMacro(NumberOfDirections, int);
  vtkSetClampMacro(ConeAngle, double, 0.0, 180.0);
  vtkGetMacro(ConeAngle, double);
  ///@}

  ///@{
  /**
   * Seeds from a mask: an input vtkImageData without the DirectionArrayName
   * array is a mask (a region of interest). Its voxels whose active scalar
   * is not 0 give SeedsPerVoxel seeds each (1: the voxel's centre; more:
   * spread uniformly over the voxel, from RandomSeed, so the same settings
   * give the same seeds: riemann::MaskSeedPoints), each with the direction
   * SeedDirection says: E1 (default), the direction g makes cheapest at the
   * seed (for a diffusion tensor's inverse D^-1, the principal diffusion
   * direction: trace BOTH ways for tractography), or RANDOM, a random unit
   * vector (from RandomSeed too). SeedIds number the seeds in the image's
   * point order, which for a NIfTI file of qfac -1 is not the file's:
   * VTK's reader reverses its slices (the world positions are the file's).
   */
  enum SeedDirections
  {
    E1 = 0,
    RANDOM = 1
  };
  vtkSetClampMacro(SeedsPerVoxel, int, 1, 1000);
  vtkGetMacro(SeedsPerVoxel, int);
  vtkSetClampMacro(SeedDirection, int, E1, RANDOM);
  vtkGetMacro(SeedDirection, int);
  void SetSeedDirectionToE1() { this->SetSeedDirection(E1); }
  void SetSeedDirectionToRandom() { this->SetSeedDirection(RANDOM); }
  vtkSetMacro(RandomSeed, unsigned int);
  vtkGetMacro(RandomSeed, unsigned int);
  ///@}

  ///@{
  /**
   * Tractography's stops, each off by default (see the class comment). The
   * masks' and regions' active scalars are read at the voxel holding each
   * point (not 0: set), in the image's own placement (origin, spacing,
   * direction). MaximumAngle is in degrees per unit length (0: off).
   */
  enum MaskPorts
  {
    StopMaskPort = 1,
    IncludeRegionPort = 2,
    ExcludeRegionPort = 3
  };
  vtkSetSmartPointerMacro(StopMask, vtkImageData);
  vtkGetSmartPointerMacro(StopMask, vtkImageData);
  vtkSetClampMacro(StopFractionalAnisotropy, double, 0.0, 1.0);
  vtkGetMacro(StopFractionalAnisotropy, double);
  vtkSetClampMacro(MaximumAngle, double, 0.0, 1e6);
  vtkGetMacro(MaximumAngle, double);
  ///@}

  ///@{
  /// Which tracts are kept (see the class comment): through IncludeRegion,
  /// avoiding ExcludeRegion, at least MinimumLength long (0: any). None by default.
  vtkSetSmartPointerMacro(IncludeRegion, vtkImageData);
  vtkGetSmartPointerMacro(IncludeRegion, vtkImageData);
  vtkSetSmartPointerMacro(ExcludeRegion, vtkImageData);
  vtkGetSmartPointerMacro(ExcludeRegion, vtkImageData);
  vtkSetClampMacro(MinimumLength, double, 0.0, 1e12);
  vtkGetMacro(MinimumLength, double);
  ///@}

  ///@{
  /// Tracts of the last execution dropped by IncludeRegion, ExcludeRegion or
  /// MinimumLength: in all, and by why (TractRejections).
  vtkIdType GetNumberOfRejectedTracts() const;
  vtkIdType GetNumberOfRejectedTracts(int why) const;
  ///@}

  /// Also the masks' and regions' times.
  vtkMTimeType GetMTime() override;

  ///@{
  /// Name of the seeds' point-data direction vectors (default "Direction").
  vtkSetStringMacro(DirectionArrayName);
  vtkGetStringMacro(DirectionArrayName);
  ///@}

  ///@{
  /// FORWARD (default), BACKWARD or BOTH.
  vtkSetClampMacro(IntegrationDirection, int, FORWARD, BOTH);
  vtkGetMacro(IntegrationDirection, int);
  void SetIntegrationDirectionToForward() { this->SetIntegrationDirection(FORWARD); }
  void SetIntegrationDirectionToBackward() { this->SetIntegrationDirection(BACKWARD); }
  void SetIntegrationDirectionToBoth() { this->SetIntegrationDirection(BOTH); }
  ///@}

  ///@{
  /// Stop geodesics leaving DomainBounds (xmin,xmax,ymin,ymax,zmin,zmax). Off by default.
  vtkSetMacro(UseDomainBounds, bool);
  vtkGetMacro(UseDomainBounds, bool);
  vtkBooleanMacro(UseDomainBounds, bool);
  vtkSetVector6Macro(DomainBounds, double);
  vtkGetVector6Macro(DomainBounds, double);
  ///@}

  ///@{
  /// Also integrate the Jacobi fields and output `TransverseJacobian` and
  /// `TransverseJacobianSingularValues` (see the class comment). Off by default.
  vtkSetMacro(ComputeTransverseJacobian, bool);
  vtkGetMacro(ComputeTransverseJacobian, bool);
  vtkBooleanMacro(ComputeTransverseJacobian, bool);
  ///@}

  ///@{
  /**
   * The seed-direction pairs of the last execution that made no line (fewer
   * than two points), in all and by why they stopped (ReasonForTermination:
   * NOT_INITIALIZED for a zero or non-finite direction, DEGENERATE_METRIC,
   * OUT_OF_DATA for a seed outside a sampled metric's volume, OUT_OF_DOMAIN
   * for one outside DomainBounds, ...). Each also makes one warning.
   */
  vtkIdType GetNumberOfUntracedSeeds() const;
  vtkIdType GetNumberOfUntracedSeeds(int reason) const;
  ///@}

protected:
  vtkRiemannGeodesicTracer();
  ~vtkRiemannGeodesicTracer() override;

  int FillDataPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  // The declared settings' defaults (vtkRiemannGeodesicTracer.settings.json) are set by the constructor.
  double StartPosition[3];
  double StartDirection[3];
  int NumberOfDirections;
  double ConeAngle;
  char* DirectionArrayName = nullptr;
  int IntegrationDirection;
  bool UseDomainBounds = false;
  double DomainBounds[6] = { -1.0, 1.0, -1.0, 1.0, -1.0, 1.0 };
  bool ComputeTransverseJacobian;
  int SeedsPerVoxel;
  int SeedDirection;
  unsigned int RandomSeed;
  vtkSmartPointer<vtkImageData> StopMask;
  double StopFractionalAnisotropy;
  double MaximumAngle;
  vtkSmartPointer<vtkImageData> IncludeRegion;
  vtkSmartPointer<vtkImageData> ExcludeRegion;
  double MinimumLength;
  /// Untraced seed-direction pairs by reason (index: the reason's code).
  std::vector<vtkIdType> UntracedSeeds;
  /// Dropped tracts by why (index: TractRejections).
  std::vector<vtkIdType> RejectedTracts;

private:
  vtkRiemannGeodesicTracer(const vtkRiemannGeodesicTracer&) = delete;
  void operator=(const vtkRiemannGeodesicTracer&) = delete;
};

#endif
