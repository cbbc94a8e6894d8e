#!/usr/bin/env bash
# RiemannVTK: one entry point on Debian 12.
#
#   ./run.sh [ARGS...]        build, then run the demo (Examples/demo.py ARGS)
#   ./run.sh demo [ARGS...]   same
#   ./run.sh test [ARGS...]   build, then run all tests but the fuzzers (extra ARGS
#                             go to ctest, e.g. ./run.sh test -R '^Python\.' -V)
#   ./run.sh bench [ARGS...]  build, then run build/bin/RiemannBenchmarks
#                             (ARGS go to google-benchmark, e.g. --benchmark_filter=Gauss)
#   ./run.sh build            install missing packages, configure, build; nothing else
#   ./run.sh sanitize [ARGS...]  Clang build with AddressSanitizer (+ LeakSanitizer)
#                             and UndefinedBehaviorSanitizer in build-asan/ (no Python
#                             wrapping, no benchmarks), then the C++ and CLI tests
#                             (ctest -L Cxx, then -L Cli; extra ARGS go to both,
#                             e.g. -V). Any sanitizer report fails it; reports:
#                             build-asan/sanitizer-logs/ (Testing/Fuzz/README.md)
#   ./run.sh fuzz [ARGS...]   build, then the libFuzzer targets (Clang, ASan, UBSan)
#                             in build/fuzz, then fuzz each for 20 s (ctest -L Fuzz;
#                             extra ARGS go to ctest). Not part of `test`: a tree of
#                             its own, with its own time (Testing/Fuzz/README.md)
#
# Each run installs missing Debian packages (only when something is missing),
# configures build/ once (Ninja) and builds incrementally, so a re-run with
# nothing changed takes a second or two.
# Environment: RIEMANN_CMAKE_ARGS  extra arguments for the first configure.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
BUILD_DIR="$ROOT/build"
# Debian's VTK Python bindings exist for this interpreter only (a pyenv or
# conda `python3` earlier on PATH has no vtkmodules).
PYTHON=/usr/bin/python3
# Where vtk_module_wrap_python puts the `riemann` package in the build tree
# (RIEMANN_PYTHON_DESTINATION in CMakeLists.txt).
PYTHONPATH_BUILD="$BUILD_DIR/lib/python3/dist-packages"
# -noreset: Xvfb otherwise resets when its last client disconnects and
# refuses connections meanwhile, failing a test that opens a second window.
XVFB=(xvfb-run -a -s "-screen 0 1280x1024x24 -noreset")
# ccache (when installed; step 1 installs it) for the three builds: GCC, the
# sanitizer build and the fuzzer build (./run.sh fuzz). Paths under the
# checkout are hashed relative to it and the build folder is not hashed, so
# a fresh clone elsewhere (what CI builds) reuses the library objects of an
# earlier build of the same sources. The test executables are compiled again:
# their RIEMANN_TEST_DATA_DIR define holds the checkout's absolute path.
export CCACHE_BASEDIR="$ROOT" CCACHE_NOHASHDIR=1

PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libvtk9-dev python3-vtk9 vtk9
  # Named although libvtk9-dev brings them: the Theora and Ogg headers
  # (riemann-film-frames reads films back) and Python's embedding library
  # (riemann-studio's Python shell).
  libtheora-dev libogg-dev libpython3-dev
  libeigen3-dev libembree-dev libopenimageio-dev openimageio-tools libginac-dev
  libcli11-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev libhwy-dev
  python3-numpy xvfb xauth libgl1-mesa-dri
  clang libclang-rt-14-dev glslang-tools
  qtbase5-dev libqt5opengl5-dev libvtk9-qt-dev
  openmpi-bin libopenmpi-dev python3-mpi4py
  ccache
  # SciPy: the comparisons of Testing/Benchmarks (between_points_vs_scipy.py,
  # trace_vs_scipy.py); no test needs it.
  python3-scipy
  # DIPY and nibabel: the tractography interop tests (nibabel reads our .trk
  # and .tck) and the DIPY comparison (Examples/tractography_dipy.py,
  # Testing/Benchmarks); never needed by the library.
  python3-dipy python3-nibabel
  # MRtrix3: tckgen and dwi2tensor for Testing/Benchmarks/tractography_vs_mrtrix.py
  # (the benchmark only; no test or library needs it).
  mrtrix3
  # ParaView 5.11 and what its plugin build needs (the plugin RiemannVTK,
  # ParaView/). Installed without recommends: python3-paraview, recommended,
  # conflicts with python3-vtk9 (its hierarchy files are unpacked instead,
  # unpack_paraview_hierarchy).
  paraview paraview-dev libqt5svg5-dev qtxmlpatterns5-dev-tools
)
# Where python3-paraview's wrapping hierarchy files are unpacked (the
# plugin's client-server wrapping reads them; RIEMANN_PARAVIEW_DEB_DIR).
PARAVIEW_DEB_DIR="$BUILD_DIR/paraview-deb"
PARAVIEW_HIERARCHY="usr/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView"

log() { printf '[run.sh] %s\n' "$*" >&2; }
die() { printf '[run.sh] error: %s\n' "$*" >&2; exit 1; }

usage() {
  sed -n '2,27s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"
}

