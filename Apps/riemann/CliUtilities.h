// Helpers shared by the `riemann` subcommands: argument parsing and checking,
// loading a metric, catching VTK errors, and writing output files whole or not
// at all.
//
// Error convention, layer by layer (one per layer; the CLI translates):
//  - Core (Common/Metric, C++ without VTK): exceptions (or a false return plus
//    an error text) with a message that says where: the JSON path, the
//    column of an expression, the file and line.
//  - VTK layer (the vtkRiemann* classes): vtkErrorMacro, an empty output, and
//    GetLastError() where the class has one (vtkRiemannMetric, vtkRiemannScene).
//  - CLI (this folder): one message on stderr, "riemann: error: <what>", and
//    an exit status: 1 for a runtime failure (a metric that does not load, a
//    file that cannot be written, a computation that fails), 2 for a usage
//    error (an option value that is refused, a missing or unknown option),
//    3 for `render --reference` when the picture differs. Commands report by
//    throwing Failure; main() prints it. Usage errors are found before any
//    work: every numeric option carries one of the validators below
//    (FiniteNumber, PositiveNumber, WholeNumber, Point3, Direction3, Checked),
//    which CLI11 runs while it parses, so NaN, infinities, out-of-range
//    numbers and degenerate vectors end the run with e.g.
//      riemann: error: --step: expected a finite positive number from 1e-09 to 1e+06, got "nan"
//    and status 2, and no output file is written. Checks between options
//    (--step at most --length, the camera's view-up across its view) are
//    made in the command's callback before any work, with the same status.
//    VTK's own messages never reach the terminal unasked: the CLI installs
//    its own output window (CliOutputWindow) and silences vtkLogger on
//    stderr, so VTK's text is kept, and printed plainly only with --verbose;
//    errors of the objects a command runs are collected (ErrorCollector) and
//    told in the command's one sentence.
#ifndef RiemannCliUtilities_h
#define RiemannCliUtilities_h

#include "RungeKutta.h"        // For IntegratorType

#include "vtkCommand.h"
#include "vtkLogger.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"

#include <CLI/CLI.hpp>

#include <atomic>
#include <functional>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

class vtkObject;
class vtkPolyData;
class vtkXMLWriter;
class vtkRiemannMetric;

class vtkRiemannIntegrationSettings;

