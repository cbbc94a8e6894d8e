// {"type": "sampled"} and vtkRiemannMetric::SetTensorData: tensor volumes
// as metrics, read with VTK's readers. Exact answers:
// - an affine tensor field written to a .vti (rotated grid, unequal
//   spacings) and read through a metric file naming it relatively is g
//   itself inside the volume (the cubic B-spline reproduces affine fields),
//   and the identity outside;
// - "inverse" of a constant diffusion tensor is its inverse, "scale"
//   multiplies, the same through a legacy .vtk file, a 9-component array
//   and SetTensorData;
// - bad data and bad definitions are refused with messages that say what
//   and where: a missing file, a missing or misshapen array (listing the
//   arrays), an asymmetric 9-component tensor, non-positive-definite
//   samples (how many, the first's index, position and eigenvalue), an
//   unknown format, an unknown "outside";
// - NIfTI and NRRD: the affine field in a NIfTI file with intent SYMMATRIX
//   (NIfTI's lower-triangle order) placed by a rotated q-form is g itself
//   in world coordinates; a 4D FSL-style file (six volumes, dtifit's order,
//   scl_slope 2) and raw NRRD files (Teem's order, 6 and 7 components) give the
//   inverse of their diffusion tensor; a NRRD file with rotated "space
//   directions", a "space origin" and a rotated "measurement frame" is the
//   affine field itself in world coordinates; wrong component counts and
//   sheared axes are refused.
#include "vtkRiemannMetric.h"

#include "VoxelChristoffelMetric.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNIFTIImageHeader.h"
#include "vtkNIFTIImageWriter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStructuredPointsWriter.h"
#include "vtkXMLImageDataWriter.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

namespace
{
namespace fs = std::filesystem;
using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

/// g = A + x_0 B0 + x_1 B1 + x_2 B2, positive definite near the origin.
Mat3 Affine(const Vec3& x)
{
  Mat3 a, b0, b1, b2;
  a << 3.0, 0.4, -0.2, 0.4, 2.5, 0.3, -0.2, 0.3, 2.0;
  b0 << 0.2, 0.1, 0.0, 0.1, -0.1, 0.05, 0.0, 0.05, 0.15;
  b1 << -0.1, 0.0, 0.08, 0.0, 0.2, -0.1, 0.08, -0.1, 0.1;
  b2 << 0.05, -0.07, 0.0, -0.07, 0.1, 0.0, 0.0, 0.0, -0.2;
  return a + x[0] * b0 + x[1] * b1 + x[2] * b2;
}

Mat3 Diffusion()
{
  Mat3 d;
  d << 1.6, 1.4, 0.0, 1.4, 1.6, 0.0, 0.0, 0.0, 0.3;
  return d;
}

Mat3 Rotation()
{
  return Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix();
}

/// A 9 x 8 x 7 image over a rotated box, with point data "Tensors" (6 or 9
/// components of `field`) and a scalar "FA".
vtkSmartPointer<vtkImageData> TensorImage(
  const std::function<Mat3(const Vec3&)>& field, int components = 6)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(9, 8, 7);
  image->SetSpacing(0.25, 0.3, 0.35);
  image->SetOrigin(-1.0, -1.0, -1.0);
  const Mat3 r = Rotation();
  image->SetDirectionMatrix(
    r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2));
  vtkNew<vtkDoubleArray> tensors;
  tensors->SetName("Tensors");
  tensors->SetNumberOfComponents(components);
  tensors->SetNumberOfTuples(image->GetNumberOfPoints());
  vtkNew<vtkDoubleArray> fa;
  fa->SetName("FA");
  fa->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    double x[3];
    image->GetPoint(p, x);
    const Mat3 g = field(Vec3(x[0], x[1], x[2]));
    if (components == 6)
    {
      const double values[6] = { g(0, 0), g(1, 1), g(2, 2), g(0, 1), g(1, 2), g(0, 2) };
      tensors->SetTypedTuple(p, values);
    }
    else
    {
      const double values[9] = { g(0, 0), g(0, 1), g(0, 2), g(1, 0), g(1, 1), g(1, 2), g(2, 0),
        g(2, 1), g(2, 2) };
      tensors->SetTypedTuple(p, values);
    }
    fa->SetValue(p, 0.5);
  }
  image->GetPointData()->AddArray(tensors);
  image->GetPointData()->AddArray(fa);
  return image;
}

