#include "RiemannTensorFileChecks.h"

#include "InputFiles.h"

#include "vtkAbstractArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkType.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"
#include "vtkXMLImageDataReader.h"
#include "vtk_zlib.h" // zlib, as VTK has it (the system's on Debian)

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace riemann
{
namespace
{
namespace fs = std::filesystem;

std::string Lower(std::string text)
{
  for (char& c : text)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return text;
}

std::string GiB(std::uint64_t bytes)
{
  std::ostringstream text;
  text.precision(3);
  text << static_cast<double>(bytes) / double(std::uint64_t(1) << 30) << " GiB";
  return text.str();
}

/// The first `count` bytes of the file, inflated when it is gzip (fewer when it is shorter).
std::string FirstBytes(const std::string& path, std::size_t count)
{
  std::string bytes(count, '\0');
  gzFile file = gzopen(path.c_str(), "rb"); // reads plain files as they are
  if (!file)
  {
    return std::string();
  }
  const int read = gzread(file, &bytes[0], static_cast<unsigned int>(count));
  gzclose(file);
  bytes.resize(read > 0 ? static_cast<std::size_t>(read) : 0);
  return bytes;
}

/// Bytes per value of a NIfTI datatype code; 0 for a code NIfTI-1 does not define.
int NiftiBytesPerValue(int datatype)
{
  static const std::map<int, int> sizes = { { 2, 1 }, { 4, 2 }, { 8, 4 }, { 16, 4 }, { 32, 8 },
    { 64, 8 }, { 128, 3 }, { 256, 1 }, { 512, 2 }, { 768, 4 }, { 1024, 8 }, { 1280, 8 },
    { 1536, 16 }, { 1792, 16 }, { 2048, 32 }, { 2304, 4 } };
  const auto found = sizes.find(datatype);
  return found == sizes.end() ? 0 : found->second;
}

/// `text` is exactly `count` finite numbers separated by white space.
bool FiniteNumbers(const std::string& text, int count)
{
  std::istringstream words(text);
  std::string word;
  int found = 0;
  while (words >> word)
  {
    char* stop = nullptr;
    const double value = std::strtod(word.c_str(), &stop);
    if (stop != word.c_str() + word.size() || !std::isfinite(value))
    {
      return false;
    }
    ++found;
  }
  return found == count;
}

/// A file's text in a message (PrintableFileText): at most 60 characters.
std::string Shortened(const std::string& text)
{
  return PrintableFileText(text, 60);
}

} // namespace

bool HasFileEnding(const std::string& path, const std::string& ending)
{
  const std::string text = Lower(path);
  return text.size() >= ending.size() &&
    text.compare(text.size() - ending.size(), ending.size(), ending) == 0;
}

int NrrdVtkType(const std::string& type)
{
  static const std::map<std::string, int> types = { { "float", VTK_FLOAT },
    { "double", VTK_DOUBLE }, { "signed char", VTK_SIGNED_CHAR }, { "int8", VTK_SIGNED_CHAR },
    { "int8_t", VTK_SIGNED_CHAR }, { "uchar", VTK_UNSIGNED_CHAR },
    { "unsigned char", VTK_UNSIGNED_CHAR }, { "uint8", VTK_UNSIGNED_CHAR },
    { "uint8_t", VTK_UNSIGNED_CHAR }, { "short", VTK_SHORT }, { "short int", VTK_SHORT },
    { "signed short", VTK_SHORT }, { "signed short int", VTK_SHORT }, { "int16", VTK_SHORT },
    { "int16_t", VTK_SHORT }, { "ushort", VTK_UNSIGNED_SHORT },
    { "unsigned short", VTK_UNSIGNED_SHORT }, { "unsigned short int", VTK_UNSIGNED_SHORT },
    { "uint16", VTK_UNSIGNED_SHORT }, { "uint16_t", VTK_UNSIGNED_SHORT }, { "int", VTK_INT },
    { "signed int", VTK_INT }, { "int32", VTK_INT }, { "int32_t", VTK_INT },
    { "uint", VTK_UNSIGNED_INT }, { "unsigned int", VTK_UNSIGNED_INT },
    { "uint32", VTK_UNSIGNED_INT }, { "uint32_t", VTK_UNSIGNED_INT },
    { "longlong", VTK_LONG_LONG }, { "long long", VTK_LONG_LONG },
    { "long long int", VTK_LONG_LONG }, { "signed long long", VTK_LONG_LONG },
    { "signed long long int", VTK_LONG_LONG }, { "int64", VTK_LONG_LONG },
    { "int64_t", VTK_LONG_LONG }, { "ulonglong", VTK_UNSIGNED_LONG_LONG },
    { "unsigned long long", VTK_UNSIGNED_LONG_LONG },
    { "unsigned long long int", VTK_UNSIGNED_LONG_LONG }, { "uint64", VTK_UNSIGNED_LONG_LONG },
    { "uint64_t", VTK_UNSIGNED_LONG_LONG } };
  const auto found = types.find(type);
  return found == types.end() ? VTK_VOID : found->second;
}

std::string CheckNiftiFile(const std::string& path)
{
  // Step 1: the 348-byte NIfTI-1 header (inflated for .nii.gz), either byte order.
  const std::string header = FirstBytes(path, 348);
  if (header.size() < 348)
  {
    return "the file is shorter than a NIfTI header (348 bytes)";
  }
  const auto* bytes = reinterpret_cast<const unsigned char*>(header.data());
  std::int32_t size = 0;
  std::memcpy(&size, bytes, 4);
  bool swap = false;
  if (size != 348)
  {
    std::uint32_t swapped = 0;
    for (int i = 0; i < 4; ++i)
    {
      swapped = (swapped << 8) | bytes[i];
    }
    if (swapped == 540 || size == 540)
    {
      return std::string(); // NIfTI-2: VTK checks it
    }
    if (swapped != 348)
    {
      return "not a NIfTI-1 header (sizeof_hdr is neither 348 nor 540)";
    }
    swap = true;
  }
  const auto int16 = [&](int offset)
  {
    const unsigned int a = bytes[offset], b = bytes[offset + 1];
    return static_cast<std::int16_t>(swap ? (a << 8) | b : (b << 8) | a);
  };
  const auto float32 = [&](int offset)
  {
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i)
    {
      bits |= std::uint32_t(bytes[offset + (swap ? 3 - i : i)]) << (8 * i);
    }
    float value;
    std::memcpy(&value, &bits, 4);
    return value;
  };

  // Step 2: the datatype, the dimensions and the bytes they declare.
  const int datatype = int16(70);
  const int bytesPerValue = NiftiBytesPerValue(datatype);
  if (bytesPerValue == 0)
  {
    return "unknown NIfTI datatype code " + std::to_string(datatype);
  }
  const int rank = int16(40);
  if (rank < 1 || rank > 7)
  {
    return "dim[0] is " + std::to_string(rank) + "; NIfTI images have 1 to 7 dimensions";
  }
  std::uint64_t voxels = 1;
  std::ostringstream shape;
  for (int i = 1; i <= rank; ++i)
  {
    const int length = int16(40 + 2 * i);
    if (length < 1)
    {
      return "dim[" + std::to_string(i) + "] is " + std::to_string(length) +
        "; every dimension needs at least one voxel";
    }
    voxels *= static_cast<std::uint64_t>(length);
    shape << (i > 1 ? " x " : "") << length;
  }
  const std::uint64_t data = voxels * static_cast<std::uint64_t>(bytesPerValue);
  if (data > MaximumTensorFileBytes)
  {
    return "the header declares " + shape.str() + " values of " + std::to_string(bytesPerValue) +
      " bytes (" + GiB(data) + "); tensor volumes are read up to " +
      GiB(MaximumTensorFileBytes);
  }

  // Step 3: an uncompressed file holds what it declares (a .hdr's data is in its .img).
  const std::string lower = Lower(path);
  if (HasFileEnding(lower, ".gz"))
  {
    return std::string(); // reading stops at the declared (bounded) size
  }
  fs::path dataFile = path;
  std::uint64_t offset = 0;
  if (HasFileEnding(lower, ".hdr"))
  {
    dataFile.replace_extension(".img");
    const std::string problem = InputFileProblem(dataFile.string(), "the image file");
    if (!problem.empty())
    {
      return problem;
    }
  }
  else
  {
    const float voxOffset = float32(108);
    // Converted only when it fits: a float of 2.8e20 (found by fuzzing) has
    // no uint64 value, and the conversion would be undefined.
    if (!std::isfinite(voxOffset) || voxOffset > float(MaximumTensorFileBytes))
    {
      std::ostringstream text;
      text << "vox_offset " << voxOffset << " is not a byte offset in a file read up to "
           << GiB(MaximumTensorFileBytes);
      return text.str();
    }
    offset = voxOffset >= 348.0f ? static_cast<std::uint64_t>(voxOffset) : 352;
  }
  std::error_code error;
  const std::uint64_t available = fs::file_size(dataFile, error);
  if (!error && available < offset + data)
  {
    return "the header declares " + std::to_string(data) + " bytes of voxel data after byte " +
      std::to_string(offset) + ", but the file has " + std::to_string(available) +
      " bytes (cut short?)";
  }
  return std::string();
}

