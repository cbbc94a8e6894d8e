// Tensor files that crashed or hung the sampled metric's readers
// (Testing/Data/hostile-tensors/README.md): each is now refused by
// vtkRiemannMetric with an error that says what is wrong, before VTK's
// readers see it; and the checks themselves on files written here (a NIfTI
// cut short, a NRRD whose sizes disagree with its dimension, a raw NRRD
// shorter than declared, a detached header naming a device).
#include "vtkNew.h"
#include "vtkRiemannMetric.h"

#include "Metric.h"
#include "RiemannTensorFileChecks.h"
#include "TestDataDirectory.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace
{
namespace fs = std::filesystem;

fs::path HostileTensors()
{
  return riemann::testing::SourceDirectory() / "Common" / "Core" / "Testing" /
    "Data" / "hostile-tensors";
}

fs::path Scratch(const std::string& name)
{
  return riemann::testing::TestOutputDirectory("hostile-tensors") / name;
}

/// vtkRiemannMetric's error for {"type": "sampled", "file": FILE} ("" when it loads).
std::string MetricError(const fs::path& file)
{
  const fs::path json = Scratch(file.filename().string() + ".json");
  std::ofstream(json) << R"({"type": "sampled", "file": ")" << file.string() << R"("})";
  vtkNew<vtkRiemannMetric> metric;
  return metric->SetDefinitionFile(json.c_str()) ? std::string() : metric->GetLastError();
}

using riemann::testing::WriteTestFile;

/// A little-endian NIfTI-1 header (348 bytes, then 4 of extension flags) of a
/// 2 x 2 x 2 x 6 float volume, vox_offset 352, and `dataBytes` bytes of data.
std::string Nifti(int datatype, std::size_t dataBytes)
{
  std::string bytes(352 + dataBytes, '\0');
  const auto put16 = [&](int offset, std::int16_t value) { std::memcpy(&bytes[offset], &value, 2); };
  const std::int32_t size = 348;
  std::memcpy(&bytes[0], &size, 4);
  const std::int16_t dim[8] = { 5, 2, 2, 2, 1, 6, 1, 1 };
  for (int i = 0; i < 8; ++i)
  {
    put16(40 + 2 * i, dim[i]);
  }
  put16(70, static_cast<std::int16_t>(datatype));
  put16(72, 32);
  const float offset = 352.0f;
  std::memcpy(&bytes[108], &offset, 4);
  std::memcpy(&bytes[344], "n+1", 4);
  return bytes;
}
} // namespace

TEST(HostileTensors, EachIsRefusedWithItsReason)
{
  const struct
  {
    const char* File;
    const char* Reason;
  } cases[] = {
    { "bad_datatype.nii", "unknown NIfTI datatype code 12345" },
    { "dim99.nrrd", "\"dimension: 99\"; NRRD files have 1 to 16" },
    { "gzbomb.nii.gz",
      "the header declares 512 x 512 x 512 x 6 values of 4 bytes (3 GiB); tensor volumes are "
      "read up to 2 GiB" },
    { "detached_list.nhdr", "\"data file: LIST\": data in several files is not read" },
    { "huge_extent2.vti",
      "its WholeExtent (0 2147483646 0 2147483646 0 2147483646) declares more than 2 GiB of "
      "tensors" },
    { "nan_spacing.vti", "its Spacing \"nan 0.5 0.5\" is not 3 finite numbers" },
  };
  for (const auto& c : cases)
  {
    const fs::path file = HostileTensors() / c.File;
    ASSERT_TRUE(fs::exists(file)) << file;
    const std::string error = MetricError(file);
    EXPECT_NE(error.find(c.Reason), std::string::npos) << c.File << ": " << error;
  }
}

