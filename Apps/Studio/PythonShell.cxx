#include "PythonShell.h"

#include "StudioPython.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QShowEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QTextCharFormat>
#include <QTextCursor>
#include <QVBoxLayout>

namespace riemann
{
namespace studio
{
PythonShell::PythonShell(StudioMainWindow* window, QWidget* parent)
  : QWidget(parent)
  , Window(window)
  , Output(new QPlainTextEdit(this))
  , Prompt(new QLabel(QStringLiteral(">>>"), this))
  , Line(new QLineEdit(this))
{
  const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
  this->Output->setObjectName("PythonShellOutput");
  this->Output->setReadOnly(true);
  this->Output->setFont(mono);
  this->Output->setMaximumBlockCount(5000);
  this->Line->setObjectName("PythonShellInput");
  this->Line->setFont(mono);
  this->Prompt->setFont(mono);
  this->Line->installEventFilter(this);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(this->Output, 1);
  auto* row = new QHBoxLayout;
  row->addWidget(this->Prompt);
  row->addWidget(this->Line, 1);
  layout->addLayout(row);

  QObject::connect(this->Line, &QLineEdit::returnPressed, this, [this]() {
    const QString line = this->Line->text();
    this->Line->clear();
    this->Enter(line);
  });
}

PythonShell::~PythonShell()
{
  if (this->Started)
  {
    StudioPython::Instance().Detach(this->Window);
  }
}

bool PythonShell::Start()
{
  StudioPython& python = StudioPython::Instance();
  if (!this->Started)
  {
    this->Started = true;
    python.Attach(this->Window, [this](const QString& text, bool error) { this->Append(text, error); });
    if (python.Available())
    {
      this->Append(QStringLiteral("Python %1 with the studio module: studio.items(), studio.add(\"geodesics\", "
                                  "ConeAngle=20), studio.undo(), ... (help(studio)); import riemann and VTK "
                                  "as in scripts.\n")
                     .arg(StudioPython::Version()),
        false);
    }
    else
    {
      this->Append(python.Error() + "\n", true);
      this->Line->setEnabled(false);
    }
  }
  return python.Available();
}

int PythonShell::RunScript(const QString& path)
{
  if (!this->Start())
  {
    return 1;
  }
  return StudioPython::Instance().RunScript(path);
}

void PythonShell::showEvent(QShowEvent* event)
{
  this->Start();
  QWidget::showEvent(event);
}

bool PythonShell::Enter(const QString& line)
{
  if (!this->Start())
  {
    return false;
  }
  StudioPython& python = StudioPython::Instance();
  if (python.Busy())
  {
    return false;
  }
  this->Append(this->Prompt->text() + " " + line + "\n", false);
  if (!line.trimmed().isEmpty() && (this->History.isEmpty() || this->History.last() != line))
  {
    this->History << line;
  }
  this->HistoryAt = this->History.size();
  // The console waits while the line runs (studio.render() lets the window
  // paint meanwhile, but no second line may start inside the first).
  this->Line->setEnabled(false);
  const bool more = python.Push(line);
  this->Line->setEnabled(true);
  this->Line->setFocus();
  this->Prompt->setText(more ? QStringLiteral("...") : QStringLiteral(">>>"));
  return more;
}

QString PythonShell::Transcript() const
{
  return this->Output->toPlainText();
}

bool PythonShell::eventFilter(QObject* watched, QEvent* event)
{
  if (watched == this->Line && event->type() == QEvent::KeyPress && !this->History.isEmpty())
  {
    const int key = static_cast<QKeyEvent*>(event)->key();
    if (key == Qt::Key_Up || key == Qt::Key_Down)
    {
      this->HistoryAt = std::max(0, std::min<int>(this->History.size(),
        this->HistoryAt + (key == Qt::Key_Up ? -1 : 1)));
      this->Line->setText(this->HistoryAt < this->History.size() ? this->History[this->HistoryAt] : QString());
      return true;
    }
  }
  return QWidget::eventFilter(watched, event);
}

void PythonShell::Append(const QString& text, bool error)
{
  QTextCursor cursor = this->Output->textCursor();
  cursor.movePosition(QTextCursor::End);
  QTextCharFormat format;
  format.setForeground(error ? QColor(200, 40, 40) : this->palette().color(QPalette::Text));
  cursor.insertText(text, format);
  this->Output->setTextCursor(cursor);
  this->Output->verticalScrollBar()->setValue(this->Output->verticalScrollBar()->maximum());
}
}
}