NrrdHeader ReadNrrdHeader(const std::string& path)
{
  // At most 1 MiB and a byte is read (a first "line" of a gigabyte without a
  // newline once went into memory whole); Bytes is where the header ends in
  // what was read, never past the file's end.
  constexpr std::size_t most = std::size_t(1) << 20;
  std::string text(most + 1, '\0');
  std::ifstream in(path, std::ios::binary);
  in.read(&text[0], static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));

  NrrdHeader header;
  std::size_t start = 0;
  bool first = true;
  while (start < text.size())
  {
    const std::size_t newline = text.find('\n', start);
    const std::size_t end = newline == std::string::npos ? text.size() : newline + 1;
    if (end > most)
    {
      header.TooLong = true;
      break;
    }
    std::string line = text.substr(start, (newline == std::string::npos ? text.size() : newline) - start);
    header.Bytes = end;
    start = end;
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    if (first)
    {
      header.Magic = line.rfind("NRRD000", 0) == 0;
      first = false;
      if (!header.Magic)
      {
        break;
      }
      continue;
    }
    if (line.empty())
    {
      break;
    }
    const std::size_t colon = line.find(": ");
    if (line[0] != '#' && colon != std::string::npos && line.find(":=") == std::string::npos)
    {
      header.Fields[line.substr(0, colon)] = line.substr(colon + 2);
    }
  }
  return header;
}

