#include "HelpMenu.h"

#include <QAction>
#include <QDesktopServices>
#include <QDir>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QUrl>

namespace riemann
{
namespace studio
{
namespace
{
/// The actions of `menu` and its submenus with shortcuts, under `path`.
void CollectShortcuts(const QMenu* menu, const QString& path, QStringList& lines)
{
  for (QAction* action : menu->actions())
  {
    const QString text = QString(action->text()).remove('&');
    if (action->menu())
    {
      CollectShortcuts(action->menu(), path + " > " + text, lines);
    }
    else if (!action->shortcuts().isEmpty())
    {
      QStringList keys;
      for (const QKeySequence& key : action->shortcuts())
      {
        keys << key.toString(QKeySequence::NativeText);
      }
      lines << path + " > " + text + ": " + keys.join(", ");
    }
  }
}

/// Open a bundled document, or say where it should have been.
void OpenDocument(QMainWindow* window, const QString& path)
{
  if (!QFileInfo::exists(path) || !QDesktopServices::openUrl(QUrl::fromLocalFile(path)))
  {
    QMessageBox::information(window, QFileInfo(path).fileName(),
      QFileInfo::exists(path) ? "No viewer opened it; the file is " + path
                              : "Not found: " + path + " (the Documentation folder beside Data)");
  }
}
} // namespace

QString DocumentationPath(const QString& dataDirectory, const QString& name)
{
  return QDir::cleanPath(dataDirectory + "/../Documentation/" + name);
}

QStringList KeyboardShortcuts(const QMenuBar* menus)
{
  QStringList lines;
  for (QAction* action : menus->actions())
  {
    if (action->menu())
    {
      CollectShortcuts(action->menu(), QString(action->text()).remove('&'), lines);
    }
  }
  return lines;
}

void AddHelpMenu(QMainWindow* window, const QString& dataDirectory)
{
  QMenu* help = window->menuBar()->addMenu("&Help");
  help->setObjectName("HelpMenu");
  help->addAction("Riemann Studio &Guide", window, [window, dataDirectory]() {
    OpenDocument(window, DocumentationPath(dataDirectory, "Studio.md"));
  }, QKeySequence::HelpContents);
  help->addAction("&Metric Format", window, [window, dataDirectory]() {
    OpenDocument(window, DocumentationPath(dataDirectory, "MetricFormat.md"));
  });
  help->addAction("&Keyboard Shortcuts", window, [window]() {
    QMessageBox box(QMessageBox::NoIcon, "Keyboard Shortcuts",
      KeyboardShortcuts(window->menuBar()).join("\n") +
        "\n\nInside view: drag to turn the observer, wheel to move, Ctrl+click a pixel to see its "
        "ray.\nOutside view: Ctrl+click places the selected item's points.",
      QMessageBox::Close, window);
    box.setObjectName("KeyboardShortcuts");
    box.exec();
  });
  help->addSeparator();
  help->addAction("&About Riemann Studio", window, [window]() {
    QMessageBox::about(window, "About Riemann Studio",
      "<b>Riemann Studio</b> (RiemannVTK)<br>Design a Riemannian metric on R<sup>3</sup> and see "
      "it from inside (curved rays) and outside.<br>Ctrl+click the inside view to see a pixel's "
      "ray. Help &gt; Metric Format has the metric files' keys.");
  });
}
} // namespace studio
} // namespace riemann
