#include "MetricEditor.h"

#include "JsonHighlighter.h"
#include "StudioDocument.h"

#include <QFontDatabase>
#include <QLabel>
#include <QPlainTextEdit>
#include <QTextBlock>
#include <QTimer>
#include <QVBoxLayout>

namespace riemann
{
namespace studio
{
MetricEditor::MetricEditor(StudioDocument* document, QWidget* parent)
  : QWidget(parent)
  , Document(document)
  , TextEdit(new QPlainTextEdit(this))
  , Status(new QLabel(this))
  , Debounce(new QTimer(this))
{
  this->TextEdit->setObjectName("MetricText");
  this->TextEdit->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  this->TextEdit->setLineWrapMode(QPlainTextEdit::NoWrap);
  this->TextEdit->setTabChangesFocus(false);
  new JsonHighlighter(this->TextEdit->document());
  this->Status->setObjectName("MetricStatus");
  this->Status->setWordWrap(true);
  this->Status->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(this->TextEdit, 1);
  layout->addWidget(this->Status);

  this->Debounce->setSingleShot(true);
  this->Debounce->setInterval(400);
  QObject::connect(this->Debounce, &QTimer::timeout, this, &MetricEditor::ApplyNow);
  QObject::connect(this->TextEdit, &QPlainTextEdit::textChanged, this, [this]() {
    if (!this->Loading)
    {
      this->Debounce->start();
    }
  });
  this->Loading = true;
  this->TextEdit->setPlainText(QString::fromStdString(document->MetricText()));
  this->Loading = false;
  this->ShowStatus(MetricStatus());
}

QString MetricEditor::SetText(const QString& text)
{
  this->Loading = true;
  this->TextEdit->setPlainText(text);
  this->Loading = false;
  this->ApplyNow();
  return this->ErrorText();
}

QString MetricEditor::Text() const
{
  return this->TextEdit->toPlainText();
}

QString MetricEditor::ErrorText() const
{
  return this->Status->property("error").toString();
}

void MetricEditor::SetDebounceDelay(int milliseconds)
{
  this->Debounce->setInterval(milliseconds);
}

void MetricEditor::ApplyNow()
{
  this->Debounce->stop();
  const std::string text = this->TextEdit->toPlainText().toStdString();
  if (text == this->Document->MetricText())
  {
    this->ShowStatus(MetricStatus());
    return;
  }
  this->ShowStatus(this->Document->SetMetricText(text));
}

void MetricEditor::ShowStatus(const MetricStatus& status)
{
  QList<QTextEdit::ExtraSelection> marks;
  if (status.Ok())
  {
    this->Status->setText(QStringLiteral("<span style='color:#2a7a2a'>Metric OK</span>"));
    this->Status->setProperty("error", QString());
  }
  else
  {
    const QString where = status.Location.Known
      ? QStringLiteral("Line %1, column %2: ").arg(status.Location.Line).arg(status.Location.Column)
      : QString();
    this->Status->setText(QStringLiteral("<span style='color:#b00020'>%1%2</span><br><i>The "
                                         "views show the last good metric.</i>")
                            .arg(where.toHtmlEscaped(), status.Message.toHtmlEscaped()));
    this->Status->setProperty("error", where + status.Message);
    if (status.Location.Known)
    {
      // Underline from the error to the end of its token (at least one character).
      QTextBlock block = this->TextEdit->document()->findBlockByNumber(status.Location.Line - 1);
      QTextCursor cursor(block);
      cursor.movePosition(QTextCursor::Right, QTextCursor::MoveAnchor,
        std::min(status.Location.Column - 1, std::max(0, block.length() - 1)));
      cursor.movePosition(QTextCursor::EndOfWord, QTextCursor::KeepAnchor);
      if (!cursor.hasSelection())
      {
        cursor.movePosition(QTextCursor::Right, QTextCursor::KeepAnchor);
      }
      QTextEdit::ExtraSelection mark;
      mark.cursor = cursor;
      mark.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
      mark.format.setUnderlineColor(QColor(0xb0, 0x00, 0x20));
      mark.format.setBackground(QColor(0xff, 0xe0, 0xe0));
      marks << mark;
    }
  }
  this->TextEdit->setExtraSelections(marks);
  Q_EMIT this->Checked(status.Ok(), this->ErrorText());
}
}
}
