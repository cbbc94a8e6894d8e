#!/usr/bin/env python3
"""Build the self-contained GPU bundle (.gpubundle/bundle.tar.xz).

Run on the Debian 12 build machine, from the repo root:
    python3 .gpubundle/build_bundle.py [--stage DIR]

Contents of the tarball (top folder b/):
  bin/    the benchmarks, test binaries, Xvfb, xkbcomp, glxinfo, eglinfo
  lib/    every shared library they need (Riemann, VTK, Embree, TBB, OIIO, X
          client libraries, Mesa's swrast_dri + libglapi for Xvfb's GLX), except
          glibc's core and the GL dispatch libraries (libGL, libGLX, libOpenGL,
          libGLdispatch, libEGL: they come from .gl/*.deb on the device);
          big libraries never called in these runs are STUBS: same SONAME, same
          dynamic symbols and versions, each function prints its name and traps
  dri/    swrast_dri.so (Xvfb's GLX provider: LIBGL_DRIVERS_PATH)
  xkb/    the XKB data for xkbcomp
  MANIFEST.txt  what is real and what is a stub
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tarfile

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
MULTIARCH = "/usr/lib/x86_64-linux-gnu"

ROOT_BINARIES = [
    f"{REPO}/build/bin/RiemannGpuPathsBenchmark",
    f"{REPO}/build/bin/RiemannSampledFrameBenchmark",
    f"{REPO}/build/bin/RiemannMeshFrameBenchmark",
    f"{REPO}/build/bin/RiemannRayTraceBenchmark",
    f"{REPO}/build/bin/RiemannCpuRayTraceBenchmark",
    f"{REPO}/build/bin/RiemannRenderingOpenGLTests",
    f"{REPO}/build/bin/RiemannRenderingCPUTests",
    "/usr/bin/Xvfb",
    "/usr/bin/xkbcomp",
]
# From Debian 12's mesa-utils-bin (apt-get download; extracted in --debs).
EXTRA_BINARIES = ["glxinfo.x86_64-linux-gnu", "eglinfo.x86_64-linux-gnu"]
# Loaded with dlopen, not in any DT_NEEDED.
DLOPENED = [
    f"{MULTIARCH}/dri/swrast_dri.so",  # Xvfb's GLX (kept in dri/)
    f"{MULTIARCH}/libGLX_mesa.so.0",  # Mesa's GLX vendor library (fallback/diagnostics)
    f"{MULTIARCH}/libtbbmalloc.so.2",  # TBB's allocator
]

# Provided by the device: glibc's core and the glvnd dispatch libraries (.gl debs).
EXCLUDE = {
    "libc.so.6", "libm.so.6", "libpthread.so.0", "libdl.so.2", "librt.so.1",
    "libresolv.so.2", "ld-linux-x86-64.so.2", "libutil.so.1", "libanl.so.1",
    "libmvec.so.1", "libnsl.so.1", "libBrokenLocale.so.1",
    "libGL.so.1", "libGLX.so.0", "libGLdispatch.so.0", "libOpenGL.so.0", "libEGL.so.1",
    "libGLESv2.so.2", "libGLESv1_CM.so.1",
}

# Never called in these runs: stubbed (their own dependencies then drop out).
STUB = [
    "libLLVM-15.so.1",  # swrast_dri's llvmpipe; Xvfb's GLX runs softpipe (GALLIUM_DRIVER)
    "libopenvdb.so.10.0",
    "libavcodec.so.59", "libavformat.so.59", "libavutil.so.57", "libswscale.so.6",
    "libopencv_core.so.406", "libopencv_imgproc.so.406", "libopencv_videoio.so.406",
    # DCMTK stays real (OIIO's static initialisers call it); its XML half is stubbed
    "libxml2.so.2",
    # libraw_r stays real: OIIO asks its version when it lists the plugins
    "libheif.so.1",
    "libOpenColorIO.so.2.1",
]


# Stubs whose functions print their name and return 0 (NULL) instead of trapping:
# OIIO's plugin constructors call them while it lists its formats.
RETURN_ZERO = {"libheif.so.1", "libLLVM-15.so.1"}


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, capture_output=True, text=True, **kw).stdout


def soname_map():
    """soname -> path, from the host's ld.so cache (x86-64 entries)."""
    table = {}
    for line in run(["ldconfig", "-p"]).splitlines()[1:]:
        m = re.match(r"\s*(\S+) \(([^)]*)\) => (\S+)", line)
        if m and "x86-64" in m.group(2) and m.group(1) not in table:
            table[m.group(1)] = m.group(3)
    for name in os.listdir(f"{REPO}/build/lib"):
        table.setdefault(name, f"{REPO}/build/lib/{name}")
    return table


def needed(path):
    out = run(["readelf", "-dW", path])
    return re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", out)


def soname_of(path):
    m = re.search(r"\(SONAME\)\s+Library soname: \[([^\]]+)\]", run(["readelf", "-dW", path]))
    return m.group(1) if m else os.path.basename(path)