namespace riemann
{
namespace cli
{
/// An error to report on stderr with exit status `Status` (1: runtime, 2: usage).
class Failure : public std::runtime_error
{
public:
  Failure(const std::string& message, int status = 1)
    : std::runtime_error(message)
    , Status(status)
  {
  }
  int Status;
};

/// "X,Y,Z" -> three finite numbers; throws Failure (status 2) naming `option`.
void ParseVector3(const std::string& text, const std::string& option, double out[3]);

/**
 * What is wrong with `text` as a list of `count` finite comma-separated
 * numbers written as `form` (e.g. "X0,X1,Y0,Y1,Z0,Z1"), or "" if nothing
 * (then `values` holds them). `count` 0: any number of them, at least one.
 */
std::string CheckNumberList(
  const std::string& text, size_t count, const std::string& form, std::vector<double>& values);

///@{
/**
 * CLI11 validators of the numeric options. CLI11 runs them on the text of the
 * option while it parses the command line, before any command runs, and
 * reports a refusal as "--option: <what the validator says>" (exit status 2).
 * Each refuses text that is not a number, NaN and infinities, and says what
 * was expected and what was given: `expected a finite positive number at
 * most 179, got "nan"`.
 */
/// A number in [low, high]; `lowOpen` / `highOpen` leave the ends out.
CLI::Validator FiniteNumber(double low, double high, bool lowOpen = false, bool highOpen = false);
/// A number > 0 and at most `high`.
CLI::Validator PositiveNumber(double high = std::numeric_limits<double>::max());
/// A whole number in [low, high] (counts, sizes).
CLI::Validator WholeNumber(long long low, long long high);
/// A point X,Y,Z: three finite numbers.
CLI::Validator Point3();
/// A direction X,Y,Z: three finite numbers, not all zero, of a length that
/// can be normalised (its square neither underflows nor overflows).
CLI::Validator Direction3();
/// An integrator's name: euler, rk4 or dp45 (the one spelling of every
/// command; "adaptive", render's old word for dp45, is still accepted).
CLI::Validator IntegratorName();
/// A validator from a check that returns what is wrong with the text ("" if nothing).
CLI::Validator Checked(
  std::function<std::string(const std::string&)> check, const std::string& description);
///@}

/// What is wrong with `v` as a direction given as `text`, or "" (see Direction3).
std::string CheckDirection(const double v[3], const std::string& text);

/// `value` as messages write it: 1e-09, 100, 1e+06.
std::string FormatNumber(double value);

/// Lower-case extension without the dot ("vtp", "csv"); "" if none.
std::string Extension(const std::string& path);

/// Load and validate a metric file; throws Failure with the parser's message.
vtkSmartPointer<vtkRiemannMetric> LoadMetric(const std::string& path);

/// A file named on the command line, with the option that named it ("-o", "--seeds").
struct NamedPath
{
  std::string Option;
  std::string Path;
};

/**
 * Before any work, the files of a command (empty paths are left out): an
 * output that is also an input or another output, or that names an existing
 * thing other than a regular file (a device, a FIFO, a folder: writing
 * whole files renames a temporary over it), is a usage error (Failure,
 * status 2) that names both options. The outputs are then registered with
 * InterruptHandling, which removes their partial files on SIGINT/SIGTERM.
 */
void CheckFilePaths(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

/**
 * Write `path` whole or not at all: `write` fills a temporary file next to
 * it, which is renamed over `path` only if `write` returns true.
 * Throws Failure (and removes the temporary file) otherwise.
 */
void WriteAtomically(const std::string& path, const std::function<bool(const std::string&)>& write);

/**
 * The compression of VTK XML output, the --compress option of every command
 * that writes .vti or .vtp: "lz4" (the default: several times faster than
 * zlib, at 80^3 zlib took 2.75 s of a 3.2 s `fields` run for an 11 %
 * smaller file), "zlib" (smallest, slow) or "none" (fastest write).
 * ParaView and VTK's readers read all three.
 */
void SetCompressor(vtkXMLWriter* writer, const std::string& compress);

/// Register --compress (lz4|zlib|none, default lz4) on `command` into `compress`.
void AddCompressOption(CLI::App* command, std::string& compress);

/// Write `data` as a .vtp file (appended binary, compressed as SetCompressor); false on failure.
bool WritePolyDataFile(
  vtkPolyData* data, const std::string& path, const std::string& compress = "lz4");

/// WritePolyDataFile through WriteAtomically: the file whole or not at all.
void WritePolyDataAtomically(
  vtkPolyData* data, const std::string& path, const std::string& compress = "lz4");

/// "euler", "rk4" or "dp45"; throws Failure (status 2) naming --integrator.
IntegratorType ParseIntegratorOption(const std::string& name);

/**
 * Collects ErrorEvent messages of the observed VTK objects instead of
 * letting them print, so the tool can report them once and exit non-zero.
 */
class ErrorCollector : public vtkCommand
{
public:
  static ErrorCollector* New() { return new ErrorCollector; }
  void Execute(vtkObject* caller, unsigned long event, void* data) override;
  void Observe(vtkObject* object);
  /// Throws Failure with the collected messages, if any.
  void ThrowIfAny(const std::string& context) const;

private:
  std::vector<std::string> Messages;
};

/**
 * The CLI's VTK output window, installed at start (Install()): every text VTK
 * sends to vtkOutputWindow or, through its error and warning macros, to
 * vtkLogger (loguru, whose stderr output, with its colour codes and stack or
 * pipeline dumps, is turned off) arrives here once. By default it is kept and
 * not printed: the command says what failed in its own sentence. With
 * --verbose (SetVerbose) each message is also printed on stderr as it comes,
 * plainly: "riemann: VTK error (vtkXMLWriter.cxx:1234): vtkXMLPolyDataWriter
 * (0x...): ...", further lines indented, no ANSI codes.
 */
class CliOutputWindow : public vtkOutputWindow
{
public:
  static CliOutputWindow* New();
  vtkTypeMacro(CliOutputWindow, vtkOutputWindow);

  /// Make a new window VTK's output window and route vtkLogger to it; returns
  /// it (VTK holds the reference).
  static CliOutputWindow* Install();
  /// Undo Install (main() calls it before returning).
  static void Uninstall();

  void DisplayText(const char* text) override;

  void SetVerbose(bool verbose) { this->Verbose = verbose; }
  bool GetVerbose() const { return this->Verbose; }

  /// The messages kept so far, one per VTK message, plain text.
  std::vector<std::string> GetMessages() const;
  /// How many of them are errors, and warnings.
  int GetNumberOfErrors() const;
  int GetNumberOfWarnings() const;

protected:
  CliOutputWindow() = default;
  ~CliOutputWindow() override = default;

private:
  CliOutputWindow(const CliOutputWindow&) = delete;
  void operator=(const CliOutputWindow&) = delete;

  /// `kind`: "error", "warning", "debug" or "text"; `where`: "file.cxx:123" or "".
  void Keep(const std::string& kind, const std::string& where, std::string text);
  static void LoggerCallback(void* self, const vtkLogger::Message& message);

  mutable std::mutex Mutex;
  std::vector<std::string> Messages;
  int NumberOfErrors = 0;
  int NumberOfWarnings = 0;
  std::atomic<bool> Verbose{ false };
  bool LoggerRouted = false;
};
} // namespace cli
} // namespace riemann

#endif
