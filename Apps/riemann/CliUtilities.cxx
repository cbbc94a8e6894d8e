#include "CliUtilities.h"

#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPolyData.h"
#include "vtkRiemannMetric.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <unistd.h>

namespace riemann
{
namespace cli
{
void ParseVector3(const std::string& text, const std::string& option, double out[3])
{
  std::stringstream stream(text);
  std::string item;
  int count = 0;
  while (std::getline(stream, item, ','))
  {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    const bool empty = item.find_first_not_of(" \t") == std::string::npos;
    if (count >= 3 || empty || *end != '\0' || !std::isfinite(value))
    {
      count = -1;
      break;
    }
    out[count++] = value;
  }
  if (count != 3 || (!text.empty() && text.back() == ','))
  {
    throw Failure(
      option + ": expected three finite comma-separated numbers X,Y,Z, got \"" + text + "\"", 2);
  }
}

std::string Extension(const std::string& path)
{
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return {};
  }
  std::string extension = path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

vtkSmartPointer<vtkRiemannMetric> LoadMetric(const std::string& path)
{
  auto metric = vtkSmartPointer<vtkRiemannMetric>::New();
  if (!metric->SetDefinitionFile(path.c_str()))
  {
    throw Failure(std::string("bad metric: ") + metric->GetLastError());
  }
  return metric;
}

void WriteAtomically(const std::string& path, const std::function<bool(const std::string&)>& write)
{
  // Same directory, so that rename() is atomic; the pid keeps concurrent runs apart.
  const std::string temporary = path + ".partial-" + std::to_string(::getpid());
  bool written = false;
  try
  {
    written = write(temporary);
  }
  catch (...)
  {
    std::remove(temporary.c_str());
    throw;
  }
  if (!written || std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    throw Failure("could not write " + path + " (check that its folder exists and is writable)");
  }
}

bool WritePolyDataFile(vtkPolyData* data, const std::string& path)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  writer->SetDataModeToAppended();
  return writer->Write() == 1 && writer->GetErrorCode() == 0;
}

void WritePolyDataAtomically(vtkPolyData* data, const std::string& path)
{
  WriteAtomically(
    path, [data](const std::string& temporary) { return WritePolyDataFile(data, temporary); });
}

IntegratorType ParseIntegratorOption(const std::string& name)
{
  IntegratorType type;
  if (!ParseIntegratorName(name, type))
  {
    throw Failure("--integrator: \"" + name + "\": expected euler, rk4 or dp45", 2);
  }
  return type;
}

void ErrorCollector::Execute(vtkObject* caller, unsigned long, void* data)
{
  std::string message = data ? static_cast<const char*>(data) : "unknown error";
  // VTK prefixes "ERROR: In file, line N\nvtkClass (0x...): "; keep the last part.
  const size_t separator = message.find("): ");
  if (separator != std::string::npos)
  {
    message = message.substr(separator + 3);
  }
  while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back())))
  {
    message.pop_back();
  }
  this->Messages.push_back((caller ? std::string(caller->GetClassName()) + ": " : "") + message);
}

void ErrorCollector::Observe(vtkObject* object)
{
  object->AddObserver(vtkCommand::ErrorEvent, this);
}

void ErrorCollector::ThrowIfAny(const std::string& context) const
{
  if (this->Messages.empty())
  {
    return;
  }
  std::string text = context;
  for (const std::string& m : this->Messages)
  {
    text += "\n  " + m;
  }
  throw Failure(text);
}
} // namespace cli
} // namespace riemann
