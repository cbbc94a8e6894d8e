// Tests of the field filters (vtkRiemannCurvatureField, vtkRiemannVolumeForm,
// vtkRiemannMetricTensorField) against closed forms:
// - round unit 3-sphere in stereographic coordinates, g = n^2 I with
//   n = 2/(1+r^2): S = 6, K = 1 on every plane, Ric = 2 g; total volume 2 pi^2;
// - Poincare ball n = 2/(1-r^2): S = -6; degenerate (NaN) for r >= 1;
// - twist diffeomorphism (flat, det J = 1): zero curvature, volume form 1;
// - constant tensor diag(2,3,1): volume form sqrt(6).
#include "vtkRiemannCurvatureField.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannMetricTensorField.h"
#include "vtkRiemannVolumeForm.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
constexpr const char* SphereJson = R"json({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})json";
constexpr const char* PoincareJson = R"json({"type":"conformal","n":"2/(1-x^2-y^2-z^2)"})json";
constexpr const char* TwistJson = R"json({"type":"diffeo","preset":"twist"})json";
constexpr const char* TensorJson =
  R"json({"type":"tensor","matrix":[[2,0,0],[0,3,0],[0,0,1]]})json";
const double Pi = std::acos(-1.0);

vtkSmartPointer<vtkRiemannMetric> MakeMetric(const char* json)
{
  auto metric = vtkSmartPointer<vtkRiemannMetric>::New();
  EXPECT_TRUE(metric->SetDefinition(json)) << metric->GetLastError();
  return metric;
}

template <typename Filter>
vtkSmartPointer<Filter> MakeFilter(const char* json, double half, int n)
{
  auto filter = vtkSmartPointer<Filter>::New();
  filter->SetMetric(MakeMetric(json));
  filter->SetBounds(-half, half, -half, half, -half, half);
  filter->SetDimensions(n, n, n);
  return filter;
}

/// Counts warnings and errors of an algorithm (and keeps them off stderr).
struct EventCounter
{
  int Warnings = 0;
  int Errors = 0;
  vtkNew<vtkCallbackCommand> Callback;
  explicit EventCounter(vtkObject* object)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(
      [](vtkObject*, unsigned long event, void* client, void*)
      {
        auto* self = static_cast<EventCounter*>(client);
        (event == vtkCommand::WarningEvent ? self->Warnings : self->Errors)++;
      });
    object->AddObserver(vtkCommand::WarningEvent, this->Callback);
    object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
  }
};

/// tail(R) = int_R^inf 8/(1+r^2)^3 4 pi r^2 dr (the sphere's volume outside radius R).
double SphereTail(double r)
{
  return 2 * Pi * Pi - 4 * Pi * std::atan(r) +
    4 * Pi * r * (1 - r * r) / ((1 + r * r) * (1 + r * r));
}
}

TEST(CurvatureField, RoundSphere)
{
  auto filter = MakeFilter<vtkRiemannCurvatureField>(SphereJson, 1.5, 7);
  filter->Update();
  vtkImageData* out = vtkImageData::SafeDownCast(filter->GetOutput());
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(out->GetNumberOfPoints(), 343);
  vtkPointData* pd = out->GetPointData();
  vtkDataArray* ricci = pd->GetArray("Ricci");
  ASSERT_NE(ricci, nullptr);
  ASSERT_EQ(ricci->GetNumberOfComponents(), 6);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    const double n = 2.0 / (1.0 + x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    EXPECT_NEAR(pd->GetArray("ScalarCurvature")->GetTuple1(i), 6.0, 1e-9);
    for (const char* name :
      { "SectionalXY", "SectionalXZ", "SectionalYZ", "SectionalMin", "SectionalMax" })
    {
      EXPECT_NEAR(pd->GetArray(name)->GetTuple1(i), 1.0, 1e-9) << name;
    }
    // |Rm|^2 of constant curvature 1 in 3D: 2 n(n-1) K^2 = 12.
    EXPECT_NEAR(pd->GetArray("RiemannNorm")->GetTuple1(i), std::sqrt(12.0), 1e-9);
    double r[6];
    ricci->GetTuple(i, r);
    const double expected[6] = { 2 * n * n, 2 * n * n, 2 * n * n, 0, 0, 0 };
    for (int c = 0; c < 6; ++c)
    {
      EXPECT_NEAR(r[c], expected[c], 1e-9) << "component " << c;
    }
  }
}

