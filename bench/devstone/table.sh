#!/usr/bin/env bash
# Prints the DEVStone table of docs/performance.md: the median of 5 runs per case.
#   bash bench/devstone/table.sh [path/to/devstone]
set -euo pipefail
exe=${1:-build/bench/devstone/devstone}
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
field() { sed -E "s/.*\"$1\":([^,}]*).*/\1/"; }
echo "| variant | d | w | atomics | internal = external | build s (CPU) | sim s (CPU) | transitions/s (CPU) | sim s (wall) |"
echo "|---|---|---|---|---|---|---|---|---|"
cases="LI:10 LI:40 LI:100 LI:200 HI:10 HI:40 HI:100 HI:200 HO:10 HO:40 HO:100 HO:200 HOmod:20"
for c in $cases; do
  v=${c%%:*}; n=${c##*:}
  runs=$(for _ in 1 2 3 4 5; do "$exe" --variant "$v" --depth "$n" --width "$n"; done)
  first=$(echo "$runs" | head -n 1)
  b=$(echo "$runs" | field build_cpu_seconds | median)
  s=$(echo "$runs" | field sim_cpu_seconds | median)
  w=$(echo "$runs" | field sim_seconds | median)
  tr=$(echo "$first" | field internal)
  printf "| %s | %s | %s | %s | %s | %s | %s | %.3g | %s |\n" "$v" "$n" "$n" \
    "$(echo "$first" | field atomics)" "$tr" "$b" "$s" "$(echo "2 * $tr / $s" | bc -l)" "$w"
done
