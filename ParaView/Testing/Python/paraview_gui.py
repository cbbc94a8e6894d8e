"""Drive the real ParaView (the GUI, under Xvfb) with its XML event scripts.

ParaView plays a test script of Qt events (--test-script=X.xml --exit): the
same clicks a user makes. A script is written here from named steps
(Steps.apply_source, Steps.set_file, Steps.save_data, ...), ParaView runs it
with the plugin loaded (--plugins=RiemannVTK), and the log is read: a script
that fails exits 1, but a proxy whose execution fails does not stop
ParaView, so the log's errors are returned for the test to judge.

Environment (set by ParaView/Testing/CMakeLists.txt): RIEMANN_PARAVIEW
(the paraview executable), RIEMANN_PARAVIEW_PLUGIN_DIR (the plugin's folder).
"""

import os
import re
import socket
import subprocess
import tempfile
import time
from xml.sax.saxutils import quoteattr

PANEL = ("pqClientMainWindow/propertiesDock/propertiesPanel/scrollArea/qt_scrollarea_viewport/"
         "scrollAreaWidgetContents/PropertiesFrame/ProxyPanel")


class Steps:
    """The events of one script, named after what a user does."""

    def __init__(self):
        self.events = []

    def event(self, obj, command, arguments=""):
        self.events.append((obj, command, arguments))
        return self

    def menu(self, menu, category, item):
        self.event("pqClientMainWindow/menubar", "activate", menu)
        return self.event(f"pqClientMainWindow/menubar/{menu}/{category}", "activate", item)

    def apply(self):
        return self.event("pqClientMainWindow/propertiesDock/propertiesPanel/Accept", "activate")

    def apply_source(self, proxy, **settings):
        """Sources > Riemann > proxy, then its settings, then Apply."""
        self.menu("menuSources", "Riemann", proxy)
        return self.settings(settings).apply()

    def apply_filter(self, proxy, **settings):
        """Filters > Riemann > proxy on the selected source, its settings, Apply."""
        self.menu("menuFilters", "Riemann", proxy)
        return self.settings(settings).apply()

    def apply_filter_with_inputs(self, proxy, inputs, **settings):
        """Filters > Riemann > proxy for a filter of several inputs: ParaView asks which
        source goes to which input (its Select Input dialog); `inputs` maps an input's
        name to the source's row under builtin: (0 for the first source made)."""
        self.menu("menuFilters", "Riemann", proxy)
        dialog = "pqClientMainWindow/SelectInputDialog"
        for name, row in inputs.items():
            self.event(f"{dialog}/buttonFrame/{name}", "activate")
            # The pipeline's tree: builtin: (row 0), then the sources under it ("row|column" last).
            self.event(f"{dialog}/pipelineView", "currentChanged", f"/0/{row}|0")
        self.event(f"{dialog}/buttonBox/1QPushButton0", "activate")
        return self.settings(settings).apply()

    def open_file(self, path):
        """File > Open of `path` (the reader ParaView picks for its extension), then Apply."""
        self.event("pqClientMainWindow/menubar", "activate", "menu_File")
        self.event("pqClientMainWindow/menubar/menu_File", "activate", "actionFileOpen")
        self.event("pqClientMainWindow/FileOpenDialog", "filesSelected", path)
        return self.apply()

    def apply_vtk_source(self, proxy):
        """Sources > Alphabetical > proxy (one of ParaView's own), with its defaults."""
        self.menu("menuSources", "Alphabetical", proxy)
        return self.apply()

    def settings(self, settings):
        """The panel's settings before Apply: file properties only, so far."""
        for name, value in settings.items():
            self.set_file(name, value)
        return self

    def set_file(self, prop, path):
        return self.event(f"{PANEL}/{prop}/FileChooser/FileLineEdit", "set_string", path)

    def set_text(self, prop, text):
        return self.event(f"{PANEL}/{prop}/{prop}", "set_string", text)

    def set_parameter(self, row, name, value):
        """The Metric's Parameters table: a new row `row` (0, 1, ...) giving `name` the value `value`."""
        table = f"{PANEL}/Parameters/ScalarValueList"
        self.event(f"{table}/Add", "activate")
        # Cells are "row.column"; an edit is opened, then accepted with its text.
        for column, text in ((0, name), (1, str(value))):
            self.event(f"{table}/Table", "edit", f"{row}.{column}")
            self.event(f"{table}/Table", "editAccepted", f"{row}.{column},{text}")
        return self

    def last_time(self):
        """The animation toolbar's Last Frame: ParaView's time to the end."""
        return self.event("pqClientMainWindow/VCRToolbar/actionVCRLastFrame", "activate")

    def save_data(self, path):
        """File > Save Data of the selected output, as `path` (its writer's defaults)."""
        self.event("pqClientMainWindow/menubar", "activate", "menu_File")
        self.event("pqClientMainWindow/menubar/menu_File", "activate", "actionFileSaveData")
        self.event("pqClientMainWindow/FileSaveDialog", "filesSelected", path)
        return self.event("pqClientMainWindow/WriterSettingsDialog/widget/OKButton", "activate")

    def open_inside_view(self):
        """Split the first view and make the new half a Riemann Inside View (it becomes active)."""
        frames = ("pqClientMainWindow/centralwidget/MultiViewWidget/CoreWidget/qt_tabwidget_stackedwidget/"
                  "MultiViewWidget1/Container")
        self.event(f"{frames}/Frame.0/SplitHorizontal", "activate")
        return self.event(f"{frames}/Frame.2/CentralWidgetFrame/EmptyView/scrollArea/qt_scrollarea_viewport/"
                          "widgetFoo/ConvertActionsFrame/RiemannInsideView", "activate")

    def save_pictures(self, what, path, width, height):
        """File > Save <what> (Screenshot, Animation) of the active view at width x height:
        its file dialog, then its options dialog's resolution and OK."""
        self.event("pqClientMainWindow/menubar", "activate", "menu_File")
        self.event("pqClientMainWindow/menubar/menu_File", "activate", f"actionFileSave{what}")
        self.event(f"pqClientMainWindow/Save{what}FileDialog", "filesSelected", path)
        dialog = f"pqClientMainWindow/Save{what}Dialog"
        resolution = f"{dialog}/scrollArea/qt_scrollarea_viewport/Container/ProxyWidget/ImageResolution"
        self.event(f"{resolution}/width", "set_string", str(width))
        self.event(f"{resolution}/height", "set_string", str(height))
        return self.event(f"{dialog}/widget/OKButton", "activate")

    def save_screenshot(self, path, width, height):
        """File > Save Screenshot of the active view at width x height."""
        return self.save_pictures("Screenshot", path, width, height)

    def save_animation(self, path, width, height):
        """File > Save Animation of the active view over all time steps at width x height:
        numbered pictures path.0000.png, ... (ParaView's names for a .png)."""
        return self.save_pictures("Animation", path, width, height)

    def save_state(self, path):
        self.event("pqClientMainWindow/menubar", "activate", "menu_File")
        self.event("pqClientMainWindow/menubar/menu_File", "activate", "actionFileSaveServerState")
        return self.event("pqClientMainWindow/FileSaveServerStateDialog", "filesSelected", path)

    def xml(self):
        lines = ['<?xml version="1.0" ?>', "<pqevents>"]
        for obj, command, arguments in self.events:
            lines.append(f"  <pqevent object={quoteattr(obj)} command={quoteattr(command)} "
                         f"arguments={quoteattr(arguments)} />")
        lines.append("</pqevents>")
        return "\n".join(lines) + "\n"


