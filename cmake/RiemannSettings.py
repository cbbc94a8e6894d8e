#!/usr/bin/env python3
"""Make every surface's code from the settings declarations.

    RiemannSettings.py --output DIR DECLARATION.settings.json...

Each declaration (`<Class>.settings.json`, next to the VTK class it
configures; Documentation/Settings.md) states a class's user-facing
settings once. For each, this writes into DIR:

- `<Class minus "vtk">Declaration.h` (RiemannExponentialMapDeclaration.h): the table riemann::declared::<Class>::Settings
  (SettingDeclaration.h) and its typed constants (Default::, Minimum::,
  Maximum::), VTK-free, for the class's constructor, the VTK-free cores and
  the apps;
- `<Class>SettingAccess.h`: ApplySettings(object, values) and
  SettingValues(object), which set and read the declared VTK properties
  from JSON values (the apps' projects, forms and options);
- `ParaView/<Class>.xml`: the class's server-manager proxy for ParaView.

A declaration that is malformed stops the build with its file and key.
"""

import argparse
import json
import os
import sys
from xml.sax.saxutils import quoteattr, escape

KINDS = {
    "boolean": "Boolean",
    "integer": "Integer",
    "number": "Number",
    "point": "Point",
    "direction": "Direction",
    "choice": "Choice",
    "number_list": "NumberList",
    "bounds": "Bounds",
    "dimensions": "Dimensions",
}
KEYS = {"like", "name", "type", "default", "minimum", "maximum", "minimum_exclusive", "maximum_exclusive",
        "choices", "unit", "label", "help", "aliases", "commands"}
TOP_KEYS = {"class", "label", "help", "paraview_group", "settings", "presets", "abstract",
            "inputs", "metric_port", "integration"}
# What a ParaView input may require (the VTK class's input types).
INPUT_TYPES = {"vtkDataSet", "vtkImageData", "vtkPolyData", "vtkDataObject"}


class DeclarationError(Exception):
    pass


def words(name):
    """NumberOfDirections -> 'Number Of Directions' (ParaView's label rule)."""
    out = ""
    for i, c in enumerate(name):
        if c.isupper() and i > 0 and not name[i - 1].isupper():
            out += " "
        out += c
    return out


def table_header(cls):
    """The VTK-free table's header: named without "vtk", as VTK-free code includes it."""
    return cls[len("vtk"):] + "Declaration.h"


def cxx_string(text):
    return json.dumps(text)


def cxx_number(x):
    if x in (float("inf"), float("-inf")):
        return ("-" if x < 0 else "") + "1e300"
    return repr(float(x))


def check(where, condition, why):
    if not condition:
        raise DeclarationError(f"{where}: {why}")


def read_declaration(path):
    where = os.path.basename(path)
    try:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
    except json.JSONDecodeError as e:
        raise DeclarationError(f"{where}:{e.lineno}:{e.colno}: {e.msg}")
    check(where, isinstance(doc, dict), "expected an object")
    for key in doc:
        check(where, key in TOP_KEYS, f"unknown key \"{key}\"")
    check(where, isinstance(doc.get("class"), str), "\"class\": expected the VTK class name")
    expected = os.path.basename(path)[: -len(".settings.json")]
    check(where, doc["class"] == expected, f"\"class\" is {doc['class']}, the file is for {expected}")
    settings = doc.get("settings")
    check(where, isinstance(settings, list) and settings, "\"settings\": expected a list")
    check_pipeline(where, doc)
    return doc


def check_pipeline(where, doc):
    """The pipeline facts ParaView's proxy needs: the data inputs it shows (each a VTK input
    port), the VTK class's metric port (GetMetricPort()) and its integration settings
    (vtkRiemannIntegrationSettings' defaults, or one of its presets)."""
    inputs = doc.get("inputs", [])
    check(where, isinstance(inputs, list), "\"inputs\": expected a list")
    for i, item in enumerate(inputs):
        at = f"{where}: inputs[{i}]"
        check(at, isinstance(item, dict) and set(item) <= {"name", "port", "types", "help", "optional"},
              "expected {\"name\", \"port\", \"types\", \"help\"} and perhaps \"optional\"")
        check(at, isinstance(item.get("optional", False), bool), "\"optional\": true or false")
        check(at, isinstance(item.get("name"), str) and item["name"][:1].isupper(), "\"name\": the property's name")
        check(at, item.get("port") == i, f"\"port\": the shown data inputs are ports 0, 1, ... in order ({i} here)")
        check(at, isinstance(item.get("types"), list) and item["types"] and set(item["types"]) <= INPUT_TYPES,
              f"\"types\": a list of {', '.join(sorted(INPUT_TYPES))}")
        check(at, isinstance(item.get("help"), str) and item["help"], "\"help\" is missing")
    if "metric_port" in doc:
        # A field filter's optional dataset (port 0) is not shown: its metric port is 1 regardless.
        check(where, isinstance(doc["metric_port"], int) and doc["metric_port"] >= len(inputs),
              "\"metric_port\": the VTK class's GetMetricPort(), after the data inputs shown")
    integration = doc.get("integration")
    check(where, integration is None or (isinstance(integration, str) and
          (integration == "default" or integration[:1].isupper())),
          "\"integration\": \"default\" or the name of a vtkRiemannIntegrationSettings preset")


