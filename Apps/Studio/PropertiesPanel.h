/**
 * @file PropertiesPanel.h
 * @brief The properties panel (ParaView's): a form for a list of settings
 * (PropertySpec), checked as typed, applied with Apply or automatically.
 *
 * A value that does not pass CheckPropertyValue is marked red with the
 * reason next to it and under the form, and Apply stays disabled: a bad
 * value is never applied. Auto-apply applies each good edit when it is
 * finished (Enter, leaving the field, picking a choice).
 */
#ifndef RiemannStudio_PropertiesPanel_h
#define RiemannStudio_PropertiesPanel_h

#include "PipelineItem.h"

#include <QWidget>

#include <functional>
#include <map>

class QCheckBox;
class QFormLayout;
class QLabel;
class QPushButton;

namespace riemann
{
namespace studio
{
class PropertiesPanel : public QWidget
{
  Q_OBJECT
public:
  /// Takes the edited settings; returns "" or why they were refused.
  using Applier = std::function<QString(const nlohmann::json&)>;

  explicit PropertiesPanel(QWidget* parent = nullptr);

  void Show(const QString& title, const std::vector<PropertySpec>& specs,
    const nlohmann::json& values, Applier apply);
  void Clear(const QString& message);

  /// Apply the pending edits; false (nothing applied) while one is bad.
  bool Apply();
  bool HasPendingEdits() const { return !this->Pending.empty(); }
  void SetAutoApply(bool on);
  bool AutoApply() const;

  /// The editor of setting `key` (component `index` for vectors), for tests.
  QWidget* Field(const std::string& key, int index = 0) const;
  /// The problem shown for `key` ("" when none).
  QString FieldError(const std::string& key) const;
  QString Message() const;

Q_SIGNALS:
  void Applied(const QString& error);

private:
  QWidget* MakeEditor(const PropertySpec& spec, const nlohmann::json& value);
  void Edited(const PropertySpec& spec, bool finished);
  nlohmann::json ReadEditor(const PropertySpec& spec, QString& problem) const;
  void UpdateState();

  QLabel* Title;
  QWidget* FormHost;
  QFormLayout* Form = nullptr;
  QLabel* Status;
  QPushButton* ApplyButton;
  QPushButton* ResetButton;
  QCheckBox* AutoApplyBox;
  std::vector<PropertySpec> Specs;
  nlohmann::json Values;
  Applier ApplyFunction;
  std::map<std::string, std::vector<QWidget*>> Editors;
  std::map<std::string, nlohmann::json> Pending;
  std::map<std::string, QString> Problems;
};
}
}

#endif
