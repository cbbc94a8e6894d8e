#!/bin/bash
# RiemannVTK's GPU benchmarks and GPU-vs-CPU tests on a machine with an NVIDIA
# GPU and no X server, VTK or internet: run from the repo root, with .gl/ (the
# glvnd debs) and .gpubundle/ (bundle.tar.xz from build_bundle.py) beside it.
#
#   bash .gpubundle/device.sh          # writes $OUT/gpu.log and friends
#
# Xvfb (from the bundle, its GLX provided by Mesa's softpipe) is the X server;
# the programs' GLX goes through glvnd to the NVIDIA driver
# (__GLX_VENDOR_LIBRARY_NAME=nvidia). Every step has a timeout; the script
# always ends with a summary and exit 0.
#
# For a local test: RIEMANN_GL_VENDOR=mesa RIEMANN_EXTRA_LD_PATH=<dir with a
# real libLLVM> RIEMANN_CLIENT_GALLIUM=llvmpipe RIEMANN_SMALL=1 (64x36 benchmarks, short test filters;
# RIEMANN_SMALL_TESTS=0: whole test binaries all the same). RIEMANN_ONLY=paths:
# the OpenGL tests and the two GPU paths' benchmark, nothing else.
# RIEMANN_ONLY=sampled: the sampled lens's GPU-vs-CPU tests, then that benchmark.
set -u
REPO=$(pwd)
OUT=${OUT:-/tmp/riemann-out}
mkdir -p "$OUT"
B=${RIEMANN_BUNDLE_DIR:-/tmp/rb}/b
VENDOR=${RIEMANN_GL_VENDOR:-nvidia}
SMALL=${RIEMANN_SMALL:-0}
if [ "$SMALL" = 1 ]; then W=64 H=36; else W=1920 H=1080; fi
T0=$(date +%s.%N)
SUMMARY=/tmp/riemann-summary.txt
: >"$SUMMARY"

elapsed() { python3 -c "import time,sys; print('%.1f' % (time.time() - float(sys.argv[1])))" "$1"; }
banner() { echo; echo "=================== [$(elapsed "$T0") s] $*"; }
# Steps start only while RIEMANN_DEADLINE seconds (from the start) are not
# spent, each with a timeout that ends it by then: keep the run's timeout_s above it.
DEADLINE=${RIEMANN_DEADLINE:-540}
# step NAME TIMEOUT COMMAND...: run with a timeout, record rc and seconds
step() {
  local name=$1 limit=$2; shift 2
  local left=$(python3 -c "import time,sys; print(int($DEADLINE - (time.time() - float(sys.argv[1]))))" "$T0")
  if [ "$left" -lt 15 ]; then
    echo "!!! $name SKIPPED: ${left}s left before the deadline"
    echo "$name: SKIPPED (deadline)" >>"$SUMMARY"
    return 1
  fi
  [ "$left" -lt "$limit" ] && limit=$left
  banner "$name (timeout ${limit}s): $*"
  local t=$(date +%s.%N)
  timeout -k 5 "$limit" "$@"
  local rc=$?
  local s=$(elapsed "$t")
  [ $rc = 124 ] || [ $rc = 137 ] && echo "!!! $name TIMED OUT after ${limit}s"
  echo "--- $name: rc=$rc, ${s}s"
  echo "$name: rc=$rc ${s}s" >>"$SUMMARY"
  return $rc
}