TEST(CurvatureField, PoincareBallAndDegeneratePoints)
{
  // Inside radius 0.5: the box [-0.28, 0.28]^3 (corner radius 0.485).
  auto filter = MakeFilter<vtkRiemannCurvatureField>(PoincareJson, 0.28, 5);
  filter->Update();
  vtkDataArray* s = filter->GetOutput()->GetPointData()->GetArray("ScalarCurvature");
  for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
  {
    EXPECT_NEAR(s->GetTuple1(i), -6.0, 1e-9);
  }
  // Over [-1.5, 1.5]^3 with 7^3 points, the 27 points with r < 1 are
  // defined; the rest are NaN with one warning.
  filter->SetBounds(-1.5, 1.5, -1.5, 1.5, -1.5, 1.5);
  filter->SetDimensions(7, 7, 7);
  EventCounter events(filter);
  filter->Update();
  EXPECT_EQ(events.Warnings, 1);
  EXPECT_EQ(events.Errors, 0);
  s = filter->GetOutput()->GetPointData()->GetArray("ScalarCurvature");
  int nans = 0;
  for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
  {
    nans += std::isnan(s->GetTuple1(i)) ? 1 : 0;
  }
  EXPECT_EQ(nans, 343 - 27);
}

TEST(CurvatureField, TwistIsFlat)
{
  auto filter = MakeFilter<vtkRiemannCurvatureField>(TwistJson, 1.0, 5);
  filter->Update();
  vtkPointData* pd = filter->GetOutput()->GetPointData();
  for (const char* name : { "ScalarCurvature", "Ricci", "SectionalXY", "SectionalXZ", "SectionalYZ",
         "SectionalMin", "SectionalMax", "RiemannNorm" })
  {
    vtkDataArray* a = pd->GetArray(name);
    ASSERT_NE(a, nullptr) << name;
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < a->GetNumberOfComponents(); ++c)
      {
        EXPECT_NEAR(a->GetComponent(i, c), 0.0, 1e-9) << name;
      }
    }
  }
}

TEST(CurvatureField, InputPointsAndShallowCopy)
{
  vtkNew<vtkPolyData> input;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.1, 0.2, 0.3);
  points->InsertNextPoint(-0.4, 0.0, 0.2);
  input->SetPoints(points);
  vtkNew<vtkCallbackCommand> unused;
  vtkNew<vtkRiemannCurvatureField> filter;
  filter->SetMetric(MakeMetric(SphereJson));
  filter->SetInputData(input);
  filter->Update();
  vtkPolyData* out = vtkPolyData::SafeDownCast(filter->GetOutput());
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(out->GetNumberOfPoints(), 2);
  EXPECT_EQ(out->GetPoints(), input->GetPoints());
  EXPECT_NEAR(out->GetPointData()->GetArray("ScalarCurvature")->GetTuple1(1), 6.0, 1e-9);
  EXPECT_EQ(input->GetPointData()->GetNumberOfArrays(), 0);
}

TEST(FieldAlgorithm, ErrorsGiveEmptyOutput)
{
  vtkNew<vtkRiemannCurvatureField> filter;
  EventCounter events(filter);
  filter->Update();
  EXPECT_EQ(events.Errors, 1);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  filter->SetMetric(MakeMetric(SphereJson));
  filter->SetBounds(1, -1, -1, 1, -1, 1);
  filter->Update();
  EXPECT_EQ(events.Errors, 2);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  filter->SetBounds(-1, 1, -1, 1, -1, 1);
  filter->SetDimensions(0, 3, 3);
  filter->Update();
  EXPECT_EQ(events.Errors, 3);
  filter->SetDimensions(3, 3, 3);
  filter->Update();
  EXPECT_EQ(events.Errors, 3);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 27);
}

TEST(FieldAlgorithm, ProgressAndAbort)
{
  auto filter = MakeFilter<vtkRiemannVolumeForm>(SphereJson, 2.0, 41);
  struct State
  {
    int Calls = 0;
    double Last = -1;
    bool Abort = false;
  } state;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&state);
  progress->SetCallback(
    [](vtkObject* caller, unsigned long, void* client, void* data)
    {
      auto* s = static_cast<State*>(client);
      s->Calls++;
      s->Last = *static_cast<double*>(data);
      if (s->Abort && s->Last > 0)
      {
        static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
      }
    });
  filter->AddObserver(vtkCommand::ProgressEvent, progress);
  filter->Update();
  EXPECT_GT(state.Calls, 2);
  EXPECT_DOUBLE_EQ(state.Last, 1.0);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 41 * 41 * 41);
  state = State{};
  state.Abort = true;
  filter->Modified();
  filter->Update();
  EXPECT_LT(state.Last, 1.0);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  filter->AbortExecuteOff();
}

TEST(VolumeForm, TwistIsExactlyEight)
{
  auto filter = MakeFilter<vtkRiemannVolumeForm>(TwistJson, 1.0, 21);
  filter->Update();
  EXPECT_NEAR(filter->GetVolumeIntegral(), 8.0, 1e-9);
  vtkDataArray* field = filter->GetOutput()->GetFieldData()->GetArray("VolumeIntegral");
  ASSERT_NE(field, nullptr);
  EXPECT_EQ(field->GetTuple1(0), filter->GetVolumeIntegral());
}

