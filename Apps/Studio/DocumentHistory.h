/**
 * @class riemann::studio::DocumentHistory
 * @brief Undo and redo for riemann-studio's document (issue 32): a
 * QUndoStack of the document's changes, one command class per kind of
 * change (DocumentChanges.h): an item added, removed, renamed, shown or
 * hidden, its properties applied; the metric text applied, a parameter, t;
 * the scene; the observer; the inside view's ray settings.
 *
 * How a change is seen: whatever path makes it (the browser, the properties
 * panel, the editor, a slider, a drag, a script), the document or one of
 * its items signals, and after the event that made it the history compares
 * the document's fingerprint (ProjectFingerprint: the project text of the
 * document) with the one it last knew. A difference is one command holding
 * both texts, named by what differs; undo makes the document hold the text
 * before (ApplyProject), redo the text after, so the document after undo
 * is the document before, exactly (its project text). Moves of the
 * observer, a slider or t closer than MergeSeconds to the previous of the
 * same kind merge: a drag is one step.
 */
#ifndef RiemannStudioDocumentHistory_h
#define RiemannStudioDocumentHistory_h

#include <QObject>
#include <QUndoStack>

#include <functional>
#include <string>

namespace riemann
{
namespace studio
{
class PipelineItem;
class StudioDocument;

class DocumentHistory : public QObject
{
  Q_OBJECT
public:
  /// Changes of one kind closer than this in time merge (a drag is one step).
  static constexpr double MergeSeconds = 0.7;

  /// `restored` runs after undo or redo changed the document (the window
  /// shows the metric text again, ...).
  DocumentHistory(StudioDocument* document, std::function<void()> restored, QObject* parent);

  QUndoStack* Stack() { return &this->Undo; }
  /// A new document (opened, or the first): no history, this is its start.
  void Reset();
  /// Compare the document with the last known state and record a change (now).
  void Record();
  /**
   * While paused (an animation export moving t and the observer frame by
   * frame, then putting them back) changes are not recorded; resuming
   * compares once, so what is left changed is one step.
   */
  void SetPaused(bool paused);
  /// The document's fingerprint as of the last comparison (ProjectFingerprint).
  const std::string& Fingerprint() const { return this->Known; }

Q_SIGNALS:
  /// The document was compared with its last state (after any change,
  /// undo or redo): Fingerprint() is current.
  void Compared();

private:
  void ScheduleRecord();
  void Watch(PipelineItem* item);
  /// Make the document hold the project text `json` (undo and redo).
  void Restore(const std::string& json);

  StudioDocument* Doc;
  std::function<void()> Restored;
  QUndoStack Undo;
  std::string Known;
  bool Restoring = false;
  bool Pending = false;
  bool Paused = false;
};
} // namespace studio
} // namespace riemann

#endif