TEST(HostileTensors, NiftiHeadersAreChecked)
{
  const fs::path good = Scratch("good.nii");
  WriteTestFile(good, Nifti(16, 2 * 2 * 2 * 6 * 4));
  EXPECT_EQ(riemann::CheckNiftiFile(good.string()), "");
  const fs::path cut = Scratch("cut.nii");
  WriteTestFile(cut, Nifti(16, 100));
  EXPECT_NE(riemann::CheckNiftiFile(cut.string())
              .find("declares 192 bytes of voxel data after byte 352, but the file has 452 bytes"),
    std::string::npos)
    << riemann::CheckNiftiFile(cut.string());
  const fs::path tiny = Scratch("tiny.nii");
  WriteTestFile(tiny, "not a header");
  EXPECT_NE(riemann::CheckNiftiFile(tiny.string()).find("shorter than a NIfTI header"),
    std::string::npos);
}

TEST(HostileTensors, NrrdHeadersAreChecked)
{
  const std::string header = "NRRD0004\ntype: float\ndimension: 4\nsizes: 6 2 2 2\n"
                             "encoding: raw\nendian: little\n";
  const fs::path good = Scratch("good.nrrd");
  WriteTestFile(good, header + "\n" + std::string(6 * 8 * 4, '\0'));
  EXPECT_EQ(riemann::CheckNrrdFile(good.string()), "");
  const struct
  {
    const char* Name;
    std::string Bytes;
    const char* Reason;
  } cases[] = {
    { "short.nrrd", header + "\n" + std::string(10, '\0'),
      "declares 192 bytes of values, but the file has 10 after its header" },
    { "sizes.nrrd", "NRRD0004\ntype: float\ndimension: 4\nsizes: 6 2 2\nencoding: raw\n\n",
      "\"dimension: 4\" but 3 sizes" },
    { "zero.nrrd", "NRRD0004\ntype: float\ndimension: 4\nsizes: 6 0 2 2\nencoding: raw\n\n",
      "\"0\" is not a positive count" },
    { "type.nrrd", "NRRD0004\ntype: quad\ndimension: 1\nsizes: 6\nencoding: raw\n\n",
      "unknown type \"quad\"" },
    { "encoding.nrrd", "NRRD0004\ntype: float\ndimension: 1\nsizes: 6\nencoding: bzip2\n\n",
      "\"encoding: bzip2\"; tensor files are read raw or gzip" },
    { "device.nhdr", header + "data file: /dev/zero\n",
      "/dev/zero: the data file is not a regular file" },
    { "missing.nhdr", header + "data file: nowhere.raw\n", "nowhere.raw: the data file does not exist" },
    { "huge.nrrd",
      "NRRD0004\ntype: double\ndimension: 4\nsizes: 6 1000 1000 1000\nencoding: gzip\n\n",
      "the header declares more than 2 GiB of values" },
  };
  for (const auto& c : cases)
  {
    const fs::path file = Scratch(c.Name);
    WriteTestFile(file, c.Bytes);
    const std::string problem = riemann::CheckNrrdFile(file.string());
    EXPECT_NE(problem.find(c.Reason), std::string::npos) << c.Name << ": " << problem;
  }
}

