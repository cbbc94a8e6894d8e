#include "PropertiesPanel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

namespace riemann
{
namespace studio
{
namespace
{
int ComponentCount(const PropertySpec& spec)
{
  switch (spec.Type)
  {
    case PropertySpec::Vector3:
    case PropertySpec::Integers3:
      return 3;
    case PropertySpec::Numbers6:
      return 6;
    default:
      return 1;
  }
}

/// "x, y, z; x, y, z" as [[x, y, z], [x, y, z]]; empty text is no points.
nlohmann::json ReadPoints(const QString& text, QString& problem)
{
  nlohmann::json points = nlohmann::json::array();
  const QStringList parts = text.split(';', Qt::SkipEmptyParts);
  for (int i = 0; i < parts.size(); ++i)
  {
    const QStringList xyz = parts[i].split(',', Qt::SkipEmptyParts);
    nlohmann::json point = nlohmann::json::array();
    for (const QString& coordinate : xyz)
    {
      bool ok = false;
      const double number = coordinate.trimmed().toDouble(&ok);
      if (!ok)
      {
        problem = QStringLiteral("point %1: \"%2\" is not a number").arg(i + 1).arg(coordinate.trimmed());
        return nlohmann::json();
      }
      point.push_back(number);
    }
    if (point.size() != 3)
    {
      problem = QStringLiteral("point %1: expected x, y, z").arg(i + 1);
      return nlohmann::json();
    }
    points.push_back(point);
  }
  return points;
}

QString NumberText(const nlohmann::json& value)
{
  return value.is_number() ? QString::number(value.get<double>(), 'g', 12) : QString();
}

const QString BadStyle = QStringLiteral("background: #ffe0e0; border: 1px solid #b00020;");
}

PropertiesPanel::PropertiesPanel(QWidget* parent)
  : QWidget(parent)
  , Title(new QLabel(this))
  , FormHost(new QWidget)
  , Status(new QLabel(this))
  , ApplyButton(new QPushButton(QStringLiteral("Apply"), this))
  , ResetButton(new QPushButton(QStringLiteral("Reset"), this))
  , AutoApplyBox(new QCheckBox(QStringLiteral("Auto apply"), this))
{
  this->setObjectName("PropertiesPanel");
  this->ApplyButton->setObjectName("ApplyButton");
  this->AutoApplyBox->setObjectName("AutoApply");
  this->Title->setWordWrap(true);
  this->Status->setWordWrap(true);
  this->Status->setObjectName("PropertiesStatus");
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(this->ApplyButton);
  buttons->addWidget(this->ResetButton);
  buttons->addStretch(1);
  buttons->addWidget(this->AutoApplyBox);
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setWidget(this->FormHost);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addLayout(buttons);
  layout->addWidget(this->Title);
  layout->addWidget(scroll, 1);
  layout->addWidget(this->Status);
  QObject::connect(this->ApplyButton, &QPushButton::clicked, this, &PropertiesPanel::Apply);
  QObject::connect(this->ResetButton, &QPushButton::clicked, this, [this]() {
    this->Show(this->Title->text(), this->Specs, this->Values, this->ApplyFunction);
  });
  this->Clear(QString());
}

void PropertiesPanel::Clear(const QString& message)
{
  this->Show(QString(), {}, nlohmann::json::object(), nullptr);
  this->Title->setText(message);
}

void PropertiesPanel::Show(const QString& title, const std::vector<PropertySpec>& specs,
  const nlohmann::json& values, Applier apply)
{
  this->Specs = specs;
  this->Values = values;
  this->ApplyFunction = std::move(apply);
  this->Editors.clear();
  this->Pending.clear();
  this->Problems.clear();
  this->Title->setText(title);
  delete this->Form;
  qDeleteAll(this->FormHost->findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly));
  this->Form = new QFormLayout(this->FormHost);
  for (const PropertySpec& spec : this->Specs)
  {
    QWidget* editor = this->MakeEditor(spec, values.value(spec.Key, nlohmann::json()));
    auto* label = new QLabel(spec.Label, this->FormHost);
    label->setToolTip(spec.Help);
    this->Form->addRow(label, editor);
  }
  this->UpdateState();
}

QWidget* PropertiesPanel::MakeEditor(const PropertySpec& spec, const nlohmann::json& value)
{
  auto* host = new QWidget(this->FormHost);
  auto* row = new QHBoxLayout(host);
  row->setContentsMargins(0, 0, 0, 0);
  std::vector<QWidget*>& editors = this->Editors[spec.Key];
  const QString name = QString::fromStdString(spec.Key);
  if (spec.Type == PropertySpec::Choice)
  {
    auto* combo = new QComboBox(host);
    combo->addItems(spec.Choices);
    combo->setEditable(spec.OpenChoice);
    combo->setCurrentText(value.is_string() ? QString::fromStdString(value.get<std::string>()) : QString());
    QObject::connect(combo, QOverload<int>::of(&QComboBox::activated), this,
      [this, spec]() { this->Edited(spec, true); });
    editors.push_back(combo);
  }
  else if (spec.Type == PropertySpec::Boolean)
  {
    auto* check = new QCheckBox(host);
    check->setChecked(value.is_boolean() && value.get<bool>());
    QObject::connect(check, &QCheckBox::toggled, this, [this, spec]() { this->Edited(spec, true); });
    editors.push_back(check);
  }
  else if (spec.Type == PropertySpec::PointList)
  {
    auto* line = new QLineEdit(host);
    QStringList points;
    for (const nlohmann::json& point : value.is_array() ? value : nlohmann::json::array())
    {
      QStringList xyz;
      for (const nlohmann::json& number : point)
      {
        xyz << NumberText(number);
      }
      points << xyz.join(", ");
    }
    line->setText(points.join("; "));
    line->setPlaceholderText("x, y, z; x, y, z");
    QObject::connect(line, &QLineEdit::textEdited, this, [this, spec]() { this->Edited(spec, false); });
    QObject::connect(line, &QLineEdit::editingFinished, this, [this, spec]() { this->Edited(spec, true); });
    editors.push_back(line);
  }
  else if (spec.Type == PropertySpec::NumberList)
  {
    auto* line = new QLineEdit(host);
    QStringList numbers;
    for (const nlohmann::json& number : value.is_array() ? value : nlohmann::json::array())
    {
      numbers << NumberText(number);
    }
    line->setText(numbers.join(", "));
    line->setPlaceholderText("1, 2.5, 4");
    QObject::connect(line, &QLineEdit::textEdited, this, [this, spec]() { this->Edited(spec, false); });
    QObject::connect(line, &QLineEdit::editingFinished, this, [this, spec]() { this->Edited(spec, true); });
    editors.push_back(line);
  }
  else
  {
    const int count = ComponentCount(spec);
    for (int i = 0; i < count; ++i)
    {
      auto* line = new QLineEdit(host);
      line->setText(NumberText(count == 1 ? value : value.is_array() && value.size() > std::size_t(i)
            ? value[i] : nlohmann::json()));
      QObject::connect(line, &QLineEdit::textEdited, this, [this, spec]() { this->Edited(spec, false); });
      QObject::connect(line, &QLineEdit::editingFinished, this, [this, spec]() { this->Edited(spec, true); });
      editors.push_back(line);
    }
  }
  for (std::size_t i = 0; i < editors.size(); ++i)
  {
    editors[i]->setObjectName(name + (editors.size() > 1 ? QString::number(i) : QString()));
    editors[i]->setToolTip(spec.Help);
    row->addWidget(editors[i], 1);
  }
  return host;
}

nlohmann::json PropertiesPanel::ReadEditor(const PropertySpec& spec, QString& problem) const
{
  const std::vector<QWidget*>& editors = this->Editors.at(spec.Key);
  if (auto* combo = qobject_cast<QComboBox*>(editors.front()))
  {
    return combo->currentText().toStdString();
  }
  if (auto* check = qobject_cast<QCheckBox*>(editors.front()))
  {
    return check->isChecked();
  }
  if (spec.Type == PropertySpec::PointList)
  {
    return ReadPoints(static_cast<QLineEdit*>(editors.front())->text(), problem);
  }
  // A list is one field of comma-separated numbers; a vector, one field each.
  QStringList texts;
  for (QWidget* editor : editors)
  {
    texts << static_cast<QLineEdit*>(editor)->text().trimmed();
  }
  if (spec.Type == PropertySpec::NumberList)
  {
    texts = texts.front().split(',', Qt::SkipEmptyParts);
  }
  nlohmann::json numbers = nlohmann::json::array();
  for (int i = 0; i < texts.size(); ++i)
  {
    const QString text = texts[i].trimmed();
    bool ok = false;
    const double number = text.toDouble(&ok);
    if (!ok)
    {
      problem = texts.size() > 1
        ? QStringLiteral("number %1: \"%2\" is not a number").arg(i + 1).arg(text)
        : QStringLiteral("\"%1\" is not a number").arg(text);
      return nlohmann::json();
    }
    numbers.push_back(number);
  }
  if (spec.Type == PropertySpec::NumberList)
  {
    return numbers;
  }
  return editors.size() == 1 && !numbers.empty() ? numbers[0] : numbers;
}

void PropertiesPanel::Edited(const PropertySpec& spec, bool finished)
{
  QString problem;
  const nlohmann::json value = this->ReadEditor(spec, problem);
  if (problem.isEmpty())
  {
    problem = CheckPropertyValue(spec, value);
  }
  if (problem.isEmpty())
  {
    this->Problems.erase(spec.Key);
    if (this->Values.value(spec.Key, nlohmann::json()) != value)
    {
      this->Pending[spec.Key] = value;
    }
    else
    {
      this->Pending.erase(spec.Key);
    }
  }
  else
  {
    this->Problems[spec.Key] = spec.Label + ": " + problem;
  }
  for (QWidget* editor : this->Editors.at(spec.Key))
  {
    editor->setStyleSheet(problem.isEmpty() ? QString() : BadStyle);
    editor->setToolTip(problem.isEmpty() ? spec.Help : problem);
  }
  this->UpdateState();
  if (finished && this->AutoApply() && this->Problems.empty() && !this->Pending.empty())
  {
    this->Apply();
  }
}

bool PropertiesPanel::Apply()
{
  if (!this->Problems.empty() || !this->ApplyFunction)
  {
    return false;
  }
  if (this->Pending.empty())
  {
    return true;
  }
  nlohmann::json changes = nlohmann::json::object();
  for (const auto& entry : this->Pending)
  {
    changes[entry.first] = entry.second;
  }
  const QString error = this->ApplyFunction(changes);
  if (error.isEmpty())
  {
    for (const auto& entry : this->Pending)
    {
      this->Values[entry.first] = entry.second;
    }
    this->Pending.clear();
  }
  this->UpdateState();
  if (!error.isEmpty())
  {
    this->Status->setText(QStringLiteral("<span style='color:#b00020'>%1</span>").arg(error.toHtmlEscaped()));
  }
  Q_EMIT this->Applied(error);
  return error.isEmpty();
}

void PropertiesPanel::SetAutoApply(bool on)
{
  this->AutoApplyBox->setChecked(on);
}

bool PropertiesPanel::AutoApply() const
{
  return this->AutoApplyBox->isChecked();
}

void PropertiesPanel::UpdateState()
{
  this->ApplyButton->setEnabled(this->Problems.empty() && !this->Pending.empty());
  this->ResetButton->setEnabled(!this->Pending.empty() || !this->Problems.empty());
  QStringList problems;
  for (const auto& entry : this->Problems)
  {
    problems << entry.second.toHtmlEscaped();
  }
  this->Status->setText(problems.isEmpty() ? QString()
                                           : QStringLiteral("<span style='color:#b00020'>%1</span><br><i>Not applied.</i>")
                                               .arg(problems.join("<br>")));
}

QWidget* PropertiesPanel::Field(const std::string& key, int index) const
{
  auto editors = this->Editors.find(key);
  return editors == this->Editors.end() || index >= static_cast<int>(editors->second.size())
    ? nullptr
    : editors->second[index];
}

QString PropertiesPanel::FieldError(const std::string& key) const
{
  auto problem = this->Problems.find(key);
  return problem == this->Problems.end() ? QString() : problem->second;
}

QString PropertiesPanel::Message() const
{
  return this->Status->text();
}
}
}