/// A folder of this test's own: ctest runs the tests two at a time, and two
/// tests writing bad.json in one folder read each other's.
fs::path Folder()
{
  const char* output = std::getenv("RIEMANN_TEST_OUTPUT_DIR");
  fs::path folder = fs::path(output ? output : fs::temp_directory_path().string()) / "sampled" /
    ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(folder);
  return folder;
}

void WriteVti(vtkImageData* image, const fs::path& path)
{
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1);
}

/// A metric file `name` next to the data holding `json`; returns its path.
fs::path MetricFile(const std::string& name, const std::string& json)
{
  const fs::path path = Folder() / name;
  std::ofstream(path) << json;
  return path;
}

/**
 * g at x as the spline of the samples gives it: what these tests check is
 * how files are read and placed, which the spline reproduces exactly for
 * affine fields. The default reading ("christoffel": "voxels") holds the
 * samples in float, trilinear, and constant between the outer voxels and
 * the faces (CommonMetric.VoxelChristoffel tests it).
 */
Mat3 MetricAt(vtkRiemannMetric* metric, const Vec3& x)
{
  double read[9];
  EXPECT_TRUE(metric->EvaluateMetricTensor(x.data(), read));
  const std::shared_ptr<const riemann::Metric> current = metric->GetMetric();
  const auto* voxels = dynamic_cast<const riemann::VoxelChristoffelMetric*>(current.get());
  if (!voxels)
  {
    return Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(read);
  }
  Mat3 spline;
  EXPECT_TRUE(voxels->GetExact().Tensor(x, spline));
  return spline;
}

/// The definition's error, or "" if it was accepted.
std::string ErrorOf(const std::string& json)
{
  vtkNew<vtkRiemannMetric> metric;
  const fs::path path = MetricFile("bad.json", json);
  return metric->SetDefinitionFile(path.c_str()) ? std::string() : metric->GetLastError();
}
} // namespace

TEST(SampledMetric, AffineFieldFromAVtiFileIsReproduced)
{
  WriteVti(TensorImage(Affine), Folder() / "affine.vti");
  vtkNew<vtkRiemannMetric> metric;
  const fs::path path =
    MetricFile("affine.json", R"({"type": "sampled", "file": "affine.vti", "array": "Tensors"})");
  ASSERT_TRUE(metric->SetDefinitionFile(path.c_str())) << metric->GetLastError();
  EXPECT_EQ(metric->GetFamilyName(), "tensor");
  // Inside, one cell from the faces: g itself. Grid point (4, 4, 3) and around.
  for (const Vec3& index : { Vec3(4, 4, 3), Vec3(2.3, 5.1, 1.7), Vec3(6.2, 1.5, 4.9) })
  {
    const Vec3 x = Vec3(-1, -1, -1) + Rotation() * index.cwiseProduct(Vec3(0.25, 0.3, 0.35));
    EXPECT_LT((MetricAt(metric, x) - Affine(x)).cwiseAbs().maxCoeff(), 1e-12) << index.transpose();
  }
  EXPECT_EQ(MetricAt(metric, Vec3(5, 5, 5)), Mat3::Identity()); // outside: Euclidean
  // SetTime re-reads the definition from the same folder.
  EXPECT_TRUE(metric->SetTime(0.5)) << metric->GetLastError();
}

