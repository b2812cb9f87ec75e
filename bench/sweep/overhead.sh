#!/usr/bin/env bash
# The per-case overhead and the local scaling of `yardsim sweep` (docs/performance.md): 1,000
# cases of 10 steps with -j 1 and -j 2, and 24 cases of the barge study with -j 1 and -j 2.
#   bash bench/sweep/overhead.sh [build/cli/yardsim]
set -euo pipefail
exe=${1:-build/cli/yardsim}
root="$(cd "$(dirname "$0")/../.." && pwd)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# (sweep, jobs) => wall of the whole sweep, per case, and the mean run and case times recorded
measure() {
  local sweep=$1 jobs=$2 out="$tmp/out-$RANDOM"
  local t0 t1
  t0=$(date +%s.%N)
  "$exe" sweep "$sweep" -o "$out" -j "$jobs" --quiet > /dev/null
  t1=$(date +%s.%N)
  python3 - "$out/cases.csv" "$t0" "$t1" "$jobs" "$(basename "$sweep")" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
wall = float(sys.argv[3]) - float(sys.argv[2])
n = len(rows)
run = sum(float(r["run_wall_s"]) for r in rows) / n
case = sum(float(r["wall_s"]) for r in rows) / n
print(f"{sys.argv[5]} -j {sys.argv[4]}: {n} cases in {wall:.3f} s wall, {wall / n * 1e3:.2f} ms per case, "
      f"{n / wall:.1f} cases/s; per case: run {run * 1e3:.2f} ms, case in its process {case * 1e3:.2f} ms, "
      f"overhead beyond the run {(wall * int(sys.argv[4]) / n - run) * 1e3:.2f} ms (x jobs)")
PY
}
measure "$root/bench/sweep/overhead.yaml" 1
measure "$root/bench/sweep/overhead.yaml" 2
measure "$root/examples/sweeps/barge_operability/sweep.yaml" 1
measure "$root/examples/sweeps/barge_operability/sweep.yaml" 2
