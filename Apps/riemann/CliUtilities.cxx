#include "CliUtilities.h"

#include "SettingValues.h"

#include "Interrupts.h"
#include "RiemannVtkMessages.h"

#include "vtkAlgorithm.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPolyData.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkXMLPolyDataWriter.h"

#include "vtkObjectFactory.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace riemann
{
namespace cli
{
std::string FormatNumber(double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

namespace
{
/// The whole of `text` as one finite number (strtod's syntax, no blanks).
bool ParseFinite(const std::string& text, double& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())))
  {
    return false;
  }
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return *end == '\0' && std::isfinite(value);
}

std::string Got(const std::string& text)
{
  return "got \"" + text + "\"";
}
} // namespace

std::string CheckNumberList(
  const std::string& text, size_t count, const std::string& form, std::vector<double>& values)
{
  values.clear();
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    const bool empty = item.find_first_not_of(" \t") == std::string::npos;
    if (empty || *end != '\0')
    {
      return "\"" + item + "\" is not a number (expected " + form + ")";
    }
    if (!std::isfinite(value))
    {
      return "\"" + item + "\" is not finite (expected " + form + ")";
    }
    values.push_back(value);
  }
  if ((count > 0 && values.size() != count) || values.empty() ||
    (!text.empty() && text.back() == ','))
  {
    return "expected " + (count > 0 ? std::to_string(count) + " " : std::string()) +
      "comma-separated numbers " + form + ", " + Got(text);
  }
  return {};
}

void ParseVector3(const std::string& text, const std::string& option, double out[3])
{
  std::vector<double> values;
  if (!CheckNumberList(text, 3, "X,Y,Z", values).empty())
  {
    throw Failure(
      option + ": expected three finite comma-separated numbers X,Y,Z, " + Got(text), 2);
  }
  std::copy(values.begin(), values.end(), out);
}

std::string CheckDirection(const double v[3], const std::string& text)
{
  const std::string why = DirectionProblem(v);
  return why.empty() ? std::string() : "\"" + text + "\" " + why;
}

CLI::Validator Checked(
  std::function<std::string(const std::string&)> check, const std::string& description)
{
  return CLI::Validator([check](std::string& text) { return check(text); }, description);
}

CLI::Validator FiniteNumber(double low, double high, bool lowOpen, bool highOpen)
{
  const double largest = std::numeric_limits<double>::max();
  // The messages' phrase: "a finite positive number at most 179", "a finite
  // positive number from 1e-09 to 1e+06", "a finite non-negative number at most 255".
  std::string expected = (low > 0 || (low == 0 && lowOpen)) ? "a finite positive number"
    : low == 0                                              ? "a finite non-negative number"
                                                            : "a finite number";
  const bool lowShown = low != 0 && low != -largest;
  const bool highShown = high != largest;
  if (lowShown && highShown && !lowOpen && !highOpen)
  {
    expected += " from " + FormatNumber(low) + " to " + FormatNumber(high);
  }
  else
  {
    if (lowShown)
    {
      expected += (lowOpen ? " greater than " : " at least ") + FormatNumber(low);
    }
    if (lowShown && highShown)
    {
      expected += " and";
    }
    if (highShown)
    {
      expected += (highOpen ? " less than " : " at most ") + FormatNumber(high);
    }
  }
  // For --help: "(0, 100]", "[1e-09, 1e+06]".
  const std::string interval = (lowOpen ? "(" : "[") +
    (low == -largest ? std::string("-inf") : FormatNumber(low)) + ", " +
    (high == largest ? std::string("inf") : FormatNumber(high)) + (highOpen ? ")" : "]");
  return Checked(
    [=](const std::string& text) -> std::string
    {
      double value = 0.0;
      const bool inside = ParseFinite(text, value) && (lowOpen ? value > low : value >= low) &&
        (highOpen ? value < high : value <= high);
      return inside ? std::string() : "expected " + expected + ", " + Got(text);
    },
    "in " + interval);
}