def within(s, x):
    """Whether the number x is in the declared range (either end may be exclusive)."""
    lo, hi = s.get("minimum", -1e300), s.get("maximum", 1e300)
    return (x > lo if s.get("minimum_exclusive") else x >= lo) and \
        (x < hi if s.get("maximum_exclusive") else x <= hi)


def valid_value(s, value):
    """Whether `value` is one setting `s` may hold (a preset's)."""
    kind = s["type"]
    number = lambda x: isinstance(x, (int, float)) and not isinstance(x, bool)
    in_range = lambda x: number(x) and within(s, x)
    if kind == "choice":
        return value in s["choices"]
    if kind == "boolean":
        return isinstance(value, bool)
    if kind == "integer":
        return in_range(value) and float(value).is_integer()
    if kind == "number":
        return in_range(value)
    if kind in ("point", "direction"):
        return isinstance(value, list) and len(value) == 3 and all(number(x) for x in value) and \
            (kind == "point" or any(x != 0 for x in value))
    if kind == "bounds":
        return isinstance(value, list) and len(value) == 6 and all(number(x) for x in value) and \
            all(value[2 * a] < value[2 * a + 1] for a in range(3))
    if kind == "dimensions":
        return isinstance(value, list) and len(value) == 3 and \
            all(in_range(x) and float(x).is_integer() for x in value)
    return isinstance(value, list) and all(in_range(x) for x in value)


def check_declaration(doc):
    where = doc["class"] + ".settings.json"
    settings = doc["settings"]
    names = set()
    for i, s in enumerate(settings):
        at = f"{where}: settings[{i}]"
        check(at, isinstance(s, dict), "expected an object")
        for key in s:
            check(at, key in KEYS, f"unknown key \"{key}\"")
        check(at, isinstance(s.get("name"), str) and s["name"][:1].isupper(),
              "\"name\": expected the VTK property's name")
        at = f"{where}: {s['name']}"
        check(at, s["name"] not in names, "declared twice")
        names.add(s["name"])
        check(at, s.get("type") in KINDS, f"\"type\": expected one of {', '.join(KINDS)}")
        check(at, "default" in s, "\"default\" is missing")
        check(at, isinstance(s.get("help"), str) and s["help"], "\"help\" is missing")
        kind = s["type"]
        d = s["default"]
        if kind == "choice":
            check(at, isinstance(s.get("choices"), list) and s["choices"], "\"choices\": expected names")
            check(at, d in s["choices"], "the default is not one of the choices")
        elif kind == "boolean":
            check(at, isinstance(d, bool), "the default must be true or false")
        elif kind in ("point", "direction"):
            check(at, isinstance(d, list) and len(d) == 3, "the default must be three numbers")
        elif kind == "bounds":
            check(at, valid_value(s, d), "the default must be six numbers x0,x1,y0,y1,z0,z1 with x0 < x1, y0 < y1, z0 < z1")
        elif kind == "dimensions":
            check(at, "minimum" in s and "maximum" in s and -2**31 <= s["minimum"] and s["maximum"] < 2**31,
                  "dimensions need a minimum and a maximum within an int's range")
            check(at, valid_value(s, d), "the default must be three whole numbers in the range")
        elif kind == "number_list":
            check(at, isinstance(d, list), "the default must be a list")
            for key in ("add", "clear", "count", "get"):
                check(at, isinstance(s.get("commands", {}).get(key), str),
                      f"\"commands\": \"{key}\" is missing")
        else:
            check(at, isinstance(d, (int, float)) and not isinstance(d, bool), "the default must be a number")
            if kind == "integer":
                check(at, float(d).is_integer(), "the default must be whole")
                # The VTK property and ParaView's IntVectorProperty hold an int.
                check(at, "minimum" in s and "maximum" in s and -2**31 <= s["minimum"] and s["maximum"] < 2**31,
                      "an integer needs a minimum and a maximum within an int's range")
        if kind in ("integer", "number"):
            check(at, within(s, d), f"the default {d} is outside the declared range")
        aliases = s.get("aliases", {})
        for surface in aliases:
            check(at, surface in ("cli", "scene", "choices", "project"), f"\"aliases\": unknown surface \"{surface}\"")
        for old, new in aliases.get("choices", {}).items():
            check(at, kind == "choice" and new in s.get("choices", []), f"\"aliases\": {old} names no choice")
        check(at, isinstance(aliases.get("cli", []), list), "\"aliases\": \"cli\" must be a list of option names")
        check(at, isinstance(aliases.get("scene", ""), str), "\"aliases\": \"scene\" must be a key")
        # Old property names ("ConeAxis") or a project format's old keys ("focal-point").
        check(at, isinstance(aliases.get("project", []), list) and
              all(isinstance(k, str) and k[:1].isalpha() for k in aliases.get("project", [])),
              "\"aliases\": \"project\" must be a list of old property names or project keys")
    by_name = {s["name"]: s for s in settings}
    for preset, values in doc.get("presets", {}).items():
        at = f"{where}: presets.{preset}"
        check(at, preset[:1].isupper() and preset.isalnum(), "a preset is named as a C++ namespace (Rays)")
        for name, value in values.items():
            check(at, name in by_name, f"{name} is not a declared setting")
            s = by_name[name]
            check(at, valid_value(s, value), f"{name}: {value} is not a valid value")