TEST(SampledMetric, InverseAndScaleThroughEveryFormat)
{
  const Mat3 expected = 2.0 * Diffusion().inverse();
  const Vec3 x(-0.4, -0.2, 0.1);
  // .vti, 6 components, default array (the only 6- or 9-component one).
  WriteVti(TensorImage([](const Vec3&) { return Diffusion(); }), Folder() / "dti.vti");
  vtkNew<vtkRiemannMetric> metric;
  fs::path path = MetricFile(
    "dti.json", R"({"type": "sampled", "file": "dti.vti", "inverse": true, "scale": 2})");
  ASSERT_TRUE(metric->SetDefinitionFile(path.c_str())) << metric->GetLastError();
  EXPECT_LT((MetricAt(metric, x) - expected).cwiseAbs().maxCoeff(), 1e-12);
  // Legacy .vtk, 9 components (it keeps no direction: an axis-aligned grid).
  {
    vtkSmartPointer<vtkImageData> image = TensorImage([](const Vec3&) { return Diffusion(); }, 9);
    image->SetDirectionMatrix(1, 0, 0, 0, 1, 0, 0, 0, 1);
    vtkNew<vtkStructuredPointsWriter> writer;
    writer->SetInputData(image);
    writer->SetFileName((Folder() / "dti9.vtk").c_str());
    writer->SetFileTypeToBinary();
    ASSERT_EQ(writer->Write(), 1);
  }
  path = MetricFile("dti9.json",
    R"({"type": "sampled", "file": "dti9.vtk", "array": "Tensors", "inverse": true, "scale": 2})");
  ASSERT_TRUE(metric->SetDefinitionFile(path.c_str())) << metric->GetLastError();
  EXPECT_LT((MetricAt(metric, x) - expected).cwiseAbs().maxCoeff(), 1e-12);
  // In memory.
  ASSERT_TRUE(metric->SetTensorData(
    TensorImage([](const Vec3&) { return Diffusion(); }), "Tensors", true, 2.0))
    << metric->GetLastError();
  EXPECT_LT((MetricAt(metric, x) - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_TRUE(metric->SetTime(0.3));
  EXPECT_LT((MetricAt(metric, x) - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NE(std::string(metric->GetDefinition()).find("\"inverse\": true"), std::string::npos);
}

TEST(SampledMetric, BadDataAndDefinitionsSayWhatAndWhere)
{
  WriteVti(TensorImage(Affine), Folder() / "affine.vti");
  std::string error = ErrorOf(R"({"type": "sampled", "file": "missing.vti"})");
  EXPECT_NE(error.find("metric.file: "), std::string::npos) << error;
  EXPECT_NE(error.find("missing.vti: the tensor file does not exist"), std::string::npos) << error;

  error = ErrorOf(R"({"type": "sampled", "file": "affine.vti", "array": "D"})");
  EXPECT_NE(error.find("no point-data array \"D\"; the arrays are Tensors (6 components), FA (1 "
                       "component)"),
    std::string::npos)
    << error;
  error = ErrorOf(R"({"type": "sampled", "file": "affine.vti", "array": "FA"})");
  EXPECT_NE(error.find("array \"FA\" has 1 components; a tensor has 6"), std::string::npos)
    << error;

  {
    vtkSmartPointer<vtkImageData> image = TensorImage(Affine, 9);
    vtkDataArray* tensors = image->GetPointData()->GetArray("Tensors");
    tensors->SetComponent(10, 1, 7.0); // (0, 1) no longer equals (1, 0)
    WriteVti(image, Folder() / "asymmetric.vti");
  }
  error = ErrorOf(R"({"type": "sampled", "file": "asymmetric.vti"})");
  EXPECT_NE(error.find("the tensor of point 10 is not symmetric"), std::string::npos) << error;

  {
    vtkSmartPointer<vtkImageData> image = TensorImage(Affine);
    vtkDataArray* tensors = image->GetPointData()->GetArray("Tensors");
    tensors->SetComponent(9 + 2 * 72, 2, -1.0); // point (0, 1, 2): ZZ = -1
    WriteVti(image, Folder() / "indefinite.vti");
  }
  error = ErrorOf(R"({"type": "sampled", "file": "indefinite.vti"})");
  EXPECT_NE(error.find("1 of 504 samples are not positive definite; the first is sample (0, 1, 2)"),
    std::string::npos)
    << error;
  EXPECT_EQ(ErrorOf(R"({"type": "sampled", "file": "indefinite.vti", "repair": "clamp"})"), "");

  std::ofstream(Folder() / "tensors.txt") << "not a volume";
  error = ErrorOf(R"({"type": "sampled", "file": "tensors.txt"})");
  EXPECT_NE(error.find("unknown tensor volume format \".txt\""), std::string::npos) << error;
  error = ErrorOf(R"({"type": "sampled", "file": "affine.vti", "outside": "wrap"})");
  EXPECT_NE(error.find("metric.outside: expected \"euclidean\""), std::string::npos) << error;
  EXPECT_EQ(ErrorOf(R"({"type": "sampled", "file": "affine.vti", "outside": "stop"})"), "");
  error = ErrorOf(R"({"type": "sampled", "file": "affine.vti", "scale": -1})");
  EXPECT_NE(error.find("the scale must be a finite positive number"), std::string::npos) << error;
  error = ErrorOf(R"({"type": "sampled", "file": "affine.vti", "inverse": "yes"})");
  EXPECT_NE(error.find("metric.inverse: expected true or false"), std::string::npos) << error;
  error = ErrorOf(R"({"type": "sampled", "file": "affine.vti", "smoothing": 2})");
  EXPECT_NE(error.find("smoothing"), std::string::npos) << error;

  vtkNew<vtkRiemannMetric> metric;
  EXPECT_FALSE(metric->SetTensorData(nullptr, "Tensors"));
  EXPECT_NE(std::string(metric->GetLastError()).find("tensor data: no image"), std::string::npos);
}

namespace
{
/// A 9 x 8 x 7 voxel image at the origin (VTK axes), each voxel's tuple the
/// `order` components (indices into the row-major 3 x 3) of `field` at
/// world point `place`(voxel position).
vtkSmartPointer<vtkImageData> VoxelImage(const std::function<Mat3(const Vec3&)>& field,
  const std::vector<int>& order, const std::function<Vec3(const Vec3&)>& place, double scale = 1.0)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(9, 8, 7);
  image->SetSpacing(0.25, 0.3, 0.35);
  vtkNew<vtkFloatArray> values;
  values->SetName("NIFTI");
  values->SetNumberOfComponents(static_cast<int>(order.size()));
  values->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    double x[3];
    image->GetPoint(p, x);
    const Mat3 g = field(place(Vec3(x[0], x[1], x[2])));
    for (std::size_t c = 0; c < order.size(); ++c)
    {
      values->SetComponent(p, static_cast<int>(c), g(order[c] / 3, order[c] % 3) / scale);
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

/// The q-form matrix x -> r x + offset.
vtkSmartPointer<vtkMatrix4x4> QForm(const Mat3& r, const Vec3& offset)
{
  auto qform = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      qform->SetElement(i, j, r(i, j));
    }
    qform->SetElement(i, 3, offset[i]);
  }
  return qform;
}
} // namespace

TEST(SampledMetric, NiftiAndNrrdFilesArePlacedAndOrdered)
{
  // NIfTI, intent SYMMATRIX (XX XY YY XZ YZ ZZ), a rotated q-form with an
  // offset: g at world points is the affine field there.
  const Mat3 r = Rotation();
  const Vec3 offset(-1.0, -0.5, -1.0);
  const auto world = [&](const Vec3& voxel) -> Vec3 { return r * voxel + offset; };
  {
    vtkNew<vtkNIFTIImageWriter> writer;
    writer->SetInputData(VoxelImage(Affine, { 0, 3, 4, 6, 7, 8 }, world));
    writer->SetQFormMatrix(QForm(r, offset));
    vtkNew<vtkNIFTIImageHeader> header;
    header->SetIntentCode(vtkNIFTIImageHeader::IntentSymMatrix);
    writer->SetNIFTIHeader(header);
    writer->SetFileName((Folder() / "affine.nii.gz").c_str());
    writer->Write();
  }
  vtkNew<vtkRiemannMetric> metric;
  fs::path path = MetricFile("nifti.json", R"({"type": "sampled", "file": "affine.nii.gz"})");
  ASSERT_TRUE(metric->SetDefinitionFile(path.c_str())) << metric->GetLastError();
  for (const Vec3& voxel : { Vec3(1.0, 1.2, 0.9), Vec3(0.6, 1.5, 1.4), Vec3(1.4, 0.7, 0.8) })
  {
    const Vec3 x = world(voxel);
    // Float samples: g to float rounding.
    EXPECT_LT((MetricAt(metric, x) - Affine(x)).cwiseAbs().maxCoeff(), 2e-6) << voxel.transpose();
  }

  // FSL dtifit: six volumes (XX XY XZ YY YZ ZZ), values stored halved with
  // scl_slope 2; the metric is the inverse of D.
  const Mat3 expected = Diffusion().inverse();
  {
    vtkNew<vtkNIFTIImageWriter> writer;
    writer->SetInputData(VoxelImage([](const Vec3&) { return Diffusion(); }, { 0, 1, 2, 4, 5, 8 },
      [](const Vec3& v) { return v; }, 2.0));
    writer->SetTimeDimension(6);
    writer->SetRescaleSlope(2.0);
    writer->SetFileName((Folder() / "dtifit_tensor.nii").c_str());
    writer->Write();
  }
  path =
    MetricFile("fsl.json", R"({"type": "sampled", "file": "dtifit_tensor.nii", "inverse": true, "components": "fsl"})");
  ASSERT_TRUE(metric->SetDefinitionFile(path.c_str())) << metric->GetLastError();
  EXPECT_LT((MetricAt(metric, Vec3(0.8, 0.9, 1.0)) - expected).cwiseAbs().maxCoeff(), 1e-5);

  // NRRD, Teem's order, raw doubles: 6 components, and 7 with a confidence
  // first. (VTK 9.1's vtkNrrdReader misreads ASCII-encoded doubles.)
  for (const bool masked : { false, true })
  {
    SCOPED_TRACE(masked ? "masked" : "6 components");
    const std::uint16_t probe = 1;
    const bool little = *reinterpret_cast<const unsigned char*>(&probe) == 1;
    std::ofstream nrrd(Folder() / "dti.nrrd", std::ios::binary);
    nrrd << "NRRD0004\ntype: double\ndimension: 4\nsizes: " << (masked ? 7 : 6)
         << " 3 3 3\nspacings: nan 0.5 0.5 0.5\nkinds: "
         << (masked ? "3D-masked-symmetric-matrix" : "3D-symmetric-matrix")
         << " domain domain domain\nendian: " << (little ? "little" : "big")
         << "\nencoding: raw\n\n";
    const Mat3 d = Diffusion();
    for (int voxel = 0; voxel < 27; ++voxel)
    {
      std::vector<double> tuple = { d(0, 0), d(0, 1), d(0, 2), d(1, 1), d(1, 2), d(2, 2) };
      if (masked)
      {
        tuple.insert(tuple.begin(), 1.0);
      }
      nrrd.write(reinterpret_cast<const char*>(tuple.data()),
        static_cast<std::streamsize>(tuple.size() * sizeof(double)));
    }
    nrrd.close();
    path = MetricFile("nrrd.json", R"({"type": "sampled", "file": "dti.nrrd", "inverse": true})");
    ASSERT_TRUE(metric->SetDefinitionFile(path.c_str())) << metric->GetLastError();
    EXPECT_LT((MetricAt(metric, Vec3(0.4, 0.5, 0.6)) - expected).cwiseAbs().maxCoeff(), 1e-12);
  }

  // NRRD placed by rotated "space directions" and a "space origin", with
  // its tensors in a rotated "measurement frame" (columns: the frame's axes
  // in world coordinates): g at world points is the affine field there.
  {
    const Mat3 axes = Rotation() * Vec3(0.3, 0.4, 0.5).asDiagonal();
    const Vec3 origin(-0.8, -0.6, -0.9);
    const Mat3 frame = Eigen::AngleAxisd(-0.7, Vec3(2, -1, 1).normalized()).toRotationMatrix();
    const std::uint16_t probe = 1;
    const bool little = *reinterpret_cast<const unsigned char*>(&probe) == 1;
    std::ofstream nrrd(Folder() / "oriented.nrrd", std::ios::binary);
    const auto vector = [](const Vec3& v)
    {
      std::ostringstream text;
      text.precision(17);
      text << "(" << v[0] << "," << v[1] << ", " << v[2] << ")";
      return text.str();
    };
    nrrd << "NRRD0004\n# oriented diffusion volume\ntype: double\ndimension: 4\nspace: "
            "right-anterior-superior\nsizes: 6 6 5 4\nspace directions: none "
         << vector(axes.col(0)) << " " << vector(axes.col(1)) << " " << vector(axes.col(2))
         << "\nkinds: 3D-symmetric-matrix domain domain domain\nendian: "
         << (little ? "little" : "big") << "\nencoding: raw\nspace origin: " << vector(origin)
         << "\nmeasurement frame: " << vector(frame.col(0)) << " " << vector(frame.col(1)) << " "
         << vector(frame.col(2)) << "\nmodality:=DWMRI\n\n";
    for (int k = 0; k < 4; ++k)
    {
      for (int j = 0; j < 5; ++j)
      {
        for (int i = 0; i < 6; ++i)
        {
          // Stored in the measurement frame: M^T g M, so that M (M^T g M) M^T = g.
          const Mat3 d = frame.transpose() * Affine(origin + axes * Vec3(i, j, k)) * frame;
          const double tuple[6] = { d(0, 0), d(0, 1), d(0, 2), d(1, 1), d(1, 2), d(2, 2) };
          nrrd.write(reinterpret_cast<const char*>(tuple), sizeof(tuple));
        }
      }
    }
    nrrd.close();
    path = MetricFile("oriented.json", R"({"type": "sampled", "file": "oriented.nrrd"})");
    ASSERT_TRUE(metric->SetDefinitionFile(path.c_str())) << metric->GetLastError();
    for (const Vec3& voxel : { Vec3(1.5, 1.2, 1.3), Vec3(2.6, 2.5, 1.9), Vec3(3.9, 1.7, 1.1) })
    {
      // Voxel indices a cell away from the faces, where the B-spline
      // reproduces affine fields (at the faces the samples are clamped).
      const Vec3 x = origin + axes * voxel;
      EXPECT_LT((MetricAt(metric, x) - Affine(x)).cwiseAbs().maxCoeff(), 1e-12)
        << voxel.transpose();
    }
    // Within the outer voxels' faces the data; just beyond them, Euclidean.
    EXPECT_NE(MetricAt(metric, origin + axes * Vec3(-0.45, 2.0, 2.0)), Mat3::Identity());
    EXPECT_EQ(MetricAt(metric, origin + axes * Vec3(-0.55, 2.0, 2.0)), Mat3::Identity());

    // Sheared axes and malformed vectors are refused, saying which field.
    std::ofstream sheared(Folder() / "sheared.nhdr");
    sheared << "NRRD0004\ntype: double\ndimension: 4\nsizes: 6 2 2 2\nspace dimension: 3\n"
               "space directions: none (1,0,0) (0.5,1,0) (0,0,1)\nkinds: 3D-symmetric-matrix "
               "domain domain domain\nencoding: raw\nendian: little\ndata file: sheared.raw\n";
    sheared.close();
    std::ofstream(Folder() / "sheared.raw", std::ios::binary) << std::string(6 * 8 * 8, '\0');
    std::string error = ErrorOf(R"({"type": "sampled", "file": "sheared.nhdr"})");
    EXPECT_NE(error.find("shears the voxel grid"), std::string::npos) << error;
  }

  // A NIfTI image of 4 values per voxel is not a tensor volume.
  {
    vtkNew<vtkNIFTIImageWriter> writer;
    writer->SetInputData(VoxelImage(Affine, { 0, 1, 2, 3 }, [](const Vec3& v) { return v; }));
    writer->SetFileName((Folder() / "four.nii").c_str());
    writer->Write();
  }
  const std::string error = ErrorOf(R"({"type": "sampled", "file": "four.nii"})");
  EXPECT_NE(error.find("four.nii: the NIfTI image has 4 values per voxel"), std::string::npos)
    << error;
}

TEST(SampledMetric, SixNiftiVolumesWithoutAnIntentNeedTheirOrder)
{
  // Six volumes and no intent code: FSL's dtifit writes XX XY XZ YY YZ ZZ,
  // MRtrix (mrconvert dt.mif dt.nii) XX YY ZZ XY XZ YZ. Read as the other's,
  // a tensor is another (or no) metric: the file is refused until
  // "components" says which, and then read exactly (float samples).
  const auto writeSix = [](const std::string& name, const std::vector<int>& order, bool symmatrix)
  {
    vtkNew<vtkNIFTIImageWriter> writer;
    writer->SetInputData(VoxelImage(Affine, order, [](const Vec3& v) { return v; }));
    writer->SetTimeDimension(6);
    if (symmatrix)
    {
      vtkNew<vtkNIFTIImageHeader> header;
      header->SetIntentCode(vtkNIFTIImageHeader::IntentSymMatrix);
      writer->SetNIFTIHeader(header);
    }
    writer->SetFileName((Folder() / name).c_str());
    writer->Write();
  };
  // VoxelImage's picks index the row-major 3 x 3 tensor.
  writeSix("mrtrix.nii", { 0, 4, 8, 1, 2, 5 }, false);
  writeSix("fsl.nii", { 0, 1, 2, 4, 5, 8 }, false);
  writeSix("symmatrix.nii", { 0, 1, 4, 2, 5, 8 }, true);
  const Vec3 x(0.8, 0.9, 1.0);

  std::string error = ErrorOf(R"({"type": "sampled", "file": "mrtrix.nii"})");
  EXPECT_NE(error.find("mrtrix.nii: six values per voxel and no intent code saying their order"),
    std::string::npos)
    << error;
  EXPECT_NE(error.find("\"components\": \"fsl\""), std::string::npos) << error;
  for (const auto& [file, order] : std::vector<std::pair<std::string, std::string>>{
         { "mrtrix.nii", "mrtrix" }, { "fsl.nii", "fsl" }, { "symmatrix.nii", "dipy" } })
  {
    SCOPED_TRACE(file);
    vtkNew<vtkRiemannMetric> metric;
    const fs::path path = MetricFile(
      "six.json", R"({"type": "sampled", "file": ")" + file + R"(", "components": ")" + order + R"("})");
    ASSERT_TRUE(metric->SetDefinitionFile(path.c_str())) << metric->GetLastError();
    EXPECT_LT((MetricAt(metric, x) - Affine(x)).cwiseAbs().maxCoeff(), 2e-6);
  }
  // The intent says the order: no key needed; a key that contradicts it is refused.
  EXPECT_EQ(ErrorOf(R"({"type": "sampled", "file": "symmatrix.nii"})"), "");
  error = ErrorOf(R"({"type": "sampled", "file": "symmatrix.nii", "components": "mrtrix"})");
  EXPECT_NE(error.find("its intent code (NIFTI_INTENT_SYMMATRIX) says"), std::string::npos) << error;
  // Read in the wrong order, the same file is another metric.
  vtkNew<vtkRiemannMetric> wrong;
  const fs::path path =
    MetricFile("wrong.json", R"({"type": "sampled", "file": "fsl.nii", "components": "mrtrix"})");
  if (wrong->SetDefinitionFile(path.c_str()))
  {
    EXPECT_GT((MetricAt(wrong, x) - Affine(x)).cwiseAbs().maxCoeff(), 0.05);
  }
  // Only NIfTI files take the key, and only its three orders.
  WriteVti(TensorImage(Affine), Folder() / "affine-six.vti");
  error = ErrorOf(R"({"type": "sampled", "file": "affine-six.vti", "components": "fsl"})");
  EXPECT_NE(error.find("\"components\" is the order of a NIfTI file's six volumes"), std::string::npos)
    << error;
  error = ErrorOf(R"({"type": "sampled", "file": "fsl.nii", "components": "afni"})");
  EXPECT_NE(error.find("metric.components: expected \"fsl\""), std::string::npos) << error;
}

TEST(SampledMetric, FslFrameTensorsAreTurnedFromTheVoxelAxes)
{
  // dtifit's tensors are in FSL's voxel axes: the file's voxel axes, the
  // first reversed when they are right-handed in the world. A rotated
  // q-form r with qfac +1 (right-handed: A = r diag(-1, 1, 1)) and with
  // qfac -1 (the file's third axis is -r's third column, left-handed:
  // A = r diag(1, 1, -1)). Stored: A^T g A, so that A (A^T g A) A^T = g.
  const Mat3 r = Rotation();
  const Vec3 offset(-1.0, -0.5, -1.0);
  const auto world = [&](const Vec3& voxel) -> Vec3 { return r * voxel + offset; };
  for (const double qfac : { 1.0, -1.0 })
  {
    SCOPED_TRACE(qfac > 0 ? "qfac +1" : "qfac -1");
    const Mat3 axes = r * Vec3(qfac > 0 ? -1.0 : 1.0, 1.0, qfac > 0 ? 1.0 : -1.0).asDiagonal();
    const std::string name = qfac > 0 ? "fsl-right.nii.gz" : "fsl-left.nii.gz";
    {
      vtkNew<vtkNIFTIImageWriter> writer;
      writer->SetInputData(
        VoxelImage([&](const Vec3& x) -> Mat3 { return axes.transpose() * Affine(x) * axes; },
          { 0, 1, 2, 4, 5, 8 }, world));
      writer->SetTimeDimension(6);
      writer->SetQFormMatrix(QForm(r, offset));
      writer->SetQFac(qfac);
      writer->SetFileName((Folder() / name).c_str());
      writer->Write();
    }
    vtkNew<vtkRiemannMetric> fsl;
    fs::path path = MetricFile(
      "fsl-frame.json", R"({"type": "sampled", "file": ")" + name + R"(", "frame": "fsl", "components": "fsl"})");
    ASSERT_TRUE(fsl->SetDefinitionFile(path.c_str())) << fsl->GetLastError();
    vtkNew<vtkRiemannMetric> asWritten;
    path = MetricFile(
      "world-frame.json", R"({"type": "sampled", "file": ")" + name + R"(", "components": "fsl"})");
    ASSERT_TRUE(asWritten->SetDefinitionFile(path.c_str())) << asWritten->GetLastError();
    for (const Vec3& voxel : { Vec3(1.0, 1.2, 0.9), Vec3(0.6, 1.5, 1.4), Vec3(1.4, 0.7, 0.8) })
    {
      const Vec3 x = world(voxel);
      // Float samples: g to float rounding.
      EXPECT_LT((MetricAt(fsl, x) - Affine(x)).cwiseAbs().maxCoeff(), 2e-6) << voxel.transpose();
      // Read in world axes, the same file is another metric: the frame matters.
      EXPECT_GT((MetricAt(asWritten, x) - Affine(x)).cwiseAbs().maxCoeff(), 0.05)
        << voxel.transpose();
    }
  }

  // "fsl" is for NIfTI files with a placement; other values are refused.
  std::string error =
    ErrorOf(R"({"type": "sampled", "file": "fsl-left.nii.gz", "frame": "voxel"})");
  EXPECT_NE(error.find("metric.frame: expected \"world\""), std::string::npos) << error;
  WriteVti(TensorImage(Affine), Folder() / "affine.vti");
  error = ErrorOf(R"({"type": "sampled", "file": "affine.vti", "frame": "fsl"})");
  EXPECT_NE(error.find("affine.vti: \"frame\": \"fsl\" is for NIfTI files"), std::string::npos)
    << error;
  {
    vtkNew<vtkNIFTIImageWriter> writer;
    writer->SetInputData(VoxelImage(Affine, { 0, 1, 2, 4, 5, 8 }, [](const Vec3& v) { return v; }));
    writer->SetFileName((Folder() / "unplaced.nii").c_str());
    writer->Write();
  }
  EXPECT_EQ(ErrorOf(R"({"type": "sampled", "file": "unplaced.nii", "components": "fsl"})"), "");
  error = ErrorOf(R"({"type": "sampled", "file": "unplaced.nii", "frame": "fsl", "components": "fsl"})");
  EXPECT_NE(error.find("needs the file's q-form or s-form"), std::string::npos) << error;
}
