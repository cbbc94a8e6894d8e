/**
 * @file RiemannTensorFileChecks.h
 * @brief Private to Common/Core: NIfTI and NRRD tensor files checked
 * against their own headers before VTK's readers see them.
 *
 * VTK 9.1's vtkNIFTIImageReader and vtkNrrdReader trust the header: an
 * unknown NIfTI datatype, a NRRD "dimension: 99" with four sizes, or a
 * detached header whose "data file: LIST" names other files crash them
 * (SIGSEGV), and a small gzip file whose header declares gigabytes keeps
 * them inflating. These checks read only the header (for .nii.gz, its first
 * bytes through zlib) and the file sizes, and say what is wrong.
 */
#ifndef RiemannTensorFileChecks_h
#define RiemannTensorFileChecks_h

#include "RiemannIOMedicalModule.h" // For export macro (tested on their own)

#include <array>
#include <cstdint>
#include <map>
#include <string>

namespace riemann
{
/// Whether `path` ends with `ending` (lower case, ".nii.gz"), whatever its case.
RIEMANNIOMEDICAL_EXPORT bool HasFileEnding(const std::string& path, const std::string& ending);

/// The most voxel data a tensor file may declare: 2 GiB (a 256^3 tensor
/// volume of floats is 0.4 GiB).
constexpr std::uint64_t MaximumTensorFileBytes = std::uint64_t(2) << 30;

/// "" when the NIfTI-1 file (.nii, .nii.gz, .hdr with its .img) at `path` can be given to
/// vtkNIFTIImageReader, else why not. NIfTI-2 headers pass to VTK's own checks.
RIEMANNIOMEDICAL_EXPORT std::string CheckNiftiFile(const std::string& path);

/// A NRRD header: its "field: value" lines (comments and "key:=value" pairs
/// left out) and its length in bytes, up to and including the blank line
/// that ends an attached header (a detached .nhdr is all header).
struct NrrdHeader
{
  std::map<std::string, std::string> Fields;
  std::uint64_t Bytes = 0;
  /// The file starts with the NRRD magic (NRRD000X).
  bool Magic = false;
  /// The header ran past 1 MiB (reading stopped there).
  bool TooLong = false;
};

/// The VTK type of a NRRD type name ("float", "unsigned short", "int32_t", ...); VTK_VOID for a
/// name NRRD does not define.
int NrrdVtkType(const std::string& type);

/// Read the header of the NRRD file at `path`.
RIEMANNIOMEDICAL_EXPORT NrrdHeader ReadNrrdHeader(const std::string& path);

/// "" when the NRRD file (.nrrd, or a detached .nhdr) at `path` can be given to vtkNrrdReader,
/// else why not.
RIEMANNIOMEDICAL_EXPORT std::string CheckNrrdFile(const std::string& path);

/**
 * "" when the VTK XML image file (.vti) at `path` may be read whole, else
 * why not: its header is read (vtkXMLImageDataReader::UpdateInformation,
 * no data) and its whole extent must be ordered, at most
 * MaximumTensorFileBytes of 6 floats a point, and, where it is stored
 * raw, no larger than the file. VTK 9.1's reader trusts the extent: a
 * WholeExtent of 2^31 points an axis made it write past its arrays.
 */
RIEMANNIOMEDICAL_EXPORT std::string CheckVtiFile(const std::string& path);
} // namespace riemann

#endif
