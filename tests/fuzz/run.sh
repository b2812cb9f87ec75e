#!/usr/bin/env bash
# (build folder with YARDSIM_FUZZ=ON, seconds for the scene loader, seconds for the mesh readers)
# => each fuzz target run from the example seeds and tests/fuzz/corpus for that long; fails on a
# crash, a sanitizer report, an uncaught exception, a leak, an input slower than 10 s (a hang) or
# more than 2 GB of memory. New interesting inputs go to out/fuzz/<target>/ (merge them into
# tests/fuzz/corpus/ with -merge=1, README.md); the figures (executions, per second) are printed.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:?usage: run.sh BUILD_DIR [SCENE_SECONDS] [MESH_SECONDS]}"
scene_s="${2:-240}"
mesh_s="${3:-60}"
work="$root/out/fuzz"
rm -rf "$work" && mkdir -p "$work"
bash "$root/tests/fuzz/make_seeds.sh" "$work/seeds" >/dev/null
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$root/tests/lsan_suppressions.txt"
for spec in "scene_loader_fuzz scene $scene_s 32768" "mesh_reader_fuzz mesh $mesh_s 65536"; do
  read -r target kind seconds maxlen <<<"$spec"
  mkdir -p "$work/$target"
  echo "fuzz: $target for $seconds s"
  "$build/tests/fuzz/$target" "$work/$target" "$root/tests/fuzz/corpus/$kind" "$work/seeds/$kind" \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len="$maxlen" \
    -artifact_prefix="$work/$target-" -print_final_stats=1 -close_fd_mask=3 \
    2>"$work/$target.log" || { tail -n 60 "$work/$target.log" >&2; echo "fuzz: $target found a problem (inputs: $work/$target-*)" >&2; exit 1; }
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/$target.log" | grep -o '[0-9]*$')
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$work/$target.log" | grep -o '[0-9]*$')
  echo "fuzz: $target: $runs executions in $seconds s ($rate per second), no finding"
done