def resolve_likes(docs):
    """A setting {"like": "vtkOther.Name", ...} is vtkOther's Name with the keys given here
    changed (a default, say): one declaration of a range, label and help shared by classes."""
    by_class = {doc["class"]: doc for doc in docs}
    for doc in docs:
        for i, s in enumerate(doc["settings"]):
            if "like" not in s:
                continue
            where = f"{doc['class']}.settings.json: settings[{i}]"
            cls, _, name = s["like"].partition(".")
            check(where, cls in by_class, f"\"like\": no declaration of {cls}")
            found = [o for o in by_class[cls]["settings"] if o.get("name") == name]
            check(where, found and "like" not in found[0], f"\"like\": {cls} declares no {name} of its own")
            merged = dict(found[0])
            merged.update({k: v for k, v in s.items() if k != "like"})
            doc["settings"][i] = merged


def setting_row(s):
    kind = s["type"]
    commands = s.get("commands", {})
    fields = [
        cxx_string(s["name"]),
        "riemann::SettingDeclaration::" + KINDS[kind],
        cxx_string(json.dumps(s["default"])),
        cxx_number(s.get("minimum", -1e300)),
        "true" if s.get("minimum_exclusive") else "false",
        cxx_number(s.get("maximum", 1e300)),
        cxx_string("|".join(s.get("choices", []))),
        cxx_string(s.get("unit", "")),
        cxx_string(s.get("label", words(s["name"]))),
        cxx_string(s["help"]),
        cxx_string(",".join(s.get("aliases", {}).get("cli", []))),
        cxx_string(commands.get("add", "")),
        cxx_string(commands.get("clear", "")),
        cxx_string(commands.get("count", "")),
        cxx_string(commands.get("get", "")),
        cxx_string(s.get("aliases", {}).get("scene", "")),
        cxx_string(",".join(f"{old}={new}" for old, new in s.get("aliases", {}).get("choices", {}).items())),
        cxx_string(",".join(s.get("aliases", {}).get("project", []))),
        "true" if s.get("maximum_exclusive") else "false",
    ]
    return "  { " + ", ".join(fields) + " },"


