#include "RiemannTractFiles.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <Eigen/LU>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace riemann
{
namespace
{
/// The most points a streamline file may hold when read (about 2.4 GB of float32).
constexpr std::uint64_t MaximumTractPoints = 200000000;

std::runtime_error FileError(const std::string& path, const std::string& what)
{
  return std::runtime_error(path + ": " + what);
}

/// Append `value`'s bytes, little-endian (this library's hosts are; checked below).
template <typename T>
void Put(std::string& bytes, T value)
{
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

template <typename T>
T Get(const std::string& bytes, std::size_t offset)
{
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

bool HostIsLittleEndian()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

void WriteWhole(const std::string& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out)
  {
    throw FileError(path, "could not be written");
  }
}

std::string ReadWhole(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw FileError(path, "could not be opened");
  }
  std::ostringstream contents;
  contents << in.rdbuf();
  return contents.str();
}

/// The 4x4 voxel-to-world affine of a reference: world = Origin + Direction diag(Spacing) ijk.
Eigen::Matrix4d VoxelToWorld(const TractReference& reference)
{
  Eigen::Matrix4d affine = Eigen::Matrix4d::Identity();
  affine.topLeftCorner<3, 3>() = reference.Direction * reference.Spacing.asDiagonal();
  affine.topRightCorner<3, 1>() = reference.Origin;
  return affine;
}

/// NIfTI's axis codes of an affine's voxel axes: for each, the world axis it
/// runs closest to, as R/L, A/P, S/I by its sign (nibabel's aff2axcodes).
std::string AxisCodes(const Mat3& axes)
{
  static const char positive[3] = { 'R', 'A', 'S' };
  static const char negative[3] = { 'L', 'P', 'I' };
  std::string codes;
  for (int voxelAxis = 0; voxelAxis < 3; ++voxelAxis)
  {
    Eigen::Index worldAxis = 0;
    axes.col(voxelAxis).cwiseAbs().maxCoeff(&worldAxis);
    codes += axes(worldAxis, voxelAxis) >= 0.0 ? positive[worldAxis] : negative[worldAxis];
  }
  return codes;
}

/// Which world axis (0, 1, 2) an axis code names and whether it is the positive end.
bool AxisOfCode(char code, int& axis, bool& positive)
{
  static const std::string positives = "RAS";
  static const std::string negatives = "LPI";
  const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(code)));
  if (positives.find(upper) != std::string::npos)
  {
    axis = static_cast<int>(positives.find(upper));
    positive = true;
    return true;
  }
  if (negatives.find(upper) != std::string::npos)
  {
    axis = static_cast<int>(negatives.find(upper));
    positive = false;
    return true;
  }
  return false;
}

void CheckPointCount(const std::string& path, std::uint64_t points)
{
  if (points > MaximumTractPoints)
  {
    throw FileError(path, "holds more than " + std::to_string(MaximumTractPoints) +
        " points (about " + std::to_string(points) + "), more than riemann reads");
  }
}

std::vector<Tract> ReadTck(const std::string& path, const std::string& bytes)
{
  // The header: "mrtrix tracks", key: value lines, "END".
  std::size_t end = bytes.find("\nEND\n");
  if (bytes.compare(0, 14, "mrtrix tracks\n") != 0 || end == std::string::npos)
  {
    throw FileError(path, "not an MRtrix .tck file (no \"mrtrix tracks\" header ending in END)");
  }
  std::istringstream header(bytes.substr(14, end - 14));
  std::string line, datatype;
  long long offset = -1;
  while (std::getline(header, line))
  {
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos)
    {
      continue;
    }
    const std::string key = line.substr(0, colon);
    std::istringstream value(line.substr(colon + 1));
    if (key == "datatype")
    {
      value >> datatype;
    }
    else if (key == "file")
    {
      std::string dot;
      value >> dot >> offset;
      if (dot != ".")
      {
        throw FileError(path, "its data is in another file (\"file: " + dot + "\"), not read");
      }
    }
  }
  const std::size_t size = datatype == "Float32LE" ? 4 : datatype == "Float64LE" ? 8 : 0;
  if (size == 0)
  {
    throw FileError(path, "datatype \"" + datatype + "\": riemann reads Float32LE and Float64LE");
  }
  if (offset < static_cast<long long>(end + 5) || offset > static_cast<long long>(bytes.size()))
  {
    throw FileError(path, "\"file: . " + std::to_string(offset) + "\" is not an offset in the file");
  }
  std::vector<Tract> tracts;
  Tract current;
  const std::size_t triplet = 3 * size;
  CheckPointCount(path, (bytes.size() - static_cast<std::size_t>(offset)) / triplet);
  for (std::size_t at = static_cast<std::size_t>(offset); at + triplet <= bytes.size(); at += triplet)
  {
    Vec3 x;
    for (int c = 0; c < 3; ++c)
    {
      x[c] = size == 4 ? Get<float>(bytes, at + c * size) : Get<double>(bytes, at + c * size);
    }
    if (std::isinf(x[0]))
    {
      return tracts; // the end
    }
    if (std::isnan(x[0]))
    {
      tracts.push_back(std::move(current));
      current.clear();
      continue;
    }
    current.push_back(x);
  }
  throw FileError(path, "ends before its end marker (a truncated .tck file)");
}