TEST(HostileTensors, GzipNrrdIsReadWhole)
{
  // 40^3 tensors diag(2, 3, 4), gzip-encoded, 0.1 apart from the origin.
  // VTK 9.1's vtkNrrdReader gave 47,998 of the 64,000 tuples as zeros (so
  // "not positive definite", or with "repair": "clamp" a wrong metric,
  // silently); the file is now inflated by zlib, whole.
  const fs::path file = HostileTensors() / "gz_40_gzip.nrrd";
  for (const char* repair : { "", R"(, "repair": "clamp")" })
  {
    const fs::path json = Scratch(std::string("gzip") + (*repair ? "-clamp" : "") + ".json");
    std::ofstream(json) << R"({"type": "sampled", "file": ")" << file.string() << "\"" << repair
                        << "}";
    vtkNew<vtkRiemannMetric> metric;
    ASSERT_TRUE(metric->SetDefinitionFile(json.c_str())) << metric->GetLastError();
    int checked = 0;
    for (double x = 0.05; x < 3.9; x += 0.37)
    {
      for (double y = 0.0; y < 3.9; y += 0.53)
      {
        for (double z = 0.1; z < 3.9; z += 0.71)
        {
          riemann::Mat3 g;
          ASSERT_TRUE(metric->GetMetric()->Tensor(riemann::Vec3(x, y, z), g));
          const riemann::Mat3 expected = riemann::Vec3(2, 3, 4).asDiagonal();
          // The default reading ("christoffel": "voxels") interpolates the
          // samples in float; a tuple read as zero would be off by 2 or more.
          EXPECT_LT((g - expected).cwiseAbs().maxCoeff(), 1e-6) << x << ", " << y << ", " << z;
          ++checked;
        }
      }
    }
    EXPECT_GT(checked, 300);
  }
}