diagnostics() {
  banner "DIAGNOSTICS"
  echo "LD_LIBRARY_PATH=$LD_LIBRARY_PATH"
  echo "--- libGLX_nvidia candidates:"; echo "$NVGLX_ALL"
  for d in /usr/local/nvidia /usr/local/nvidia/lib64 /usr/local/nvidia/lib /usr/local/nvidia/share/glvnd/egl_vendor.d; do
    echo "--- ls $d"; ls -la "$d" 2>&1 | head -80
  done
  echo "--- ldconfig -p | grep -i 'GLX\|nvidia\|libGL\|EGL'"
  ldconfig -p | grep -i 'GLX\|nvidia\|libGL\.\|EGL' | head -40
  if [ -n "$NVGLX" ]; then
    echo "--- ldd $NVGLX"; ldd "$NVGLX" 2>&1 | head -30
  fi
  echo "--- glxinfo -B with LD_DEBUG=libs (GLX lines)"
  LD_DEBUG=libs timeout 30 "$B/bin/glxinfo" -B 2>&1 | grep -i 'glx\|nvidia\|error\|cannot' | head -40
  echo "--- server GLX through Mesa softpipe (__GLX_VENDOR_LIBRARY_NAME=mesa)"
  __GLX_VENDOR_LIBRARY_NAME=mesa GALLIUM_DRIVER=softpipe timeout 30 "$B/bin/glxinfo" -B 2>&1 | head -30
  echo "--- eglinfo (NVIDIA EGL, device platform)"
  __EGL_VENDOR_LIBRARY_FILENAMES=${EGLJSON:-} timeout 30 "$B/bin/eglinfo" 2>&1 | grep -i 'vendor\|renderer\|version\|platform\|error' | head -30
  echo "--- Xvfb log"; cat "$OUT/xvfb.log" 2>/dev/null | tail -40
}

