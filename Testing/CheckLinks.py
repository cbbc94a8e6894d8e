"""Each third-party library is linked only where its folder says (issue 29).

Reads the direct dependencies (DT_NEEDED, `readelf -d`) of every
libRiemann*.so in the build and checks them against the table below: the
layer rules of Documentation/Architecture.md as sonames. A library may need
only the third-party libraries and Riemann libraries listed for it (VTK's
own libvtk*, the C and C++ runtimes and zlib-like system pieces are checked
apart: none in the VTK-free base layer).

KNOWN lists what is linked today against the intended layering, with why:
the test reports them, and fails on anything else (a new violation), and on
a known one that went away (so that the table is kept true).

Usage: CheckLinks.py BUILD_LIB_DIR
"""
import os
import re
import subprocess
import sys

# Libraries every Riemann library may need.
RUNTIME = re.compile(r"^(libstdc\+\+|libm|libc|libgcc_s|ld-linux-x86-64|libpthread|libdl)\.so")
VTK = re.compile(r"^libvtk")

# Riemann library -> (third-party soname prefixes, Riemann libraries, may it need VTK)
CORE = ["RiemannCommonSettings", "RiemannCommonMetricFormat", "RiemannCommonExpressions", "RiemannCommonJacobi",
        "RiemannCommonDistance", "RiemannCommonMetric", "RiemannCommonPackets"]
ALLOWED = {
    # The VTK-free core, bottom up: the packet engine (Highway), the metric
    # core (nothing but the engine), typed expressions (GiNaC; Highway for
    # their packet interpreter), Jacobi fields, distance fields, the JSON
    # metric format.
    "RiemannCommonSettings": ([], [], False),
    "RiemannCommonPackets": (["libhwy"], [], False),
    "RiemannCommonMetric": ([], ["RiemannCommonPackets", "RiemannCommonSettings"], False),
    "RiemannCommonExpressions": (["libginac", "libcln", "libhwy"],
                                 ["RiemannCommonMetric", "RiemannCommonPackets", "RiemannCommonSettings"], False),
    "RiemannCommonJacobi": ([], ["RiemannCommonMetric", "RiemannCommonPackets", "RiemannCommonSettings"], False),
    "RiemannCommonDistance": ([], ["RiemannCommonMetric", "RiemannCommonPackets", "RiemannCommonSettings"], False),
    "RiemannCommonMetricFormat": ([], ["RiemannCommonExpressions", "RiemannCommonMetric",
                                       "RiemannCommonPackets", "RiemannCommonSettings"], False),
    "RiemannRenderingCore": ([], CORE, False),
    "RiemannRenderingMeshes": (["libembree3"], ["RiemannRenderingCore"] + CORE, False),
    "RiemannRenderingImageIO": (["libOpenImageIO", "libOpenImageIO_Util"],
                                ["RiemannRenderingCore"] + CORE, False),
    "RiemannCommonCore": (["libz"], CORE, True),
    "RiemannFiltersGeodesics": (["libtbb"], ["RiemannCommonCore"] + CORE, True),
    "RiemannFiltersFields": (["libtbb"], ["RiemannCommonCore"] + CORE, True),
    "RiemannRenderingScene": ([], ["RiemannCommonCore", "RiemannRenderingCore"] + CORE, True),
    "RiemannRenderingCPU": (["libtbb"],
                            ["RiemannRenderingScene", "RiemannRenderingImageIO",
                             "RiemannRenderingMeshes", "RiemannCommonCore", "RiemannRenderingCore"] + CORE,
                            True),
    "RiemannFiltersRays": (["libtbb"],
                           ["RiemannFiltersGeodesics", "RiemannRenderingScene", "RiemannRenderingMeshes",
                            "RiemannCommonCore", "RiemannRenderingCore"] + CORE, True),
    "RiemannRenderingOpenGL": (["libGLEW"],
                               ["RiemannRenderingImageIO", "RiemannRenderingMeshes", "RiemannRenderingScene",
                                "RiemannRenderingCore", "RiemannCommonCore"] + CORE, True),
}

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


def main(folder):
    problems, seen_known, checked = [], set(), 0
    for name in sorted(os.listdir(folder)):
        m = re.match(r"^lib(Riemann\w+)\.so$", name)
        if not m:
            continue
        library = m.group(1)
        if library not in ALLOWED:
            problems.append("%s: not in CheckLinks.py's table (add its rule)" % library)
            continue
        third_party, riemann, vtk = ALLOWED[library]
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
    sys.exit(main(sys.argv[1]))
