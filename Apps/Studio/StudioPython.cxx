// Python.h first: it may change how system headers are read.
#include <Python.h>

#include "StudioPython.h"

#include "StudioMainWindow.h"
#include "StudioScripting.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

#include <cstdio>
#include <iostream>

namespace riemann
{
namespace studio
{
namespace
{
/// The `studio` module's Python side: arguments and results cross as JSON.
constexpr const char* StudioModuleSource = R"PY(
"""riemann-studio's document from Python (Documentation/Studio.md, "Python")."""
import json as _json
import _studio


class StudioError(RuntimeError):
    """What the window would have said: a bad setting, a file it cannot read, ..."""


def _call(name, *args):
    ok, result = _studio.call(name, _json.dumps(list(args)))
    value = _json.loads(result)
    if not ok:
        raise StudioError(value)
    return value


def open(path):
    """Open a project, metric or scene file, as File > Open."""
    _call("open", str(path))


def items():
    """The pipeline's items, by name, in the browser's order."""
    return _call("items")


def add(kind, **properties):
    """Add an item of `kind` ("geodesics", "ray-bundle", "exponential-map",
    "conjugate-locus", "field", "distance-field", "connect", "camera-path")
    with these properties; returns its name."""
    return _call("add", kind, properties)


def set(item, **properties):
    """Apply properties to the item named `item` (all or none)."""
    _call("set", item, properties)


def get(item):
    """The item's settings, with its "kind", "class" (the toolkit class it
    runs), "visible", and "preset" when a new item starts from a preset of
    the class's declaration."""
    return _call("get", item)


def properties(item):
    """The fields of the item's properties panel, in order: key, label, type,
    minimum, maximum, minimum_exclusive, maximum_exclusive, non_zero, choices, help, display
    (as ParaView's ListProperties)."""
    return _call("properties", item)


def python():
    """The Python script that rebuilds the session, as File > Export >
    Python Script writes it."""
    return _call("python")


def remove(item):
    _call("remove", item)


def rename(item, name):
    """Rename the item; returns its new name."""
    return _call("rename", item, name)


def parameter(pointer, value=None):
    """A metric parameter's slider value, by JSON pointer ("/parameters/a"); with `value`, set it."""
    return _call("parameter", pointer, value)


def observer(position=None, look_at=None, view_up=None):
    """The observer (the inside view's camera) as a dict; move it with any of the three."""
    moves = {"position": position, "look_at": look_at, "view_up": view_up}
    return _call("observer", {key: None if value is None else [float(v) for v in value]
                              for key, value in moves.items()})


def show(item, visible=True):
    _call("show", item, bool(visible))


def metric(text=None):
    """The metric's JSON text; with `text`, apply it first (raises on errors)."""
    return _call("metric", text)


def time(t=None):
    """The metric's time t; with `t`, set it first."""
    return _call("time", t)


def undo():
    """Undo the last change; returns its name, or None when there is none."""
    return _call("undo")


def redo():
    return _call("redo")


def save(path):
    """Save the project to `path`."""
    _call("save", str(path))


def project():
    """The document as its project file holds it (a dict)."""
    return _call("project")


def screenshot(path, view="inside", size=None):
    """A PNG of "inside", "outside", "both" or "window"; `size` (w, h) in pixels."""
    _call("screenshot", str(path), view, None if size is None else [int(s) for s in size])


def export_animation(path, frames=60, view="inside", size=(640, 480), time=(0, 1), camera_path=None):
    """A film (.ogv) or numbered PNGs; t over `time` (None: t stays); along a camera path item."""
    options = {"frames": int(frames), "view": view, "size": [int(s) for s in size],
               "time": None if time is None else [float(t) for t in time]}
    if camera_path is not None:
        options["camera_path"] = camera_path
    _call("export_animation", str(path), options)


def render():
    """Draw the views and wait until every item has computed."""
    _call("render")


def select(item=None):
    """Select the item in the pipeline browser (its properties show); None: the metric."""
    _call("select", item)


def dock(which, visible=True, height=None):
    """Show or hide a dock: "python" (this shell) or "spreadsheet"; `height` in pixels."""
    _call("dock", which, bool(visible), None if height is None else int(height))


def wait(seconds):
    """Let the window go on (events, jobs finishing, pictures) for `seconds`."""
    _call("wait", float(seconds))


def cancel():
    """The Cancel button: every running job stops, its item keeps its last result."""
    _call("cancel")


def running():
    """How many jobs are running now (items computing, a CPU picture)."""
    return _call("running")
)PY";

/// The console, the output streams and the script runner.
constexpr const char* BootstrapSource = R"PY(
import sys as _sys
import types as _types
import _studio

class _StudioStream:
    def __init__(self, error):
        self._error = error
    def write(self, text):
        _studio.write(str(text), self._error)
        return len(text)
    def flush(self):
        pass
    def isatty(self):
        return False

_sys.stdout = _StudioStream(False)
_sys.stderr = _StudioStream(True)
_studio_module = _types.ModuleType("studio")
_studio_module.__file__ = "studio.py"
exec(compile(_studio_source, "studio.py", "exec"), _studio_module.__dict__)
_sys.modules["studio"] = _studio_module

import code as _code
_studio_console = _code.InteractiveConsole({"__name__": "__console__", "studio": _studio_module})

def _studio_run(path):
    import os, runpy, traceback
    _sys.argv = [path]
    _sys.path.insert(0, os.path.dirname(os.path.abspath(path)))
    try:
        runpy.run_path(path, run_name="__main__")
        return 0
    except SystemExit as stop:
        if stop.code is None:
            return 0
        if isinstance(stop.code, int):
            return stop.code
        print(stop.code, file=_sys.stderr)
        return 1
    except BaseException:
        traceback.print_exc()
        return 1
    finally:
        _sys.path.pop(0)
)PY";

PyObject* CallStudioFunction(PyObject*, PyObject* args)
{
  const char* name = nullptr;
  const char* json = nullptr;
  if (!PyArg_ParseTuple(args, "ss", &name, &json))
  {
    return nullptr;
  }
  StudioMainWindow* window = StudioPython::Instance().Window();
  nlohmann::json result;
  bool ok = true;
  try
  {
    if (!window)
    {
      throw std::runtime_error("no riemann-studio window is open");
    }
    result = CallStudio(*window, name, nlohmann::json::parse(json));
  }
  catch (const std::exception& e)
  {
    ok = false;
    result = e.what();
  }
  const std::string text = result.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return Py_BuildValue("(Os)", ok ? Py_True : Py_False, text.c_str());
}

PyObject* WriteOutput(PyObject*, PyObject* args)
{
  const char* text = nullptr;
  int error = 0;
  if (!PyArg_ParseTuple(args, "sp", &text, &error))
  {
    return nullptr;
  }
  StudioPython::Instance().Write(QString::fromUtf8(text), error != 0);
  Py_RETURN_NONE;
}

PyMethodDef StudioMethods[] = {
  { "call", CallStudioFunction, METH_VARARGS, "call(name, json_arguments) -> (ok, json_result)" },
  { "write", WriteOutput, METH_VARARGS, "write(text, error): to the Python shell" },
  { nullptr, nullptr, 0, nullptr },
};

PyModuleDef StudioModule = { PyModuleDef_HEAD_INIT, "_studio",
  "riemann-studio's side of the studio module", -1, StudioMethods, nullptr, nullptr, nullptr,
  nullptr };

PyObject* InitStudioModule()
{
  return PyModule_Create(&StudioModule);
}

/// The folder of the `riemann` Python package: the build's or install's
/// lib/python3/dist-packages beside bin/.
QString RiemannPackageFolder()
{
  const QDir bin(QCoreApplication::applicationDirPath());
  const QString folder = bin.absoluteFilePath("../lib/python3/dist-packages");
  return QFileInfo(folder + "/riemann").isDir() ? QDir::cleanPath(folder) : QString();
}

/// The text of the Python exception being raised (and clears it).
QString PythonErrorText()
{
  PyObject *type = nullptr, *value = nullptr, *traceback = nullptr;
  PyErr_Fetch(&type, &value, &traceback);
  QString text = QStringLiteral("Python error");
  if (value)
  {
    PyObject* string = PyObject_Str(value);
    if (string)
    {
      text = QString::fromUtf8(PyUnicode_AsUTF8(string));
      Py_DECREF(string);
    }
  }
  Py_XDECREF(type);
  Py_XDECREF(value);
  Py_XDECREF(traceback);
  PyErr_Clear();
  return text;
}

PyObject* MainDictionary()
{
  return PyModule_GetDict(PyImport_AddModule("__main__"));
}
} // namespace

