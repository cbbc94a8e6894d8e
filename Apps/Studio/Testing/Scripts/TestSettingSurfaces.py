"""The studio's surfaces of every declared setting (riemann-studio --script ... --exit).

For each kind of item whose toolkit class has a declaration
(`<Class>.settings.json`, Documentation/Settings.md), and each declared
setting of it:

1. the properties panel has its field, with the declared label, type and range;
2. a new item has the declared default (and the integration settings'
   fields, with the declared labels, types and ranges);
3. a project saved with other values and opened again gives those values back
   under the property's name (the project key);
4. the exported Python sets it, and run, builds filters that hold those values.

Python.TestSettingSurfaces walks the VTK classes, the ParaView XML and the
commands' options.
"""
import importlib.util
import os
import sys
import tempfile

import studio

SOURCE = os.path.dirname(os.environ["RIEMANN_DATA_DIR"])
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message, file=sys.stderr)


def declarations():
    spec = importlib.util.spec_from_file_location(
        "RiemannSettings", os.path.join(SOURCE, "cmake", "RiemannSettings.py"))
    generator = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(generator)
    _, docs = generator.declarations_of(SOURCE)
    return {doc["class"]: doc for doc in docs}


# Declared settings an item leaves out on purpose, and why: no field, not in its settings.
LEFT_OUT = {
    ("geodesics", "SeedsPerVoxel"): "a mask input's seeds: the studio's geodesics have none",
    ("geodesics", "SeedDirection"): "a mask input's seeds: the studio's geodesics have none",
    ("geodesics", "RandomSeed"): "a mask input's seeds: the studio's geodesics have none",
}
LEFT_OUT.update({("ray-bundle", name): "the inside view's (its size, projection, scene settings)"
                 for name in ("Width", "Height", "Projection", "UseSceneSettings")})

# Declared classes an item also runs, on its result, with their settings in the
# item's form (display settings: they only redraw), and the key of their
# filter in the exported Python's `items` (the item's name and this suffix).
PARTS = {
    "distance-field": [("vtkRiemannCutLocus", " cut locus")],
}

# Items without integration settings of their own, and why.
NO_INTEGRATION = {
    "ray-bundle": "its rays are the inside view's: the document's ray settings",
    "field": "a field of the metric at grid points: nothing is integrated",
    "distance-field": "the eikonal solver on a grid: nothing is integrated",
    "camera-path": "its frames are transported with its own largest step (Step)",
}

FIELD_TYPES = {"integer": "integer", "number": "number", "point": "vector3", "direction": "vector3",
               "choice": "choice", "boolean": "boolean", "number_list": "number_list",
               "bounds": "numbers6", "dimensions": "integers3"}


def other_value(s):
    """A valid value other than the default, small enough to compute quickly."""
    kind, d = s["type"], s["default"]
    lo, hi = s.get("minimum", -1e300), s.get("maximum", 1e300)
    if kind == "integer":
        return d - 1 if d - 1 >= lo and d > 3 else min(d + 1, hi)
    if kind == "number":
        x = d * 0.5 if d != 0 else 0.5
        return x if (x > lo if s.get("minimum_exclusive") else x >= lo) and \
            (x < hi if s.get("maximum_exclusive") else x <= hi) else (lo + hi) / 2
    if kind == "point":
        return [0.25, -0.5, 0.75]
    if kind == "direction":
        return [0.0, 1.0, 0.0] if d != [0, 1, 0] else [1.0, 0.0, 0.0]
    if kind == "choice":
        return [c for c in s["choices"] if c != d][0]
    if kind == "boolean":
        return not d
    if kind == "bounds":
        return [-1.0, 1.0, -1.5, 1.5, -0.5, 0.5]
    if kind == "dimensions":
        return [9, 8, 7]  # small: quick jobs
    return [0.5, 1.5]


def same(a, b):
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        return float(a) == float(b)
    return a == b


def getter(s, obj):
    if s["type"] == "number_list":
        return [getattr(obj, s["commands"]["get"])(i) for i in range(getattr(obj, s["commands"]["count"])())]
    value = getattr(obj, "Get" + s["name"])()
    if s["type"] == "choice":
        return s["choices"][value]
    return list(value) if s["type"] in ("point", "direction", "bounds", "dimensions") else value


