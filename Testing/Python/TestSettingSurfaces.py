"""Every declared setting is on every surface with the declared default and range.

Walks the declarations (`<Class>.settings.json` next to the VTK classes,
Documentation/Settings.md), resolved as the build resolves them
(cmake/RiemannSettings.py), and checks each setting on:

1. the VTK class, through Python: a new object's Get<Name>() is the default;
2. the ParaView server-manager XML made from it: the property, its
   default_values and its range domain;
3. the `riemann` commands that run the class: --help names the option and
   its old spellings with the default and the range, and a value past the
   range is refused (status 2) naming the option;
4. the generator itself: a default and a maximum changed in a copy of a
   declaration change the C++ constants and the XML made from it.

The studio's forms, project keys and exported Python are walked by
Apps/Studio/Testing/Scripts/TestSettingSurfaces.py.
"""
import copy
import importlib.util
import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import riemann

SOURCE = os.path.dirname(os.environ["RIEMANN_DATA_DIR"])
BIN = os.environ["RIEMANN_BIN_DIR"]
BUILD = os.path.dirname(BIN)
PARAVIEW = os.path.join(BUILD, "Common", "Settings", "ParaView")

# The commands that show each declared class's settings.
COMMANDS = {
    "vtkRiemannExponentialMap": ["expmap"],
    "vtkRiemannConjugateLocus": ["conjugate"],
    "vtkRiemannGeodesicConnector": ["connect"],
    "vtkRiemannGeodesicTracer": ["trace", "connectivity"],
    "vtkRiemannCurvatureField": ["fields"],
    "vtkRiemannVolumeForm": ["fields"],
    "vtkRiemannMetricTensorField": ["fields"],
    "vtkRiemannDistanceField": ["distance"],
    "vtkRiemannCutLocus": ["distance"],
    "vtkRiemannMinimalGeodesics": ["distance"],
    "vtkRiemannIntegrationSettings": ["trace", "expmap", "conjugate", "connect", "connectivity", "render"],
    "vtkRiemannPictureSettings": ["render"],
}
# render's camera options default to the scene's camera (render --help says so).
SCENE_CAMERA = ("Position", "LookAt", "ViewUp", "ViewAngle", "Projection")
# The integration settings' defaults are those of the filter a command runs
# (render: the scene's); the classes below give them.
INTEGRATION_DEFAULTS = {
    "trace": "vtkRiemannGeodesicTracer",
    "expmap": "vtkRiemannExponentialMap",
    "conjugate": "vtkRiemannConjugateLocus",
    "connect": "vtkRiemannGeodesicConnector",
    "connectivity": "vtkRiemannGeodesicTracer",
    "render": None,
}
# Settings a command leaves out on purpose, and why: the option must not be listed.
LEFT_OUT = {
    ("conjugate", "MaximumError"): "the integration error follows the locus's --tolerance",
    ("connect", "MaximumError"): "--tolerance is the connector's; dp45 integrates to a thousandth of it",
    ("render", "MinimumIntegrationStep"): "a ray's adaptive step is bounded relative to its step",
    ("render", "MaximumIntegrationStep"): "a ray's adaptive step is bounded relative to its step",
}
LEFT_OUT.update({("connectivity", name): "--tract-counts seeds every labelled voxel along e1, both ways"
                 for name in ("StartPosition", "StartDirection", "NumberOfDirections", "ConeAngle",
                              "IntegrationDirection", "SeedDirection", "ComputeTransverseJacobian")})
