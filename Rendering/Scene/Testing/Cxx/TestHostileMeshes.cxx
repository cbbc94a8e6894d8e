// Mesh files that crashed the renderers before the readers validated them
// (Testing/Data/hostile-meshes/README.md): each is now refused with a
// SceneDefinitionError that says what is wrong, before VTK's filters or
// Embree see it. Good PLY files (ASCII and binary, both byte orders,
// written here byte by byte) still load, binary STL files are checked
// against their triangle count, only regular files are read, and a
// vtkPolyData with a bad cell is refused too (MeshFromPolyData, the actors' path).
#include "RiemannPlyCheck.h"
#include "RiemannPolyDataMesh.h"
#include "RiemannScene.h"
#include "RiemannStlCheck.h"
#include "TestDataDirectory.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;

/// The regression inputs, found from the Data folder (not from __FILE__: ccache shares
/// objects between checkouts, and Ninja gives relative paths).
fs::path HostileMeshes()
{
  return riemann::testing::SourceDirectory() / "Rendering" / "Scene" / "Testing" /
    "Data" / "hostile-meshes";
}

fs::path Scratch(const std::string& name)
{
  return riemann::testing::TestOutputDirectory("hostile-meshes") / name;
}

/// The message of the SceneDefinitionError that reading `file` as a scene mesh throws ("" if none).
std::string LoadError(const fs::path& file)
{
  riemann::Scene scene;
  riemann::SceneObject object;
  object.Type = riemann::ObjectType::Mesh;
  object.MeshFile = file.string();
  scene.Objects.push_back(object);
  try
  {
    riemann::LoadSceneMeshes(scene);
  }
  catch (const riemann::SceneDefinitionError& e)
  {
    return e.what();
  }
  return std::string();
}

/// One triangle: a PLY header for `format` and its body.
std::string TrianglePly(const std::string& format, const std::string& body)
{
  return "ply\nformat " + format +
    " 1.0\ncomment written by TestHostileMeshes\nelement vertex 3\nproperty float x\n"
    "property float y\nproperty float z\nelement face 1\nproperty list uchar int "
    "vertex_indices\nend_header\n" +
    body;
}

/// The binary body of the triangle (0,0,0), (1,0,0), (0,1,0) with face indices `indices`.
std::string BinaryTriangle(bool bigEndian, const std::vector<std::int32_t>& indices)
{
  std::string body;
  const auto put = [&](const void* value, std::size_t size)
  {
    std::string bytes(static_cast<const char*>(value), size);
    if (bigEndian)
    {
      bytes.assign(bytes.rbegin(), bytes.rend()); // this test runs on little-endian machines
    }
    body += bytes;
  };
  const float xyz[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  for (float v : xyz)
  {
    put(&v, sizeof(v));
  }
  const unsigned char count = static_cast<unsigned char>(indices.size());
  put(&count, 1);
  for (std::int32_t index : indices)
  {
    put(&index, sizeof(index));
  }
  return body;
}

using riemann::testing::WriteTestFile;
} // namespace

TEST(HostileMeshes, EachIsRefusedWithItsReason)
{
  const struct
  {
    const char* File;
    const char* Reason;
  } cases[] = {
    { "badindex.obj", "refers to point 999999998 (counting from 0), but the mesh has 3 points" },
    { "badconn.vtp", "refers to point 999999999 (counting from 0), but the mesh has 3 points" },
    { "badindex.ply", "face 1 refers to vertex 99999999, but there are 3 vertices" },
    { "trunc05_ok.ply", "the file ends in element face, row 4126 of 15360 (cut short?)" },
    { "trunc001_ok_ascii.ply", "the file ends in element vertex, row 134 of 7680 (cut short?)" },
  };
  for (const auto& c : cases)
  {
    const fs::path file = HostileMeshes() / c.File;
    ASSERT_TRUE(fs::exists(file)) << file;
    const std::string error = LoadError(file);
    EXPECT_NE(error.find(c.Reason), std::string::npos) << c.File << ": " << error;
    EXPECT_NE(error.find(file.string()), std::string::npos) << "names the file: " << error;
  }
}

