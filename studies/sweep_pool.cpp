#include "studies/sweep_pool.hpp"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <deque>
#include <stdexcept>
#include <thread>

namespace yardsim::studies {

namespace fs = std::filesystem;

CaseProcess::CaseProcess(const SweepSpec& spec, const SweepCase& c, const fs::path& out, int rank)
    : spec_(&spec), case_(c), out_(out), rank_(rank), start_(std::chrono::steady_clock::now()) {
  const pid_t parent = getpid();
  std::fflush(nullptr);  // nothing buffered is written twice
  pid_ = fork();
  if (pid_ < 0)
    throw std::runtime_error(std::string("sweep: fork failed: ") + std::strerror(errno));
  if (pid_ == 0) {
    // (child) => dies with the parent, runs the case, leaves without the parent's atexit work
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(3);
    int code = 0;
    try {
      runCase(*spec_, case_, out_, rank_);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sweep: case %zu: %s\n", case_.id, e.what());
      code = 3;
    }
    std::fflush(nullptr);
    _exit(code);
  }
}

std::optional<CaseRecord> CaseProcess::poll() {
  int status = 0;
  const pid_t done = waitpid(pid_, &status, WNOHANG);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  CaseRecord r;
  r.id = case_.id;
  r.values = case_.values;
  r.rank = rank_;
  r.collected.assign(spec_->collect.size(), std::nan(""));
  r.wall = elapsed;
  const fs::path file = caseDir(out_, case_.id) / "case.yaml";
  if (done == 0) {
    if (spec_->caseTimeout <= 0.0 || elapsed < spec_->caseTimeout) return std::nullopt;
    kill(pid_, SIGKILL);
    waitpid(pid_, &status, 0);
    r.status = "timeout";
    r.message = "killed after the case_timeout of " + formatValue(spec_->caseTimeout, false) +
                " s wall time";
    writeCaseRecord(r, file);
    return r;
  }
  if (auto own = readCaseRecord(file); own && WIFEXITED(status) && WEXITSTATUS(status) == 0)
    return own;
  r.status = "crashed";
  r.message = WIFSIGNALED(status)
                  ? "the case's process died of signal " + std::to_string(WTERMSIG(status)) + " (" +
                        strsignal(WTERMSIG(status)) + ")"
                  : "the case's process exited with status " + std::to_string(WEXITSTATUS(status)) +
                        " without a record";
  writeCaseRecord(r, file);
  return r;
}

void pollPause() {
  std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

void runLocalPool(const SweepSpec& spec, const std::vector<SweepCase>& cases, const fs::path& out,
                  const PoolOptions& o) {
  std::deque<SweepCase> todo(cases.begin(), cases.end());
  std::vector<std::unique_ptr<CaseProcess>> running;
  const std::size_t jobs = std::max<std::size_t>(1, o.jobs);
  // (queue, slots) => a child per free slot; each finished one reported and its slot freed
  while (!todo.empty() || !running.empty()) {
    while (running.size() < jobs && !todo.empty()) {
      running.push_back(std::make_unique<CaseProcess>(spec, todo.front(), out, o.rank));
      todo.pop_front();
    }
    bool any = false;
    for (std::size_t i = 0; i < running.size();) {
      if (auto r = running[i]->poll()) {
        if (o.onDone) o.onDone(*r);
        running.erase(running.begin() + static_cast<std::ptrdiff_t>(i));
        any = true;
      } else {
        ++i;
      }
    }
    if (!any) pollPause();
  }
}

}  // namespace yardsim::studies
