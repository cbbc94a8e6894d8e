/**
 * @class   vtkRiemannDirectionGrid
 * @brief   Directions spread evenly over the unit sphere or a cap of it,
 * triangulated: the direction grid of the exponential map and of the
 * conjugate locus.
 *
 * vtkRiemannDirectionGrid (a source) outputs NumberOfDirections unit vectors
 * as the points of a triangulated surface (the unit sphere, or the spherical
 * cap of half-angle ConeAngle degrees around ConeAxis when ConeAngle < 180),
 * with point data `DirectionId` (the point's index).
 *
 * The directions are a Fibonacci lattice (heights evenly spaced, so every
 * direction stands for the same solid angle; longitudes advancing by the
 * golden angle). The triangulation is the spherical Delaunay triangulation:
 * stereographic projection from -ConeAxis maps circles on the sphere to
 * circles in the plane, so the planar Delaunay triangulation (vtkDelaunay2D)
 * of the projected directions is the spherical one. On the whole sphere the
 * region around -ConeAxis that the projection sends to infinity is closed by
 * a fan over its boundary loop. Triangles are oriented with their normals
 * pointing away from the centre of the sphere.
 *
 * Surfaces over the grid (geodesic spheres, the conjugate locus) reuse the
 * triangles with other points: point i of those is a function of direction i.
 */
#ifndef vtkRiemannDirectionGrid_h
#define vtkRiemannDirectionGrid_h

#include "RiemannFiltersGeodesicsModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <string> // For Build
#include <vector> // For AppendTriangles

class vtkCellArray;

class RIEMANNFILTERSGEODESICS_EXPORT vtkRiemannDirectionGrid : public vtkPolyDataAlgorithm
{
public:
  static vtkRiemannDirectionGrid* New();
  vtkTypeMacro(vtkRiemannDirectionGrid, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of directions. The default and the most a grid has (more are
   * refused with an error and an empty output) are declared in
   * vtkRiemannDirectionGrid.settings.json (100 and 1e6), as every surface
   * shows them.
   */
  vtkSetClampMacro(NumberOfDirections, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfDirections, int);
  ///@}

  ///@{
  /// Restrict the directions to the cap of half-angle ConeAngle (degrees)
  /// around ConeAxis (180: the whole sphere).
  vtkSetVector3Macro(ConeAxis, double);
  vtkGetVector3Macro(ConeAxis, double);
  vtkSetClampMacro(ConeAngle, double, 0.0, 180.0);
  vtkGetMacro(ConeAngle, double);
  ///@}

  /**
   * The grid's directions and triangles for these settings, or false with a
   * message (a zero or non-finite axis, more than the declared maximum of NumberOfDirections). `grid` receives the points (unit
   * directions), the triangles and DirectionId. Used by the filters that
   * shoot geodesics over the grid. With `owner` (the filter building it),
   * the triangulation reports progress as the owner's and stops when the
   * owner's AbortExecute is set (riemann::JobStop): false, message "stopped".
   */
  VTK_WRAPEXCLUDE static bool Build(int numberOfDirections, const double axis[3], double coneAngle,
    vtkPolyData* grid, std::string& message, vtkAlgorithm* owner = nullptr);

  /**
   * A surface over the grid: for each triangle of `grid` whose three
   * directions have a point in the surface (surfacePointIds[direction] >= 0),
   * append the triangle of those points to `triangles`. Returns how many
   * were appended.
   */
  VTK_WRAPEXCLUDE static vtkIdType AppendTriangles(
    vtkPolyData* grid, const std::vector<vtkIdType>& surfacePointIds, vtkCellArray* triangles);

  /**
   * The last error this filter reported (also raised through vtkErrorMacro),
   * or "" when its last update succeeded (ErrorConventions.md).
   */
  const char* GetLastError() const { return this->LastError.c_str(); }

protected:
  vtkRiemannDirectionGrid();
  ~vtkRiemannDirectionGrid() override = default;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  // The declared defaults (vtkRiemannDirectionGrid.settings.json), set in the constructor.
  int NumberOfDirections;
  double ConeAxis[3];
  double ConeAngle;

  /// GetLastError(): set by vtkRiemannReportErrorMacro, cleared where RequestData starts.
  std::string LastError;

private:
  vtkRiemannDirectionGrid(const vtkRiemannDirectionGrid&) = delete;
  void operator=(const vtkRiemannDirectionGrid&) = delete;
};

#endif
