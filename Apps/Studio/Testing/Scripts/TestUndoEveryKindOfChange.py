"""Undo and redo of every kind of change, as a script (riemann-studio --script ... --exit).

For each kind of change (an item added, removed, renamed, hidden, its
properties applied; the metric text, a parameter, t, the observer moved):
the document after the change differs from before; after studio.undo() its
project text equals the text before, exactly; after studio.redo() the text
after. The last step is also compared as saved project files.
"""
import os
import sys
import tempfile

import studio

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message, file=sys.stderr)


def undoable(kind, change):
    before = studio.project()
    change()
    studio.render()
    after = studio.project()
    check(after != before, "%s: the change changed the document" % kind)
    name = studio.undo()
    check(name is not None, "%s: there is a step to undo" % kind)
    check(studio.project() == before, "%s: undo (%s) gives the document before" % (kind, name))
    check(studio.redo() == name, "%s: redo names the same step" % kind)
    check(studio.project() == after, "%s: redo gives the document after" % kind)
    print("%-22s undo/redo: %s" % (kind, name))


studio.metric('{"type": "graph", "parameters": {"a": 0.8}, '
              '"f": "a * exp(-(x^2 + y^2 + z^2) / 0.5)"}')
fan = studio.add("geodesics", NumberOfDirections=6, ConeAngle=10)
studio.add("camera-path", PathType="geodesic", Length=2.0)
studio.render()

undoable("item added", lambda: studio.add("geodesics", NumberOfDirections=4))
undoable("item removed", lambda: studio.remove(studio.items()[-1]))
undoable("item renamed", lambda: studio.rename(fan, "Fan of six"))
undoable("item hidden", lambda: studio.show(studio.items()[0], False))
undoable("properties applied", lambda: studio.set(studio.items()[0], ConeAngle=25, ColorMap="magma"))
undoable("metric text", lambda: studio.metric(
    '{"type": "graph", "parameters": {"a": 0.8}, "f": "a * exp(-(x^2 + y^2) / 0.3)"}'))
undoable("parameter", lambda: studio.parameter("/parameters/a", 1.4))
undoable("t", lambda: studio.time(0.5))
undoable("observer moved", lambda: studio.observer(position=(0.4, 0.6, 3.0), look_at=(0, 0.1, 0)))

# The same, as saved project files: undo, save; redo, undo, save again.
with tempfile.TemporaryDirectory() as folder:
    first, second = os.path.join(folder, "a.json"), os.path.join(folder, "b.json")
    studio.undo()
    studio.save(first)
    studio.redo()
    studio.undo()
    studio.save(second)
    with open(first) as a, open(second) as b:
        check(a.read() == b.read(), "saved project texts equal after undo, redo, undo")

sys.exit(1 if failures else 0)
