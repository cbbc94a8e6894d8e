#include "ProjectSession.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace riemann
{
namespace studio
{
namespace
{
const QString Organisation = QStringLiteral("RiemannVTK");
const QString Application = QStringLiteral("riemann-studio");
const QString RecentKey = QStringLiteral("recentFiles");
} // namespace

QString ProjectSession::StartFolder() const
{
  if (!this->ProjectPath.isEmpty())
  {
    return QFileInfo(this->ProjectPath).absolutePath();
  }
  return this->LastFolder.isEmpty() ? QDir::currentPath() : this->LastFolder;
}

void ProjectSession::RememberFolderOf(const QString& path)
{
  if (!path.isEmpty())
  {
    this->LastFolder = QFileInfo(path).absolutePath();
  }
}

QStringList ProjectSession::RecentFiles()
{
  QStringList existing;
  const QSettings settings(Organisation, Application);
  for (const QString& path : settings.value(RecentKey).toStringList())
  {
    if (QFileInfo::exists(path))
    {
      existing << path;
    }
  }
  return existing;
}

void ProjectSession::AddRecentFile(const QString& path)
{
  const QString absolute = QFileInfo(path).absoluteFilePath();
  QStringList recent = RecentFiles();
  recent.removeAll(absolute);
  recent.prepend(absolute);
  while (recent.size() > MaximumRecentFiles)
  {
    recent.removeLast();
  }
  QSettings settings(Organisation, Application);
  settings.setValue(RecentKey, recent);
}
} // namespace studio
} // namespace riemann