CLI::Validator PositiveNumber(double high)
{
  return FiniteNumber(0.0, high, true, false);
}

CLI::Validator WholeNumber(long long low, long long high)
{
  const std::string expected =
    "a whole number from " + std::to_string(low) + " to " + std::to_string(high);
  return Checked(
    [=](const std::string& text) -> std::string
    {
      const bool digits = !text.empty() &&
        std::all_of(text.begin() + (text[0] == '-' || text[0] == '+'), text.end(),
          [](unsigned char c) { return std::isdigit(c); }) &&
        text.find_first_of("0123456789") != std::string::npos;
      errno = 0;
      const long long value = digits ? std::strtoll(text.c_str(), nullptr, 10) : 0;
      const bool inside = digits && errno == 0 && value >= low && value <= high;
      return inside ? std::string() : "expected " + expected + ", " + Got(text);
    },
    "in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
}

CLI::Validator Point3()
{
  return Checked(
    [](const std::string& text) -> std::string
    {
      std::vector<double> values;
      return CheckNumberList(text, 3, "X,Y,Z", values).empty()
        ? std::string()
        : "expected three finite comma-separated numbers X,Y,Z, " + Got(text);
    },
    "X,Y,Z");
}

CLI::Validator Direction3()
{
  return Checked(
    [](const std::string& text) -> std::string
    {
      std::vector<double> values;
      if (!CheckNumberList(text, 3, "X,Y,Z", values).empty())
      {
        return "expected three finite comma-separated numbers X,Y,Z, " + Got(text);
      }
      return CheckDirection(values.data(), text);
    },
    "X,Y,Z (not 0,0,0)");
}

CLI::Validator IntegratorName()
{
  return Checked(
    [](const std::string& text) -> std::string
    {
      IntegratorType type;
      return ParseIntegratorName(text, type) ? std::string()
                                             : "expected euler, rk4 or dp45, " + Got(text);
    },
    "euler|rk4|dp45");
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

namespace
{
/// The same file: the same inode where both exist, else the same normal absolute path.
bool SamePath(const std::string& a, const std::string& b)
{
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error))
  {
    const bool same = fs::equivalent(a, b, error);
    if (!error)
    {
      return same;
    }
  }
  const fs::path left = fs::weakly_canonical(fs::absolute(a), error);
  const fs::path right = fs::weakly_canonical(fs::absolute(b), error);
  return left == right;
}
} // namespace

void CheckFilePaths(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs)
{
  namespace fs = std::filesystem;
  for (std::size_t i = 0; i < outputs.size(); ++i)
  {
    const NamedPath& output = outputs[i];
    if (output.Path.empty())
    {
      continue;
    }
    std::error_code error;
    const fs::file_status status = fs::status(output.Path, error);
    if (!error && fs::exists(status) && !fs::is_regular_file(status))
    {
      throw Failure(output.Option + " " + output.Path + ": " +
          (fs::is_directory(status) ? "is a folder" : "is not a regular file (a device, FIFO or socket)") +
          "; outputs are written whole, as a temporary file renamed over the name: give a file name",
        2);
    }
    // Before any work: a long render or trace once failed only at its end.
    const fs::path folder = fs::path(output.Path).parent_path();
    if (!folder.empty() && !fs::is_directory(folder, error))
    {
      throw Failure(output.Option + " " + output.Path + ": the folder " + folder.string() +
          " does not exist; create it first",
        2);
    }
    for (const NamedPath& input : inputs)
    {
      if (!input.Path.empty() && SamePath(input.Path, output.Path))
      {
        throw Failure(output.Option + " " + output.Path + ": is also the input " + input.Option +
            "; writing it would replace the input: choose another output name",
          2);
      }
    }
    for (std::size_t j = 0; j < i; ++j)
    {
      if (!outputs[j].Path.empty() && SamePath(outputs[j].Path, output.Path))
      {
        throw Failure(output.Option + " " + output.Path + ": is also " + outputs[j].Option +
            "; one would replace the other: give each output its own name",
          2);
      }
    }
  }
  for (const NamedPath& output : outputs)
  {
    if (!output.Path.empty())
    {
      InterruptHandling::AddOutput(output.Path);
    }
  }
}

