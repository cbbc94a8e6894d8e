// The integration settings as the geodesic filters (vtkRiemannGeodesicTracer,
// vtkRiemannExponentialMap, vtkRiemannConjugateLocus) use them:
// - every unusable value of every setting is refused by name: an ErrorEvent,
//   empty outputs on every port, and GetLastError() naming the setting; a
//   usable value again gives the output back;
// - a settings object shared between two filters (SetIntegrationSettings)
//   reaches both: modifying it makes each filter's next Update recompute;
// - SetIntegratorTypeFromName takes the command line's words and refuses
//   others without changing the integrator.
#include "vtkRiemannConjugateLocus.h"
#include "vtkRiemannExponentialMap.h"
#include "vtkRiemannGeodesicAlgorithm.h"
#include "vtkRiemannGeodesicTracer.h"
#include "RiemannIntegrationSettingsDeclaration.h"
#include "SettingValues.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include "ErrorObserver.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace
{
constexpr const char* TwistJson = R"({"type":"diffeo","preset":"twist"})";
// The unit round sphere in stereographic coordinates: conjugate points at arc length pi.
constexpr const char* SphereJson = R"J({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})J";

vtkSmartPointer<vtkRiemannMetric> MakeMetric(const char* json)
{
  auto metric = vtkSmartPointer<vtkRiemannMetric>::New();
  EXPECT_TRUE(metric->SetDefinition(json)) << metric->GetLastError();
  return metric;
}

using riemann::testing::ErrorObserver;

/// Points and cells over every output port.
vtkIdType OutputSize(vtkRiemannGeodesicAlgorithm* filter)
{
  vtkIdType size = 0;
  for (int port = 0; port < filter->GetNumberOfOutputPorts(); ++port)
  {
    vtkPolyData* output = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(port));
    EXPECT_NE(output, nullptr) << "port " << port;
    if (output)
    {
      size += output->GetNumberOfPoints() + output->GetNumberOfCells();
    }
  }
  return size;
}

/// The last ArcLength of every line of port 0 (the geodesics, or the bundle).
std::vector<double> FinalArcLengths(vtkRiemannGeodesicAlgorithm* filter)
{
  vtkPolyData* output = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  vtkDataArray* arcLength = output->GetPointData()->GetArray("ArcLength");
  std::vector<double> lengths;
  if (!arcLength)
  {
    ADD_FAILURE() << "no ArcLength array";
    return lengths;
  }
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* lines = output->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(count, ids);)
  {
    lengths.push_back(arcLength->GetTuple1(ids[count - 1]));
  }
  return lengths;
}

/// One unusable value of one setting, and the name GetLastError() must show.
struct BadSetting
{
  std::string Description;
  std::string Name;
  std::function<void(vtkRiemannIntegrationSettings*)> Apply;
};

std::vector<BadSetting> BadSettings()
{
  using Setter = void (vtkRiemannIntegrationSettings::*)(double);
  const struct
  {
    const char* Name;
    Setter Set;
  } doubles[] = {
    { "InitialIntegrationStep", &vtkRiemannIntegrationSettings::SetInitialIntegrationStep },
    { "MaximumError", &vtkRiemannIntegrationSettings::SetMaximumError },
    { "MaximumPropagation", &vtkRiemannIntegrationSettings::SetMaximumPropagation },
    { "MinimumIntegrationStep", &vtkRiemannIntegrationSettings::SetMinimumIntegrationStep },
    { "MaximumIntegrationStep", &vtkRiemannIntegrationSettings::SetMaximumIntegrationStep },
  };
  const double values[] = { std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::infinity(), 0.0, -1.0 };
  std::vector<BadSetting> bad;
  for (const auto& setting : doubles)
  {
    for (double value : values)
    {
      const Setter set = setting.Set;
      bad.push_back({ std::string(setting.Name) + " = " + std::to_string(value), setting.Name,
        [set, value](vtkRiemannIntegrationSettings* s) { (s->*set)(value); } });
    }
  }
  bad.push_back({ "MaximumNumberOfSteps = 0", "MaximumNumberOfSteps",
    [](vtkRiemannIntegrationSettings* s) { s->SetMaximumNumberOfSteps(0); } });
  bad.push_back(
    { "MinimumIntegrationStep 0.5 > MaximumIntegrationStep 0.1", "MinimumIntegrationStep",
      [](vtkRiemannIntegrationSettings* s)
      {
        s->SetMinimumIntegrationStep(0.5);
        s->SetMaximumIntegrationStep(0.1);
      } });
  return bad;
}

