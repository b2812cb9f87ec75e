// The Slurm job array: tasks, chunks and the batch script.
#include <catch2/catch.hpp>

#include "studies/sweep_slurm.hpp"

using namespace yardsim::studies;

TEST_CASE("A Slurm array has one task per chunk and each task picks its chunk") {
  SlurmArray a;
  a.exe = "/opt/yardsim/bin/yardsim";
  a.sweep = "/home/u/it's/sweep.yaml";
  a.out = "/scratch/out";
  a.cases = 10;
  a.chunk = 4;
  a.cpus = 2;
  a.caseTimeout = 60;
  CHECK(slurmTasks(a) == 3);
  const std::string s = slurmScript(a);
  CHECK_THAT(s, Catch::StartsWith("#!/bin/bash\n"));
  CHECK_THAT(s, Catch::Contains("#SBATCH --array=0-2\n"));
  CHECK_THAT(s, Catch::Contains("#SBATCH --cpus-per-task=2\n"));
  CHECK_THAT(s, Catch::Contains("#SBATCH --time=7\n"));  // 60 s x 4 / 2 + 300 s => 7 min
  CHECK_THAT(
      s,
      Catch::Contains(
          "exec '/opt/yardsim/bin/yardsim' sweep '/home/u/it'\\''s/sweep.yaml' -o '/scratch/out' "
          "--array-task --chunk 4 -j \"${SLURM_CPUS_PER_TASK:-2}\"\n"));
  std::vector<SweepCase> cases;
  for (std::size_t i = 0; i < 10; ++i) cases.push_back({i, {double(i)}});
  CHECK(chunkOf(cases, 4, 0).front().id == 0);
  CHECK(chunkOf(cases, 4, 2).size() == 2);
  CHECK(chunkOf(cases, 4, 2).back().id == 9);
  CHECK(chunkOf(cases, 4, 3).empty());
}
