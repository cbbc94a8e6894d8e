"""Each third-party library is linked only where its folder says (issue 29).

Reads the direct dependencies (DT_NEEDED, `readelf -d`) of every
libRiemann*.so in the build and checks them: a library may need only the
Riemann libraries CMake declares it depends on (RiemannModuleGraph.json,
directly or through others), VTK only if it is a VTK module, and only the
third-party libraries listed for it below (VTK's
own libvtk*, the C and C++ runtimes and zlib-like system pieces are checked
apart: none in the VTK-free base layer).

KNOWN lists what is linked today against the intended layering, with why:
the test reports them, and fails on anything else (a new violation), and on
a known one that went away (so that the table is kept true).

Usage: CheckLinks.py BUILD_LIB_DIR MODULE_GRAPH_JSON
"""
import os
import re
import subprocess
import sys

# Libraries every Riemann library may need.
RUNTIME = re.compile(r"^(libstdc\+\+|libm|libc|libgcc_s|ld-linux-x86-64|libpthread|libdl)\.so")
VTK = re.compile(r"^libvtk")

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ModuleGraph import ModuleGraph  # noqa: E402

# Riemann library -> the soname prefixes of the third-party libraries it may
# need. Which Riemann libraries each may need, and whether VTK, is not
# written here: it is CMake's declaration (RiemannModuleGraph.json). This
# table is about what the linker brings for the third-party targets (the
# GiNaC target needs libcln; VTK's SMP backend brings libtbb): Embree only
# in Rendering/Meshes, OpenImageIO only in Rendering/ImageIO, Highway only in
# Common/Packets, Common/Metric (the families' kernels) and Common/Expressions,
# GiNaC only in Common/Expressions.
THIRD_PARTY = {
    "RiemannCommonSettings": [],
    "RiemannCommonPackets": ["libhwy"],
    "RiemannCommonGlsl": [],
    "RiemannCommonMetric": ["libhwy"],
    "RiemannCommonExpressions": ["libginac", "libcln", "libhwy"],
    "RiemannCommonJacobi": [],
    "RiemannCommonDistance": [],
    "RiemannCommonTractography": [],
    "RiemannCommonMetricFormat": [],
    "RiemannCommonObserver": [],
    "RiemannRenderingCore": [],
    "RiemannRenderingMeshes": ["libembree3"],
    "RiemannRenderingImageIO": ["libOpenImageIO", "libOpenImageIO_Util"],
    "RiemannCommonCore": [],
    # libtbb: the tracts of a trace are joined in parallel (vtkSMPTools).
    "RiemannIOMedical": ["libz", "libtbb"],
    "RiemannIOFilm": [],
    "RiemannFiltersGeodesics": ["libtbb"],
    "RiemannFiltersFields": ["libtbb"],
    "RiemannRenderingScene": [],
    "RiemannRenderingCPU": ["libtbb"],
    "RiemannFiltersRays": ["libtbb"],
    "RiemannRenderingOpenGL": ["libGLEW"],
}


def allowed_of(graph):
    """Riemann library file name -> (third-party prefixes, Riemann libraries, may it need VTK)."""
    allowed = {}
    for name in graph.names():
        library = graph.file_name(name)
        allowed[library] = (THIRD_PARTY.get(library),
                            sorted(graph.file_name(other) for other in graph.closure(name)),
                            graph.libraries[name]["kind"] == "vtk-module")
    return allowed


# Linked today against the layering above: (library, dependency) -> why.
KNOWN = {
    # None since the meshes' hierarchy moved to Rendering/Meshes: the GPU
    # module had linked the CPU tracer's module for it, which brought Embree's
    # ray queries and the geodesic filters in.
}


def needed(path):
    out = subprocess.run(["readelf", "-d", path], capture_output=True, text=True, check=True).stdout
    return re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", out)


def riemann_name(soname):
    m = re.match(r"^lib(Riemann\w+)\.so", soname)
    return m.group(1) if m else None


def main(folder, graph_file):
    problems, seen_known, checked = [], set(), 0
    ALLOWED = allowed_of(ModuleGraph(graph_file))
    for name in sorted(os.listdir(folder)):
        m = re.match(r"^lib(Riemann\w+)\.so$", name)
        if not m:
            continue
        library = m.group(1)
        if library not in ALLOWED:
            problems.append("%s: not in the module graph CMake wrote" % library)
            continue
        third_party, riemann, vtk = ALLOWED[library]
        if third_party is None:
            problems.append("%s: not in CheckLinks.py's THIRD_PARTY table (add its rule)" % library)
            continue
        checked += 1
        for dependency in needed(os.path.join(folder, name)):
            other = riemann_name(dependency)
            if RUNTIME.match(dependency):
                continue
            if other:
                if other in riemann:
                    continue
                if (library, other) in KNOWN:
                    seen_known.add((library, other))
                    continue
                problems.append("%s links %s: not a dependency its layer allows" % (library, other))
            elif VTK.match(dependency):
                if not vtk:
                    problems.append("%s links VTK (%s): it is in the VTK-free base layer" % (library, dependency))
            elif not any(re.match(re.escape(prefix) + r"[._\-0-9]", dependency) for prefix in third_party):
                problems.append("%s links %s: not among its third-party libraries %s"
                                % (library, dependency, third_party or "(none)"))
    for key, why in KNOWN.items():
        if key in seen_known:
            print("known: %s links %s: %s" % (key[0], key[1], why))
        else:
            problems.append("%s no longer links %s: remove it from KNOWN" % key)
    print("%d libraries checked" % checked)
    for p in problems:
        print("FAIL: " + p)
    if checked == 0:
        print("FAIL: no libRiemann*.so in " + folder)
        return 1
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