TEST(VolumeForm, ConstantTensor)
{
  vtkNew<vtkRiemannVolumeForm> filter;
  filter->SetMetric(MakeMetric(TensorJson));
  filter->SetBounds(-1, 2, 0, 1, -0.5, 0.5);
  filter->SetDimensions(4, 3, 2);
  filter->Update();
  EXPECT_NEAR(filter->GetVolumeIntegral(), std::sqrt(6.0) * 3.0, 1e-12);
  // One point on an axis: midpoint rule there, weight = max - min.
  filter->SetDimensions(4, 3, 1);
  filter->Update();
  EXPECT_NEAR(filter->GetVolumeIntegral(), std::sqrt(6.0) * 3.0, 1e-12);
  vtkDataArray* v = filter->GetOutput()->GetPointData()->GetArray("VolumeForm");
  EXPECT_NEAR(v->GetTuple1(0), std::sqrt(6.0), 1e-14);
}

// The round sphere's total volume 2 pi^2 from the box [-L, L]^3 with
// spacing h. The box lies between the balls of radius L and sqrt(3) L, so
//   2 pi^2 - tail(L) <= V_box <= 2 pi^2 - tail(sqrt(3) L).
// Trapezoid error for f = 8/(1+r^2)^3: the leading Euler-Maclaurin term is
//   -(h^2/12) int_box Laplacian f = -(h^2/12) flux of grad f through the box,
// with |f'(r)| = 48 r/(1+r^2)^4 <= 48/L^7 on the faces (r >= L), area 24 L^2:
//   |E2| <= 96 h^2 / L^5.
// The higher terms are boundary terms of the same kind (smaller still) plus
// the aliasing error of an analytic integrand, O(exp(-2 pi a/h)) with a >= 1
// the distance of the poles x = +-i sqrt(1+y^2+z^2) from the real axis:
// about 3e-6 relative for h = 0.5, so E = 96 h^2/L^5 + 1e-4 is a safe margin.
// L = 8, h = 0.25 (65^3 points): the window is [19.674, 19.727], 0.27% wide.
TEST(VolumeForm, RoundSphereTotalVolume)
{
  const double L = 8.0;
  const int n = 65;
  const double h = 2 * L / (n - 1);
  auto filter = MakeFilter<vtkRiemannVolumeForm>(SphereJson, L, n);
  filter->Update();
  const double integral = filter->GetVolumeIntegral();
  const double lower = 2 * Pi * Pi - SphereTail(L);
  const double upper = 2 * Pi * Pi - SphereTail(std::sqrt(3.0) * L);
  const double error = 96 * h * h / std::pow(L, 5) + 1e-4;
  EXPECT_GE(integral, lower - error);
  EXPECT_LE(integral, upper + error);
  std::cout << "sphere volume over [-8,8]^3, h = 0.25: " << integral << " in [" << lower << ", "
            << upper << "] (2 pi^2 = " << 2 * Pi * Pi << ")\n";
  // The closed form of the tail: tail(0) is the whole volume.
  EXPECT_NEAR(SphereTail(0.0), 2 * Pi * Pi, 1e-12);
}

TEST(MetricTensorField, TensorInverseEigenvalues)
{
  vtkNew<vtkPolyData> input;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.3, -0.2, 0.7);
  input->SetPoints(points);
  vtkNew<vtkRiemannMetricTensorField> filter;
  filter->SetMetric(
    MakeMetric(R"json({"type":"tensor","matrix":[[2,1,0],[1,3,0.5],[0,0.5,1]]})json"));
  filter->SetInputData(input);
  filter->Update();
  vtkPointData* pd = filter->GetOutput()->GetPointData();
  double g[6], gi[6], ev[3];
  pd->GetArray("MetricTensor")->GetTuple(0, g);
  pd->GetArray("InverseMetricTensor")->GetTuple(0, gi);
  pd->GetArray("MetricEigenvalues")->GetTuple(0, ev);
  EXPECT_EQ(pd->GetTensors(), pd->GetArray("MetricTensor"));
  const double expected[6] = { 2, 3, 1, 1, 0.5, 0 }; // XX YY ZZ XY YZ XZ
  for (int c = 0; c < 6; ++c)
  {
    EXPECT_NEAR(g[c], expected[c], 1e-14);
  }
  // g * g^-1 = I from the 6-component forms.
  auto full = [](const double* t, int r, int c)
  {
    static const int index[3][3] = { { 0, 3, 5 }, { 3, 1, 4 }, { 5, 4, 2 } };
    return t[index[r][c]];
  };
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      double sum = 0;
      for (int k = 0; k < 3; ++k)
      {
        sum += full(g, r, k) * full(gi, k, c);
      }
      EXPECT_NEAR(sum, r == c ? 1.0 : 0.0, 1e-12);
    }
  }
  EXPECT_LT(ev[0], ev[1]);
  EXPECT_LT(ev[1], ev[2]);
  EXPECT_NEAR(ev[0] + ev[1] + ev[2], 6.0, 1e-12);              // trace
  EXPECT_NEAR(ev[0] * ev[1] * ev[2], 2 * 2.75 - 1 * 1, 1e-12); // det = 4.5
}
