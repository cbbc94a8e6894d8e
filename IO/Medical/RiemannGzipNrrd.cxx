#include "RiemannGzipNrrd.h"
#include "RiemannTensorFileChecks.h"

#include "vtkByteSwap.h"
#include "vtkDataArray.h"
#include "vtkEndian.h"
#include "vtkPointData.h"
#include "vtkType.h"
#include "vtk_zlib.h" // zlib, as VTK has it (the system's on Debian)

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace riemann
{
namespace
{
/// Inflate `compressed` (gzip or zlib) into exactly `size` bytes at `out`.
void Inflate(const char* compressed, std::size_t length, unsigned char* out, std::size_t size)
{
  z_stream stream;
  std::memset(&stream, 0, sizeof(stream));
  if (inflateInit2(&stream, 15 + 32) != Z_OK) // 32: a gzip or a zlib header
  {
    throw std::runtime_error("zlib could not start inflating");
  }
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed));
  stream.avail_in = static_cast<uInt>(std::min<std::size_t>(length, 0xffffffffu));
  std::size_t produced = 0;
  int status = Z_OK;
  while (status == Z_OK && produced < size)
  {
    stream.next_out = out + produced;
    stream.avail_out = static_cast<uInt>(std::min<std::size_t>(size - produced, 1u << 30));
    const uInt before = stream.avail_out;
    status = inflate(&stream, Z_NO_FLUSH);
    produced += before - stream.avail_out;
  }
  unsigned char extra = 0;
  if (status == Z_OK)
  {
    // Full: the stream must end here, with nothing more to give.
    stream.next_out = &extra;
    stream.avail_out = 1;
    status = inflate(&stream, Z_NO_FLUSH);
    if (stream.avail_out == 0)
    {
      inflateEnd(&stream);
      throw std::runtime_error("the gzip data inflates to more than the " +
        std::to_string(size) + " bytes the header declares");
    }
  }
  const bool ended = status == Z_STREAM_END || status == Z_BUF_ERROR;
  inflateEnd(&stream);
  if (produced < size)
  {
    throw std::runtime_error("the gzip data inflates to " + std::to_string(produced) +
      " bytes; the header declares " + std::to_string(size) + " (cut short?)");
  }
  if (!ended)
  {
    throw std::runtime_error("the gzip data is corrupt (zlib status " + std::to_string(status) + ")");
  }
}

} // namespace

bool IsGzipNrrd(const std::string& path)
{
  const NrrdHeader header = ReadNrrdHeader(path);
  const auto encoding = header.Fields.find("encoding");
  return encoding != header.Fields.end() && (encoding->second == "gzip" || encoding->second == "gz");
}

vtkSmartPointer<vtkImageData> ReadGzipNrrdImage(const std::string& path)
{
  // Step 1: the header: type, sizes (components first in 4D), byte order.
  NrrdHeader header = ReadNrrdHeader(path);
  std::map<std::string, std::string>& fields = header.Fields;
  std::ifstream in(path, std::ios::binary);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t body = static_cast<std::size_t>(std::min<std::uint64_t>(header.Bytes, file.size()));
  if (fields.count("data file") || fields.count("datafile"))
  {
    throw std::runtime_error("a detached gzip NRRD header is not read; attach the data");
  }
  const int type = NrrdVtkType(fields["type"]);
  if (type == VTK_VOID)
  {
    throw std::runtime_error("unknown type \"" + fields["type"] + "\"");
  }
  std::vector<long long> sizes;
  std::istringstream words(fields["sizes"]);
  for (long long size; words >> size;)
  {
    sizes.push_back(size);
  }
  if (sizes.size() != 3 && sizes.size() != 4)
  {
    throw std::runtime_error("a tensor volume has 3 or 4 axes; \"sizes: " + fields["sizes"] + "\"");
  }
  const bool components = sizes.size() == 4;
  const int count = components ? static_cast<int>(sizes[0]) : 1;
  const long long* axes = sizes.data() + (components ? 1 : 0);

  // Step 2: the values, inflated in place.
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(static_cast<int>(axes[0]), static_cast<int>(axes[1]),
    static_cast<int>(axes[2]));
  image->AllocateScalars(type, count);
  vtkDataArray* values = image->GetPointData()->GetScalars();
  const int valueSize = values->GetDataTypeSize();
  const std::size_t bytes =
    static_cast<std::size_t>(values->GetNumberOfValues()) * static_cast<std::size_t>(valueSize);
  auto* out = static_cast<unsigned char*>(values->GetVoidPointer(0));
  Inflate(file.data() + body, file.size() - body, out, bytes);
#ifdef VTK_WORDS_BIGENDIAN
  const bool swap = fields["endian"] != "big";
#else
  const bool swap = fields["endian"] == "big";
#endif
  if (swap && valueSize > 1)
  {
    vtkByteSwap::SwapVoidRange(out, bytes / static_cast<std::size_t>(valueSize),
      static_cast<std::size_t>(valueSize));
  }
  values->Modified();

  // Step 3: "spacings" (the voxel axes' only, NaN for the components').
  std::istringstream spacingWords(fields["spacings"]);
  std::vector<double> spacings;
  for (std::string word; spacingWords >> word;)
  {
    spacings.push_back(std::strtod(word.c_str(), nullptr));
  }
  if (spacings.size() == sizes.size())
  {
    const double* s = spacings.data() + (components ? 1 : 0);
    if (std::isfinite(s[0]) && std::isfinite(s[1]) && std::isfinite(s[2]) && s[0] > 0 &&
      s[1] > 0 && s[2] > 0)
    {
      image->SetSpacing(s[0], s[1], s[2]);
    }
  }
  return image;
}
} // namespace riemann