TEST(HostileTensors, GzipNrrdSizesMustMatch)
{
  // A gzip body that inflates to less than the header declares.
  const std::string header = "NRRD0004\ntype: float\ndimension: 4\nsizes: 6 2 2 2\n"
                             "encoding: gzip\nendian: little\n\n";
  std::ifstream in(HostileTensors() / "gz_40_gzip.nrrd", std::ios::binary);
  const std::string original((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t body = original.find("\n\n") + 2;
  const fs::path more = Scratch("more.nrrd");
  WriteTestFile(more, header + original.substr(body)); // 1.5 MB of values for 192 bytes
  const std::string error = MetricError(more);
  EXPECT_NE(error.find("inflates to more than the 192 bytes the header declares"),
    std::string::npos)
    << error;
  const fs::path less = Scratch("less.nrrd");
  WriteTestFile(less,
    "NRRD0004\ntype: float\ndimension: 4\nsizes: 6 80 40 40\nencoding: gzip\nendian: little\n\n" +
      original.substr(body));
  EXPECT_NE(MetricError(less).find("inflates to 1536000 bytes; the header declares 3072000"),
    std::string::npos)
    << MetricError(less);
}

TEST(HostileTensors, VtiHeadersAreChecked)
{
  // A 2 x 2 x 2 image of 6 float64 values a point, raw appended data (384
  // bytes): good as written; each case changes one attribute.
  const auto vti = [](const std::string& extent, const std::string& spacing, int points)
  {
    const std::uint32_t bytes = static_cast<std::uint32_t>(points * 6 * 8);
    std::string data(4 + bytes, '\0');
    std::memcpy(&data[0], &bytes, 4);
    for (int i = 0; i < points; ++i)
    {
      const double tensor[6] = { 2, 3, 4, 0, 0, 0 };
      std::memcpy(&data[4 + 48 * i], tensor, 48);
    }
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"0.1\" "
           "byte_order=\"LittleEndian\" header_type=\"UInt32\">\n<ImageData WholeExtent=\"" +
      extent + "\" Origin=\"0 0 0\" Spacing=\"" + spacing +
      "\">\n<Piece Extent=\"" + extent +
      "\">\n<PointData><DataArray type=\"Float64\" Name=\"Tensors\" "
      "NumberOfComponents=\"6\" format=\"appended\" offset=\"0\"/></PointData>\n"
      "</Piece>\n</ImageData>\n<AppendedData encoding=\"raw\">\n_" +
      data + "\n</AppendedData>\n</VTKFile>\n";
  };
  const fs::path good = Scratch("good.vti");
  WriteTestFile(good, vti("0 1 0 1 0 1", "0.5 0.5 0.5", 8));
  EXPECT_EQ(riemann::CheckVtiFile(good.string()), "");
  EXPECT_EQ(MetricError(good), "");
  const struct
  {
    const char* Name;
    std::string Bytes;
    const char* Reason;
  } cases[] = {
    { "more.vti", vti("0 99 0 99 0 99", "0.5 0.5 0.5", 8),
      "its WholeExtent declares 1000000 points (0.0224 GiB of tensors at the least) but the file "
      "has" },
    { "reversed.vti", vti("0 1 3 0 0 1", "0.5 0.5 0.5", 8),
      "its WholeExtent is empty or reversed on axis 1 (3 to 0)" },
    { "huge.vti", vti("0 4000 0 4000 0 4000", "0.5 0.5 0.5", 8),
      "declares more than 2 GiB of tensors" },
    { "nan.vti", vti("0 1 0 1 0 1", "0.5 nan 0.5", 8),
      "its Spacing \"0.5 nan 0.5\" is not 3 finite numbers" },
    { "word.vti", vti("0 1 0 1 0 1", "0.5 0.5 x", 8), "its Spacing \"0.5 0.5 x\"" },
    { "two.vti", vti("0 1 0 1 0 1", "0.5 0.5", 8), "is not 3 finite numbers" },
  };
  for (const auto& c : cases)
  {
    const fs::path file = Scratch(c.Name);
    WriteTestFile(file, c.Bytes);
    const std::string problem = riemann::CheckVtiFile(file.string());
    EXPECT_NE(problem.find(c.Reason), std::string::npos) << c.Name << ": " << problem;
    EXPECT_NE(MetricError(file).find(c.Reason), std::string::npos) << c.Name;
  }
  EXPECT_NE(riemann::CheckVtiFile("/dev/zero").find("is not a regular file"), std::string::npos);
}

TEST(HostileTensors, FoundByFuzzing)
{
  // Testing/Fuzz/tensor-corpus/found-*: a NIfTI vox_offset of 2.8e20 (its
  // conversion to an integer was undefined), a NRRD header whose last line
  // has no newline (its length was counted a byte past the file), a NUL
  // byte in a size.
  const fs::path corpus =
    riemann::testing::SourceDirectory() / "Testing" / "Fuzz" / "tensor-corpus";
  EXPECT_NE(riemann::CheckNiftiFile((corpus / "found-vox-offset-2.8e20.nii").string())
              .find("vox_offset 2.81751e+20 is not a byte offset"),
    std::string::npos);
  const fs::path cut = Scratch("no-newline.nrrd");
  WriteTestFile(cut, "NRRD0004\ntype: float");
  const riemann::NrrdHeader header = riemann::ReadNrrdHeader(cut.string());
  EXPECT_TRUE(header.Magic);
  EXPECT_EQ(header.Bytes, 20u) << "the file's length, not a byte more";
  EXPECT_EQ(header.Fields.at("type"), "float");
  // A NUL byte inside a size ended strtoull's reading: "40666...6\0..." passed
  // as a count (found-nul-in-sizes.nrrd).
  const fs::path nul = Scratch("nul-size.nrrd");
  WriteTestFile(nul, std::string("NRRD0004\ntype: float\ndimension: 1\nsizes: 6\0\0 \nencoding: raw\n\n", 61));
  EXPECT_NE(riemann::CheckNrrdFile(nul.string()).find("\"6\\x00\\x00\" is not a positive count"),
    std::string::npos)
    << riemann::CheckNrrdFile(nul.string());
  EXPECT_NE(riemann::CheckNrrdFile((corpus / "found-nul-in-sizes.nrrd").string()).find("is not a positive count"),
    std::string::npos);
  // Binary text is shown as \xNN, never raw.
  const fs::path binary = Scratch("binary.nrrd");
  WriteTestFile(binary, std::string("NRRD0004\ntype: fl\x01\0at\ndimension: 1\nsizes: 6\nencoding: raw\n\n", 58));
  EXPECT_NE(riemann::CheckNrrdFile(binary.string()).find("unknown type \"fl\\x01\\x00at\""),
    std::string::npos)
    << riemann::CheckNrrdFile(binary.string());
}

