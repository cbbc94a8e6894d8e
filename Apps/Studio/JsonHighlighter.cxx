#include "JsonHighlighter.h"

#include "MetricText.h"

namespace riemann
{
namespace studio
{
JsonHighlighter::JsonHighlighter(QTextDocument* document)
  : QSyntaxHighlighter(document)
{
  this->Key.setForeground(QColor(0x1f, 0x5f, 0xbf));
  this->Key.setFontWeight(QFont::Bold);
  this->String.setForeground(QColor(0x1a, 0x7f, 0x37));
  this->Number.setForeground(QColor(0xaf, 0x52, 0x00));
  this->Keyword.setForeground(QColor(0x8f, 0x2f, 0x9f));
  this->Punctuation.setForeground(QColor(0x60, 0x60, 0x60));
}

void JsonHighlighter::highlightBlock(const QString& text)
{
  // Spans are byte offsets in UTF-8; map them back to UTF-16 positions.
  const QByteArray utf8 = text.toUtf8();
  std::vector<int> position(utf8.size() + 1, 0);
  int characters = 0;
  for (int byte = 0; byte < utf8.size(); ++byte)
  {
    position[byte] = characters;
    const unsigned char c = static_cast<unsigned char>(utf8[byte]);
    if ((c & 0xC0) != 0x80)
    {
      // A 4-byte sequence is a surrogate pair in UTF-16.
      characters += c >= 0xF0 ? 2 : 1;
    }
  }
  position[utf8.size()] = characters;
  // Continuation bytes map to the position of the character after their lead.
  for (const TextSpan& span : HighlightJson(utf8.toStdString()))
  {
    const QTextCharFormat* format = span.Type == TextSpan::Key ? &this->Key
      : span.Type == TextSpan::String                          ? &this->String
      : span.Type == TextSpan::Number                          ? &this->Number
      : span.Type == TextSpan::Keyword                         ? &this->Keyword
                                                               : &this->Punctuation;
    const int start = position[span.Start];
    const int end = position[std::min<int>(span.Start + span.Length, utf8.size())];
    this->setFormat(start, end - start, *format);
  }
}
}
}
