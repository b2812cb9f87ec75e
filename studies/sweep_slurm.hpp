#pragma once
// Slurm job arrays for `yardsim sweep` (`--slurm-array`): a batch script with one array task
// per chunk of cases; each task runs `yardsim sweep SWEEP -o OUT --array-task`, which picks its
// chunk from SLURM_ARRAY_TASK_ID and runs the cases of it not yet recorded; then
// `yardsim sweep --collect OUT` gathers what the tasks wrote.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "studies/sweep_spec.hpp"

namespace yardsim::studies {

struct SlurmArray {
  std::filesystem::path exe;    // the yardsim binary the tasks run
  std::filesystem::path sweep;  // the sweep file
  std::filesystem::path out;    // OUT
  std::size_t cases = 0;
  std::size_t chunk = 1;     // cases per task
  std::size_t cpus = 1;      // per task: cases run at once (-j)
  double caseTimeout = 0.0;  // s, for the task's time limit; 0: none given
};

// (array) => the number of tasks: ceil(cases / chunk)
std::size_t slurmTasks(const SlurmArray& a);
// (array) => the batch script (#SBATCH --array=0-(tasks-1), cpus, output files)
std::string slurmScript(const SlurmArray& a);
// (cases, chunk, task) => the cases of that task's chunk
std::vector<SweepCase> chunkOf(const std::vector<SweepCase>& cases, std::size_t chunk,
                               std::size_t task);

}  // namespace yardsim::studies
