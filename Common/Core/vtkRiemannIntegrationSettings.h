/**
 * @class   vtkRiemannIntegrationSettings
 * @brief   How geodesics are integrated: one settings object, one vocabulary,
 *          for every filter and renderer of the toolkit.
 *
 * Every consumer of geodesics (vtkRiemannGeodesicTracer,
 * vtkRiemannExponentialMap, vtkRiemannConjugateLocus, vtkRiemannRayBundle,
 * vtkRiemannRayTracePass, vtkRiemannCPURayTracer) holds one of these
 * (GetIntegrationSettings()); several consumers may share one
 * (SetIntegrationSettings()), as the desktop app does so that the inside view
 * and the plotted rays always agree. The names are vtkStreamTracer's:
 *
 * - IntegratorType: EULER (the paper's), RUNGE_KUTTA4 or DORMAND_PRINCE45
 *   (adaptive, with error control). The command line spells them `euler`,
 *   `rk4` and `dp45` (GetIntegratorTypeAsString, SetIntegratorTypeFromName).
 * - InitialIntegrationStep: the step in Riemannian arc length (fixed for
 *   Euler and RK4, the first one for DORMAND_PRINCE45).
 * - MinimumIntegrationStep, MaximumIntegrationStep: bounds of the adaptive
 *   step. (The ray tracers bound it relative to InitialIntegrationStep
 *   instead, see riemann::AdaptiveMaximumStepFactor: hits are found on each
 *   step's chord, so long steps would cut corners.)
 * - MaximumError: the per-step error tolerance of DORMAND_PRINCE45 (mixed
 *   absolute/relative).
 * - MaximumPropagation: the arc length at which a geodesic (or a ray) stops.
 * - MaximumNumberOfSteps: the steps after which it stops.
 *
 * The defaults, ranges, units and help of these properties, and their names
 * in the command line, the desktop app, scene files and ParaView, are
 * declared once: vtkRiemannIntegrationSettings.settings.json (with the
 * "Rays" preset, the defaults of a picture's rays: vtkRiemannSetRayDefaults).
 * Values are stored as given; CheckSettings() names the first one outside
 * its declared range (or a minimum step above the maximum), and every
 * consumer refuses to run with it (vtkErrorMacro, empty output).
 *
 * @code{.py}
 * tracer = riemann.vtkRiemannGeodesicTracer()
 * settings = tracer.GetIntegrationSettings()
 * settings.SetIntegratorTypeToDormandPrince45()
 * settings.SetMaximumPropagation(5.0)
 * @endcode
 */
#ifndef vtkRiemannIntegrationSettings_h
#define vtkRiemannIntegrationSettings_h

#include "RiemannCommonCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <string> // For std::string

namespace riemann
{
struct GeodesicOptions;
}

class RIEMANNCOMMONCORE_EXPORT vtkRiemannIntegrationSettings : public vtkObject
{
public:
  static vtkRiemannIntegrationSettings* New();
  vtkTypeMacro(vtkRiemannIntegrationSettings, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Integrators (riemann::IntegratorType's numbering; JSON, CLI and ivars use it).
  enum Integrators
  {
    EULER = 0,
    RUNGE_KUTTA4 = 1,
    DORMAND_PRINCE45 = 2
  };

  ///@{
  /// The integrator. Default RUNGE_KUTTA4.
  vtkSetClampMacro(IntegratorType, int, EULER, DORMAND_PRINCE45);
  vtkGetMacro(IntegratorType, int);
  void SetIntegratorTypeToEuler() { this->SetIntegratorType(EULER); }
  void SetIntegratorTypeToRungeKutta4() { this->SetIntegratorType(RUNGE_KUTTA4); }
  void SetIntegratorTypeToDormandPrince45() { this->SetIntegratorType(DORMAND_PRINCE45); }
  ///@}

  ///@{
  /**
   * The integrator by its command-line name: "euler", "rk4" or "dp45"
   * ("adaptive", the renderers' old word, is accepted too). Returns false,
   * changing nothing, for any other name.
   */
  bool SetIntegratorTypeFromName(const char* name);
  const char* GetIntegratorTypeAsString() const;
  ///@}

  ///@{
  /// Step in Riemannian arc length (fixed, or the first adaptive one). Default 0.01.
  vtkSetMacro(InitialIntegrationStep, double);
  vtkGetMacro(InitialIntegrationStep, double);
  ///@}

  ///@{
  /// Bounds of the adaptive step (DORMAND_PRINCE45). Defaults 1e-7 and 0.5.
  vtkSetMacro(MinimumIntegrationStep, double);
  vtkGetMacro(MinimumIntegrationStep, double);
  vtkSetMacro(MaximumIntegrationStep, double);
  vtkGetMacro(MaximumIntegrationStep, double);
  ///@}

  ///@{
  /// Per-step error tolerance of DORMAND_PRINCE45. Default 1e-8.
  vtkSetMacro(MaximumError, double);
  vtkGetMacro(MaximumError, double);
  ///@}

  ///@{
  /// Arc length at which each geodesic stops. Default 10.
  vtkSetMacro(MaximumPropagation, double);
  vtkGetMacro(MaximumPropagation, double);
  ///@}

  ///@{
  /// Steps after which each geodesic stops. Default 100000 (GeodesicOptions).
  vtkSetMacro(MaximumNumberOfSteps, vtkIdType);
  vtkGetMacro(MaximumNumberOfSteps, vtkIdType);
  ///@}

  /**
   * "" when every setting is usable; otherwise one sentence naming the first
   * setting that is not, e.g. "InitialIntegrationStep is nan: expected a
   * finite number > 0".
   */
  std::string CheckSettings() const;

  /// Copy every setting of `other` (nothing when it is null).
  void DeepCopy(vtkRiemannIntegrationSettings* other);

  /// The settings as the core's geodesic options (the other options keep their values).
  VTK_WRAPEXCLUDE void ApplyTo(riemann::GeodesicOptions& options) const;

  /**
   * For the consumers' SetIntegrationSettings(): `slot` (owned by `owner`,
   * never null) becomes `settings`, registered by `owner`; null or the same
   * object changes nothing. Returns whether it changed.
   */
  VTK_WRAPEXCLUDE static bool Share(vtkObject* owner, vtkRiemannIntegrationSettings*& slot,
    vtkRiemannIntegrationSettings* settings);

protected:
  /// The defaults are the declared ones, the same as `riemann trace`'s and
  /// the core's (riemann::GeodesicOptions): one default per setting.
  /// Renderers then set the rays' own (vtkRiemannSetRayDefaults).
  vtkRiemannIntegrationSettings();
  ~vtkRiemannIntegrationSettings() override = default;

  int IntegratorType = RUNGE_KUTTA4;
  double InitialIntegrationStep = 0.0;
  double MinimumIntegrationStep = 0.0;
  double MaximumIntegrationStep = 0.0;
  double MaximumError = 0.0;
  double MaximumPropagation = 0.0;
  vtkIdType MaximumNumberOfSteps = 0;

private:
  vtkRiemannIntegrationSettings(const vtkRiemannIntegrationSettings&) = delete;
  void operator=(const vtkRiemannIntegrationSettings&) = delete;
};

#endif
