/**
 * @file JsonHighlighter.h
 * @brief Colours JSON text in the metric editor (keys, strings, numbers,
 * keywords, punctuation) with HighlightJson's classes.
 */
#ifndef RiemannStudio_JsonHighlighter_h
#define RiemannStudio_JsonHighlighter_h

#include <QSyntaxHighlighter>
#include <QTextCharFormat>

namespace riemann
{
namespace studio
{
class JsonHighlighter : public QSyntaxHighlighter
{
  Q_OBJECT
public:
  explicit JsonHighlighter(QTextDocument* document);

protected:
  void highlightBlock(const QString& text) override;

private:
  QTextCharFormat Key, String, Number, Keyword, Punctuation;
};
}
}

#endif
