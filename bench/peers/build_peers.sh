#!/usr/bin/env bash
# bench/peers/build_peers.sh PEERS_DIR
# Builds the peers that bench/peers/ times against yardsim, from sources already unpacked in
# PEERS_DIR (this script fetches nothing). Expected layout (each one optional):
#   PEERS_DIR/adevs                  adevs 3.3 (github smiz/adevs, tag v3.3.1): header-only
#   PEERS_DIR/devstone-comparative   github SimulationEverywhere/devstone-comparative (its
#                                    devstone/adevs/src: the DEVStone models written for adevs)
#   PEERS_DIR/cadmium_v2             github SimulationEverywhere/cadmium_v2: header-only, with
#                                    its own DEVStone in example/devstone
#   PEERS_DIR/rbdl                   RBDL 3.3.1 (github rbdl/rbdl, tag v3.3.1): built here
#   PEERS_DIR/pinocchio              Pinocchio 3.7.0 (github stack-of-tasks/pinocchio, tag
#                                    v3.7.0) with jrl-cmakemodules unpacked in pinocchio/cmake:
#                                    configured here, used header-only (no template instantiation)
# RBDL is built twice with g++ and the same flags as yardsim's Release build: -O3 -DNDEBUG
# (PEERS_DIR/_install/rbdl-generic) and -O3 -DNDEBUG -march=native (.../rbdl-native).
# A missing peer is reported and skipped; the exit status is 0 if at least one peer is usable.
set -u
peers=${1:?usage: build_peers.sh PEERS_DIR}
peers=$(cd "$peers" && pwd) || exit 2
jobs=${JOBS:-2}
usable=0
missing() { echo "build_peers: $1 missing ($2): its comparisons are skipped" >&2; }

if [[ -f $peers/adevs/include/adevs.h ]]; then
  echo "build_peers: adevs headers found"; usable=1
else missing adevs "$peers/adevs/include/adevs.h"; fi
if [[ -f $peers/devstone-comparative/devstone/adevs/src/devstone.hpp ]]; then
  echo "build_peers: adevs DEVStone models found"
else missing "adevs DEVStone models" "$peers/devstone-comparative/devstone/adevs/src"; fi
if [[ -f $peers/cadmium_v2/include/cadmium/core/simulation/root_coordinator.hpp &&
      -d $peers/cadmium_v2/example/devstone/src ]]; then
  echo "build_peers: Cadmium v2 headers and DEVStone found"; usable=1
else missing "Cadmium v2" "$peers/cadmium_v2/include, example/devstone"; fi

if [[ -f $peers/rbdl/CMakeLists.txt ]]; then
  for flavour in generic native; do
    flags="-O3 -DNDEBUG"; [[ $flavour == native ]] && flags="$flags -march=native"
    if cmake -S "$peers/rbdl" -B "$peers/_build/rbdl-$flavour" -G Ninja -DCMAKE_BUILD_TYPE=Release \
         -DCMAKE_CXX_COMPILER=g++ -DCMAKE_CXX_FLAGS_RELEASE="$flags" -DRBDL_BUILD_STATIC=OFF \
         -DRBDL_BUILD_TESTS=OFF -DRBDL_BUILD_EXECUTABLES=OFF \
         -DCMAKE_INSTALL_PREFIX="$peers/_install/rbdl-$flavour" >/dev/null &&
       cmake --build "$peers/_build/rbdl-$flavour" -j"$jobs" >/dev/null &&
       cmake --install "$peers/_build/rbdl-$flavour" >/dev/null; then
      echo "build_peers: RBDL ($flavour: $flags) installed in $peers/_install/rbdl-$flavour"; usable=1
    else
      echo "build_peers: RBDL ($flavour) failed to build: its comparisons are skipped" >&2
    fi
  done
else missing RBDL "$peers/rbdl"; fi

if [[ -f $peers/pinocchio/CMakeLists.txt && -f $peers/pinocchio/cmake/base.cmake ]]; then
  if cmake -S "$peers/pinocchio" -B "$peers/_build/pinocchio" -G Ninja -DCMAKE_BUILD_TYPE=Release \
       -DCMAKE_CXX_COMPILER=g++ -DBUILD_PYTHON_INTERFACE=OFF -DBUILD_TESTING=OFF \
       -DBUILD_WITH_URDF_SUPPORT=OFF -DBUILD_WITH_COLLISION_SUPPORT=OFF \
       -DENABLE_TEMPLATE_INSTANTIATION=OFF -DBUILD_UTILS=OFF -DBUILD_BENCHMARK=OFF \
       -DINSTALL_DOCUMENTATION=OFF -DCMAKE_INSTALL_PREFIX="$peers/_install/pinocchio" >/dev/null &&
     [[ -f $peers/_build/pinocchio/include/pinocchio/config.hpp ]]; then
    echo "build_peers: Pinocchio configured (header-only: $peers/pinocchio/include and $peers/_build/pinocchio/include)"
    usable=1
  else
    echo "build_peers: Pinocchio failed to configure (Boost, Eigen from Debian): its comparisons are skipped" >&2
  fi
else missing Pinocchio "$peers/pinocchio with jrl-cmakemodules in pinocchio/cmake"; fi

[[ $usable == 1 ]]