QString StudioPython::Version()
{
  return QString::fromUtf8(Py_GetVersion()).section(' ', 0, 0);
}

StudioPython& StudioPython::Instance()
{
  static StudioPython python;
  return python;
}

StudioPython::StudioPython()
{
  this->Started = this->Start();
}

bool StudioPython::Start()
{
  if (!Py_IsInitialized())
  {
    PyImport_AppendInittab("_studio", &InitStudioModule);
    PyConfig config;
    PyConfig_InitPythonConfig(&config);
    // Qt owns the signals (Ctrl+C in a terminal is not the shell's).
    config.install_signal_handlers = 0;
    config.parse_argv = 0;
    const PyStatus status = Py_InitializeFromConfig(&config);
    PyConfig_Clear(&config);
    if (PyStatus_Exception(status))
    {
      this->Problem = QStringLiteral("Python did not start: %1").arg(status.err_msg ? status.err_msg : "");
      return false;
    }
  }
  PyObject* globals = MainDictionary();
  PyObject* source = PyUnicode_FromString(StudioModuleSource);
  PyDict_SetItemString(globals, "_studio_source", source);
  Py_DECREF(source);
  const QString package = RiemannPackageFolder();
  if (!package.isEmpty())
  {
    PyObject* path = PySys_GetObject("path"); // borrowed
    PyObject* folder = PyUnicode_FromString(package.toUtf8().constData());
    PyList_Insert(path, 0, folder);
    Py_DECREF(folder);
  }
  PyObject* result = PyRun_String(BootstrapSource, Py_file_input, globals, globals);
  if (!result)
  {
    this->Problem = "Python's studio module did not start: " + PythonErrorText();
    return false;
  }
  Py_DECREF(result);
  return true;
}

