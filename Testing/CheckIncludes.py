"""The libraries' include graph has no cycle and follows the layers (issue 29).

Reads the `#include "..."` lines of every library source under Common/,
Filters/ and Rendering/ (tests, apps and generated headers aside) and checks:

1. Layers: a file of a library includes headers of its own library and of
   the libraries it depends on, nothing else. The dependencies are CMake's
   (target_link_libraries, vtk_module_link, vtk.module), read from the
   build's RiemannModuleGraph.json (cmake/RiemannModuleGraph.cmake): they
   are declared once, there, and an include of a library the target does
   not link fails here even where the include path happens to allow it.
2. Components: no cycle between components. A component is a header and
   the source of the same name (Foo.h + Foo.cxx), as in Lakos' physical
   design. A source without a header of its name belongs to the component
   of the header it includes first (ExpressionGinac.cxx to ExpressionGraph,
   SampledTensorFieldGlsl.cxx to SampledTensorField), and FooInternals.h is
   Foo's private part (it has no source of its own). So Metric.h <->
   GlslSource.cxx counts as a cycle, JacobiField.cxx <-> JacobiFieldInternals.h
   does not.

Usage: CheckIncludes.py SOURCE_DIR MODULE_GRAPH_JSON
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ModuleGraph import ModuleGraph  # noqa: E402


def layers_of(graph):
    """Library folder -> the library folders its files may include from: those
    of every library it depends on, as CMake declares (RiemannModuleGraph.json)."""
    return {graph.folder(name): sorted(graph.folder(other) for other in graph.closure(name)
                                       if other in graph.libraries)
            for name in graph.names()}


INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def library_files(source_dir, layers):
    """{file name: (library folder, path)} for every library source."""
    files = {}
    problems = []
    for library in layers:
        folder = os.path.join(source_dir, library)
        if not os.path.isdir(folder):
            problems.append("%s: no such folder" % library)
            continue
        for name in sorted(os.listdir(folder)):
            if name.endswith((".h", ".cxx")):
                if name in files:
                    problems.append("%s is in %s and %s" % (name, files[name][0], library))
                files[name] = (library, os.path.join(folder, name))
    return files, problems


def includes_of(path, files):
    with open(path, encoding="utf-8") as f:
        return [name for name in INCLUDE.findall(f.read()) if name in files]


def component_of(name, files, first_include):
    stem = name.rsplit(".", 1)[0]
    if name.endswith(".h") and stem.endswith("Internals") and stem[:-len("Internals")] + ".h" in files:
        return stem[:-len("Internals")]
    if name.endswith(".cxx") and stem + ".h" not in files and first_include.get(name):
        return component_of(first_include[name], files, first_include)
    return stem


def find_cycle(graph):
    """One cycle of the graph as a list of nodes, or None (iterative DFS)."""
    state = {}
    for start in sorted(graph):
        if start in state:
            continue
        stack = [(start, iter(sorted(graph[start])))]
        path = [start]
        state[start] = "open"
        while stack:
            node, edges = stack[-1]
            advanced = False
            for nxt in edges:
                if state.get(nxt) == "open":
                    return path[path.index(nxt):] + [nxt]
                if nxt not in state:
                    state[nxt] = "open"
                    stack.append((nxt, iter(sorted(graph.get(nxt, ())))))
                    path.append(nxt)
                    advanced = True
                    break
            if not advanced:
                state[node] = "done"
                stack.pop()
                path.pop()
    return None


def main(source_dir, graph_file):
    layers = layers_of(ModuleGraph(graph_file))
    files, problems = library_files(source_dir, layers)
    included = {name: includes_of(path, files) for name, (_, path) in files.items()}

    # 1. Layers.
    for name, targets in sorted(included.items()):
        library = files[name][0]
        for target in targets:
            other = files[target][0]
            if other != library and other not in layers[library]:
                problems.append("%s (%s) includes %s (%s): %s does not depend on it in CMake"
                                % (name, library, target, other, library))

    # 2. Components.
    first_include = {name: (targets[0] if targets else None) for name, targets in included.items()}
    graph = {}
    for name, targets in included.items():
        here = component_of(name, files, first_include)
        graph.setdefault(here, set())
        for target in targets:
            there = component_of(target, files, first_include)
            if there != here:
                graph[here].add(there)
    while True:
        cycle = find_cycle(graph)
        if not cycle:
            break
        problems.append("include cycle between components: " + " -> ".join(cycle))
        graph[cycle[0]].discard(cycle[1])  # report each cycle once, then look for more

    print("%d files, %d components, %d libraries checked" % (len(files), len(graph), len(layers)))
    for p in problems:
        print("FAIL: " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