def undefined_symbols(path):
    """Names of the dynamic symbols `path` needs from other objects."""
    names = set()
    for line in run(["readelf", "--dyn-syms", "-W", path]).splitlines():
        f = line.split()
        if len(f) >= 8 and f[0].endswith(":") and f[6] == "UND":
            names.add(f[7].split("@")[0])
    return names


def dynamic_symbols(path):
    """Defined dynamic symbols: (name, version, default, type, bind, size)."""
    syms = []
    for line in run(["readelf", "--dyn-syms", "-W", path]).splitlines():
        f = line.split()
        if len(f) < 8 or not f[0].endswith(":") or not f[0][:-1].isdigit():
            continue
        _, value, size, typ, bind, _vis, ndx, full = f[:8]
        if ndx == "UND" or bind == "LOCAL":
            continue
        if "@@" in full:
            name, ver = full.split("@@", 1)
            default = True
        elif "@" in full:
            name, ver = full.split("@", 1)
            default = False
        else:
            name, ver, default = full, None, True
        # readelf may append " (N)" version indices in some versions
        ver = ver.split(" ")[0] if ver else None
        if ndx == "ABS" and ((ver and name == ver) or (size == "0" and re.match(r"^[A-Z][A-Za-z0-9_.]*_[0-9.]+$", name))):
            continue  # version definition marker (LLVM_15, LIBAVUTIL_57...)
        if name in ("_end", "_edata", "__bss_start", "_init", "_fini"):
            continue
        syms.append((name, ver, default, typ, bind, int(size, 0)))
    return syms


def version_definitions(path):
    out = run(["readelf", "-VW", path])
    vers = []
    sec = re.search(r"Version definition section.*?(?=\n\S|\Z)", out, re.S)
    if sec:
        for m in re.finditer(r"Flags: (\S+)\s+Index: \d+\s+Cnt: \d+\s+Name: (\S+)", sec.group(0)):
            if m.group(1) != "BASE":
                vers.append(m.group(2))
    return vers


