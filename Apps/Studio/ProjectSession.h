/**
 * @class riemann::studio::ProjectSession
 * @brief What riemann-studio keeps about the file its document lives in:
 * the project's path, whether the document changed since it was opened or
 * saved, the folder dialogs start in, and the recent files.
 *
 * "Changed" compares the document's fingerprint (ProjectFingerprint: the
 * project text of everything a project saves of the document, without the
 * window's layout and outside camera, which move without the document
 * changing) with the one taken when it was last opened or saved, so any
 * edit by any path counts, and undoing it by hand clears the mark.
 *
 * Recent files are kept with QSettings (organisation "RiemannVTK",
 * application "riemann-studio", key "recentFiles"), newest first, at most
 * MaximumRecentFiles; files that no longer exist are left out.
 */
#ifndef RiemannStudioProjectSession_h
#define RiemannStudioProjectSession_h

#include <QString>
#include <QStringList>

#include <string>

namespace riemann
{
namespace studio
{
class ProjectSession
{
public:
  static constexpr int MaximumRecentFiles = 8;

  /// The project file ("" before one is opened or saved).
  const QString& Path() const { return this->ProjectPath; }
  void SetPath(const QString& path) { this->ProjectPath = path; }

  /// Where file dialogs start: the project's folder, else the folder of the
  /// last file opened or saved, else the working directory.
  QString StartFolder() const;
  /// A file was chosen in a dialog, opened or saved: its folder is the next start.
  void RememberFolderOf(const QString& path);

  /// The document as it is now is the file's (after open and save).
  void MarkClean(const std::string& fingerprint) { this->CleanFingerprint = fingerprint; }
  bool IsModified(const std::string& fingerprint) const
  {
    return fingerprint != this->CleanFingerprint;
  }

  static QStringList RecentFiles();
  /// Put `path` first in the recent files (absolute; once).
  static void AddRecentFile(const QString& path);

private:
  QString ProjectPath;
  QString LastFolder;
  std::string CleanFingerprint;
};
} // namespace studio
} // namespace riemann

#endif