def constants(doc):
    defaults, minima, maxima = [], [], []
    for s in doc["settings"]:
        kind, name, d = s["type"], s["name"], s["default"]
        if kind == "integer":
            defaults.append(f"constexpr long long {name} = {int(d)};")
        elif kind == "number":
            defaults.append(f"constexpr double {name} = {cxx_number(d)};")
        elif kind == "boolean":
            defaults.append(f"constexpr bool {name} = {'true' if d else 'false'};")
        elif kind in ("point", "direction"):
            defaults.append(f"constexpr double {name}[3] = {{ {', '.join(cxx_number(x) for x in d)} }};")
        elif kind == "bounds":
            defaults.append(f"constexpr double {name}[6] = {{ {', '.join(cxx_number(x) for x in d)} }};")
        elif kind == "dimensions":
            defaults.append(f"constexpr int {name}[3] = {{ {', '.join(str(int(x)) for x in d)} }};")
        elif kind == "choice":
            defaults.append(f"constexpr int {name} = {s['choices'].index(d)}; // {d}")
        if kind in ("integer", "number", "number_list", "dimensions"):
            minima.append(f"constexpr double {name} = {cxx_number(s.get('minimum', -1e300))};")
            maxima.append(f"constexpr double {name} = {cxx_number(s.get('maximum', 1e300))};")
    return defaults, minima, maxima


def preset_constants(doc):
    """namespace <Preset> { constexpr ... }: a preset's values, typed as the settings, and
    the preset as JSON text (Json), for the surfaces that start from it."""
    by_name = {s["name"]: s for s in doc["settings"]}
    blocks = []
    for preset, values in doc.get("presets", {}).items():
        lines = []
        for name, value in values.items():
            kind = by_name[name]["type"]
            if kind == "integer":
                lines.append(f"constexpr long long {name} = {int(value)};")
            elif kind == "choice":
                lines.append(f"constexpr int {name} = {by_name[name]['choices'].index(value)}; // {value}")
            elif kind == "boolean":
                lines.append(f"constexpr bool {name} = {'true' if value else 'false'};")
            elif kind in ("point", "direction"):
                lines.append(f"constexpr double {name}[3] = {{ {', '.join(cxx_number(x) for x in value)} }};")
            elif kind == "number":
                lines.append(f"constexpr double {name} = {cxx_number(value)};")
        lines.append(f"constexpr const char* Json = {cxx_string(json.dumps(values))};")
        blocks.append(f"namespace {preset}\n{{\n" + "\n".join(lines) + f"\n}} // namespace {preset}\n")
    return "".join(blocks)


def settings_header(doc):
    cls = doc["class"]
    defaults, minima, maxima = constants(doc)
    rows = "\n".join(setting_row(s) for s in doc["settings"])
    block = lambda name, lines: (f"namespace {name}\n{{\n" + "\n".join(lines) + f"\n}} // namespace {name}\n") if lines else ""
    return f"""// Generated by cmake/RiemannSettings.py from {cls}.settings.json: edit that file.
#ifndef {table_header(cls)[:-2]}_h
#define {table_header(cls)[:-2]}_h

#include "SettingDeclaration.h"

namespace riemann
{{
namespace declared
{{
namespace {cls}
{{
constexpr riemann::SettingDeclaration List[] = {{
{rows}
}};
constexpr riemann::SettingTable Settings{{ {cxx_string(cls)}, {cxx_string(doc.get("label", words(cls[len("vtkRiemann"):])))}, List,
  sizeof(List) / sizeof(List[0]) }};
{block("Default", defaults)}{block("Minimum", minima)}{block("Maximum", maxima)}{preset_constants(doc)}}} // namespace {cls}
}} // namespace declared
}} // namespace riemann

#endif
"""


def apply_lines(s):
    n, kind = s["name"], s["type"]
    if kind == "boolean":
        return [f"object->Set{n}(value.get<bool>());"]
    if kind == "integer":
        return [f"object->Set{n}(static_cast<decltype(object->Get{n}())>(value.get<double>()));"]
    if kind == "number":
        return [f"object->Set{n}(value.get<double>());"]
    if kind in ("point", "direction"):
        return [f"object->Set{n}(value.at(0).get<double>(), value.at(1).get<double>(), value.at(2).get<double>());"]
    if kind == "bounds":
        return [f"object->Set{n}(" + ", ".join(f"value.at({i}).get<double>()" for i in range(6)) + ");"]
    if kind == "dimensions":
        return [f"object->Set{n}(" + ", ".join(f"static_cast<int>(value.at({i}).get<double>())" for i in range(3)) + ");"]
    if kind == "choice":
        return [f"object->Set{n}(riemann::ChoiceIndex(riemann::declared::{{cls}}::List[{{index}}], value.get<std::string>()));"]
    c = s["commands"]
    return [f"object->{c['clear']}();",
            "for (const nlohmann::json& x : value)",
            "{",
            f"  object->{c['add']}(x.get<double>());",
            "}"]


