#!/bin/bash
# Build time of the VTK and Qt parts, cold (no ccache), three ways (issue 29):
#   base  - one file a unit (as before)
#   pch   - precompiled VTK/Qt/Eigen/std headers in every target (precompiled-headers.cmake)
#   unity - unity batches of 8 in the VTK modules, the Studio library and the CLI's common part
# Usage: Testing/Benchmarks/BuildTime/measure.sh SOURCE_DIR WORK_DIR [variants]
# The core libraries are built first, untimed; then the VTK modules, the apps
# and the Studio library are timed (they include VTK's and Qt's headers in
# every file). Prints one line a variant: seconds and compiled objects.
set -u
src=$(cd "$1" && pwd); work=$2; variants=${3:-base pch unity}
here=$(cd "$(dirname "$0")" && pwd)
export CCACHE_DISABLE=1
deps="CommonCore RiemannRenderingCore RiemannRenderingMeshes RiemannRenderingImageIO"
timed="FiltersGeodesics FiltersFields FiltersRays RenderingScene RenderingCPU RenderingOpenGL RiemannStudio riemann riemann-render"
mkdir -p "$work"
for variant in $variants; do
  build="$work/build-$variant"
  rm -rf "$build"
  extra=(-DRIEMANN_UNITY_BUILD=OFF)
  [ "$variant" = pch ] && extra+=(-DCMAKE_PROJECT_TOP_LEVEL_INCLUDES="$here/precompiled-headers.cmake")
  [ "$variant" = unity ] && extra=(-DRIEMANN_UNITY_BUILD=ON)
  cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 \
    -DRIEMANN_WRAP_PYTHON=OFF "${extra[@]}" > "$work/configure-$variant.log" 2>&1 || { echo "$variant: configure failed"; continue; }
  cmake --build "$build" -j2 --target $deps > "$work/deps-$variant.log" 2>&1
  start=$(date +%s.%N)
  cmake --build "$build" -j2 --target $timed > "$work/build-$variant.log" 2>&1
  status=$?
  end=$(date +%s.%N)
  echo "$variant: status $status, $(echo "$end - $start" | bc) s, $(grep -c 'Building CXX' "$work/build-$variant.log") compile steps"
done
