/**
 * @file HelpMenu.h
 * @brief riemann-studio's Help menu: the bundled guides (Studio.md,
 * MetricFormat.md, opened with the desktop's viewer), the keyboard
 * shortcuts of every menu, and About.
 */
#ifndef RiemannStudioHelpMenu_h
#define RiemannStudioHelpMenu_h

#include <QString>
#include <QStringList>

class QMainWindow;
class QMenuBar;

namespace riemann
{
namespace studio
{
/// The bundled document `name` ("Studio.md"): beside the data folder
/// (`dataDirectory`/../Documentation), cleaned; it may not exist.
QString DocumentationPath(const QString& dataDirectory, const QString& name);

/// "File > Save Project As...: Ctrl+Shift+S" for every action of the menu
/// bar with a shortcut, menu by menu.
QStringList KeyboardShortcuts(const QMenuBar* menus);

/// Add the Help menu to `window`'s menu bar (last, after the others).
void AddHelpMenu(QMainWindow* window, const QString& dataDirectory);
} // namespace studio
} // namespace riemann

#endif