def value_lines(s, index, cls):
    n, kind = s["name"], s["type"]
    if kind == "boolean":
        return [f"values[\"{n}\"] = object->Get{n}() != 0;"]
    if kind == "integer":
        return [f"values[\"{n}\"] = static_cast<long long>(object->Get{n}());"]
    if kind == "number":
        return [f"values[\"{n}\"] = static_cast<double>(object->Get{n}());"]
    if kind in ("point", "direction", "dimensions"):
        return [f"values[\"{n}\"] = {{ object->Get{n}()[0], object->Get{n}()[1], object->Get{n}()[2] }};"]
    if kind == "bounds":
        return [f"values[\"{n}\"] = {{ " + ", ".join(f"object->Get{n}()[{i}]" for i in range(6)) + " };"]
    if kind == "choice":
        return [f"values[\"{n}\"] = riemann::ChoiceNames(riemann::declared::{cls}::List[{index}]).at(static_cast<std::size_t>(object->Get{n}()));"]
    c = s["commands"]
    return [f"values[\"{n}\"] = nlohmann::json::array();",
            f"for (int i = 0; i < static_cast<int>(object->{c['count']}()); ++i)",
            "{",
            f"  values[\"{n}\"].push_back(object->{c['get']}(i));",
            "}"]


def access_header(doc):
    cls = doc["class"]
    applies, reads = [], []
    for index, s in enumerate(doc["settings"]):
        body = [line.replace("{cls}", cls).replace("{index}", str(index)) for line in apply_lines(s)]
        applies.append(f"    if (key == \"{s['name']}\")\n    {{\n" + "".join(f"      {l}\n" for l in body) + "    }")
        reads.extend("  " + l for l in value_lines(s, index, cls))
    applies_text = "\n".join(applies)
    reads_text = "\n".join(reads)
    return f"""// Generated by cmake/RiemannSettings.py from {cls}.settings.json: edit that file.
// The declared settings of {cls} read and set as JSON values
// (SettingValues.h); a declared setting the class lacks fails to compile here.
#ifndef {cls}SettingAccess_h
#define {cls}SettingAccess_h

#include "{cls}.h"
#include "{table_header(cls)}"
#include "SettingValues.h"

#include <nlohmann/json.hpp>

#include <string>

namespace riemann
{{
namespace settings
{{
/// The declared settings of the class.
inline const riemann::SettingTable& DeclaredSettings(const {cls}*)
{{
  return riemann::declared::{cls}::Settings;
}}

/// Set each declared setting `values` names (checked before: CheckSettingValue); other keys are left.
inline void ApplySettings({cls}* object, const nlohmann::json& values)
{{
  for (auto item = values.begin(); item != values.end(); ++item)
  {{
    const std::string& key = item.key();
    const nlohmann::json& value = item.value();
{applies_text}
  }}
}}

/// Every declared setting of `object`, keyed by name.
inline nlohmann::json SettingValues({cls}* object)
{{
  nlohmann::json values = nlohmann::json::object();
{reads_text}
  return values;
}}

template <>
struct DeclaredAccess<{cls}>
{{
  static const riemann::SettingTable& Settings() {{ return riemann::declared::{cls}::Settings; }}
  static void Apply({cls}* object, const nlohmann::json& values) {{ ApplySettings(object, values); }}
  static nlohmann::json Values({cls}* object) {{ return SettingValues(object); }}
}};
}} // namespace settings
}} // namespace riemann

#endif
"""


def xml_number(x):
    return repr(float(x)) if not float(x).is_integer() else str(int(x)) if abs(x) < 1e15 else repr(float(x))