std::string CheckNrrdFile(const std::string& path)
{
  // Step 1: the header's fields, up to the blank line (or the file's end).
  NrrdHeader header = ReadNrrdHeader(path);
  if (!header.Magic)
  {
    return "not a NRRD file (it does not start with NRRD000X)";
  }
  if (header.TooLong)
  {
    return "the header runs past 1 MiB";
  }
  std::map<std::string, std::string>& fields = header.Fields;
  const std::uint64_t headerBytes = header.Bytes;

  // Step 2: dimension, sizes, type and encoding agree.
  const std::string dimensionText = fields["dimension"];
  const int dimension = std::atoi(dimensionText.c_str());
  if (dimension < 1 || dimension > 16)
  {
    return "\"dimension: " + Shortened(dimensionText) + "\"; NRRD files have 1 to 16";
  }
  std::istringstream sizeWords(fields["sizes"]);
  std::vector<std::uint64_t> sizes;
  std::string word;
  while (sizeWords >> word)
  {
    char* stop = nullptr;
    errno = 0;
    const unsigned long long size = std::strtoull(word.c_str(), &stop, 10);
    // The whole word (a NUL byte would end strtoull early), in range.
    if (stop != word.c_str() + word.size() || errno == ERANGE || word[0] == '-' || size == 0)
    {
      return "\"sizes: " + Shortened(fields["sizes"]) + "\": \"" + Shortened(word) +
        "\" is not a positive count";
    }
    sizes.push_back(size);
  }
  if (static_cast<int>(sizes.size()) != dimension)
  {
    return "\"dimension: " + std::to_string(dimension) + "\" but " +
      std::to_string(sizes.size()) + " sizes (\"sizes: " + Shortened(fields["sizes"]) + "\")";
  }
  const int type = NrrdVtkType(fields["type"]);
  const int bytesPerValue = type == VTK_VOID ? 0 : vtkAbstractArray::GetDataTypeSize(type);
  if (bytesPerValue == 0)
  {
    return "unknown type \"" + Shortened(fields["type"]) + "\"";
  }
  std::uint64_t data = static_cast<std::uint64_t>(bytesPerValue);
  for (std::uint64_t size : sizes)
  {
    if (data > MaximumTensorFileBytes / size + 1)
    {
      data = MaximumTensorFileBytes + 1;
      break;
    }
    data *= size;
  }
  if (data > MaximumTensorFileBytes)
  {
    return "the header declares more than " + GiB(MaximumTensorFileBytes) +
      " of values (\"sizes: " + Shortened(fields["sizes"]) + "\"); tensor volumes are read up to that";
  }
  const std::string encoding = fields["encoding"];
  const bool gzip = encoding == "gzip" || encoding == "gz";
  if (encoding != "raw" && !gzip)
  {
    return "\"encoding: " + Shortened(encoding) + "\"; tensor files are read raw or gzip";
  }

  // Step 3: where the data is, and (raw) that it is all there.
  fs::path dataFile = path;
  std::uint64_t offset = headerBytes;
  const auto detached = fields.find("data file") != fields.end() ? fields.find("data file")
                                                                 : fields.find("datafile");
  if (detached != fields.end())
  {
    const std::string name = detached->second;
    if (std::any_of(name.begin(), name.end(),
          [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }))
    {
      return "\"data file: " + Shortened(name) + "\": the name has control characters";
    }
    if (name.rfind("LIST", 0) == 0 || name.find('%') != std::string::npos ||
      name.find(' ') != std::string::npos)
    {
      return "\"data file: " + Shortened(name) +
        "\": data in several files is not read; give one data file";
    }
    dataFile = fs::path(name).is_absolute() ? fs::path(name) : fs::path(path).parent_path() / name;
    offset = 0;
    const std::string problem = InputFileProblem(dataFile.string(), "the data file");
    if (!problem.empty())
    {
      return problem;
    }
  }
  if (!gzip)
  {
    std::error_code error;
    const std::uint64_t available = fs::file_size(dataFile, error);
    if (!error && available < offset + data)
    {
      return "the header declares " + std::to_string(data) + " bytes of values, but " +
        (detached != fields.end() ? "the data file has " + std::to_string(available)
                                  : "the file has " + std::to_string(available - offset) +
              " after its header") +
        " (cut short?)";
    }
  }
  return std::string();
}