void WriteAtomically(const std::string& path, const std::function<bool(const std::string&)>& write)
{
  // Same directory, so that rename() is atomic; the pid keeps concurrent runs
  // apart, and names the file for InterruptHandling.
  const std::string temporary = path + ".partial-" + InterruptHandling::PartialTag();
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
  if (InterruptHandling::Interrupted())
  {
    // Not renamed over an earlier output: what was written may be cut short.
    std::remove(temporary.c_str());
    throw Interrupted();
  }
  if (!written || std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    throw Failure("could not write " + path + " (check that its folder exists and is writable)");
  }
}

void SetCompressor(vtkXMLWriter* writer, const std::string& compress)
{
  if (compress == "none")
  {
    writer->SetCompressorTypeToNone();
  }
  else if (compress == "zlib")
  {
    writer->SetCompressorTypeToZLib();
  }
  else
  {
    writer->SetCompressorTypeToLZ4();
  }
}

void AddCompressOption(CLI::App* command, std::string& compress)
{
  command
    ->add_option("--compress", compress,
      "Compression of .vti/.vtp output: lz4 (default, fast), zlib (smallest, slow) or none")
    ->check(CLI::IsMember({ "lz4", "zlib", "none" }));
}

bool WritePolyDataFile(vtkPolyData* data, const std::string& path, const std::string& compress)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  writer->SetDataModeToAppended();
  SetCompressor(writer, compress);
  return writer->Write() == 1 && writer->GetErrorCode() == 0;
}

void WritePolyDataAtomically(
  vtkPolyData* data, const std::string& path, const std::string& compress)
{
  WriteAtomically(path,
    [data, &compress](const std::string& temporary)
    { return WritePolyDataFile(data, temporary, compress); });
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
  const std::string message = data ? static_cast<const char*>(data) : "unknown error";
  const std::string plain = PlainVtkMessage(message, caller ? caller->GetClassName() : nullptr);
  this->Messages.push_back(plain.empty() ? message : plain);
}

void ErrorCollector::Observe(vtkObject* object)
{
  object->AddObserver(vtkCommand::ErrorEvent, this);
  // The algorithms a command runs stop at their next check on SIGINT or
  // SIGTERM (Interrupts.h), as riemann-studio's Cancel stops its jobs.
  InterruptHandling::Watch(vtkAlgorithm::SafeDownCast(object));
}