def paraview_property(s):
    n, kind, d = s["name"], s["type"], s["default"]
    label = s.get("label", words(n))
    doc = f"      <Documentation>{escape(s['help'])}{' (' + escape(s['unit']) + ')' if s.get('unit') else ''}</Documentation>\n"
    attrs = f"name={quoteattr(n)} label={quoteattr(label)}"
    if kind == "boolean":
        return (f"    <IntVectorProperty {attrs} command=\"Set{n}\" number_of_elements=\"1\" default_values=\"{int(d)}\">\n"
                f"      <BooleanDomain name=\"bool\" />\n{doc}    </IntVectorProperty>\n")
    if kind == "choice":
        entries = "".join(f"        <Entry value=\"{i}\" text={quoteattr(c)} />\n" for i, c in enumerate(s["choices"]))
        return (f"    <IntVectorProperty {attrs} command=\"Set{n}\" number_of_elements=\"1\" default_values=\"{s['choices'].index(d)}\">\n"
                f"      <EnumerationDomain name=\"enum\">\n{entries}      </EnumerationDomain>\n{doc}    </IntVectorProperty>\n")
    lo, hi = s.get("minimum"), s.get("maximum")
    rng = ""
    if lo is not None or hi is not None:
        tag = "IntRangeDomain" if kind == "integer" else "DoubleRangeDomain"
        parts = (f" min=\"{xml_number(lo)}\"" if lo is not None else "") + (f" max=\"{xml_number(hi)}\"" if hi is not None else "")
        rng = f"      <{tag} name=\"range\"{parts} />\n"
    if kind == "integer":
        return (f"    <IntVectorProperty {attrs} command=\"Set{n}\" number_of_elements=\"1\" default_values=\"{int(d)}\">\n"
                f"{rng}{doc}    </IntVectorProperty>\n")
    if kind == "number":
        return (f"    <DoubleVectorProperty {attrs} command=\"Set{n}\" number_of_elements=\"1\" default_values=\"{xml_number(d)}\">\n"
                f"{rng}{doc}    </DoubleVectorProperty>\n")
    if kind in ("point", "direction", "bounds"):
        values = " ".join(xml_number(x) for x in d)
        return (f"    <DoubleVectorProperty {attrs} command=\"Set{n}\" number_of_elements=\"{len(d)}\" default_values=\"{values}\">\n"
                f"{doc}    </DoubleVectorProperty>\n")
    if kind == "dimensions":
        values = " ".join(str(int(x)) for x in d)
        each = lambda x: " ".join([xml_number(x)] * 3)
        return (f"    <IntVectorProperty {attrs} command=\"Set{n}\" number_of_elements=\"3\" default_values=\"{values}\">\n"
                f"      <IntRangeDomain name=\"range\" min=\"{each(lo)}\" max=\"{each(hi)}\" />\n"
                f"{doc}    </IntVectorProperty>\n")
    c = s["commands"]
    values = " ".join(xml_number(x) for x in d)
    count = f" default_values=\"{values}\"" if d else ""
    return (f"    <DoubleVectorProperty {attrs} command=\"{c['add']}\" clean_command=\"{c['clear']}\" repeat_command=\"1\" "
            f"number_of_elements_per_command=\"1\" use_index=\"0\" number_of_elements=\"{len(d)}\"{count}>\n"
            f"{rng}{doc}    </DoubleVectorProperty>\n")


def paraview_input(name, port, types, help_text, label=None, optional=False):
    domain = "".join(f"          <DataType value=\"{t}\" />\n" for t in types)
    label_attr = f" label={quoteattr(label)}" if label else ""
    # ParaView's Select Input dialog lets an optional input be left empty.
    hints = "      <Hints>\n        <Optional />\n      </Hints>\n" if optional else ""
    return (f"    <InputProperty name={quoteattr(name)}{label_attr} command=\"SetInputConnection\" port_index=\"{port}\">\n"
            f"      <ProxyGroupDomain name=\"groups\">\n        <Group name=\"sources\" />\n        <Group name=\"filters\" />\n      </ProxyGroupDomain>\n"
            f"      <DataTypeDomain name=\"input_type\">\n{domain}      </DataTypeDomain>\n"
            f"      <Documentation>{escape(help_text)}</Documentation>\n{hints}    </InputProperty>\n")


def paraview_inputs(doc):
    """The data inputs, then the metric: named Input when it is the only one (ParaView's
    Filters menu applies a filter to the selected source through Input)."""
    out = "".join(paraview_input(i["name"], i["port"], i["types"], i["help"], optional=i.get("optional", False))
                  for i in doc.get("inputs", []))
    if "metric_port" in doc:
        name = "Metric" if doc.get("inputs") else "Input"
        out += paraview_input(name, doc["metric_port"], ["vtkPolyData"],
                              "The metric: a Riemann Metric source (its definition, parameters and time)",
                              label="Metric")
    return out


def integration_proxy_name(preset):
    return "IntegrationSettings" + ("" if preset == "default" else preset)


