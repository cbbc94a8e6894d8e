#!/usr/bin/env bash
# Hit-position error of the CPU tracer's rays against the exact geodesics of
# a diffeomorphism metric (Phi^-1 of straight lines), per integrator and step:
# the table in README.md. Usage: Testing/Benchmarks/hit_error_table.sh [BUILD_DIR]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
RIEMANN="${1:-$ROOT/build}/bin/riemann"
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
echo "| metric | integrator | step | median error | 99th percentile | max error | pixels compared | pixels where one ray misses |"
echo "|---|---|---|---|---|---|---|---|"
for metric in twist wavy-diffeo; do
  for integrator in euler rk4 adaptive; do
    for step in 0.08 0.04 0.02 0.01; do
      line="$("$RIEMANN" render --backend cpu --quiet --scene "$ROOT/Data/scenes/paper-twist.json" \
        --metric "$ROOT/Data/metrics/$metric.json" --width 160 --height 120 \
        --integrator "$integrator" --step "$step" --max-steps 4000 --hit-error \
        -o "$OUT/x.png" 2>&1 | grep "hit error against")"
      max="$(sed -E 's/.*max ([^,]+),.*/\1/' <<<"$line")"
      median="$(sed -E 's/.*median ([^,]+),.*/\1/' <<<"$line")"
      p99="$(sed -E 's/.*99th percentile ([^ ]+) over.*/\1/' <<<"$line")"
      compared="$(sed -E 's/.* over ([0-9]+) pixels.*/\1/' <<<"$line")"
      missing="$(sed -E 's/.*; ([0-9]+) pixels where.*/\1/' <<<"$line")"
      echo "| $metric | $integrator | $step | $median | $p99 | $max | $compared | $missing |"
    done
  done
done