void ErrorCollector::ThrowIfAny(const std::string& context) const
{
  // A stopped algorithm's output is empty or partial: nothing after it runs.
  if (InterruptHandling::Interrupted())
  {
    throw Interrupted();
  }
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

vtkStandardNewMacro(CliOutputWindow);

namespace
{
/// `text` without ANSI escape sequences and trailing blanks.
std::string Plain(const std::string& text)
{
  std::string plain = WithoutAnsiEscapes(text);
  while (!plain.empty() && std::isspace(static_cast<unsigned char>(plain.back())))
  {
    plain.pop_back();
  }
  return plain;
}

const char* LoggerCallbackId = "riemann-cli";
} // namespace

CliOutputWindow* CliOutputWindow::Install()
{
  vtkNew<CliOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
  // VTK's error and warning macros write to vtkLogger as well as to the
  // output window, and loguru prints them on stderr with colour codes: turn
  // that off, and take what it logs (also the messages that VTK writes only
  // to the log) through the callback.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  if (vtkLogger::IsEnabled())
  {
    vtkLogger::AddCallback(LoggerCallbackId, &CliOutputWindow::LoggerCallback, window.Get(),
      vtkLogger::VERBOSITY_WARNING);
    window->LoggerRouted = true;
  }
  return window;
}

void CliOutputWindow::Uninstall()
{
  // Before static destruction, which would otherwise delete the window while
  // loguru still holds it.
  vtkLogger::RemoveCallback(LoggerCallbackId);
  vtkOutputWindow::SetInstance(nullptr);
}

void CliOutputWindow::DisplayText(const char* text)
{
  if (!text)
  {
    return;
  }
  const MessageTypes type = this->GetCurrentMessageType();
  // Text that comes from VTK's error and warning macros was also written to
  // vtkLogger, and so reached LoggerCallback: the base class tells it by
  // sending it nowhere (its DEFAULT display mode). So does the text of the
  // debug macros, logged at INFO and dropped here (no object of the CLI has
  // Debug on).
  if (this->LoggerRouted && this->Superclass::GetDisplayStream(type) == StreamType::Null)
  {
    return;
  }
  const char* kind = "text";
  switch (type)
  {
    case MESSAGE_TYPE_ERROR:
      kind = "error";
      break;
    case MESSAGE_TYPE_WARNING:
    case MESSAGE_TYPE_GENERIC_WARNING:
      kind = "warning";
      break;
    case MESSAGE_TYPE_DEBUG:
      kind = "debug";
      break;
    default:
      break;
  }
  // "ERROR: In /path/file.cxx, line 12\nvtkClass (0x...): message": the
  // location goes into the prefix.
  std::string message = text;
  std::string where;
  const size_t in = message.find(": In ");
  const size_t newline = message.find('\n');
  if (in != std::string::npos && newline != std::string::npos && in < newline)
  {
    std::string location = message.substr(in + 5, newline - in - 5);
    const size_t line = location.rfind(", line ");
    if (line != std::string::npos)
    {
      std::string file = location.substr(0, line);
      const size_t slash = file.find_last_of('/');
      where =
        file.substr(slash == std::string::npos ? 0 : slash + 1) + ":" + location.substr(line + 7);
    }
    message = message.substr(newline + 1);
  }
  this->Keep(kind, where, message);
}

void CliOutputWindow::LoggerCallback(void* self, const vtkLogger::Message& message)
{
  std::string where;
  if (message.filename && *message.filename)
  {
    const std::string file = message.filename;
    const size_t slash = file.find_last_of('/');
    where =
      file.substr(slash == std::string::npos ? 0 : slash + 1) + ":" + std::to_string(message.line);
  }
  const char* kind = message.verbosity <= vtkLogger::VERBOSITY_ERROR
    ? "error"
    : (message.verbosity == vtkLogger::VERBOSITY_WARNING ? "warning" : "log");
  static_cast<CliOutputWindow*>(self)->Keep(kind, where,
    std::string(message.prefix ? message.prefix : "") + (message.message ? message.message : ""));
}

void CliOutputWindow::Keep(const std::string& kind, const std::string& where, std::string text)
{
  text = Plain(text);
  // Further lines indented under the first.
  for (size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 1))
  {
    text.insert(at + 1, "  ");
  }
  const std::string line =
    "VTK " + kind + (where.empty() ? std::string() : " (" + where + ")") + ": " + text;
  std::lock_guard<std::mutex> lock(this->Mutex);
  this->Messages.push_back(line);
  this->NumberOfErrors += kind == "error";
  this->NumberOfWarnings += kind == "warning";
  if (this->Verbose)
  {
    std::cerr << "riemann: " << line << "\n" << std::flush;
  }
}

std::vector<std::string> CliOutputWindow::GetMessages() const
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  return this->Messages;
}

int CliOutputWindow::GetNumberOfErrors() const
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  return this->NumberOfErrors;
}

int CliOutputWindow::GetNumberOfWarnings() const
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  return this->NumberOfWarnings;
}
} // namespace cli
} // namespace riemann
