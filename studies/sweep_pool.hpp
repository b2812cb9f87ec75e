#pragma once
// Cases in child processes: each case runs in a fork of this process (a clean state per case,
// bit-for-bit reproducible, a crash or a hang confined to it), killed when it passes the
// sweep's case_timeout, and dies with its parent (so a killed sweep leaves no case running
// behind; resume starts it again). The local engine keeps up to N of them running.
#include <sys/types.h>
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include "studies/sweep_case.hpp"

namespace yardsim::studies {

// One case running in a child process.
class CaseProcess {
 public:
  // (spec, case, OUT, rank) => the child started
  CaseProcess(const SweepSpec& spec, const SweepCase& c, const std::filesystem::path& out,
              int rank);
  // () => the record once the child is gone (its own, or timeout/crashed written here), else
  // nullopt; a child past the case_timeout is killed
  std::optional<CaseRecord> poll();
  std::size_t id() const { return case_.id; }

 private:
  const SweepSpec* spec_;
  SweepCase case_;
  std::filesystem::path out_;
  int rank_;
  pid_t pid_ = -1;
  std::chrono::steady_clock::time_point start_;
};

struct PoolOptions {
  std::size_t jobs = 1;  // cases running at once
  int rank = 0;          // recorded in each case (the array task, when run by one)
  std::function<void(const CaseRecord&)> onDone = {};
};

// (spec, cases, OUT, options) => every case run and recorded under OUT/cases/, at most jobs at once
void runLocalPool(const SweepSpec& spec, const std::vector<SweepCase>& cases,
                  const std::filesystem::path& out, const PoolOptions& options);

// () => a short sleep while children run (1 ms)
void pollPause();

}  // namespace yardsim::studies