TEST(HostileMeshes, GoodPlyFilesStillLoad)
{
  const std::string ascii = TrianglePly("ascii", "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const std::string little = TrianglePly("binary_little_endian", BinaryTriangle(false, { 0, 1, 2 }));
  const std::string big = TrianglePly("binary_big_endian", BinaryTriangle(true, { 0, 1, 2 }));
  for (const auto& [name, bytes] : { std::pair<std::string, std::string>{ "ascii.ply", ascii },
         { "little.ply", little }, { "big.ply", big } })
  {
    const fs::path file = Scratch(name);
    WriteTestFile(file, bytes);
    EXPECT_EQ(riemann::CheckPlyFile(file.string()), "") << name;
    EXPECT_EQ(LoadError(file), "") << name;
  }
}

TEST(HostileMeshes, PlyProblemsAreNamed)
{
  const struct
  {
    const char* Name;
    std::string Bytes;
    const char* Reason;
  } cases[] = {
    { "negative.ply", TrianglePly("ascii", "0 0 0\n1 0 0\n0 1 0\n3 0 -5 2\n"),
      "face 1 refers to vertex -5, but there are 3 vertices" },
    { "word.ply", TrianglePly("ascii", "0 0 zero\n1 0 0\n0 1 0\n3 0 1 2\n"),
      "element vertex, row 1 of 3: \"zero\" is not a number" },
    { "big-index.ply", TrianglePly("binary_big_endian", BinaryTriangle(true, { 0, 1, 3 })),
      "face 1 refers to vertex 3, but there are 3 vertices" },
    { "short.ply", // the last index's 4 bytes cut off
      TrianglePly("binary_little_endian", BinaryTriangle(false, { 0, 1, 2 }).substr(0, 9 * 4 + 1 + 8)),
      "the file ends in element face, row 1 of 1 (cut short?)" },
    { "format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n",
      "header line 2: unknown format \"binary_middle_endian\"" },
    { "noend.ply", "ply\nformat ascii 1.0\nelement vertex 3\n", "no end_header line" },
    { "type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n0\n",
      "header line 4: unknown property type \"quad\"" },
    { "count.ply", "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n",
      "header line 3: an element needs a name and a count of rows" },
    // Found by fuzzing (Testing/Fuzz/mesh-corpus/found-*): the file's bytes
    // are shown as \xNN, never raw on the terminal.
    { "nul-row.ply", // a NUL byte was read as the number 0
      std::string("ply\nformat ascii 1.0\nelement v 2\nproperty float x\nend_header\n1\n\0\n", 65),
      "element v, row 2 of 2: \"\\x00\" is not a number" },
    { "binary-word.ply", TrianglePly("ascii", std::string("0 0 \x01\0\n1 0 0\n0 1 0\n3 0 1 2\n", 24)),
      "\"\\x01\\x00\" is not a number" },
    { "binary-name.ply",
      std::string("ply\nformat ascii 1.0\nelement v\x08x 2\nproperty float x\nend_header\n1\n"),
      "the file ends in element v\\x08x, row 2 of 2" },
  };
  for (const auto& c : cases)
  {
    const fs::path file = Scratch(c.Name);
    WriteTestFile(file, c.Bytes);
    const std::string problem = riemann::CheckPlyFile(file.string());
    EXPECT_NE(problem.find(c.Reason), std::string::npos) << c.Name << ": " << problem;
    EXPECT_NE(LoadError(file).find(c.Reason), std::string::npos) << c.Name;
  }
}

/// A binary STL: 80-byte header, the count, 50 bytes a triangle (normal, 3 corners, attribute).
std::string BinaryStl(std::uint32_t declared, int written, const char* header = "binary")
{
  std::string bytes(80, ' ');
  std::memcpy(&bytes[0], header, std::strlen(header));
  bytes.append(reinterpret_cast<const char*>(&declared), 4); // little-endian machines only
  for (int t = 0; t < written; ++t)
  {
    const float values[12] = { 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0 };
    bytes.append(reinterpret_cast<const char*>(values), sizeof(values));
    bytes.append(2, '\0');
  }
  return bytes;
}

TEST(HostileMeshes, StlFilesAreCheckedAgainstTheirCount)
{
  // VTK 9.1 read a binary STL cut short without a word (the missing
  // triangles were simply not there).
  const struct
  {
    const char* Name;
    std::string Bytes;
    const char* Reason; // "" : loads
  } cases[] = {
    { "good.stl", BinaryStl(2, 2), "" },
    { "solid-header.stl", BinaryStl(2, 2, "solid exported by a tool"), "" },
    { "ascii.stl",
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nendsolid t\n",
      "" },
    { "cut.stl", BinaryStl(448, 99),
      "a binary STL of 448 triangles takes 22484 bytes, the file has 5034 (cut short?)" },
    { "long.stl", BinaryStl(1, 3), "a binary STL of 1 triangles takes 134 bytes, the file has 234" },
    { "tiny.stl", "abc", "the file has 3 bytes, fewer than a binary STL's 84-byte header" },
  };
  for (const auto& c : cases)
  {
    const fs::path file = Scratch(c.Name);
    WriteTestFile(file, c.Bytes);
    const std::string problem = riemann::CheckStlFile(file.string());
    const std::string error = LoadError(file);
    if (*c.Reason == '\0')
    {
      EXPECT_EQ(problem, "") << c.Name;
      EXPECT_EQ(error, "") << c.Name;
    }
    else
    {
      EXPECT_NE(problem.find(c.Reason), std::string::npos) << c.Name << ": " << problem;
      EXPECT_NE(error.find(c.Reason), std::string::npos) << c.Name << ": " << error;
    }
  }
}

TEST(HostileMeshes, OnlyRegularFilesAreRead)
{
  EXPECT_NE(LoadError("/dev/zero").find("(/dev/zero): the mesh file is not a regular file"),
    std::string::npos)
    << LoadError("/dev/zero");
  EXPECT_NE(LoadError(Scratch("")).find("the mesh file is a folder"), std::string::npos);
  EXPECT_NE(LoadError(Scratch("nowhere.obj")).find("the mesh file does not exist"),
    std::string::npos);
}

TEST(HostileMeshes, VtkReadersMessagesArePlainSentences)
{
  // A VTK reader's error reaches the user without VTK's source path and the
  // reader's address (RiemannVtkMessages.h).
  const fs::path file = Scratch("garbage.vtp");
  WriteTestFile(file, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\"><PolyData><Piece");
  const std::string error = LoadError(file);
  EXPECT_NE(error.find("cannot read the mesh: vtkXMLPolyDataReader: "), std::string::npos) << error;
  EXPECT_EQ(error.find("ERROR: In"), std::string::npos) << error;
  EXPECT_EQ(error.find("(0x"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST(HostileMeshes, PolyDataWithABadCellIsRefused)
{
  // The path of a renderer's actors (MeshFromPolyData), with no file.
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  vtkNew<vtkCellArray> triangles;
  const vtkIdType good[3] = { 0, 1, 2 };
  const vtkIdType bad[3] = { 0, 1, 7 };
  triangles->InsertNextCell(3, good);
  triangles->InsertNextCell(3, bad);
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetPolys(triangles);
  try
  {
    riemann::MeshFromPolyData(data);
    FAIL() << "a cell past the points was accepted";
  }
  catch (const riemann::SceneDefinitionError& e)
  {
    EXPECT_NE(std::string(e.what()).find("refers to point 7 (counting from 0), but the mesh has 3"),
      std::string::npos)
      << e.what();
  }
}