class Run:
    def __init__(self, returncode, log):
        self.returncode = returncode
        self.log = log

    def errors(self):
        """The lines of the log that report errors (vtkErrorMacro, ParaView's own)."""
        return [line for line in self.log.splitlines() if re.search(r"\bERR\b|\bERROR\b|Error:", line)]


def played(steps, work, name, outputs, extra_args=()):
    """Play `steps` (run()); check that ParaView exited 0, logged no error and wrote each of
    `outputs` (a path or a list). Whether all were written."""
    from compare_outputs import check
    outputs = [outputs] if isinstance(outputs, str) else list(outputs)
    done = run(steps, work, name=name, extra_args=extra_args)
    check(done.returncode == 0, f"{name}: ParaView's script failed ({done.returncode}):\n{done.log[-3000:]}")
    check(not done.errors(), f"{name}: ParaView reported errors: {done.errors()[:5]}")
    for output in outputs:
        check(os.path.isfile(output), f"{name}: ParaView wrote no {output}")
    return all(os.path.isfile(output) for output in outputs)


class Server:
    """pvserver with the plugin, alone or under `mpirun -np ranks`, on a free port."""

    def __init__(self, work, ranks=1):
        with socket.socket() as probe:
            probe.bind(("localhost", 0))
            self.port = probe.getsockname()[1]
        command = ["/usr/bin/pvserver", f"--server-port={self.port}", "--plugins=RiemannVTK"]
        if ranks > 1:
            command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + command
        env = dict(os.environ, PV_PLUGIN_PATH=os.environ["RIEMANN_PARAVIEW_PLUGIN_DIR"])
        self.log_path = os.path.join(work, f"pvserver-{ranks}.log")
        self.log = open(self.log_path, "w", encoding="utf-8")
        self.process = subprocess.Popen(command, cwd=work, env=env, stdout=self.log, stderr=subprocess.STDOUT)
        # Ready once it listens ("Accepting connection(s): ...").
        for _ in range(600):
            with open(self.log_path, encoding="utf-8", errors="replace") as f:
                if "Accepting connection" in f.read():
                    return
            if self.process.poll() is not None:
                break
            time.sleep(0.1)
        raise RuntimeError("pvserver did not start:\n" + open(self.log_path, encoding="utf-8").read())

    def url(self):
        return f"cs://localhost:{self.port}"

    def stop(self):
        """Wait for the server to end (it exits when its client disconnects); its log."""
        try:
            self.process.wait(timeout=60)
        except subprocess.TimeoutExpired:
            self.process.kill()
        self.log.close()
        with open(self.log_path, encoding="utf-8", errors="replace") as f:
            return f.read()


def run(steps, work, name="script", extra_args=(), timeout=240):
    """Play `steps` in ParaView with the plugin loaded; its home (settings) is a fresh folder."""
    script = os.path.join(work, name + ".xml")
    with open(script, "w", encoding="utf-8") as f:
        f.write(steps.xml())
    home = tempfile.mkdtemp(prefix="home-", dir=work)
    env = dict(os.environ, HOME=home, XDG_CONFIG_HOME=os.path.join(home, ".config"))
    command = [os.environ["RIEMANN_PARAVIEW"], "--dr",
               "--plugin-search-paths=" + os.environ["RIEMANN_PARAVIEW_PLUGIN_DIR"],
               "--plugins=RiemannVTK", *extra_args, "--test-script=" + script, "--exit"]
    done = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True, timeout=timeout)
    return Run(done.returncode, done.stdout + done.stderr)