def make_stub(real, soname, outdir, provided, wanted):
    """A library with `soname` exporting `real`'s symbols: functions trap, data is zeros."""
    syms = dynamic_symbols(real)
    versions = version_definitions(real)
    asm = [
        "\t.section .note.GNU-stack,\"\",@progbits",
        "\t.text",
        "\t.p2align 4",
        "\t.type __riemann_stub_trap,@function",
        # rdi = message, rsi = length: write(2, ...), then ud2 (or return 0)
        "__riemann_stub_trap:",
        "\tmov %rsi, %rdx",
        "\tmov %rdi, %rsi",
        "\tmov $2, %edi",
        "\tmov $1, %eax",
        "\tsyscall",
    ] + (["\txor %eax, %eax", "\txor %edx, %edx", "\tret"] if soname in RETURN_ZERO
         else ["\tud2"])
    data, strings, kept, skipped = [], [], 0, 0
    for i, (name, ver, default, typ, bind, size) in enumerate(syms):
        if name in provided or name not in wanted:
            # a real library defines it too (never export a trap for it), or no
            # library of the bundle asks for it
            skipped += 1
            continue
        kept += 1
        label = name if ver is None else f"__rs_{i}"
        lines = []
        if ver is not None:
            lines.append(f"\t.symver {label}, {name}{'@@' if default else '@'}{ver}")
        glob = ".weak" if bind == "WEAK" else ".globl"
        if typ in ("FUNC", "IFUNC", "NOTYPE") and not (typ == "NOTYPE" and size > 0):
            what = "RETURNS 0" if soname in RETURN_ZERO else "CALLED"
            msg = f"RIEMANN STUB {what}: {soname} {name[:160]}\\n"
            mlen = len(msg) - 1  # "\\n" is one byte
            lines += [f"\t{glob} {label}", f"\t.type {label},@function", f"{label}:",
                      f"\tlea .Lrs_msg{i}(%rip), %rdi", f"\tmov ${mlen}, %esi",
                      "\tjmp __riemann_stub_trap", f"\t.size {label}, .-{label}"]
            asm += lines
            strings.append(f".Lrs_msg{i}:\n\t.ascii \"{msg}\"")
        elif typ == "TLS":
            lines += ["\t.section .tbss,\"awT\",@nobits", "\t.p2align 4", f"\t{glob} {label}",
                      f"\t.type {label},@tls_object", f"\t.size {label}, {size}",
                      f"{label}:", f"\t.zero {max(size, 1)}", "\t.bss"]
            data += lines
        else:  # OBJECT, COMMON, NOTYPE with a size, GNU_UNIQUE objects
            lines += ["\t.p2align 5", f"\t{glob} {label}", f"\t.type {label},@object",
                      f"\t.size {label}, {size}", f"{label}:", f"\t.zero {max(size, 1)}"]
            data += lines
    body = "\n".join(asm) + "\n\t.section .rodata\n" + "\n".join(strings) + \
        "\n\t.bss\n" + "\n".join(data) + "\n"
    base = os.path.join(outdir, "stubsrc", soname)
    os.makedirs(os.path.dirname(base), exist_ok=True)
    with open(base + ".s", "w") as f:
        f.write(body)
    with open(base + ".map", "w") as f:
        if versions:
            for n, v in enumerate(versions):
                f.write(f"{v} {{\n" + ("  local: __rs_*;\n" if n == 0 else "") + "};\n")
        else:
            f.write("{ local: __rs_*; };\n")
    out = os.path.join(outdir, "lib", soname)
    subprocess.run(["gcc", "-shared", "-nostdlib", "-o", out, base + ".s",
                    f"-Wl,-soname,{soname}", f"-Wl,--version-script={base}.map",
                    "-Wl,-z,noexecstack", "-Wl,--hash-style=both", "-Wl,-s"], check=True)
    return kept, skipped, len(versions)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--stage", default="/tmp/gb/stage")
    ap.add_argument("--debs", default="/tmp/debs/x", help="extracted mesa-utils(-bin) debs")
    ap.add_argument("--out", default=f"{REPO}/.gpubundle/bundle.tar.xz")
    ap.add_argument("--no-tar", action="store_true", help="stage only")
    args = ap.parse_args()
    stage = os.path.join(args.stage, "b")
    shutil.rmtree(args.stage, ignore_errors=True)
    for d in ("bin", "lib", "dri"):
        os.makedirs(os.path.join(stage, d))
    table = soname_map()

    roots = list(ROOT_BINARIES) + [os.path.join(args.debs, "usr/bin", b) for b in EXTRA_BINARIES]
    real = {}  # soname -> path, copied as is
    stubs = {}  # soname -> real path it imitates
    queue = list(roots) + list(DLOPENED)
    seen = set()
    while queue:
        path = queue.pop()
        if path in seen:
            continue
        seen.add(path)
        for name in needed(path):
            if name in EXCLUDE or name in real or name in stubs:
                continue
            if name not in table:
                sys.exit(f"cannot resolve {name} (needed by {path})")
            if name in STUB:
                stubs[name] = table[name]
            else:
                real[name] = table[name]
                queue.append(table[name])
    for path in DLOPENED:
        if not path.endswith("_dri.so"):
            real[soname_of(path)] = path

    # Copy binaries and real libraries.
    for b in roots:
        name = os.path.basename(b).replace(".x86_64-linux-gnu", "")
        shutil.copy2(b, os.path.join(stage, "bin", name))
    shutil.copy2(DLOPENED[0], os.path.join(stage, "dri", "swrast_dri.so"))
    for name, path in sorted(real.items()):
        shutil.copy2(os.path.realpath(path), os.path.join(stage, "lib", name))
    # Symbols the real libraries (and glibc) define: never stubbed over.
    provided = set()
    glibc = [table[n] for n in ("libc.so.6", "libm.so.6") if n in table]
    for path in list(real.values()) + glibc:
        provided.update(s[0] for s in dynamic_symbols(path))
    wanted = set()  # every symbol some binary or real library of the bundle needs
    for path in list(real.values()) + roots + [DLOPENED[0]]:
        wanted |= undefined_symbols(path)
    manifest = []
    for name, path in sorted(stubs.items()):
        kept, skipped, nver = make_stub(path, name, stage, provided, wanted)
        manifest.append(f"STUB {name} (of {os.path.realpath(path)}, "
                        f"{os.path.getsize(os.path.realpath(path))} bytes): {kept} symbols "
                        f"exported as traps or zeros, {skipped} left out (defined by a real "
                        f"library or asked for by none), {nver} versions")
    shutil.rmtree(os.path.join(stage, "stubsrc"))
    for name, path in sorted(real.items()):
        manifest.append(f"REAL {name} ({os.path.realpath(path)}, "
                        f"{os.path.getsize(os.path.realpath(path))} bytes)")
    for path in roots:
        manifest.append(f"BIN {os.path.basename(path)} ({path})")
    with open(os.path.join(stage, "MANIFEST.txt"), "w") as f:
        f.write("\n".join(manifest) + "\n")
    shutil.copytree("/usr/share/X11/xkb", os.path.join(stage, "xkb"), symlinks=True)
    # strip debug info where any
    for d in ("bin", "lib", "dri"):
        for n in os.listdir(os.path.join(stage, d)):
            subprocess.run(["strip", "--strip-unneeded", os.path.join(stage, d, n)],
                           capture_output=True)

    print(f"{len(real)} real libraries, {len(stubs)} stubs")
    total = sum(os.path.getsize(os.path.join(r, f)) for r, _, fs in os.walk(stage) for f in fs
                if not os.path.islink(os.path.join(r, f)))
    print(f"staged {total / 2**20:.1f} MiB in {stage}")
    if args.no_tar:
        return
    tar = args.out[:-3]
    subprocess.run(["tar", "-C", args.stage, "--owner=0", "--group=0", "-cf", tar, "b"], check=True)
    subprocess.run(["xz", "-9e", "-T1", "-f", tar], check=True)
    print(f"{args.out}: {os.path.getsize(args.out) / 2**20:.1f} MiB")


if __name__ == "__main__":
    main()
