#!/usr/bin/env bash
# Installs the Debian 12 packages yardsim builds against. Idempotent: packages already
# present are skipped, so a second run does nothing but check.
set -euo pipefail
packages=(
  g++ cmake ninja-build git pkg-config ca-certificates
  libeigen3-dev libboost-graph-dev libsundials-dev libfcl-dev libyaml-cpp-dev
  libspdlog-dev catch2 libcli11-dev libbenchmark-dev libode-dev
  libsqlite3-dev  # the yard's database (yard/)
  libopenblas-dev  # LAPACK's dense eigenvalues for the time-domain Rankine solver's growth check (forces/hydro)
  # STEP import (YARDSIM_WITH_STEP): OpenCASCADE 7.6, about 37 MB download, 188 MB installed
  libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-modeling-data-dev libocct-foundation-dev
  libtbb-dev  # OCCT's CMake targets name libtbb.so, which only the -dev package has
  libhdf5-dev libopenmpi-dev openmpi-bin  # sweep results in HDF5, the MPI sweep engine
  chromium  # the report's browser test (tests/report)
  python3-h5py  # the sweep tests' independent HDF5 reader (tests/studies)
  python3-yaml  # the mutation harness (tests/fuzz/mutate.py) reads the examples' YAML node trees
  libboost-filesystem1.74-dev libboost-system1.74-dev  # only to configure Pinocchio for bench/peers
  clang-14 libclang-rt-14-dev  # the CI fuzzer (YARDSIM_FUZZ, tests/fuzz): libFuzzer and the sanitizers' runtimes
  ccache  # .ci/run's compiler cache: a machine that built this tree before rebuilds only what changed
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# node and npm rebuild the report bundle and run the browser test (report/); Debian's packages
# unless a node is already installed (e.g. one that ships its own npm)
command -v node > /dev/null || missing+=(nodejs)
command -v npm > /dev/null || missing+=(npm)
# (report/node_modules) => the report bundle's pinned packages, which the browser tests need, so
# that README's test command runs every test with none skipped
report_packages() {
  local report="$(cd "$(dirname "$0")/.." && pwd)/report"
  if [ ! -d "$report/node_modules" ]; then
    echo "setup: installing the report bundle's pinned npm packages (npm ci)"
    (cd "$report" && npm ci --ignore-scripts --no-audit --no-fund)
  fi
}
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages, node and npm already installed"
  report_packages
  exit 0
fi
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
report_packages
