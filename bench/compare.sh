#!/usr/bin/env bash
# bench/compare.sh devstone|multibody|multibody-ir|ode|scenes [--build DIR] [-n 7] [--pin 1] [--nice -10] [--algos aba,rnea]
# yardsim against its peers, side by side: each round runs every side once as its own process,
# pinned to one core (taskset) and reniced, the order rotating (peer, yardsim, peer, yardsim ...);
# prints a Markdown table of yardsim/peer ratios (median and min-max over the rounds) after the
# date, the machine, the compiler flags of DIR and the load average, for docs/performance_peers.md.
# DIR must be configured with -DYARDSIM_PEERS_DIR (bench/peers/build_peers.sh); with
# -DYARDSIM_NATIVE=ON both sides are compiled with -march=native. `ode` times bench_multibody's
# RK4Step/32 against ODEWorldStep/32 and ODEQuickStep/32 (ODE from Debian). `multibody-ir`
# counts instructions per kernel call with callgrind instead (one run: the count does not
# depend on the machine's load; valgrind from Debian). `scenes` runs `yardsim run --profile` on the
# goliath turnover (as the scene has it: CSV and replay; and with `--trace jsonl`), the floating
# barge and the double pendulum (real-time factor, output's share).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=build
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do [[ ${args[i]} == --build ]] && build=${args[i + 1]}; done
flags=$(grep -E '^CMAKE_CXX_FLAGS_RELEASE:|^YARDSIM_NATIVE:' "$build/CMakeCache.txt" 2>/dev/null | tr '\n' ' ' || true)
echo "date: $(date -u '+%Y-%m-%d %H:%M UTC'); machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); $(g++ --version | head -1)"
echo "build: $build ($flags)"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 "$here/compare.py" "$@"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