/// Every bad setting on a filter that gives output with its own settings:
/// refused by name with empty output, then the output again once the
/// settings are restored.
void ExpectEveryBadSettingRefused(vtkRiemannGeodesicAlgorithm* filter)
{
  ErrorObserver errors(filter);
  vtkRiemannIntegrationSettings* settings = filter->GetIntegrationSettings();
  vtkNew<vtkRiemannIntegrationSettings> good;
  good->DeepCopy(settings);

  filter->Update();
  ASSERT_TRUE(errors.Messages.empty()) << errors.Messages[0];
  ASSERT_STREQ(filter->GetLastError(), "");
  const vtkIdType size = OutputSize(filter);
  ASSERT_GT(size, 0);

  for (const BadSetting& bad : BadSettings())
  {
    SCOPED_TRACE(bad.Description);
    const size_t before = errors.Messages.size();
    bad.Apply(settings);
    filter->Update();
    ASSERT_EQ(errors.Messages.size(), before + 1);
    EXPECT_NE(errors.Messages.back().find(bad.Name), std::string::npos) << errors.Messages.back();
    const std::string lastError = filter->GetLastError();
    EXPECT_EQ(lastError.rfind("Integration settings: " + bad.Name, 0), 0u) << lastError;
    EXPECT_NE(errors.Messages.back().find(lastError), std::string::npos);
    EXPECT_EQ(OutputSize(filter), 0);

    // Usable settings again: the same output, no error.
    settings->DeepCopy(good);
    filter->Update();
    EXPECT_EQ(errors.Messages.size(), before + 1);
    EXPECT_STREQ(filter->GetLastError(), "");
    EXPECT_EQ(OutputSize(filter), size);
  }
}
/// A filter of class T on the metric `metricJson`, integrating with
/// `settings` (shared) or, when it is null, with its own.
template <class T>
vtkSmartPointer<T> MakeFilter(const char* metricJson, vtkRiemannIntegrationSettings* settings)
{
  auto filter = vtkSmartPointer<T>::New();
  filter->SetMetric(MakeMetric(metricJson));
  filter->SetIntegrationSettings(settings);
  return filter;
}

/// A tracer of one geodesic.
vtkSmartPointer<vtkRiemannGeodesicTracer> MakeTracer(
  const char* metricJson, vtkRiemannIntegrationSettings* settings = nullptr)
{
  auto tracer = MakeFilter<vtkRiemannGeodesicTracer>(metricJson, settings);
  tracer->SetStartPosition(0.2, 0.1, -0.3);
  tracer->SetStartDirection(1.0, 0.5, 0.0);
  return tracer;
}

/// An exponential map or a conjugate locus over a few directions.
template <class T>
vtkSmartPointer<T> MakeFromObserver(
  const char* metricJson, int directions, vtkRiemannIntegrationSettings* settings = nullptr)
{
  auto filter = MakeFilter<T>(metricJson, settings);
  filter->SetObserver(0.2, 0.1, -0.3);
  filter->SetNumberOfDirections(directions);
  return filter;
}
} // namespace

TEST(IntegrationSettings, TracerRefusesEveryUnusableSetting)
{
  auto tracer = MakeTracer(TwistJson);
  tracer->GetIntegrationSettings()->SetMaximumPropagation(1.0);
  ExpectEveryBadSettingRefused(tracer);
}

TEST(IntegrationSettings, ExponentialMapRefusesEveryUnusableSetting)
{
  auto map = MakeFromObserver<vtkRiemannExponentialMap>(TwistJson, 12);
  map->AddRadius(0.5);
  map->GetIntegrationSettings()->SetMaximumPropagation(1.0);
  ExpectEveryBadSettingRefused(map);
}

TEST(IntegrationSettings, ConjugateLocusRefusesEveryUnusableSetting)
{
  auto locus = MakeFromObserver<vtkRiemannConjugateLocus>(SphereJson, 10);
  locus->GetIntegrationSettings()->SetMaximumPropagation(4.0);
  ExpectEveryBadSettingRefused(locus);
}