def main():
    declared = declarations()
    studio.metric('{"type": "euclidean"}')
    kinds = ["geodesics", "ray-bundle", "exponential-map", "conjugate-locus", "field",
             "distance-field", "connect", "camera-path"]
    walked, undeclared, values = [], [], {}
    for kind in kinds:
        name = studio.add(kind)
        item = studio.get(name)
        doc = declared.get(item["class"])
        if doc is None:
            undeclared.append("%s (%s)" % (kind, item["class"]))
            studio.remove(name)
            continue
        fields = {f["key"]: f for f in studio.properties(name)}
        # A new item starts from the declared defaults, or from the declared
        # preset it names (the tracer's Fan).
        preset = doc.get("presets", {}).get(item.get("preset"), {}) if "preset" in item else {}
        check("preset" not in item or item["preset"] in doc.get("presets", {}),
              "%s: starts from preset %r, which %s does not declare" % (kind, item.get("preset"), doc["class"]))
        parts = [(doc, name, False)] + [(declared[cls], name + suffix, True) for cls, suffix in PARTS.get(kind, [])]
        values[name] = {}
        for doc, python_key, display in parts:
            shown = walk_form(kind, doc, item, fields, preset, display)
            walked.append((name, python_key, dict(doc, settings=shown)))
            # Other values for every declared setting.
            values[name].update({s["name"]: other_value(s) for s in shown})
        # Every item that integrates shows the declared integration settings.
        for s in declared["vtkRiemannIntegrationSettings"]["settings"]:
            field = fields.get(s["name"])
            if kind in NO_INTEGRATION:
                check(field is None, "%s: integration field %s, but %s" % (kind, s["name"], NO_INTEGRATION[kind]))
                continue
            check(field is not None and field["label"] == s.get("label") and
                  field["type"] == FIELD_TYPES[s["type"]],
                  "%s: integration field %s: %r" % (kind, s["name"], field))
            if field is not None and s["type"] in ("integer", "number"):
                check(field["minimum"] == s.get("minimum", -1e300) and field["maximum"] == s.get("maximum", 1e300),
                      "%s: integration field %s range %s..%s" % (kind, s["name"], field["minimum"], field["maximum"]))
        # A short length: quick jobs.
        quick = {} if kind in NO_INTEGRATION else {"MaximumPropagation": 1.0}
        studio.set(name, **quick, **values[name])

    # An old key a project may still hold (a declared project alias) sets the setting.
    aliased = 0
    for name, _, doc in walked:
        for s in doc["settings"]:
            for old in s.get("aliases", {}).get("project", []):
                studio.set(name, **{old: values[name][s["name"]]})
                item = studio.get(name)
                check(old not in item and same(item.get(s["name"]), values[name][s["name"]]),
                      "%s: the old key %s did not set %s: %r" % (name, old, s["name"], item.get(s["name"])))
                aliased += 1
    check(aliased > 0, "no declared project alias was walked")

    # Project keys: saved and opened again.
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "walk.json")
        studio.save(path)
        studio.open(path)
        for name, _, doc in walked:
            item = studio.get(name)
            for s in doc["settings"]:
                check(same(item.get(s["name"]), values[name][s["name"]]),
                      "project: %s %s came back as %r, saved %r"
                      % (name, s["name"], item.get(s["name"]), values[name][s["name"]]))

    # The exported Python: run it, and ask its filters.
    script = studio.python()
    namespace = {"__name__": "trace"}
    argv = sys.argv
    sys.argv = ["trace"]
    try:
        exec(compile(script, "trace.py", "exec"), namespace)
    finally:
        sys.argv = argv
    for name, python_key, doc in walked:
        algorithm = namespace["items"].get(python_key)
        check(algorithm is not None, "python: no filter for %s" % python_key)
        if algorithm is None:
            continue
        check(algorithm.GetClassName() == doc["class"], "python: %s is a %s" % (python_key, algorithm.GetClassName()))
        for s in doc["settings"]:
            got = getter(s, algorithm)
            check(same(got, values[name][s["name"]]),
                  "python: %s %s is %r, the item has %r" % (python_key, s["name"], got, values[name][s["name"]]))

    print("walked %d settings of %s" % (sum(len(d["settings"]) for _, _, d in walked),
                                        ", ".join(sorted(d["class"] for _, _, d in walked))))
    print("kinds without a declaration yet: " + ", ".join(undeclared))
    check(len(walked) >= 2, "fewer than two declared kinds walked")
    return 1 if failures else 0


def walk_form(kind, doc, item, fields, preset, display):
    """Check the form's field and the new item's value of each of `doc`'s settings
    (`display`: a part's, which only redraws); returns those the item shows."""
    shown = []
    for s in doc["settings"]:
        where = "%s %s" % (kind, s["name"])
        if (kind, s["name"]) in LEFT_OUT:
            check(s["name"] not in fields and s["name"] not in item,
                  "%s: left out (%s) but in the form or the settings" % (where, LEFT_OUT[(kind, s["name"])]))
            continue
        shown.append(s)
        field = fields.get(s["name"])
        check(field is not None, "%s: no field in the properties panel" % where)
        if field is None:
            continue
        check(field["label"] == s.get("label", field["label"]), "%s: label %r" % (where, field["label"]))
        check(field["type"] == FIELD_TYPES[s["type"]], "%s: field type %s" % (where, field["type"]))
        if s["type"] in ("integer", "number", "number_list", "dimensions"):
            check(field["minimum"] == s.get("minimum", -1e300), "%s: minimum %s" % (where, field["minimum"]))
            check(field["maximum"] == s.get("maximum", 1e300), "%s: maximum %s" % (where, field["maximum"]))
            for end in ("minimum_exclusive", "maximum_exclusive"):
                check(field[end] == bool(s.get(end)), "%s: %s %s" % (where, end, field[end]))
        if s["type"] == "choice":
            check(field["choices"] == s["choices"], "%s: choices %s" % (where, field["choices"]))
        check(field["non_zero"] == (s["type"] == "direction"), "%s: non_zero" % where)
        check(field["help"].startswith(s["help"]), "%s: help %r" % (where, field["help"]))
        want = preset.get(s["name"], s["default"])
        check(same(item.get(s["name"]), want),
              "%s: a new item has %r, declared %r" % (where, item.get(s["name"]), want))
        check(field["display"] == display,
              "%s: %s" % (where, "a part's setting must only redraw" if display else "must re-run the job"))
    return shown


sys.exit(main())