std::vector<Tract> ReadTrk(const std::string& path, const std::string& bytes)
{
  if (bytes.size() < 1000 || bytes.compare(0, 5, "TRACK") != 0)
  {
    throw FileError(path, "not a TrackVis .trk file (no \"TRACK\" header of 1000 bytes)");
  }
  if (Get<std::int32_t>(bytes, 996) != 1000)
  {
    throw FileError(path, "header size is not 1000 (a big-endian or damaged .trk file)");
  }
  const int scalars = Get<std::int16_t>(bytes, 36);
  const int properties = Get<std::int16_t>(bytes, 238);
  if (scalars < 0 || properties < 0)
  {
    throw FileError(path, "negative counts of scalars or properties in its header");
  }
  Vec3 voxelSize;
  for (int a = 0; a < 3; ++a)
  {
    voxelSize[a] = Get<float>(bytes, 12 + 4 * a);
  }
  Eigen::Matrix4d voxelToRas;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      voxelToRas(r, c) = Get<float>(bytes, 440 + 4 * (4 * r + c));
    }
  }
  if (voxelToRas(3, 3) == 0.0)
  {
    voxelToRas.setIdentity(); // TrackVis 1 files: nibabel reads them so too
  }
  if (!(voxelSize.minCoeff() > 0.0) || !voxelSize.allFinite())
  {
    throw FileError(path, "voxel sizes are not positive");
  }
  // voxmm -> voxel: divide by the voxel sizes and move by half a voxel (the
  // voxmm origin is the first voxel's corner, a voxel's index its centre).
  Eigen::Matrix4d toVoxels = Eigen::Matrix4d::Identity();
  toVoxels.topLeftCorner<3, 3>() = voxelSize.cwiseInverse().asDiagonal();
  toVoxels.topRightCorner<3, 1>() = Vec3::Constant(-0.5);
  // Where the header's voxel order disagrees with the affine's axes, move
  // the voxel axes onto the affine's (permute, reverse), as nibabel does.
  const std::string order(bytes.data() + 948, 3);
  const std::string affineOrder = AxisCodes(voxelToRas.topLeftCorner<3, 3>());
  Eigen::Matrix4d reorder = Eigen::Matrix4d::Identity();
  if (order[0] != '\0' && order != affineOrder)
  {
    reorder.setZero();
    reorder(3, 3) = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      int axis = 0, target = 0;
      bool positive = true, targetPositive = true;
      bool found = false;
      if (!AxisOfCode(order[a], axis, positive))
      {
        throw FileError(path, "voxel order \"" + order + "\" is not made of R/L, A/P, S/I");
      }
      for (int b = 0; b < 3 && !found; ++b)
      {
        AxisOfCode(affineOrder[b], target, targetPositive);
        if (target == axis)
        {
          const double dimension = Get<std::int16_t>(bytes, 6 + 2 * a);
          reorder(b, a) = positive == targetPositive ? 1.0 : -1.0;
          reorder(b, 3) = positive == targetPositive ? 0.0 : dimension - 1.0;
          found = true;
        }
      }
      if (!found)
      {
        throw FileError(path, "voxel order \"" + order + "\" names an axis twice");
      }
    }
  }
  const Eigen::Matrix4d toWorld = voxelToRas * reorder * toVoxels;
  const std::uint64_t count = static_cast<std::uint32_t>(Get<std::int32_t>(bytes, 988));
  std::vector<Tract> tracts;
  std::size_t at = 1000;
  std::uint64_t points = 0;
  while (at + 4 <= bytes.size())
  {
    const std::int32_t n = Get<std::int32_t>(bytes, at);
    at += 4;
    const std::size_t need = (static_cast<std::size_t>(n) * (3 + scalars) + properties) * 4;
    if (n < 0 || at + need > bytes.size())
    {
      throw FileError(path, "streamline " + std::to_string(tracts.size()) +
          " runs past the end of the file (a truncated or damaged .trk file)");
    }
    points += static_cast<std::uint64_t>(n);
    CheckPointCount(path, points);
    Tract tract(static_cast<std::size_t>(n));
    for (std::int32_t k = 0; k < n; ++k)
    {
      Eigen::Vector4d voxmm(0.0, 0.0, 0.0, 1.0);
      for (int c = 0; c < 3; ++c)
      {
        voxmm[c] = Get<float>(bytes, at + 4 * c);
      }
      tract[static_cast<std::size_t>(k)] = (toWorld * voxmm).head<3>();
      at += 4 * static_cast<std::size_t>(3 + scalars);
    }
    at += 4 * static_cast<std::size_t>(properties);
    tracts.push_back(std::move(tract));
  }
  if (count != 0 && count != tracts.size())
  {
    throw FileError(path, "its header counts " + std::to_string(count) + " streamlines, it holds " +
        std::to_string(tracts.size()));
  }
  return tracts;
}
} // namespace

