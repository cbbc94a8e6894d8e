#include "DocumentChanges.h"

#include "DocumentHistory.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace riemann
{
namespace studio
{
namespace
{
using Json = nlohmann::json;

QString Text(const std::string& text)
{
  return QString::fromStdString(text);
}

/// The last part of a JSON pointer: "/parameters/a" -> "a".
QString ParameterName(const std::string& pointer)
{
  const std::size_t slash = pointer.rfind('/');
  return Text(slash == std::string::npos ? pointer : pointer.substr(slash + 1));
}

struct Difference
{
  ChangeKind Kind = ChangeKind::Several;
  QString Name;
  std::string MergeKey;
};

/// What differs between two item lists, if that is one item's change.
bool ItemDifference(const Json& before, const Json& after, Difference& found)
{
  if (before == after)
  {
    return false;
  }
  const auto named = [](const Json& items, const std::string& name) {
    for (const Json& item : items)
    {
      if (item.value("name", "") == name)
      {
        return true;
      }
    }
    return false;
  };
  if (after.size() == before.size() + 1)
  {
    for (const Json& item : after)
    {
      if (!named(before, item.value("name", "")))
      {
        found = { ChangeKind::AddItem, "Add " + Text(item.value("name", "")), "" };
      }
    }
    return true;
  }
  if (before.size() == after.size() + 1)
  {
    for (const Json& item : before)
    {
      if (!named(after, item.value("name", "")))
      {
        found = { ChangeKind::RemoveItem, "Delete " + Text(item.value("name", "")), "" };
      }
    }
    return true;
  }
  std::vector<std::size_t> changed;
  for (std::size_t i = 0; i < before.size() && i < after.size(); ++i)
  {
    if (before[i] != after[i])
    {
      changed.push_back(i);
    }
  }
  if (before.size() != after.size() || changed.size() != 1)
  {
    found = { ChangeKind::Several, "Change Items", "" };
    return true;
  }
  const Json& a = before[changed[0]];
  const Json& b = after[changed[0]];
  const QString name = Text(a.value("name", ""));
  if (a.value("name", "") != b.value("name", ""))
  {
    found = { ChangeKind::RenameItem, "Rename " + name + " to " + Text(b.value("name", "")), "" };
  }
  else if (a.value("visible", true) != b.value("visible", true))
  {
    found = { ChangeKind::ShowItem, (b.value("visible", true) ? "Show " : "Hide ") + name, "" };
  }
  else
  {
    found = { ChangeKind::ItemSettings, "Apply " + name + " Properties", "" };
  }
  return true;
}
} // namespace

DocumentChange::DocumentChange(ChangeKind kind, const QString& text, std::string before,
  std::string after, Restore restore, const std::string& mergeKey)
  : QUndoCommand(text)
  , TheKind(kind)
  , Before(std::move(before))
  , After(std::move(after))
  , RestoreText(std::move(restore))
  , MergeKey(mergeKey)
{
  this->LastChange.start();
}

int DocumentChange::id() const
{
  return this->MergeKey.empty() ? -1 : static_cast<int>(this->TheKind);
}

void DocumentChange::undo()
{
  this->RestoreText(this->Before);
}

void DocumentChange::redo()
{
  if (this->Done)
  {
    this->Done = false; // pushed after the change was made
    return;
  }
  this->RestoreText(this->After);
}

bool DocumentChange::mergeWith(const QUndoCommand* other)
{
  const auto* next = dynamic_cast<const DocumentChange*>(other);
  if (!next || next->TheKind != this->TheKind || next->MergeKey != this->MergeKey ||
    this->MergeKey.empty() ||
    this->LastChange.elapsed() > static_cast<qint64>(1000 * DocumentHistory::MergeSeconds))
  {
    return false;
  }
  this->After = next->After;
  this->LastChange.restart();
  return true;
}

std::unique_ptr<DocumentChange> MakeDocumentChange(
  const std::string& before, const std::string& after, DocumentChange::Restore restore)
{
  const Json a = Json::parse(before, nullptr, false);
  const Json b = Json::parse(after, nullptr, false);
  std::vector<Difference> found;
  Difference items;
  if (a.is_object() && b.is_object())
  {
    if (ItemDifference(a.value("items", Json::array()), b.value("items", Json::array()), items))
    {
      found.push_back(items);
    }
    const Json& ma = a.at("metric");
    const Json& mb = b.at("metric");
    if (ma.value("text", "") != mb.value("text", "") || ma.value("folder", "") != mb.value("folder", ""))
    {
      found.push_back({ ChangeKind::MetricText, "Edit Metric", "" });
    }
    else if (ma.value("parameter-values", Json::object()) != mb.value("parameter-values", Json::object()))
    {
      // Held here: a range-for over items() of a temporary would dangle.
      const Json valuesBefore = ma.value("parameter-values", Json::object());
      const Json valuesAfter = mb.value("parameter-values", Json::object());
      std::string pointer;
      for (const auto& value : valuesAfter.items())
      {
        if (valuesBefore.value(value.key(), Json()) != value.value())
        {
          pointer = pointer.empty() ? value.key() : std::string("several");
        }
      }
      found.push_back({ ChangeKind::Parameter,
        pointer == "several" ? QString("Move Sliders") : "Set " + ParameterName(pointer), pointer });
    }
    if (ma.value("time", 0.0) != mb.value("time", 0.0))
    {
      found.push_back({ ChangeKind::Time, "Set t", "t" });
    }
    if (a.value("scene", Json()) != b.value("scene", Json()))
    {
      found.push_back({ ChangeKind::Scene, "Change Scene", "" });
    }
    if (a.value("observer", Json()) != b.value("observer", Json()))
    {
      found.push_back({ ChangeKind::Observer, "Move Observer", "observer" });
    }
    if (a.value("inside", Json()) != b.value("inside", Json()))
    {
      found.push_back({ ChangeKind::RaySettings, "Change Ray Settings", "" });
    }
  }
  // A scene with its own metric changes both: named by the scene.
  Difference change = found.size() == 1 ? found.front() : Difference{ ChangeKind::Several, "Change Document", "" };
  if (found.size() == 2 && found[0].Kind == ChangeKind::MetricText && found[1].Kind == ChangeKind::Scene)
  {
    change = found[1];
  }
  return std::make_unique<DocumentChange>(
    change.Kind, change.Name, before, after, std::move(restore), change.MergeKey);
}
} // namespace studio
} // namespace riemann