# --- 1. Debian packages: install only what is missing ------------------------
install_packages() {
  local installed missing=() pkg
  # One dpkg-query for all packages (fast); unknown names just are not listed.
  installed="$(dpkg-query -W -f='${Package} ${db:Status-Status}\n' "${PACKAGES[@]}" 2>/dev/null \
    | awk '$2 == "installed" { print $1 }' || true)"
  for pkg in "${PACKAGES[@]}"; do
    grep -qxF "$pkg" <<<"$installed" || missing+=("$pkg")
  done
  if ((${#missing[@]} == 0)); then
    log "packages: all ${#PACKAGES[@]} present"
    return
  fi

  log "packages: installing ${#missing[@]} missing: ${missing[*]}"
  local sudo=()
  if ((EUID != 0)); then
    command -v sudo >/dev/null || die "not root and no sudo: install ${missing[*]} first"
    sudo=(sudo)
  fi
  "${sudo[@]}" apt-get update
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${missing[@]}"
}

# --- 1b. python3-paraview's hierarchy files, unpacked, never installed -------
unpack_paraview_hierarchy() {
  [[ -d "$PARAVIEW_DEB_DIR/$PARAVIEW_HIERARCHY" ]] && return
  local deb scratch
  # A copy apt already has, or one downloaded (from Debian's archive) into a
  # scratch folder: apt-get download writes into the working directory.
  deb="$(ls /var/cache/apt/archives/python3-paraview_5.11*.deb 2>/dev/null | head -n 1 || true)"
  scratch="$(mktemp -d)"
  # apt downloads as its sandbox user _apt, who must be able to write there.
  chmod a+rwx "$scratch"
  if [[ -z "$deb" ]]; then
    log "paraview: downloading python3-paraview (its hierarchy files only are unpacked)"
    (cd "$scratch" && apt-get download python3-paraview >/dev/null) \
      || { apt-get update >/dev/null && (cd "$scratch" && apt-get download python3-paraview >/dev/null); } \
      || die "apt-get download python3-paraview failed (the ParaView plugin needs its hierarchy files)"
    deb="$(ls "$scratch"/python3-paraview_*.deb | head -n 1)"
  fi
  mkdir -p "$PARAVIEW_DEB_DIR"
  dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$PARAVIEW_DEB_DIR" "./$PARAVIEW_HIERARCHY"
  rm -rf "$scratch"
  log "paraview: $(ls "$PARAVIEW_DEB_DIR/$PARAVIEW_HIERARCHY" | wc -l) hierarchy files in $PARAVIEW_DEB_DIR"
}

# --- 2. Configure once, build incrementally ----------------------------------
build() {
  if [[ ! -f "$BUILD_DIR/build.ninja" ]]; then
    log "configure: $BUILD_DIR (Ninja, Release)"
    local launcher=()
    if command -v ccache >/dev/null; then
      launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    fi
    # Word splitting of RIEMANN_CMAKE_ARGS is intended (several -D options).
    # shellcheck disable=SC2086
    cmake -S "$ROOT" -B "$BUILD_DIR" -G Ninja \
      -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
      -DPython3_EXECUTABLE="$PYTHON" \
      ${RIEMANN_CMAKE_ARGS:-}
  fi
  # Ninja re-runs CMake by itself when a CMakeLists.txt or a globbed test
  # folder changed, and does nothing when nothing changed.
  log "build: cmake --build build"
  cmake --build "$BUILD_DIR"
}

# --- 3. Modes ----------------------------------------------------------------
run_demo() {
  local demo="$ROOT/Examples/demo.py"
  [[ -f "$demo" ]] || die "no $demo yet"
  log "demo: $demo --output-dir demo-output $*"
  cd "$ROOT"
  "${XVFB[@]}" env \
    PYTHONPATH="$PYTHONPATH_BUILD${PYTHONPATH:+:$PYTHONPATH}" \
    RIEMANN_DATA_DIR="$ROOT/Data" \
    PATH="$BUILD_DIR/bin:$PATH" \
    "$PYTHON" "$demo" --output-dir demo-output "$@"
  log "demo: done, see $ROOT/demo-output"
}

run_tests() {
  # The fuzzers are a mode of their own (run_fuzz): label Fuzz is left out.
  log "test: ctest --test-dir build --output-on-failure -j2 -LE Fuzz $*"
  "${XVFB[@]}" ctest --test-dir "$BUILD_DIR" --output-on-failure -j2 -LE Fuzz "$@"
}

run_fuzz() {
  log "fuzz: cmake --build build --target RiemannFuzzers (build/fuzz)"
  cmake --build "$BUILD_DIR" --target RiemannFuzzers
  log "fuzz: ctest --test-dir build --output-on-failure -L Fuzz $*"
  ctest --test-dir "$BUILD_DIR" --output-on-failure -L Fuzz "$@"
}

# --- Sanitizer build: Clang, AddressSanitizer + UBSan (cmake/RiemannSanitize.cmake)
ASAN_BUILD_DIR="$ROOT/build-asan"
# LeakSanitizer suppressions for system libraries (Mesa, GiNaC's CLN, ...);
# never for the project's own code.
SANITIZER_SUPPRESSIONS="$ROOT/Testing/Fuzz/lsan.supp"

build_sanitize() {
  if [[ ! -f "$ASAN_BUILD_DIR/build.ninja" ]]; then
    log "configure: $ASAN_BUILD_DIR (Ninja, Clang, -fsanitize=address,undefined)"
    local launcher=()
    if command -v ccache >/dev/null; then
      launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    fi
    # The C++ tests and the riemann CLI only: the Python-wrapped modules cannot
    # be loaded into the uninstrumented /usr/bin/python3, benchmarks are not tests.
    cmake -S "$ROOT" -B "$ASAN_BUILD_DIR" -G Ninja \
      -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" \
      -DPython3_EXECUTABLE="$PYTHON" \
      -DRIEMANN_SANITIZE=ON -DRIEMANN_WRAP_PYTHON=OFF -DRIEMANN_BUILD_BENCHMARKS=OFF -DRIEMANN_BUILD_STUDIO=OFF
  fi
  log "build: cmake --build build-asan"
  cmake --build "$ASAN_BUILD_DIR"
}

run_sanitize_tests() {
  # Reports (ASan, LSan and UBSan alike: log_path is a common option, set
  # once) go to files, report.<pid>, so that a report from a riemann run
  # that was expected to fail (a CLI test of bad input) fails too.
  local logs="$ASAN_BUILD_DIR/sanitizer-logs"
  rm -rf "$logs"
  mkdir -p "$logs"
  local status=0
  # intercept_tls_get_addr=0: the __tls_get_addr interceptor of Clang 14's
  # runtime takes a dynamic TLS block that happens to start 16 bytes past a
  # page boundary for a pre-2.25 glibc block with a header, reads garbage as
  # its bounds, and LeakSanitizer's tracer then dies at exit ("Tracer caught
  # signal 11 ... LeakSanitizer has encountered a fatal error") after a test
  # that passed: a flake that failed CI once on a llvmpipe test. Without the
  # interceptor LSan still scans static TLS and every thread's stack.
  local sanitizer_env=(
    ASAN_OPTIONS="detect_leaks=1:intercept_tls_get_addr=0:log_path=$logs/report"
    LSAN_OPTIONS="suppressions=$SANITIZER_SUPPRESSIONS:print_suppressions=0"
    UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1")
  # Instrumented numerics run ~4-5 times slower than the GCC build. Left out
  # here (they run in the normal build): the two tests that CPU-trace every
  # shipped scene at full size (5 and 1.5 minutes alone), whose code paths
  # the other CPU tracer, mesh and CLI tests cover; and the 10,000-direction
  # round-sphere conjugate locus (15 s here), whose code paths the other
  # conjugate-point tests cover; and the sampled lens rendered on the GPU and
  # the CPU (70 s here), whose sampled-metric paths the SampledTensorField,
  # SampledMetric and texture-upload tests cover. Cli.riemann (its CPU
  # renders have a 60 s limit each) runs last, alone.
  local skip='CPURayTracer\.RendersEveryShippedSceneAsTheGpu|CPURayTracer\.SampledMetricsRenderOnTheGpuAsOnTheCpu|^Image\.mesh-two-bumps-cpu$|CausticSheets\.RoundSphereIsDouble'
  log "sanitize: ctest --test-dir build-asan -L Cxx -E '$skip' $*; then -L Cli"
  "${XVFB[@]}" env "${sanitizer_env[@]}" \
    ctest --test-dir "$ASAN_BUILD_DIR" --output-on-failure -j2 -L Cxx -E "$skip" "$@" \
    || status=$?
  "${XVFB[@]}" env "${sanitizer_env[@]}" \
    ctest --test-dir "$ASAN_BUILD_DIR" --output-on-failure -L Cli "$@" \
    || status=$?
  local report
  for report in "$logs"/*; do
    [[ -e "$report" ]] || continue
    log "sanitizer report: $report"
    cat "$report" >&2
    status=1
  done
  if ((status != 0)); then
    die "sanitize: tests failed or sanitizer reports (see above; logs in $logs)"
  fi
  log "sanitize: no sanitizer reports"
}

run_bench() {
  local bench="$BUILD_DIR/bin/RiemannBenchmarks"
  [[ -x "$bench" ]] || die "no $bench (no Testing/Benchmarks/Bench*.cxx yet, or libbenchmark-dev missing)"
  log "bench: $bench $*"
  "$bench" "$@"
}

mode="demo"
if (($# > 0)); then
  case "$1" in
    demo | test | bench | build | sanitize | fuzz) mode="$1"; shift ;;
    -h | --help | help) usage; exit 0 ;;
    # Anything else (e.g. --width 640) is passed on to the demo.
  esac
fi

install_packages
if [[ "$mode" == sanitize ]]; then
  build_sanitize
  run_sanitize_tests "$@"
  exit 0
fi
unpack_paraview_hierarchy
build
case "$mode" in
  demo) run_demo "$@" ;;
  test) run_tests "$@" ;;
  fuzz) run_fuzz "$@" ;;
  bench) run_bench "$@" ;;
  build) log "build: done" ;;
esac