main() {
  banner "host"
  uname -a; nproc; free -g 2>/dev/null | head -2; cat /etc/os-release 2>/dev/null | head -2
  ldd --version 2>&1 | head -1

  banner "glvnd loaders (.gl/*.deb) into /"
  for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig

  banner "bundle"
  mkdir -p "$(dirname "$B")"
  if [ ! -x "$B/bin/Xvfb" ]; then
    python3 - "$REPO/.gpubundle/bundle.tar.xz" "$(dirname "$B")" <<'EOF'
import sys, tarfile, time
t = time.time()
with tarfile.open(sys.argv[1]) as tar:
    try:
        tar.extractall(sys.argv[2], filter="tar")
    except TypeError:
        tar.extractall(sys.argv[2])
print("extracted in %.1f s" % (time.time() - t))
EOF
  fi
  grep -c REAL "$B/MANIFEST.txt"; grep STUB "$B/MANIFEST.txt" | cut -c1-60

  # The NVIDIA driver's GLX/EGL libraries.
  NVGLX_ALL=$(find /usr/local/nvidia /usr/lib /usr/lib64 /usr/local/lib /lib -name 'libGLX_nvidia.so*' 2>/dev/null)
  NVGLX=$(echo "$NVGLX_ALL" | grep -m1 'libGLX_nvidia.so.0$' || echo "$NVGLX_ALL" | head -1)
  NVDIR=${NVGLX:+$(dirname "$NVGLX")}
  echo "libGLX_nvidia: ${NVGLX:-NOT FOUND} (all: $(echo $NVGLX_ALL))"
  EGLJSON=$(find /usr/local/nvidia /usr/share/glvnd /etc/glvnd -name '*nvidia*.json' -path '*egl_vendor*' 2>/dev/null | head -1)
  echo "NVIDIA EGL vendor file: ${EGLJSON:-none}"
  local ld="$B/lib"
  [ -n "$NVDIR" ] && ld="$ld:$NVDIR"
  for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib; do
    [ -d "$d" ] && [ "$d" != "$NVDIR" ] && ld="$ld:$d"
  done
  [ -n "${RIEMANN_EXTRA_LD_PATH:-}" ] && ld="$RIEMANN_EXTRA_LD_PATH:$ld"
  export LD_LIBRARY_PATH="$ld${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  echo "LD_LIBRARY_PATH=$LD_LIBRARY_PATH"

  # Paths compiled into the binaries: RUNPATH /work/main/build/lib (LD_LIBRARY_PATH
  # wins) and the tests' fallback Data folder /work/main/Data (RIEMANN_DATA_DIR wins).
  if [ ! -e /work/main ] && [ "$REPO" != /work/main ]; then mkdir -p /work && ln -s "$REPO" /work/main; fi

  banner "Xvfb :99"
  # Xvfb runs xkbcomp from /usr/bin (compiled in).
  if [ ! -x /usr/bin/xkbcomp ]; then ln -sf "$B/bin/xkbcomp" /usr/bin/xkbcomp; echo "linked /usr/bin/xkbcomp"; fi
  mkdir -p /var/lib/xkb /tmp/.X11-unix; chmod 1777 /tmp/.X11-unix
  rm -f /tmp/.X99-lock /tmp/.X11-unix/X99
  # The server's GLX: Mesa's softpipe (libLLVM is a stub in the bundle).
  LD_LIBRARY_PATH="$B/lib" LIBGL_DRIVERS_PATH="$B/dri" GALLIUM_DRIVER=softpipe DRAW_USE_LLVM=0 \
    "$B/bin/Xvfb" :99 -screen 0 1920x1080x24 -noreset -nolisten tcp -fp built-ins \
    -xkbdir "$B/xkb" +extension GLX >"$OUT/xvfb.log" 2>&1 &
  XVFB_PID=$!
  echo $XVFB_PID >/tmp/riemann-xvfb.pid
  for i in $(seq 1 100); do
    [ -S /tmp/.X11-unix/X99 ] && break
    kill -0 $XVFB_PID 2>/dev/null || break
    sleep 0.1
  done
  if ! kill -0 $XVFB_PID 2>/dev/null || [ ! -S /tmp/.X11-unix/X99 ]; then
    echo "!!! Xvfb did not start"; cat "$OUT/xvfb.log"; echo "Xvfb: FAILED" >>"$SUMMARY"
    diagnostics; return
  fi
  echo "Xvfb pid $XVFB_PID up"
  # LIBGL_DRIVERS_PATH: Mesa's swrast, for a Mesa client (local test, diagnostics)
  # GALLIUM_DRIVER: were a program to end up on Mesa after all, softpipe (the
  # bundle's libLLVM is a stub) says so in its renderer string instead of crashing.
  export DISPLAY=:99 __GLX_VENDOR_LIBRARY_NAME=$VENDOR LIBGL_DRIVERS_PATH="$B/dri" \
    GALLIUM_DRIVER=${RIEMANN_CLIENT_GALLIUM:-softpipe}
  [ "$GALLIUM_DRIVER" = softpipe ] && export DRAW_USE_LLVM=0
  [ -n "$EGLJSON" ] && export __EGL_VENDOR_LIBRARY_FILENAMES=$EGLJSON

  banner "nvidia-smi"
  timeout 20 nvidia-smi 2>&1 | head -20

  # (1) GL check: the renderer glxinfo gets through GLX.
  step "glxinfo" 20 "$B/bin/glxinfo" -B 2>&1 | tee /tmp/glxinfo.txt
  local renderer=$(grep -m1 'OpenGL renderer string' /tmp/glxinfo.txt | sed 's/.*: //')
  echo "GL renderer (glxinfo): ${renderer:-NONE}"
  echo "GL renderer: ${renderer:-NONE}" >>"$SUMMARY"
  if [ -z "$renderer" ] || { [ "$VENDOR" = nvidia ] && ! grep -qi nvidia /tmp/glxinfo.txt; }; then
    echo "!!! no NVIDIA GLX renderer"
    diagnostics
    [ "${RIEMANN_FORCE:-0}" = 1 ] || return
  fi

  # OpenImageIO tries every reader on a file its extension's reader rejects (a
  # test's deliberately broken image): not here, where ffmpeg, OpenVDB, libheif
  # and OpenColorIO are stubs.
  export OPENIMAGEIO_OPTIONS=try_all_readers=0
  local data="$REPO/Data"
  local so="stdbuf -oL -eL"
  # RIEMANN_ONLY=paths: issue 28's check alone. The whole OpenGL test binary
  # (fragment against compute on every shipped scene: the compute path must
  # draw the same pictures on this driver), then the two paths' benchmark
  # with all the time left.
  if [ "${RIEMANN_ONLY:-}" = paths ]; then
    export RIEMANN_DATA_DIR="$data" RIEMANN_TEST_OUTPUT_DIR=/tmp/riemann-test-out
    mkdir -p "$RIEMANN_TEST_OUTPUT_DIR"
    (cd "$RIEMANN_TEST_OUTPUT_DIR" &&
      step "RiemannRenderingOpenGLTests (whole)" 90 "$B/bin/RiemannRenderingOpenGLTests" \
        --gtest_output=xml:"$OUT/gtest_opengl.xml" >>"$OUT/tests.log" 2>&1)
    grep -E '^\[ *(FAILED|PASSED) *\]|^\[==========\]' "$OUT/tests.log"
    grep -A6 'Failure' "$OUT/tests.log" | head -60
    step "RiemannGpuPathsBenchmark ${W}x${H}" 600 \
      $so "$B/bin/RiemannGpuPathsBenchmark" --width $W --height $H --repetitions 3 --data "$data"
    return
  fi
  # RIEMANN_ONLY=sampled: the sampled metrics' check. The GPU's pictures of
  # the sampled lens (both readings of "christoffel") against the CPU
  # tracer's, then the two paths' benchmark, whose one-bump grid and sampled
  # lens ("voxels") rows come first and the exact spline's last.
  if [ "${RIEMANN_ONLY:-}" = sampled ]; then
    export RIEMANN_DATA_DIR="$data" RIEMANN_TEST_OUTPUT_DIR=/tmp/riemann-test-out
    mkdir -p "$RIEMANN_TEST_OUTPUT_DIR"
    (cd "$RIEMANN_TEST_OUTPUT_DIR" &&
      step "sampled GPU-vs-CPU tests" 90 "$B/bin/RiemannRenderingCPUTests" \
        --gtest_filter='CPURayTracer.Sampled*' \
        --gtest_output=xml:"$OUT/gtest_sampled.xml" >>"$OUT/tests.log" 2>&1)
    grep -E '^\[ *(OK|FAILED|PASSED) *\]|^sampled lens|^\[==========\]' "$OUT/tests.log"
    grep -A6 'Failure' "$OUT/tests.log" | head -60
    step "RiemannGpuPathsBenchmark ${W}x${H}" 600 \
      $so "$B/bin/RiemannGpuPathsBenchmark" --width $W --height $H --repetitions 3 --data "$data"
    return
  fi
  # (2) issue 28's figures first: the fragment and the compute path side by
  # side at 1080p (ns per ray step, frames/s, the workgroup sizes)
  step "RiemannGpuPathsBenchmark ${W}x${H}" 180 \
    $so "$B/bin/RiemannGpuPathsBenchmark" --width $W --height $H --repetitions 5 --data "$data"
  # then issue 17's: the sampled lens against the analytic one,
  # fewer rays, and the frames while interacting
  step "RiemannSampledFrameBenchmark ${W}x${H}" 150 \
    $so "$B/bin/RiemannSampledFrameBenchmark" --width $W --height $H --repetitions 3 --data "$data"
  # the mesh benchmark: grid and 1M-triangle mesh on the GPU, mesh on the CPU
  step "RiemannMeshFrameBenchmark ${W}x${H}" 150 \
    $so "$B/bin/RiemannMeshFrameBenchmark" --width $W --height $H --data "$data"
  # (3) the ray-trace pass alone (2 scenes x 2 integrators x 100/300/1000 steps),
  # then CPU tracer vs GPU pass on the one-bump grid and the CPU on a mesh
  step "RiemannRayTraceBenchmark ${W}x${H}" 90 \
    $so "$B/bin/RiemannRayTraceBenchmark" --width $W --height $H --repetitions 5 --data "$data"
  step "RiemannCpuRayTraceBenchmark ${W}x${H}" 120 \
    $so "$B/bin/RiemannCpuRayTraceBenchmark" --width $W --height $H --data "$data"

  # (4) tests: GPU-vs-CPU comparisons first (and the two GPU paths), then the whole OpenGL binary, then
  # the rest of the CPU binary. Full gtest output: $OUT/tests.log.
  export RIEMANN_DATA_DIR="$data" RIEMANN_TEST_OUTPUT_DIR=/tmp/riemann-test-out
  rm -rf "$RIEMANN_TEST_OUTPUT_DIR"; mkdir -p "$RIEMANN_TEST_OUTPUT_DIR"
  local compare='CPURayTracer.RendersEveryShippedSceneAsTheGpu:RendererActors.*'
  # RayTracePassPaths.* (fragment vs compute on every shipped scene) runs in
  # the whole OpenGL test binary below.
  local rest="-$compare"
  local ogl=''
  if [ "${RIEMANN_SMALL_TESTS:-$SMALL}" = 1 ]; then
    compare='CPURayTracer.RendersEveryShippedSceneAsTheGpu:RendererActors.GpuDrawsActorsAsTheCpuTracer'
    ogl='--gtest_filter=RayTracePass.EuclideanSphereColours:RayTracePass.EnvironmentImageByDirection'
    rest='--gtest_filter=MeshBVH.*:CPURayTracer.StreamsAndSingleQueriesAgree'
  else
    rest="--gtest_filter=$rest"
  fi
  (cd "$RIEMANN_TEST_OUTPUT_DIR" &&
    step "GPU-vs-CPU tests" 120 "$B/bin/RiemannRenderingCPUTests" --gtest_filter="$compare" \
      --gtest_output=xml:"$OUT/gtest_compare.xml" >>"$OUT/tests.log" 2>&1)
  tail -n 25 "$OUT/tests.log" | grep -E '^\[ *(OK|FAILED|PASSED|SKIPPED) *\]|Failure|error|Expected|Which is|ms total' | tail -20
  (cd "$RIEMANN_TEST_OUTPUT_DIR" &&
    step "RiemannRenderingOpenGLTests (whole)" 60 "$B/bin/RiemannRenderingOpenGLTests" $ogl \
      --gtest_output=xml:"$OUT/gtest_opengl.xml" >>"$OUT/tests.log" 2>&1)
  (cd "$RIEMANN_TEST_OUTPUT_DIR" &&
    step "RiemannRenderingCPUTests (the rest)" 90 "$B/bin/RiemannRenderingCPUTests" "$rest" \
      --gtest_output=xml:"$OUT/gtest_cpu_rest.xml" >>"$OUT/tests.log" 2>&1)
  banner "test results (from $OUT/tests.log)"
  grep -E '^\[ *(OK|FAILED|PASSED|SKIPPED) *\]|^\[==========\]' "$OUT/tests.log"
  grep -B2 -A8 'Failure' "$OUT/tests.log" | head -80
  # a few small pictures, if any
  grep -h 'RIEMANN STUB' "$OUT/tests.log" | sort | uniq -c | head -20
  find /tmp/riemann-test-out /tmp/riemann-cpu-* -maxdepth 2 -name '*.png' -size -2M 2>/dev/null | head -2 |
    while read -r f; do cp "$f" "$OUT/$(basename "$f" | tr -c 'A-Za-z0-9._\n-' '_')"; done
}

main 2>&1 | tee -a "$OUT/gpu.log"
{
  banner "Xvfb log"
  tail -30 "$OUT/xvfb.log" 2>/dev/null
  [ -s /tmp/riemann-xvfb.pid ] && kill "$(cat /tmp/riemann-xvfb.pid)" 2>/dev/null
  rm -f /tmp/riemann-xvfb.pid
  banner "SUMMARY"
  sed 's/^/  /' "$SUMMARY"
  grep -E '^--- .*: rc=|GL renderer|^!!!|^\| |GL renderer:|throughput|difference|ratio' "$OUT/gpu.log" | head -60
  ls -la "$OUT"
} 2>&1 | tee -a "$OUT/gpu.log"
exit 0
