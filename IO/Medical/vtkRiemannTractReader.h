/**
 * @class   vtkRiemannTractReader
 * @brief   Reads a tract file (TrackVis .trk, MRtrix .tck) as polylines.
 *
 * One polyline a streamline, in world coordinates: a .tck's points as
 * written, a .trk's through its header's voxel-to-RAS affine and voxel
 * order, as nibabel reads them (riemann::ReadTractFile,
 * RiemannTractFiles.h). The points are doubles computed from the file's
 * float32 values. Cell data `TractId` numbers the streamlines in the file's
 * order. These are the files `riemann trace -o X.trk|X.tck` writes, and
 * MRtrix's, DIPY's and TrackVis's.
 *
 * A file that is missing, not a streamline file, truncated or whose counts
 * disagree is reported through vtkErrorMacro (GetLastError says why, naming
 * the file) and gives an empty output.
 */
#ifndef vtkRiemannTractReader_h
#define vtkRiemannTractReader_h

#include "RiemannIOMedicalModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // For FileName, LastError

class RIEMANNIOMEDICAL_EXPORT vtkRiemannTractReader : public vtkPolyDataAlgorithm
{
public:
  static vtkRiemannTractReader* New();
  vtkTypeMacro(vtkRiemannTractReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The .trk or .tck file.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /// Why the last execution produced no output ("" after one that did).
  const char* GetLastError() const { return this->LastError.c_str(); }

protected:
  vtkRiemannTractReader();
  ~vtkRiemannTractReader() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  std::string FileName;
  std::string LastError;

private:
  vtkRiemannTractReader(const vtkRiemannTractReader&) = delete;
  void operator=(const vtkRiemannTractReader&) = delete;
};

#endif