def paraview_integration(doc):
    preset = doc.get("integration")
    if preset is None:
        return ""
    return (f"    <ProxyProperty name=\"IntegrationSettings\" label=\"Integration\" command=\"SetIntegrationSettings\">\n"
            f"      <ProxyListDomain name=\"proxy_list\">\n"
            f"        <Proxy group=\"riemann_integration\" name=\"{integration_proxy_name(preset)}\" />\n"
            f"      </ProxyListDomain>\n"
            f"      <Documentation>How the geodesics are integrated (vtkRiemannIntegrationSettings)</Documentation>\n"
            f"    </ProxyProperty>\n")


def settings_proxies(doc, label, help_text):
    """A settings object (no pipeline): one proxy with the declared defaults, and one per
    preset with the preset's values as its defaults (the filters that start from it)."""
    cls = doc["class"]
    variants = [("default", {})] + list(doc.get("presets", {}).items())
    out = ""
    for preset, values in variants:
        settings = [dict(x, default=values.get(x["name"], x["default"])) for x in doc["settings"]]
        props = "".join(paraview_property(x) for x in settings)
        name = integration_proxy_name(preset) if cls == "vtkRiemannIntegrationSettings" else \
            cls[len("vtkRiemann"):] + ("" if preset == "default" else preset)
        out += (f"   <Proxy name=\"{name}\" class=\"{cls}\" label={quoteattr(label)}>\n"
                f"    <Documentation short_help={quoteattr(label)}>{help_text}</Documentation>\n{props}   </Proxy>\n")
    return out


def paraview_xml(doc):
    cls = doc["class"]
    group = doc.get("paraview_group", "filters")
    label = doc.get("label", words(cls[len("vtkRiemann"):]))
    help_text = escape(doc.get("help", label))
    header = f"<!-- Generated by cmake/RiemannSettings.py from {cls}.settings.json: edit that file. -->\n"
    if group == "riemann_settings":
        group = "riemann_integration" if cls == "vtkRiemannIntegrationSettings" else group
        return (f"{header}<ServerManagerConfiguration>\n  <ProxyGroup name=\"{group}\">\n"
                f"{settings_proxies(doc, label, help_text)}  </ProxyGroup>\n</ServerManagerConfiguration>\n")
    props = paraview_inputs(doc) + "".join(paraview_property(s) for s in doc["settings"]) + paraview_integration(doc)
    return f"""{header}<ServerManagerConfiguration>
  <ProxyGroup name="{group}">
   <SourceProxy name="{cls[len('vtk'):]}" class="{cls}" label={quoteattr(label)}>
    <Documentation short_help={quoteattr(label)}>{help_text}</Documentation>
{props}    <Hints>
      <ShowInMenu category="Riemann" />
    </Hints>
   </SourceProxy>
  </ProxyGroup>
</ServerManagerConfiguration>
"""


def declarations_of(source):
    """Every declaration of the tree at `source`, resolved and checked as the build does
    (the folders CMake globs: Common/*, Filters/*, Rendering/*); for the tests that walk them."""
    files = []
    for top in ("Common", "Filters", "Rendering"):
        for module in sorted(os.listdir(os.path.join(source, top))):
            folder = os.path.join(source, top, module)
            if os.path.isdir(folder):
                files += [os.path.join(folder, f) for f in sorted(os.listdir(folder))
                          if f.endswith(".settings.json")]
    docs = [read_declaration(f) for f in files]
    resolve_likes(docs)
    for doc in docs:
        check_declaration(doc)
    return files, docs


def write_whole(path, text):
    """Written whole or not at all (a build stopped half-way leaves no half header)."""
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", required=True)
    parser.add_argument("declarations", nargs="+")
    args = parser.parse_args()
    os.makedirs(os.path.join(args.output, "ParaView"), exist_ok=True)
    try:
        docs = [read_declaration(path) for path in args.declarations]
        resolve_likes(docs)
        for doc in docs:
            check_declaration(doc)
            cls = doc["class"]
            write_whole(os.path.join(args.output, table_header(cls)), settings_header(doc))
            write_whole(os.path.join(args.output, f"{cls}SettingAccess.h"), access_header(doc))
            # An abstract class (a base whose settings its subclasses take with "like") has no proxy.
            if not doc.get("abstract"):
                write_whole(os.path.join(args.output, "ParaView", f"{cls}.xml"), paraview_xml(doc))
    except DeclarationError as e:
        print(f"RiemannSettings.py: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
