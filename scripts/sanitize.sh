#!/usr/bin/env bash
# (optional build folder, default build-san) => the whole test suite under AddressSanitizer +
# UndefinedBehaviorSanitizer, as CI ran it until 2026-11-28: clang-14 at -O1, libFuzzer's
# coverage (so the same build also serves tests/fuzz/run.sh), no benchmarks, no [[gnu::flatten]],
# the tests tagged [long] left out (the Release suite runs them). About an hour of a 2-core
# machine from scratch, which is why CI now builds only the fuzz targets (docs/robustness.md).
# Without precompiled headers: the tests' shared headers are checked under GCC only (clang
# compares a header's macros with each test's more strictly; not tried as of 2026-11-28).
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build-san}"
CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DYARDSIM_WERROR=ON -DYARDSIM_FUZZ=ON \
  -DYARDSIM_BUILD_BENCH=OFF -DYARDSIM_PCH=OFF
cmake --build "$build" -j2
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS=suppressions="$PWD/tests/lsan_suppressions.txt" \
  ctest --test-dir "$build" --output-on-failure -j2
