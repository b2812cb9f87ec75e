#include "studies/sweep_slurm.hpp"

#include <algorithm>
#include <cmath>

namespace yardsim::studies {

namespace fs = std::filesystem;

namespace {
// (text) => single-quoted for a POSIX shell
std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}
}  // namespace

std::size_t slurmTasks(const SlurmArray& a) {
  const std::size_t chunk = std::max<std::size_t>(1, a.chunk);
  return (a.cases + chunk - 1) / chunk;
}

std::string slurmScript(const SlurmArray& a) {
  const std::size_t tasks = slurmTasks(a);
  std::string s = "#!/bin/bash\n";
  s += "# yardsim sweep as a Slurm job array: submit with `sbatch " +
       (a.out / "sweep.sbatch").string() + "`,\n";
  s += "# then gather the results with `yardsim sweep --collect " + a.out.string() + "`.\n";
  s += "# " + std::to_string(a.cases) + " cases, " + std::to_string(a.chunk) +
       " per task; a task run again runs only\n";
  s += "# the cases of its chunk that have no record yet.\n";
  s += "#SBATCH --job-name=yardsim-sweep\n";
  s += "#SBATCH --array=0-" + std::to_string(tasks == 0 ? 0 : tasks - 1) + "\n";
  s += "#SBATCH --ntasks=1\n";
  s += "#SBATCH --cpus-per-task=" + std::to_string(a.cpus) + "\n";
  s += "#SBATCH --output=" + (a.out / "slurm" / "task-%a.out").string() + "\n";
  if (a.caseTimeout > 0) {
    // (time-out per case, chunk, cpus) => an upper bound on the task's time, with a margin
    const double seconds =
        std::ceil(a.caseTimeout * static_cast<double>(a.chunk) / static_cast<double>(a.cpus)) + 300;
    const long m = static_cast<long>(std::ceil(seconds / 60.0));
    s += "#SBATCH --time=" + std::to_string(m) + "\n";
  }
  s += "set -eu\n";
  s += ": \"${SLURM_ARRAY_TASK_ID:?this script is a Slurm array task (sbatch sets "
       "SLURM_ARRAY_TASK_ID)}\"\n";
  s += "exec " + quoted(a.exe.string()) + " sweep " + quoted(a.sweep.string()) + " -o " +
       quoted(a.out.string()) + " --array-task --chunk " + std::to_string(a.chunk) +
       " -j \"${SLURM_CPUS_PER_TASK:-" + std::to_string(a.cpus) + "}\"\n";
  return s;
}

std::vector<SweepCase> chunkOf(const std::vector<SweepCase>& cases, std::size_t chunk,
                               std::size_t task) {
  chunk = std::max<std::size_t>(1, chunk);
  const std::size_t from = std::min(cases.size(), task * chunk),
                    to = std::min(cases.size(), from + chunk);
  return {cases.begin() + static_cast<std::ptrdiff_t>(from),
          cases.begin() + static_cast<std::ptrdiff_t>(to)};
}

}  // namespace yardsim::studies