# Declared classes that no command runs by themselves, and why.
NO_COMMAND = {
    "vtkRiemannDirectionGrid": "built inside expmap and conjugate (their cone settings)",
    "vtkRiemannRayBundle": "render --bundle N draws one with render's picture (its size, projection, scene)",
    "vtkRiemannCameraPath": "render --camera-path reads a camera path file (CameraPathFile.h, CameraPaths.md) "
                            "and --frames counts its frames",
}

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def load_generator():
    spec = importlib.util.spec_from_file_location(
        "RiemannSettings", os.path.join(SOURCE, "cmake", "RiemannSettings.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def cxx_g(x):
    """A number as C++'s ostream writes it by default (the range words)."""
    return "%g" % x


def shortest(x):
    """A JSON number as SettingText writes it: whole ones as they are, others in the
    shortest text that reads back the same (ShortestNumberText)."""
    if isinstance(x, int) or (x == int(x) and abs(x) < 1e6):
        return str(int(x))
    for digits in range(1, 18):
        text = "%.*g" % (digits, x)
        if float(text) == x:
            return text
    return repr(x)


def default_text(setting):
    d, kind = setting["default"], setting["type"]
    if kind in ("point", "direction", "bounds", "dimensions"):
        return ",".join(shortest(x) for x in d)
    if kind == "number_list":
        return ", ".join(shortest(x) for x in d) if d else "none"
    if kind == "boolean":
        return "true" if d else "false"
    if kind == "choice":
        return d
    return shortest(d)


# Every declaration (main() fills it), for the checks that read another class's.
DOCS = []


# --- 1. The VTK class ---------------------------------------------------------
def check_vtk_defaults(doc):
    cls = doc["class"]
    obj = getattr(riemann, cls)()
    for s in doc["settings"]:
        name, kind, d = s["name"], s["type"], s["default"]
        where = "%s.%s" % (cls, name)
        if kind == "number_list":
            count = getattr(obj, s["commands"]["count"])()
            got = [getattr(obj, s["commands"]["get"])(i) for i in range(count)]
            check(got == d, "%s: the new object has %s, declared %s" % (where, got, d))
            continue
        got = getattr(obj, "Get" + name)()
        want = s["choices"].index(d) if kind == "choice" else d
        if kind in ("point", "direction", "bounds", "dimensions"):
            got = list(got)
        check(got == want, "%s: the new object has %r, declared %r" % (where, got, want))


# --- 2. The ParaView XML ------------------------------------------------------
def check_paraview(doc):
    cls = doc["class"]
    path = os.path.join(PARAVIEW, cls + ".xml")
    check(os.path.isfile(path), "%s: no ParaView XML at %s" % (cls, path))
    if not os.path.isfile(path):
        return
    root = ET.parse(path).getroot()
    proxies = root.findall("./ProxyGroup/SourceProxy") + root.findall("./ProxyGroup/Proxy")
    check(proxies and all(p.get("class") == cls for p in proxies), "%s: the XML's proxies are not of the class" % cls)
    if not proxies:
        return
    # A settings object has one proxy per preset after its own: each preset's values are its defaults.
    presets = doc.get("presets", {}) if root.find("./ProxyGroup/Proxy") is not None else {}
    check(len(proxies) == 1 + len(presets), "%s: %d proxies for %d presets" % (cls, len(proxies), len(presets)))
    for proxy, (preset, values) in zip(proxies[1:], presets.items()):
        for p in proxy:
            if p.get("name") in values:
                s = next(x for x in doc["settings"] if x["name"] == p.get("name"))
                v = values[p.get("name")]
                want = [float(s["choices"].index(v))] if s["type"] == "choice" else [float(v)]
                check([float(x) for x in p.get("default_values").split()] == want,
                      "%s preset %s: %s defaults to %s, declared %s" % (cls, preset, p.get("name"), p.get("default_values"), want))
    proxy = proxies[0]
    check_pipeline_properties(doc, proxy)
    properties = {p.get("name"): p for p in proxy if p.tag.endswith("VectorProperty")}
    check(set(properties) == {s["name"] for s in doc["settings"]},
          "%s: XML properties %s, declared %s" % (cls, sorted(properties), [s["name"] for s in doc["settings"]]))
    for s in doc["settings"]:
        p = properties.get(s["name"])
        if p is None:
            continue
        where = "%s.%s (ParaView)" % (cls, s["name"])
        kind, d = s["type"], s["default"]
        values = [float(v) for v in p.get("default_values", "").split()]
        want = [s["choices"].index(d)] if kind == "choice" else \
            [float(bool(d))] if kind == "boolean" else \
            [float(x) for x in d] if isinstance(d, list) else [float(d)]
        check(values == want, "%s: default_values %s, declared %s" % (where, values, want))
        check(p.get("label") == s.get("label", p.get("label")), "%s: label %s" % (where, p.get("label")))
        domain = p.find("IntRangeDomain") if kind in ("integer", "dimensions") else p.find("DoubleRangeDomain")
        if "minimum" in s or "maximum" in s:
            check(domain is not None, "%s: no range domain" % where)
            if domain is not None:
                # One bound per element (a grid's three counts: each has the range).
                elements = 3 if kind == "dimensions" else 1
                if "minimum" in s:
                    check([float(x) for x in domain.get("min").split()] == [s["minimum"]] * elements,
                          "%s: min %s" % (where, domain.get("min")))
                if "maximum" in s:
                    check([float(x) for x in domain.get("max").split()] == [s["maximum"]] * elements,
                          "%s: max %s" % (where, domain.get("max")))
        if kind == "choice":
            entries = [e.get("text") for e in p.find("EnumerationDomain")]
            check(entries == s["choices"], "%s: entries %s" % (where, entries))


def check_pipeline_properties(doc, proxy):
    """The proxy's inputs are the declared data inputs, then the metric at the class's
    GetMetricPort(); a geodesic filter's integration settings start from its preset."""
    cls = doc["class"]
    inputs = [(p.get("name"), int(p.get("port_index"))) for p in proxy if p.tag == "InputProperty"]
    want = [(i["name"], i["port"]) for i in doc.get("inputs", [])]
    if "metric_port" in doc:
        want.append(("Metric" if doc.get("inputs") else "Input", doc["metric_port"]))
        obj = getattr(riemann, cls)()
        check(obj.GetMetricPort() == doc["metric_port"],
              "%s: GetMetricPort() is %d, declared %d" % (cls, obj.GetMetricPort(), doc["metric_port"]))
        check(obj.GetNumberOfInputPorts() == doc["metric_port"] + 1,
              "%s: %d input ports, the metric's is the last (%d)" % (cls, obj.GetNumberOfInputPorts(), doc["metric_port"]))
    check(inputs == want, "%s: ParaView inputs %s, declared %s" % (cls, inputs, want))
    integration = [p for p in proxy if p.tag == "ProxyProperty" and p.get("name") == "IntegrationSettings"]
    check(bool(integration) == ("integration" in doc), "%s: integration settings %s in ParaView" % (cls, bool(integration)))
    if integration and "integration" in doc:
        preset = doc["integration"]
        name = integration[0].find("./ProxyListDomain/Proxy").get("name")
        check(name == "IntegrationSettings" + ("" if preset == "default" else preset),
              "%s: integration proxy %s for preset %s" % (cls, name, preset))
        # The VTK object starts from the same preset.
        settings = getattr(riemann, cls)().GetIntegrationSettings()
        declared = next(d for d in DOCS if d["class"] == "vtkRiemannIntegrationSettings")
        values = declared.get("presets", {}).get(preset, {})
        for s in declared["settings"]:
            v = values.get(s["name"], s["default"])
            v = s["choices"].index(v) if s["type"] == "choice" else v
            got = getattr(settings, "Get" + s["name"])()
            check(got == v, "%s: integration %s is %r, its preset %s says %r" % (cls, s["name"], got, preset, v))


# --- 3. The commands ------------------------------------------------------------
def command_line_name(name):
    """CommandLineName: NumberOfDirections -> --number-of-directions, MinimumFA ->
    --minimum-fa, GPUPath -> --gpu-path."""
    out = "--"
    for i, c in enumerate(name):
        follows_small = i + 1 < len(name) and name[i + 1].islower()
        if c.isupper() and i > 0 and (not name[i - 1].isupper() or follows_small):
            out += "-"
        out += c.lower()
    return out


def help_entry(help_text, option):
    """What --help says of `option`: its names (with the old spellings) and its help,
    which CLI11 writes on the names' line or the next one (the command's
    description above "Options:" may start a line with an option too)."""
    lines = help_text.split("\nOptions:", 1)[-1].splitlines()
    for i, line in enumerate(lines):
        words = line.split()
        if not words or option not in words[0].split(","):
            continue
        entry = [line]
        for more in lines[i + 1:]:
            if more.startswith("    ") and not more.strip().startswith("-"):
                entry.append(more)
            else:
                break
        return " ".join(l.strip() for l in entry)
    return None


def command_default(cls, command, s):
    """What a command's --help says the default is: the declared one, or for the
    integration settings the command's filter's own (render: the scene's)."""
    if cls == "vtkRiemannPictureSettings" and s["name"] in SCENE_CAMERA:
        return "(default: the scene's camera, else %s)" % default_text(s)
    if cls != "vtkRiemannIntegrationSettings":
        return "(default %s)" % default_text(s)
    filter_class = INTEGRATION_DEFAULTS[command]
    if filter_class is None:
        return "(default: the scene's)"
    value = getter_of(getattr(riemann, filter_class)().GetIntegrationSettings(), s)
    return "(default %s)" % default_text(dict(s, default=value))


def getter_of(obj, s):
    value = getattr(obj, "Get" + s["name"])()
    return s["choices"][value] if s["type"] == "choice" else value


def past_range(s):
    if s["type"] in ("integer", "number") and "maximum" in s:
        x = s["maximum"] * 2 + 1
        return str(int(x)) if s["type"] == "integer" else cxx_g(x)
    if s["type"] == "direction":
        return "0,0,0"
    if s["type"] == "dimensions":
        return "%d,1,1" % (s["maximum"] * 2 + 1)
    if s["type"] == "bounds":
        return "1,0,-1,1,-1,1"
    if s["type"] == "choice":
        return "nothing-of-the-sort"
    return None


def check_commands(doc):
    cls = doc["class"]
    commands = COMMANDS.get(cls)
    check(commands is not None or cls in NO_COMMAND,
          "%s: no command runs it and it is not in NO_COMMAND (say which command shows its settings)" % cls)
    for command in commands or []:
        result = subprocess.run([os.path.join(BIN, "riemann"), command, "--help"],
                                capture_output=True, text=True)
        check(result.returncode == 0, "riemann %s --help: status %d" % (command, result.returncode))
        text = result.stdout
        for s in doc["settings"]:
            where = "riemann %s: %s" % (command, s["name"])
            option = command_line_name(s["name"])
            entry = help_entry(text, option)
            if (command, s["name"]) in LEFT_OUT:
                check(entry is None, "%s: left out (%s) but listed" % (where, LEFT_OUT[(command, s["name"])]))
                continue
            check(entry is not None, "%s: --help has no %s" % (where, option))
            if entry is None:
                continue
            for alias in s.get("aliases", {}).get("cli", []):
                check(alias in entry, "%s: --help does not name the old spelling %s: %s" % (where, alias, entry))
            want = command_default(cls, command, s)
            check(want in entry, "%s: --help does not say %s: %s" % (where, want, entry))
            for bound in ("minimum", "maximum"):
                if bound in s and s["type"] in ("integer", "number", "number_list", "dimensions"):
                    check(cxx_g(s[bound]) in entry, "%s: --help does not give the %s %s: %s"
                          % (where, bound, cxx_g(s[bound]), entry))
            # Past the range, and on an end the declaration excludes.
            bad = [past_range(s)]
            for bound in ("minimum", "maximum"):
                if s.get(bound + "_exclusive") and s["type"] == "number":
                    bad.append(cxx_g(s[bound]))
            for value in (b for b in bad if b is not None):
                metric = os.path.join(SOURCE, "Data", "metrics", "euclidean.json")
                run = subprocess.run([os.path.join(BIN, "riemann"), command, "-m", metric,
                                      option, value, "-o", "never.vtp"], capture_output=True, text=True)
                check(run.returncode == 2 and option in run.stderr,
                      "%s: %s %s: status %d, %s" % (where, option, value, run.returncode, run.stderr.strip()))


# --- 4. The generator -----------------------------------------------------------
def check_generator_follows(generator, files):
    """A default and a maximum changed in the declaration change what is made from it."""
    with tempfile.TemporaryDirectory() as folder:
        copies = []
        for f in files:
            target = os.path.join(folder, os.path.basename(f))
            with open(f) as src, open(target, "w") as dst:
                dst.write(src.read())
            copies.append(target)
        path = os.path.join(folder, "vtkRiemannExponentialMap.settings.json")
        with open(path) as f:
            doc = json.load(f)
        for s in doc["settings"]:
            if s.get("like") == "vtkRiemannDirectionGrid.NumberOfDirections":
                s["default"], s["maximum"] = 123, 5000
        with open(path, "w") as f:
            json.dump(doc, f)
        out = os.path.join(folder, "out")
        run = subprocess.run([sys.executable, os.path.join(SOURCE, "cmake", "RiemannSettings.py"),
                              "--output", out] + copies, capture_output=True, text=True)
        check(run.returncode == 0, "the generator failed on a changed copy: " + run.stderr)
        if run.returncode != 0:
            return
        with open(os.path.join(out, "RiemannExponentialMapDeclaration.h")) as f:
            header = f.read()
        check("constexpr long long NumberOfDirections = 123;" in header,
              "the changed default is not the class's constant")
        check('"123", 1.0, false, 5000.0' in header, "the changed default and range are not in the table")
        xml = ET.parse(os.path.join(out, "ParaView", "vtkRiemannExponentialMap.xml")).getroot()
        p = xml.find(".//IntVectorProperty[@name='NumberOfDirections']")
        check(p.get("default_values") == "123" and p.find("IntRangeDomain").get("max") == "5000",
              "the changed default and range are not in the ParaView XML")
        # A malformed declaration stops the build with its file and key.
        doc["settings"][1]["default"] = "many"
        with open(path, "w") as f:
            json.dump(doc, f)
        run = subprocess.run([sys.executable, os.path.join(SOURCE, "cmake", "RiemannSettings.py"),
                              "--output", out] + copies, capture_output=True, text=True)
        check(run.returncode == 1 and "vtkRiemannExponentialMap" in run.stderr and "default" in run.stderr,
              "a malformed declaration: status %d, %s" % (run.returncode, run.stderr.strip()))


def main():
    generator = load_generator()
    files, docs = generator.declarations_of(SOURCE)
    DOCS.extend(docs)
    check(len(files) >= 4, "only %d declarations found under %s" % (len(files), SOURCE))
    count = 0
    for doc in docs:
        count += len(doc["settings"])
        if doc.get("abstract"):
            # A base class: its settings are walked in the subclasses that take them ("like").
            check(any(s.get("name") == t["name"] for other in docs if not other.get("abstract")
                      for s in other["settings"] for t in doc["settings"]),
                  "%s: abstract, and no class takes its settings" % doc["class"])
            check(not os.path.exists(os.path.join(PARAVIEW, doc["class"] + ".xml")),
                  "%s: abstract, but it has a ParaView proxy" % doc["class"])
            continue
        check_vtk_defaults(doc)
        check_paraview(doc)
        check_commands(doc)
    check_generator_follows(generator, files)
    print("%d classes, %d declared settings walked" % (len(docs), count))
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