// One settings object for a tracer and an exponential map: a longer
// MaximumPropagation in it lengthens both filters' geodesics.
TEST(IntegrationSettings, SharedSettingsReachTracerAndExponentialMap)
{
  vtkNew<vtkRiemannIntegrationSettings> settings;
  settings->SetMaximumPropagation(1.0);
  auto tracer = MakeTracer(TwistJson, settings);
  auto map = MakeFromObserver<vtkRiemannExponentialMap>(TwistJson, 12, settings);
  ASSERT_EQ(tracer->GetIntegrationSettings(), settings.Get());
  ASSERT_EQ(map->GetIntegrationSettings(), settings.Get());

  const auto expectLengths = [&](double length)
  {
    tracer->Update();
    map->Update();
    ASSERT_STREQ(tracer->GetLastError(), "");
    ASSERT_STREQ(map->GetLastError(), "");
    const std::vector<double> traced = FinalArcLengths(tracer);
    ASSERT_EQ(traced.size(), 1u);
    EXPECT_NEAR(traced[0], length, 1e-12);
    const std::vector<double> bundle = FinalArcLengths(map);
    ASSERT_EQ(bundle.size(), 12u);
    for (double l : bundle)
    {
      EXPECT_NEAR(l, length, 1e-12);
    }
  };
  expectLengths(1.0);
  const vtkMTimeType tracerTime = tracer->GetOutput()->GetMTime();
  const vtkMTimeType mapTime = map->GetOutput()->GetMTime();

  settings->SetMaximumPropagation(2.0);
  expectLengths(2.0);
  EXPECT_GT(tracer->GetOutput()->GetMTime(), tracerTime);
  EXPECT_GT(map->GetOutput()->GetMTime(), mapTime);

  // A setting made unusable in the shared object is refused by both.
  settings->SetMaximumNumberOfSteps(0);
  tracer->Update();
  map->Update();
  EXPECT_NE(std::string(tracer->GetLastError()).find("MaximumNumberOfSteps"), std::string::npos)
    << tracer->GetLastError();
  EXPECT_NE(std::string(map->GetLastError()).find("MaximumNumberOfSteps"), std::string::npos)
    << map->GetLastError();
  EXPECT_EQ(OutputSize(tracer), 0);
  EXPECT_EQ(OutputSize(map), 0);
}

// One settings object for a tracer and a conjugate locus on the round sphere:
// with MaximumPropagation 3 the search stops before the antipode (pi); with 4
// every direction finds it.
TEST(IntegrationSettings, SharedSettingsReachTracerAndConjugateLocus)
{
  vtkNew<vtkRiemannIntegrationSettings> settings;
  settings->SetMaximumPropagation(3.0);
  auto tracer = MakeTracer(SphereJson, settings);
  auto locus = MakeFromObserver<vtkRiemannConjugateLocus>(SphereJson, 10, settings);

  tracer->Update();
  locus->Update();
  std::vector<double> traced = FinalArcLengths(tracer);
  ASSERT_EQ(traced.size(), 1u);
  EXPECT_NEAR(traced[0], 3.0, 1e-12);
  EXPECT_EQ(locus->GetOutput()->GetNumberOfPoints(), 0);

  settings->SetMaximumPropagation(4.0);
  tracer->Update();
  locus->Update();
  traced = FinalArcLengths(tracer);
  ASSERT_EQ(traced.size(), 1u);
  EXPECT_NEAR(traced[0], 4.0, 1e-12);
  vtkPolyData* points = locus->GetOutput();
  ASSERT_EQ(points->GetNumberOfPoints(), 10);
  vtkDataArray* arcLength = points->GetPointData()->GetArray("ArcLength");
  ASSERT_NE(arcLength, nullptr);
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    EXPECT_NEAR(arcLength->GetTuple1(i), M_PI, 1e-5) << "point " << i;
  }
}

