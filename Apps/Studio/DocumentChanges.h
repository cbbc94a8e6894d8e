/**
 * @file DocumentChanges.h
 * @brief The commands of riemann-studio's undo stack (DocumentHistory): one
 * class per kind of change, each holding the document's project text before
 * and after and naming the change as Edit > Undo shows it ("Add Geodesics",
 * "Rename Fan to Rays", "Move Observer"). MakeDocumentChange tells which
 * kind a change is from the two texts.
 */
#ifndef RiemannStudioDocumentChanges_h
#define RiemannStudioDocumentChanges_h

#include <QElapsedTimer>
#include <QUndoCommand>

#include <functional>
#include <memory>
#include <string>

namespace riemann
{
namespace studio
{
/// Kinds of change; the command ids that QUndoStack merges by.
enum class ChangeKind : int
{
  AddItem = 1,
  RemoveItem,
  RenameItem,
  ShowItem,
  ItemSettings,
  MetricText,
  Parameter,
  Time,
  Scene,
  Observer,
  RaySettings,
  Several
};

class DocumentChange : public QUndoCommand
{
public:
  using Restore = std::function<void(const std::string&)>;
  DocumentChange(ChangeKind kind, const QString& text, std::string before, std::string after,
    Restore restore, const std::string& mergeKey = std::string());

  int id() const override;
  void undo() override;
  void redo() override;
  bool mergeWith(const QUndoCommand* other) override;
  ChangeKind Kind() const { return this->TheKind; }

private:
  ChangeKind TheKind;
  std::string Before;
  std::string After;
  Restore RestoreText;
  /// Merges only with the same key (the slider's parameter), and in time.
  std::string MergeKey;
  QElapsedTimer LastChange;
  bool Done = true; // made before it was pushed: the first redo does nothing
};

/// The command for the change from `before` to `after` (two fingerprints),
/// named and kinded by what differs.
std::unique_ptr<DocumentChange> MakeDocumentChange(
  const std::string& before, const std::string& after, DocumentChange::Restore restore);
} // namespace studio
} // namespace riemann

#endif
