#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <stdexcept>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "studies/sweep_collect.hpp"
#include "studies/sweep_mpi.hpp"
#include "studies/sweep_pool.hpp"
#include "studies/sweep_slurm.hpp"

namespace yardsim::cli {

namespace fs = std::filesystem;
using namespace yardsim::studies;

namespace {

// (sweep file, quiet) => the spec and its cases, checked at the door (the first case's scene
// loaded and assembled); nullopt once every error is printed
std::optional<std::pair<SweepSpec, std::vector<SweepCase>>> readChecked(const std::string& file,
                                                                        bool print) {
  models::Diagnostics d;
  SweepSpec spec = readSweepSpec(file, d);
  std::vector<SweepCase> cases;
  if (!d.hasErrors()) cases = expandCases(spec);
  if (!d.hasErrors() && cases.empty()) d.error({file, 1, 1}, "sweep.vary", "the sweep has no case");
  if (!d.hasErrors()) {
    const models::Diagnostics first = checkCase(spec, cases.front());
    for (const auto& e : first.all())
      e.severity == models::Diagnostic::Severity::Error
          ? d.error(e.where, e.keyPath, e.message, e.hint)
          : d.warning(e.where, e.keyPath, e.message, e.hint);
  }
  if (print)
    for (const auto& e : d.all()) std::fprintf(stderr, "%s\n", models::format(e).c_str());
  if (d.hasErrors()) {
    if (print)
      std::fprintf(stderr, "%s: %zu error(s); no case was run\n", file.c_str(), d.errorCount());
    return std::nullopt;
  }
  return std::make_pair(std::move(spec), std::move(cases));
}

// (cases, OUT) => those with no record yet
std::vector<SweepCase> missing(const SweepSpec& spec, const std::vector<SweepCase>& cases,
                               const fs::path& out) {
  std::vector<SweepCase> todo;
  const auto rs = gatherRecords(spec, cases, out);
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (rs[i].status == "missing") todo.push_back(cases[i]);
  return todo;
}

// (spec, cases, OUT, cases to run, workers) => an estimate of their run time from the cases
// already recorded (a resume), printed; whether there was one
bool doorEstimate(const SweepSpec& spec, const std::vector<SweepCase>& cases, const fs::path& out,
                  std::size_t todo, std::size_t workers) {
  double sum = 0.0;
  std::size_t n = 0;
  for (const auto& r : gatherRecords(spec, cases, out))
    if (r.status == "ok") sum += r.wall, ++n;
  if (n == 0 || todo == 0) return false;
  std::printf(
      "sweep: estimate %.3g s for the %zu case(s) to run on %zu worker(s) (%.3g s a case, the "
      "mean of %zu recorded)\n",
      sum / static_cast<double>(n) * static_cast<double>(todo) / static_cast<double>(workers), todo,
      workers, sum / static_cast<double>(n), n);
  return true;
}

// Per finished case: a line, and after the first one the estimate for the rest.
struct Reporter {
  std::size_t total, todo, workers;
  bool quiet;
  bool estimated = false;  // at the door already
  std::size_t done = 0;
  // (record) => printed
  void operator()(const CaseRecord& r) {
    ++done;
    if (done == 1 && todo > 1 && !estimated)
      std::printf(
          "sweep: estimate %.3g s for the remaining %zu case(s) on %zu worker(s) (the first took "
          "%.3g s)\n",
          r.wall * static_cast<double>(todo - 1) / static_cast<double>(workers), todo - 1, workers,
          r.wall);
    if (!quiet || r.status != "ok")
      std::printf("sweep: [%zu/%zu] case %zu %s (%.3g s)%s%s\n", done, todo, r.id, r.status.c_str(),
                  r.wall, r.message.empty() ? "" : ": ", r.message.substr(0, 300).c_str());
    std::fflush(stdout);
  }
};

// (spec, cases, OUT) => the results gathered and written, and a summary line
int collectAndReport(const SweepSpec& spec, const std::vector<SweepCase>& cases,
                     const fs::path& out) {
  const SweepCounts n = writeSweepResults(spec, gatherRecords(spec, cases, out), out);
  std::printf("sweep: %zu case(s): %zu ok, %zu not ok, %zu missing; %zu within the limits\n",
              n.total, n.ok, n.failed, n.missing, n.passed);
  std::printf("written: %s/cases.csv, sweep.h5, sweep.html\n", out.string().c_str());
  if (n.missing > 0)
    std::printf("sweep: run the same command again to run the %zu missing case(s)\n", n.missing);
  return kOk;
}

// (a) => the cases of this array task run (SLURM_ARRAY_TASK_ID picks the chunk)
int arrayTask(const SweepArgs& a, const SweepSpec& spec, const std::vector<SweepCase>& cases) {
  const char* id = std::getenv("SLURM_ARRAY_TASK_ID");
  if (!id || a.chunk == 0) {
    std::fprintf(
        stderr, "sweep --array-task: needs SLURM_ARRAY_TASK_ID in the environment and --chunk N\n");
    return kInvalidInput;
  }
  const std::size_t task = std::strtoul(id, nullptr, 10);
  writePlan(spec, a.outdir);
  const auto todo = missing(spec, chunkOf(cases, a.chunk, task), a.outdir);
  Reporter rep{cases.size(), todo.size(), a.jobs, a.quiet};
  runLocalPool(spec, todo, a.outdir, {a.jobs, static_cast<int>(task), std::ref(rep)});
  std::printf(
      "sweep: array task %zu ran %zu case(s); gather with `yardsim sweep --collect %s` when all "
      "tasks are done\n",
      task, todo.size(), a.outdir.c_str());
  return kOk;
}

// (a) => OUT/sweep.sbatch written
int slurmArray(const SweepArgs& a, const SweepSpec& spec, const std::vector<SweepCase>& cases) {
  writePlan(spec, a.outdir);
  SlurmArray s;
  s.exe = fs::read_symlink("/proc/self/exe");
  s.sweep = fs::absolute(a.sweep);
  s.out = fs::absolute(a.outdir);
  s.cases = cases.size();
  s.chunk = a.chunk > 0 ? a.chunk : std::max<std::size_t>(1, (cases.size() + 99) / 100);
  s.cpus = a.jobs;
  s.caseTimeout = spec.caseTimeout;
  fs::create_directories(s.out / "slurm");
  std::ofstream(s.out / "sweep.sbatch") << slurmScript(s);
  std::printf(
      "sweep: %zu case(s) in %zu array task(s) of %zu\nwritten: %s\nsubmit: sbatch %s\nthen:   "
      "yardsim sweep --collect %s\n",
      cases.size(), slurmTasks(s), s.chunk, (s.out / "sweep.sbatch").c_str(),
      (s.out / "sweep.sbatch").c_str(), s.out.c_str());
  return kOk;
}

// (a) => the cases spread over the MPI ranks; rank 0 gathers
int mpiSweep(const SweepArgs& a, const SweepSpec& spec, const std::vector<SweepCase>& cases) {
  MpiSession session;
  const MpiWorld w = session.world();
  std::vector<SweepCase> todo;
  bool ok = true;
  if (w.rank == 0) {
    try {
      writePlan(spec, a.outdir);
      todo = missing(spec, cases, a.outdir);
      std::printf("sweep: %zu case(s), %zu recorded, %zu to run on %d MPI rank(s)\n", cases.size(),
                  cases.size() - todo.size(), todo.size(), w.size);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sweep: %s\n", e.what());
      ok = false;
    }
  }
  if (!session.broadcast(ok)) return kInvalidInput;
  Reporter rep{cases.size(), todo.size(), static_cast<std::size_t>(w.size), true};
  runMpiSchedule(session, spec, cases, todo, a.outdir, std::ref(rep));
  return w.rank == 0 ? collectAndReport(spec, cases, a.outdir) : kOk;
}

}  // namespace

int sweepCommand(const SweepArgs& a) {
  try {
    if (!a.collect.empty()) {  // (OUT) => its plan's sweep, gathered
      const auto checked = readChecked(planSweepFile(a.collect).string(), true);
      if (!checked) return kInvalidInput;
      return collectAndReport(checked->first, checked->second, a.collect);
    }
    if (a.sweep.empty()) {
      std::fprintf(stderr, "sweep: expected a sweep file (or --collect OUT)\n");
      return kInvalidInput;
    }
    const bool mpi = launchedByMpi();
    const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
    const auto checked = readChecked(a.sweep, !mpi || !rank || std::string(rank) == "0");
    if (!checked) return kInvalidInput;
    const auto& [spec, cases] = *checked;
    if (mpi) return mpiSweep(a, spec, cases);
    if (a.arrayTask) return arrayTask(a, spec, cases);
    if (a.slurmArray) return slurmArray(a, spec, cases);
    writePlan(spec, a.outdir);
    const auto todo = missing(spec, cases, a.outdir);
    std::printf("sweep: %zu case(s), %zu recorded, %zu to run with -j %zu\n", cases.size(),
                cases.size() - todo.size(), todo.size(), a.jobs);
    const bool estimated = doorEstimate(spec, cases, a.outdir, todo.size(), a.jobs);
    if (a.dryRun) return kOk;
    Reporter rep{cases.size(), todo.size(), a.jobs, a.quiet, estimated};
    runLocalPool(spec, todo, a.outdir, {a.jobs, 0, std::ref(rep)});
    return collectAndReport(spec, cases, a.outdir);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return kInvalidInput;
  }
}

}  // namespace yardsim::cli