std::vector<Tract> JoinTracesIntoTracts(vtkPolyData* lines, std::vector<TractRecord>* records)
{
  if (records)
  {
    records->clear();
  }
  vtkDataArray* reasonArray = lines->GetCellData()->GetArray("ReasonForTermination");
  vtkDataArray* seedIds = lines->GetCellData()->GetArray("SeedIds");
  vtkDataArray* arcLength = lines->GetPointData()->GetArray("ArcLength");
  vtkCellArray* cells = lines->GetLines();
  // Cell data count vertices before lines (vtkPolyData's cell order).
  const vtkIdType firstLineCell = lines->GetNumberOfVerts();

  // Step 1, serial and cheap: the tracts, each a run of consecutive lines
  // of one seed (lines of fewer than two points skipped).
  struct Run
  {
    vtkIdType First;
    vtkIdType Count;
  };
  std::vector<Run> runs;
  std::vector<vtkIdType> kept;
  long long lastSeed = std::numeric_limits<long long>::min();
  for (vtkIdType line = 0; line < cells->GetNumberOfCells(); ++line)
  {
    if (cells->GetCellSize(line) < 2)
    {
      continue;
    }
    const vtkIdType cell = firstLineCell + line;
    const long long seed =
      seedIds ? static_cast<long long>(seedIds->GetComponent(cell, 0)) : static_cast<long long>(cell);
    if (seed != lastSeed || runs.empty())
    {
      runs.push_back({ static_cast<vtkIdType>(kept.size()), 0 });
      if (records)
      {
        records->emplace_back();
        records->back().SeedId = seed;
      }
      lastSeed = seed;
    }
    kept.push_back(line);
    ++runs.back().Count;
  }

  // Step 2, in parallel (a quarter of a 2-thread trace's time was this,
  // serially, through vtkPolyData's cell links): each tract's points, its
  // backward line reversed, then its forward line, the seed point once.
  std::vector<Tract> tracts(runs.size());
  vtkPoints* points = lines->GetPoints();
  vtkSMPTools::For(0, static_cast<vtkIdType>(runs.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkNew<vtkIdList> ids;
      Tract line;
      for (vtkIdType r = begin; r < end; ++r)
      {
        Tract& tract = tracts[static_cast<std::size_t>(r)];
        for (vtkIdType q = 0; q < runs[r].Count; ++q)
        {
          const vtkIdType lineId = kept[static_cast<std::size_t>(runs[r].First + q)];
          cells->GetCellAtId(lineId, ids);
          const vtkIdType n = ids->GetNumberOfIds();
          line.resize(static_cast<std::size_t>(n));
          for (vtkIdType k = 0; k < n; ++k)
          {
            points->GetPoint(ids->GetId(k), line[static_cast<std::size_t>(k)].data());
          }
          const bool backward = arcLength && arcLength->GetComponent(ids->GetId(n - 1), 0) < 0.0;
          if (records && reasonArray)
          {
            const int reason = static_cast<int>(reasonArray->GetComponent(firstLineCell + lineId, 0));
            TractRecord& record = (*records)[static_cast<std::size_t>(r)];
            (backward ? record.StopAtStart : record.StopAtEnd) = reason;
          }
          if (backward)
          {
            // Before what the seed has so far, reversed: from its far end to the seed.
            Tract joined(line.rbegin(), line.rend());
            joined.insert(joined.end(), tract.begin() + (tract.empty() ? 0 : 1), tract.end());
            tract = std::move(joined);
          }
          else
          {
            tract.insert(tract.end(), line.begin() + (tract.empty() ? 0 : 1), line.end());
          }
        }
      }
    });
  return tracts;
}