void StudioPython::Attach(StudioMainWindow* window, std::function<void(const QString&, bool)> output)
{
  this->Target = window;
  this->Output = std::move(output);
}

void StudioPython::Detach(StudioMainWindow* window)
{
  if (this->Target == window)
  {
    this->Target = nullptr;
    this->Output = nullptr;
  }
}

void StudioPython::Write(const QString& text, bool error)
{
  if (this->Output)
  {
    this->Output(text, error);
  }
  if (this->Mirror || !this->Output)
  {
    (error ? std::cerr : std::cout) << text.toStdString() << std::flush;
  }
}

bool StudioPython::Push(const QString& line)
{
  if (!this->Started)
  {
    return false;
  }
  ++this->Running;
  PyObject* console = PyDict_GetItemString(MainDictionary(), "_studio_console"); // borrowed
  PyObject* more = PyObject_CallMethod(console, "push", "s", line.toUtf8().constData());
  --this->Running;
  if (!more)
  {
    this->Write(PythonErrorText() + "\n", true);
    return false;
  }
  const bool needsMore = PyObject_IsTrue(more) == 1;
  Py_DECREF(more);
  return needsMore;
}

int StudioPython::RunScript(const QString& path)
{
  if (!this->Started)
  {
    this->Write(this->Problem + "\n", true);
    return 1;
  }
  ++this->Running;
  PyObject* run = PyDict_GetItemString(MainDictionary(), "_studio_run"); // borrowed
  PyObject* status = PyObject_CallFunction(run, "s", path.toUtf8().constData());
  --this->Running;
  if (!status)
  {
    this->Write(PythonErrorText() + "\n", true);
    return 1;
  }
  const long code = PyLong_AsLong(status);
  Py_DECREF(status);
  return static_cast<int>(code);
}
}
}