TEST(IntegrationSettings, IntegratorTypeFromName)
{
  vtkNew<vtkRiemannIntegrationSettings> settings;
  const struct
  {
    const char* Name;
    int Type;
  } names[] = {
    { "euler", vtkRiemannIntegrationSettings::EULER },
    { "rk4", vtkRiemannIntegrationSettings::RUNGE_KUTTA4 },
    { "dp45", vtkRiemannIntegrationSettings::DORMAND_PRINCE45 },
    { "adaptive", vtkRiemannIntegrationSettings::DORMAND_PRINCE45 },
    { "euler", vtkRiemannIntegrationSettings::EULER },
  };
  for (const auto& name : names)
  {
    const vtkMTimeType before = settings->GetMTime();
    const int previous = settings->GetIntegratorType();
    EXPECT_TRUE(settings->SetIntegratorTypeFromName(name.Name)) << name.Name;
    EXPECT_EQ(settings->GetIntegratorType(), name.Type) << name.Name;
    // "adaptive" is a synonym: its name reads back as dp45.
    const std::string expected = std::string(name.Name) == "adaptive" ? "dp45" : name.Name;
    EXPECT_EQ(settings->GetIntegratorTypeAsString(), expected);
    if (previous != name.Type)
    {
      EXPECT_GT(settings->GetMTime(), before) << name.Name;
    }
  }

  // Refused, changing nothing (not even the modification time).
  settings->SetIntegratorTypeToRungeKutta4();
  const vtkMTimeType before = settings->GetMTime();
  for (const char* bad : { "rk5", "RK4", "", "dp45 ", "runge-kutta" })
  {
    EXPECT_FALSE(settings->SetIntegratorTypeFromName(bad)) << '"' << bad << '"';
    EXPECT_EQ(settings->GetIntegratorType(), vtkRiemannIntegrationSettings::RUNGE_KUTTA4) << bad;
  }
  EXPECT_FALSE(settings->SetIntegratorTypeFromName(nullptr));
  EXPECT_EQ(settings->GetIntegratorType(), vtkRiemannIntegrationSettings::RUNGE_KUTTA4);
  EXPECT_EQ(settings->GetMTime(), before);
  EXPECT_STREQ(settings->GetIntegratorTypeAsString(), "rk4");
}

TEST(IntegrationSettings, DefaultsAndRangesAreTheDeclarations)
{
  // vtkRiemannIntegrationSettings takes its defaults and its checks from its
  // declaration (vtkRiemannIntegrationSettings.settings.json), as the CLI,
  // the app and scenes do.
  vtkNew<vtkRiemannIntegrationSettings> settings;
  struct Property
  {
    const char* Name;
    double (vtkRiemannIntegrationSettings::*Get)();
    void (vtkRiemannIntegrationSettings::*Set)(double);
  };
  const Property properties[] = {
    { "InitialIntegrationStep", &vtkRiemannIntegrationSettings::GetInitialIntegrationStep,
      &vtkRiemannIntegrationSettings::SetInitialIntegrationStep },
    { "MinimumIntegrationStep", &vtkRiemannIntegrationSettings::GetMinimumIntegrationStep,
      &vtkRiemannIntegrationSettings::SetMinimumIntegrationStep },
    { "MaximumIntegrationStep", &vtkRiemannIntegrationSettings::GetMaximumIntegrationStep,
      &vtkRiemannIntegrationSettings::SetMaximumIntegrationStep },
    { "MaximumError", &vtkRiemannIntegrationSettings::GetMaximumError,
      &vtkRiemannIntegrationSettings::SetMaximumError },
    { "MaximumPropagation", &vtkRiemannIntegrationSettings::GetMaximumPropagation,
      &vtkRiemannIntegrationSettings::SetMaximumPropagation },
  };
  const riemann::SettingTable& table = riemann::declared::vtkRiemannIntegrationSettings::Settings;
  EXPECT_EQ(settings->GetIntegratorType(),
    riemann::ChoiceIndex(*table.Find("IntegratorType"),
      riemann::DefaultValue(*table.Find("IntegratorType")).get<std::string>()));
  EXPECT_EQ(settings->GetMaximumNumberOfSteps(),
    riemann::DefaultValue(*table.Find("MaximumNumberOfSteps")).get<long long>());
  ASSERT_EQ(settings->CheckSettings(), "");
  for (const Property& p : properties)
  {
    const riemann::SettingDeclaration& setting = *table.Find(p.Name);
    SCOPED_TRACE(setting.Name);
    const double original = (settings.Get()->*p.Get)();
    EXPECT_EQ(original, riemann::DefaultValue(setting).get<double>());
    // Just outside the range: refused, naming the property and the range.
    const double outside = setting.MinimumExclusive ? setting.Minimum : setting.Minimum / 2;
    (settings.Get()->*p.Set)(std::string(p.Name) == "MaximumIntegrationStep" ? 2 * setting.Maximum : outside);
    const std::string error = settings->CheckSettings();
    EXPECT_EQ(error.rfind(std::string(setting.Name) + " is ", 0), 0u) << error;
    EXPECT_NE(error.find(riemann::DescribeSettingRange(setting)), std::string::npos) << error;
    (settings.Get()->*p.Set)(original);
    EXPECT_EQ(settings->CheckSettings(), "");
  }
  settings->SetMaximumNumberOfSteps(0);
  EXPECT_EQ(settings->CheckSettings(),
    "MaximumNumberOfSteps is 0: expected a whole number from 1 to 1e+09 (steps)");
}