void WriteTckFile(const std::string& path, const std::vector<Tract>& tracts)
{
  if (!HostIsLittleEndian())
  {
    throw FileError(path, "streamline files are written on little-endian hosts only");
  }
  std::string data;
  std::size_t values = 3;
  for (const Tract& tract : tracts)
  {
    values += 3 * (tract.size() + 1);
  }
  data.reserve(values * sizeof(float));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (const Tract& tract : tracts)
  {
    for (const Vec3& x : tract)
    {
      Put(data, static_cast<float>(x[0]));
      Put(data, static_cast<float>(x[1]));
      Put(data, static_cast<float>(x[2]));
    }
    Put(data, nan);
    Put(data, nan);
    Put(data, nan);
  }
  Put(data, inf);
  Put(data, inf);
  Put(data, inf);
  // The header names its own length in "file: . OFFSET": pad it to a size
  // that holds the digits whatever they are.
  std::ostringstream header;
  header << "mrtrix tracks\ndatatype: Float32LE\ncount: " << tracts.size()
         << "\ntotal_count: " << tracts.size() << "\nwritten_by: riemann trace\nfile: . ";
  std::string head = header.str();
  const std::size_t offset = ((head.size() + 16 + 5) / 64 + 1) * 64;
  head += std::to_string(offset) + "\nEND\n";
  head.resize(offset, '\0');
  WriteWhole(path, head + data);
}

void WriteTrkFile(const std::string& path, const std::vector<Tract>& tracts,
  const TractReference& reference, const std::vector<TractRecord>* records)
{
  const bool withRecords = records && records->size() == tracts.size();
  if (!HostIsLittleEndian())
  {
    throw FileError(path, "streamline files are written on little-endian hosts only");
  }
  const Eigen::Matrix4d voxelToRas = VoxelToWorld(reference);
  const Eigen::Matrix4d rasToVoxel = voxelToRas.inverse();
  std::string bytes;
  bytes.append("TRACK\0", 6);
  for (int a = 0; a < 3; ++a)
  {
    Put(bytes, static_cast<std::int16_t>(std::min(reference.Dimensions[a], 32767)));
  }
  for (int a = 0; a < 3; ++a)
  {
    Put(bytes, static_cast<float>(reference.Spacing[a]));
  }
  for (int a = 0; a < 3; ++a)
  {
    Put(bytes, 0.0f); // origin: unused by TrackVis 2 readers
  }
  Put(bytes, std::int16_t(0)); // n_scalars
  bytes.append(200, '\0');
  Put(bytes, std::int16_t(withRecords ? 3 : 0)); // n_properties
  std::string names(200, '\0');
  if (withRecords)
  {
    names.replace(0, 7, "seed_id");
    names.replace(20, 13, "stop_at_start");
    names.replace(40, 11, "stop_at_end");
  }
  bytes.append(names);
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      Put(bytes, static_cast<float>(voxelToRas(r, c)));
    }
  }
  bytes.append(444, '\0'); // reserved
  const std::string order = AxisCodes(reference.Direction);
  bytes.append(order);
  bytes.append(1, '\0');
  bytes.append(4, '\0'); // pad2
  for (int i = 0; i < 6; ++i)
  {
    Put(bytes, 0.0f); // image_orientation_patient
  }
  bytes.append(2, '\0'); // pad1
  bytes.append(6, '\0'); // invert_x, y, z, swap_xy, yz, zx
  Put(bytes, static_cast<std::int32_t>(tracts.size()));
  Put(bytes, std::int32_t(2));    // version
  Put(bytes, std::int32_t(1000)); // hdr_size
  if (bytes.size() != 1000)
  {
    throw std::logic_error("a .trk header of " + std::to_string(bytes.size()) + " bytes");
  }
  for (std::size_t t = 0; t < tracts.size(); ++t)
  {
    Put(bytes, static_cast<std::int32_t>(tracts[t].size()));
    for (const Vec3& x : tracts[t])
    {
      const Eigen::Vector4d voxel = rasToVoxel * Eigen::Vector4d(x[0], x[1], x[2], 1.0);
      for (int c = 0; c < 3; ++c)
      {
        Put(bytes, static_cast<float>((voxel[c] + 0.5) * reference.Spacing[c]));
      }
    }
    if (withRecords)
    {
      // float32, as .trk stores properties: exact for seed numbers below 2^24.
      Put(bytes, static_cast<float>((*records)[t].SeedId));
      Put(bytes, static_cast<float>((*records)[t].StopAtStart));
      Put(bytes, static_cast<float>((*records)[t].StopAtEnd));
    }
  }
  WriteWhole(path, bytes);
}

std::vector<Tract> ReadTractFile(const std::string& path)
{
  if (!HostIsLittleEndian())
  {
    throw FileError(path, "streamline files are read on little-endian hosts only");
  }
  const std::string bytes = ReadWhole(path);
  const auto endsWith = [&](const char* ending)
  {
    const std::size_t n = std::strlen(ending);
    return path.size() >= n && path.compare(path.size() - n, n, ending) == 0;
  };
  if (endsWith(".tck"))
  {
    return ReadTck(path, bytes);
  }
  if (endsWith(".trk"))
  {
    return ReadTrk(path, bytes);
  }
  throw FileError(path, "not a streamline file (.tck or .trk)");
}
} // namespace riemann