std::string CheckVtiFile(const std::string& path)
{
  const std::string notRegular = InputFileProblem(path, "the tensor file");
  if (!notRegular.empty())
  {
    return notRegular;
  }
  // Step 1: the header alone (the XML up to the data; no array is read).
  vtkNew<vtkXMLImageDataReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return "not a VTK XML image file";
  }
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  vtkInformation* info = reader->GetOutputInformation(0);
  if (!info || !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    return "its header has no WholeExtent";
  }
  std::array<int, 6> extent{};
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent.data());
  // VTK reads "nan" or "x" in a geometry attribute as nothing and keeps its
  // default: the attributes' own text must be finite numbers.
  vtkXMLDataParser* parser = reader->GetXMLParser();
  vtkXMLDataElement* image = parser && parser->GetRootElement()
    ? parser->GetRootElement()->FindNestedElementWithName("ImageData")
    : nullptr;
  for (const auto& [name, count] : { std::pair<const char*, int>{ "Spacing", 3 },
         { "Origin", 3 }, { "Direction", 9 } })
  {
    const char* text = image ? image->GetAttribute(name) : nullptr;
    if (text && !FiniteNumbers(text, count))
    {
      return std::string("its ") + name + " \"" + Shortened(text) + "\" is not " +
        std::to_string(count) + " finite numbers";
    }
  }

  // Step 2: the points it declares, and the bytes they take at the least.
  std::uint64_t points = 1;
  for (int axis = 0; axis < 3; ++axis)
  {
    const std::int64_t count =
      static_cast<std::int64_t>(extent[2 * axis + 1]) - extent[2 * axis] + 1;
    if (count < 1)
    {
      return "its WholeExtent is empty or reversed on axis " + std::to_string(axis) + " (" +
        std::to_string(extent[2 * axis]) + " to " + std::to_string(extent[2 * axis + 1]) + ")";
    }
    points *= static_cast<std::uint64_t>(count); // each count < 2^32: no overflow before the check
    if (points > MaximumTensorFileBytes)
    {
      break;
    }
  }
  constexpr std::uint64_t leastBytesPerPoint = 6 * sizeof(float);
  if (points > MaximumTensorFileBytes / leastBytesPerPoint)
  {
    std::ostringstream extentText;
    extentText << extent[0] << " " << extent[1] << " " << extent[2] << " " << extent[3] << " "
               << extent[4] << " " << extent[5];
    return "its WholeExtent (" + extentText.str() + ") declares more than " +
      GiB(MaximumTensorFileBytes) + " of tensors; tensor volumes are read up to that";
  }
  // Step 3: uncompressed data must be in the file. (Compressed data may be
  // smaller; its blocks are checked by VTK's reader as it inflates them.)
  std::error_code error;
  const std::uint64_t fileBytes = fs::file_size(path, error);
  const std::string header = FirstBytes(path, 4096);
  const bool compressed = header.find("compressor=") != std::string::npos;
  if (!error && !compressed && points * leastBytesPerPoint > fileBytes &&
    header.find("format=\"ascii\"") == std::string::npos)
  {
    return "its WholeExtent declares " + std::to_string(points) + " points (" +
      GiB(points * leastBytesPerPoint) + " of tensors at the least) but the file has " +
      std::to_string(fileBytes) + " bytes";
  }
  return std::string();
}
} // namespace riemann
