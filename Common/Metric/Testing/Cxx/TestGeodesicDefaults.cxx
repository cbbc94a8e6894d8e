// The core's plain defaults of how a geodesic is integrated
// (riemann::GeodesicOptions) are the declared defaults of
// vtkRiemannIntegrationSettings (vtkRiemannIntegrationSettings.settings.json):
// the core keeps its own struct defaults, and this test keeps them equal.
#include "GeodesicTrace.h"
#include "RiemannIntegrationSettingsDeclaration.h"

#include <gtest/gtest.h>

TEST(GeodesicOptions, DefaultsAreTheDeclaredOnes)
{
  namespace declared = riemann::declared::vtkRiemannIntegrationSettings::Default;
  const riemann::GeodesicOptions options;
  EXPECT_EQ(static_cast<int>(options.Integrator), declared::IntegratorType);
  EXPECT_EQ(options.Step, declared::InitialIntegrationStep);
  EXPECT_EQ(options.MinimumStep, declared::MinimumIntegrationStep);
  EXPECT_EQ(options.MaximumStep, declared::MaximumIntegrationStep);
  EXPECT_EQ(options.Tolerance, declared::MaximumError);
  EXPECT_EQ(options.MaximumLength, declared::MaximumPropagation);
  EXPECT_EQ(options.MaximumSteps, declared::MaximumNumberOfSteps);
}
