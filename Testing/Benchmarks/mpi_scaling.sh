#!/usr/bin/env bash
# Strong scaling of `mpirun -np N riemann COMMAND` for N = 1, 2, 4 (issue 16).
#
# Each job takes 20 s or more on one rank. Every rank runs one thread
# (VTK_SMP_BACKEND_IN_USE=Sequential), so that the ranks are the only
# parallelism; the last column is one process with VTK's threads on every
# core, the single-machine alternative. N above the core count is
# oversubscribed: it shows the overhead of more ranks, not a speed-up.
# Outputs are the parallel formats (.pvti/.pvtp, one piece file per rank) or,
# for render, the gathered picture, written under $TMPDIR (default /tmp):
# with TMPDIR=/dev/shm they go to memory, which takes the ranks' writes in
# parallel as a cluster's parallel file system would; a single local disk
# does not, and then the writing (2 GB for fields) sets the time.
#
# Usage: [TMPDIR=/dev/shm] [COMMANDS="fields render"] Testing/Benchmarks/mpi_scaling.sh [BUILD_DIR] [RANKS...]
# Prints a Markdown table: wall seconds, speed-up and efficiency against N = 1.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-$root/build}"
shift || true
ranks=("${@:-1 2 4}")
read -r -a ranks <<<"${ranks[*]}"
riemann="$build/bin/riemann"
metrics="$root/Data/metrics"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# 20,000 seeds in the two-bump box, reproducible.
python3 - "$work/seeds.csv" <<'EOF'
import random, sys
random.seed(2)
with open(sys.argv[1], "w") as f:
    f.write("x,y,z,dx,dy,dz\n")
    for _ in range(20000):
        f.write(",".join(repr(random.uniform(-1.5, 1.5)) for _ in range(6)) + "\n")
EOF

declare -A jobs=(
  [fields]="fields -m $metrics/two-bumps.json --dims 220,220,220 -o $work/f.pvti"
  [trace]="trace -m $metrics/two-bumps.json --seeds $work/seeds.csv -l 10 --transverse-jacobian -o $work/t.pvtp"
  [expmap]="expmap -m $metrics/two-bumps.json --directions 20000 -l 5 --radii 2,4 -o $work/e.pvtp --wavefronts $work/w.pvtp"
  [conjugate]="conjugate -m $metrics/astigmatic-lens.json --seed -3,0,0 --cone-axis 1,0,0 --cone-angle 14 -n 70000 -k 3 -l 9 -o $work/c.pvtp --surface $work/s.pvtp"
  [render]="render --backend cpu -s $root/Data/scenes/paper-two-bumps.json --width 1440 --height 810 -o $work/r.png"
)

seconds() { # seconds of one run of the command line "$@"
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null 2>"$work/log" || { cat "$work/log" >&2; exit 1; }
  end=$(date +%s.%N)
  python3 -c "print(f'{$end - $start:.2f}')"
}

header="| command |"
rule="|---|"
for n in "${ranks[@]}"; do
  header+=" N=$n |"
  rule+="---|"
done
echo "$header 1 rank, threads on all cores |"
echo "$rule---|"
for command in ${COMMANDS:-fields trace expmap conjugate render}; do
  read -r -a job <<<"${jobs[$command]}"
  row="| $command |"
  one=""
  for n in "${ranks[@]}"; do
    t=$(VTK_SMP_BACKEND_IN_USE=Sequential seconds mpirun --allow-run-as-root --oversubscribe \
      -x VTK_SMP_BACKEND_IN_USE -np "$n" "$riemann" "${job[@]}")
    one="${one:-$t}"
    row+=" $(python3 -c "print(f'{$t} s, {$one / $t:.2f}x, {100 * $one / $t / $n:.0f}%')") |"
  done
  threads=$(seconds "$riemann" "${job[@]}")
  echo "$row $threads s |"
done
