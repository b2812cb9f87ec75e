#pragma once
// One DEVStone run as one JSON line, shared by bench/devstone/devstone and the peers' DEVStone
// harnesses in bench/peers/ (same fields, so bench/compare.sh reads both alike). Times in
// seconds: build = model construction, flattening and initialisation; sim = the simulation.
// Minor page faults per phase: build_faults (the model), setup_faults (flatten and
// initialisation; -1 where a harness counts them in build_faults), sim_faults.
#include <sys/resource.h>

#include <cstdio>
#include <ctime>

#include "devstone_counts.hpp"

namespace yardsim::bench::devstone {

// () => process CPU time, s
inline double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// () => minor page faults of the process so far (a first touch of a fresh page: deterministic,
// unlike time on a loaded machine)
inline long minorFaults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

struct RunTimes {
  double build = 0.0, sim = 0.0;        ///< wall, s
  double buildCpu = 0.0, simCpu = 0.0;  ///< process CPU, s
  // minor page faults per phase; setup < 0: not split from build (a peer's harness)
  long buildFaults = 0, setupFaults = -1, simFaults = 0;
};

// (simulator name, variant, size, counted and expected transitions, times) => one JSON line on
// stdout; returns whether the counts equal the closed form
inline bool printRun(const char* simulator, const char* variant, int depth, int width,
                     const Counts& got, const Counts& want, const RunTimes& t) {
  const bool ok =
      got.internal == want.internal && got.external == want.external && got.atomics == want.atomics;
  std::printf(
      "{\"simulator\":\"%s\",\"variant\":\"%s\",\"depth\":%d,\"width\":%d,\"atomics\":%llu,"
      "\"internal\":%llu,"
      "\"external\":%llu,\"expected\":%llu,\"build_seconds\":%.6f,\"sim_seconds\":%.6f,"
      "\"transitions_per_second\":%.0f,\"counts_ok\":%s,\"build_cpu_seconds\":%.6f,"
      "\"sim_cpu_seconds\":%.6f,\"build_faults\":%ld,\"setup_faults\":%ld,\"sim_faults\":%ld}\n",
      simulator, variant, depth, width, static_cast<unsigned long long>(got.atomics),
      static_cast<unsigned long long>(got.internal), static_cast<unsigned long long>(got.external),
      static_cast<unsigned long long>(want.internal), t.build, t.sim,
      t.sim > 0 ? static_cast<double>(got.internal + got.external) / t.sim : 0.0,
      ok ? "true" : "false", t.buildCpu, t.simCpu, t.buildFaults, t.setupFaults, t.simFaults);
  return ok;
}

}  // namespace yardsim::bench::devstone
