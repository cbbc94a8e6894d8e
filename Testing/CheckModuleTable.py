"""Documentation/Architecture.md's module table says what CMake declares.

The dependencies are declared once, in CMake (RiemannModuleGraph.json,
cmake/RiemannModuleGraph.cmake). Each row of the table for a Riemann library
must give that library's folder and kind, name exactly the Riemann libraries
it links ("depends on (ours)", what a row lists after "tests also" aside),
and, in "third-party", exactly its VTK modules and a word for each other
third-party target. A dependency added in CMake and not in the table, or
the other way round, fails here.

Usage: CheckModuleTable.py ARCHITECTURE_MD MODULE_GRAPH_JSON
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ModuleGraph import ModuleGraph  # noqa: E402

# How the table names a third-party CMake target that is not a VTK module.
WORDS = {
    "nlohmann_json::nlohmann_json": "nlohmann_json",
    "Eigen3::Eigen": "Eigen",
    "hwy::hwy": "Highway",
    "PkgConfig::GINAC": "GiNaC",
    "embree": "Embree",
    "OpenImageIO::OpenImageIO": "OpenImageIO",
    "Threads::Threads": "Threads",
}
KINDS = {"plain library": "library", "VTK module": "vtk-module"}
EDGE = re.compile(r"^\s*(\w+)\s+(-->|-\.->)\s+(\w+)\s*$")
ROW = re.compile(r"^\|\s*`(Riemann::\w+)`\s*\|\s*`([^`]+)`\s*\|([^|]*)\|([^|]*)\|([^|]*)\|\s*$")


def declared_part(cell):
    """A cell without what it says of the tests ("; tests also ...")."""
    return re.split(r"tests also", cell)[0]


def check_diagram(graph, short, lines):
    """The mermaid diagram's arrows between Riemann libraries are CMake's
    direct dependencies: solid where public, dotted where private."""
    problems = []
    drawn = {}
    for m in filter(None, map(EDGE.match, lines)):
        if m.group(1) in short and m.group(3) in short:
            drawn[(short[m.group(1)], short[m.group(3)])] = m.group(2) == "-->"
    declared = {}
    for name in graph.names():
        public = set(graph.libraries[name]["public"])
        for other in graph.direct(name):
            declared[(name, other)] = other in public
    for edge in sorted(set(declared) - set(drawn)):
        problems.append("the diagram has no arrow %s -> %s (CMake links it)" % edge)
    for edge in sorted(set(drawn) - set(declared)):
        problems.append("the diagram draws %s -> %s; CMake does not link it" % edge)
    for edge in sorted(set(drawn) & set(declared)):
        if drawn[edge] != declared[edge]:
            problems.append("the diagram's arrow %s -> %s is %s; CMake's dependency is %s"
                            % (edge + (("solid" if drawn[edge] else "dotted"),
                                       ("public" if declared[edge] else "private"))))
    return problems


def main(table_file, graph_file):
    graph = ModuleGraph(graph_file)
    with open(table_file, encoding="utf-8") as f:
        lines = f.read().splitlines()
    rows = {m.group(1): m.groups()[1:] for m in map(ROW.match, lines) if m}
    short = {name.split("::", 1)[1]: name for name in graph.names()}
    problems = check_diagram(graph, short, lines)
    for name in graph.names():
        if name not in rows:
            problems.append("%s: no row in the module table" % name)
            continue
        folder, kind, ours, third = rows[name]
        entry = graph.libraries[name]
        if folder != entry["folder"]:
            problems.append("%s: the table says folder %s, CMake %s" % (name, folder, entry["folder"]))
        kind_words = [word for word in KINDS if word in kind]
        if [KINDS[word] for word in kind_words] != [entry["kind"]]:
            problems.append("%s: the table says kind %r, CMake %s" % (name, kind.strip(), entry["kind"]))
        said = {short[word] for word in re.findall(r"\b\w+\b", declared_part(ours)) if word in short}
        declared = set(graph.direct(name))
        for missing in sorted(declared - said):
            problems.append("%s links %s (CMake); the table does not say so" % (name, missing))
        for extra in sorted(said - declared):
            problems.append("%s: the table says it depends on %s; CMake does not link it" % (name, extra))
        third_said = set(re.findall(r"VTK::\w+", declared_part(third)))
        vtk = {d for d in entry["third_party"] if d.startswith("VTK::")}
        for missing in sorted(vtk - third_said):
            problems.append("%s uses %s (vtk.module); the table does not say so" % (name, missing))
        for extra in sorted(third_said - vtk):
            problems.append("%s: the table says it uses %s; its vtk.module does not" % (name, extra))
        for target in sorted(set(entry["third_party"]) - vtk):
            word = WORDS.get(target)
            if word is None:
                problems.append("%s links %s: give it a word in CheckModuleTable.py's WORDS" % (name, target))
            elif word not in third:
                problems.append("%s links %s; the table's third-party cell does not say %s"
                                % (name, target, word))
    for name in sorted(set(rows) - set(graph.names())):
        problems.append("%s: a row of the table, but no such library in CMake" % name)
    print("%d modules checked against %s" % (len(graph.names()), os.path.basename(table_file)))
    for p in problems:
        print("FAIL: " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
