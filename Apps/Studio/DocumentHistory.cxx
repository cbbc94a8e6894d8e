#include "DocumentHistory.h"

#include "DocumentChanges.h"
#include "PipelineItem.h"
#include "ProjectFile.h"
#include "StudioDocument.h"

#include <QTimer>

#include <nlohmann/json.hpp>

#include <map>

namespace riemann
{
namespace studio
{
DocumentHistory::DocumentHistory(
  StudioDocument* document, std::function<void()> restored, QObject* parent)
  : QObject(parent)
  , Doc(document)
  , Restored(std::move(restored))
{
  // Every signal of a change schedules one comparison after the event that
  // made it (several signals of one change make one command).
  for (auto signal : { &StudioDocument::MetricChanged, &StudioDocument::SceneChanged,
         &StudioDocument::ObserverMoved })
  {
    QObject::connect(document, signal, this, &DocumentHistory::ScheduleRecord);
  }
  QObject::connect(document, &StudioDocument::ItemRemoved, this, &DocumentHistory::ScheduleRecord);
  QObject::connect(document, &StudioDocument::ItemAdded, this, [this](PipelineItem* item) {
    this->Watch(item);
    this->ScheduleRecord();
  });
  for (const auto& item : document->Items())
  {
    this->Watch(item.get());
  }
  this->Reset();
}

void DocumentHistory::Watch(PipelineItem* item)
{
  QObject::connect(item, &PipelineItem::NameChanged, this, &DocumentHistory::ScheduleRecord);
  QObject::connect(item, &PipelineItem::VisibilityChanged, this, &DocumentHistory::ScheduleRecord);
  QObject::connect(item, &PipelineItem::SettingsChanged, this, &DocumentHistory::ScheduleRecord);
}

void DocumentHistory::Reset()
{
  this->Undo.clear();
  this->Known = ProjectFingerprint(*this->Doc);
  Q_EMIT this->Compared();
}

void DocumentHistory::ScheduleRecord()
{
  if (this->Restoring || this->Pending)
  {
    return;
  }
  this->Pending = true;
  QTimer::singleShot(0, this, [this]() {
    this->Pending = false;
    this->Record();
  });
}

void DocumentHistory::SetPaused(bool paused)
{
  this->Paused = paused;
  if (!paused)
  {
    this->Record();
  }
}

void DocumentHistory::Record()
{
  if (this->Restoring || this->Paused)
  {
    return;
  }
  const std::string now = ProjectFingerprint(*this->Doc);
  if (now != this->Known)
  {
    auto change = MakeDocumentChange(
      this->Known, now, [this](const std::string& json) { this->Restore(json); });
    this->Known = now;
    this->Undo.push(change.release());
  }
  Q_EMIT this->Compared();
}

void DocumentHistory::Restore(const std::string& json)
{
  this->Restoring = true;
  try
  {
    const ProjectData project = ParseProject(json, "");
    ApplyProject(project, *this->Doc);
    // A project lists the sliders moved from the text's numbers; one moved
    // since goes back to the text's number (the same text keeps the values).
    const nlohmann::json text = nlohmann::json::parse(project.MetricText, nullptr, false);
    const std::map<std::string, double> now = this->Doc->ParameterValues();
    for (const auto& value : now)
    {
      if (project.ParameterValues.count(value.first) == 0 && text.is_object())
      {
        const nlohmann::json::json_pointer pointer(value.first);
        if (text.contains(pointer) && text.at(pointer).is_number())
        {
          this->Doc->SetParameterValue(value.first, text.at(pointer).get<double>());
        }
      }
    }
  }
  catch (const ProjectError&)
  {
    // A fingerprint parses (it was written by this document); a scene file
    // deleted since is the only failure, and the document keeps its state.
  }
  this->Known = ProjectFingerprint(*this->Doc);
  if (this->Restored)
  {
    this->Restored();
  }
  this->Restoring = false;
  Q_EMIT this->Compared();
}
} // namespace studio
} // namespace riemann
