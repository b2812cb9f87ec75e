// `yardsim sweep` as a user runs it: the same 3 x 3 sweep of the pendulum on local cores
// (-j 2), on two MPI ranks (mpirun -n 2) and as a Slurm job array (its batch script run once
// per task with SLURM_ARRAY_TASK_ID set, then --collect) gives the same HDF5 case table, read
// back by h5py; a sweep killed part-way and resumed gives that table too, running no case twice;
// a case above a resource ceiling (steps, recorded rows) is refused at the door unless the scene
// raises it with `limits:`.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "support/scene_files.hpp"
#include "support/shell_command.hpp"
#include "support/test_paths.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;

using Result = yardsim::testing::ShellResult;

// (shell command) => exit status and output, killed after 300 s
Result shell(const std::string& command) { return yardsim::testing::shell(command, 300); }

const std::string kExe = YARDSIM_EXE;
const std::string kSweep =
    std::string(YARDSIM_SOURCE_DIR) + "/tests/studies/data/pendulum_sweep/sweep.yaml";
const std::string kDump = std::string(YARDSIM_SOURCE_DIR) + "/tests/studies/sweep_h5_dump.py";

// (OUT) => the case table of OUT/sweep.h5 as h5py reads it
std::string table(const std::string& out) {
  const Result r =
      shell(std::string(YARDSIM_PYTHON3) + " " + kDump + " " + out + "/sweep.h5 table");
  INFO(r.out);
  REQUIRE(r.status == 0);
  return r.out;
}

// (folder) => every case record's text by case folder
std::map<std::string, std::string> records(const fs::path& out) {
  std::map<std::string, std::string> m;
  if (!fs::exists(out / "cases")) return m;
  for (const auto& d : fs::directory_iterator(out / "cases"))
    if (fs::exists(d.path() / "case.yaml")) {
      std::ifstream is(d.path() / "case.yaml");
      std::ostringstream s;
      s << is.rdbuf();
      m[d.path().filename().string()] = s.str();
    }
  return m;
}

}  // namespace

TEST_CASE("Local cores, MPI ranks and a Slurm array give the same HDF5 case table", "[long]") {
  yardsim::testing::SceneDir dir;
  const std::string local = dir.file("local"), mpi = dir.file("mpi"), array = dir.file("array");
  const Result l = shell(kExe + " sweep " + kSweep + " -o " + local + " -j 2 --quiet");
  INFO(l.out);
  REQUIRE(l.status == 0);
  CHECK_THAT(l.out, Catch::Contains("9 case(s), 0 recorded, 9 to run with -j 2"));
  CHECK_THAT(l.out, Catch::Contains("estimate"));
  CHECK_THAT(l.out, Catch::Contains("9 case(s): 9 ok, 0 not ok, 0 missing; 3 within the limits"));
  const std::string expected = table(local);
  CHECK(std::count(expected.begin(), expected.end(), '\n') == 10);

  // (Open MPI's own allocations at exit) => not reported by LeakSanitizer in the sanitizer build
  const Result m =
      shell("mpirun --allow-run-as-root --oversubscribe -x ASAN_OPTIONS=detect_leaks=0 -n 2 " +
            kExe + " sweep " + kSweep + " -o " + mpi);
  INFO(m.out);
  REQUIRE(m.status == 0);
  CHECK_THAT(m.out, Catch::Contains("9 to run on 2 MPI rank(s)"));
  CHECK(table(mpi) == expected);
  // (records) => both ranks ran cases (rank 0 schedules and runs between requests)
  std::set<std::string> ranks;
  for (const auto& [name, text] : records(mpi)) ranks.insert(text.substr(text.find("rank: "), 7));
  CHECK(ranks.size() == 2);

  const Result s = shell(kExe + " sweep " + kSweep + " -o " + array + " --slurm-array --chunk 4");
  INFO(s.out);
  REQUIRE(s.status == 0);
  std::ifstream script(array + "/sweep.sbatch");
  const std::string text((std::istreambuf_iterator<char>(script)),
                         std::istreambuf_iterator<char>());
  CHECK_THAT(text, Catch::Contains("#SBATCH --array=0-2\n"));
  for (int task = 2; task >= 0; --task) {  // (the scheduler's order is any order)
    const Result t = shell("env SLURM_ARRAY_TASK_ID=" + std::to_string(task) +
                           " SLURM_CPUS_PER_TASK=1 bash " + array + "/sweep.sbatch");
    INFO(t.out);
    REQUIRE(t.status == 0);
    CHECK_THAT(t.out, Catch::Contains("array task " + std::to_string(task) + " ran " +
                                      (task == 2 ? "1" : "4")));
  }
  const Result c = shell(kExe + " sweep --collect " + array);
  INFO(c.out);
  REQUIRE(c.status == 0);
  CHECK(table(array) == expected);
}

TEST_CASE("A sweep killed part-way resumes with the missing cases only and the same table") {
  yardsim::testing::SceneDir dir;
  const std::string whole = dir.file("whole"), killed = dir.file("killed");
  REQUIRE(shell(kExe + " sweep " + kSweep + " -o " + whole + " -j 2 --quiet").status == 0);

  // (sweep with one job) => killed with SIGKILL once three cases are recorded
  std::vector<std::string> args{kExe, "sweep", kSweep, "-o", killed, "-j", "1", "--quiet"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  REQUIRE(posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ) == 0);
  const auto start = std::chrono::steady_clock::now();
  while (records(killed).size() < 3 &&
         std::chrono::steady_clock::now() - start < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  posix_spawn_file_actions_destroy(&fa);
  std::this_thread::sleep_for(
      std::chrono::milliseconds(200));  // the running case dies with its parent
  const auto before = records(killed);
  REQUIRE(before.size() >= 3);
  REQUIRE(before.size() < 9);

  const Result r = shell(kExe + " sweep " + kSweep + " -o " + killed + " -j 2 --quiet");
  INFO(r.out);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("9 case(s), " + std::to_string(before.size()) + " recorded, " +
                                    std::to_string(9 - before.size()) + " to run"));
  CHECK_THAT(r.out, Catch::Contains("mean of " + std::to_string(before.size()) +
                                    " recorded"));  // the estimate
  const auto after = records(killed);
  CHECK(after.size() == 9);
  for (const auto& [name, text] : before)
    CHECK(after.at(name) == text);  // not run again (wall time differs)
  CHECK(table(killed) == table(whole));
  // a third run has nothing left to run
  CHECK_THAT(shell(kExe + " sweep " + kSweep + " -o " + killed + " --quiet").out,
             Catch::Contains("9 recorded, 0 to run"));
}

TEST_CASE("A bad sweep file is refused at the door with exit 1 and file:line:col") {
  yardsim::testing::SceneDir dir;
  const auto bad =
      dir.write("bad.yaml", "sweep:\n  scene: " + std::string(YARDSIM_SOURCE_DIR) +
                                "/tests/studies/data/pendulum_sweep/scene.yaml\n"
                                "  vary: {speed: [1, 2]}\n  collect: [max(pendulum.nothing)]\n");
  const Result r = shell(kExe + " sweep " + bad.string() + " -o " + dir.file("out"));
  INFO(r.out);
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Catch::Contains(bad.string() +
                                    ":3:17: error: sweep.vary.speed: no root parameter 'speed'"));
  CHECK_THAT(r.out, Catch::Contains("did you mean 'speed_deg'?"));
  CHECK_FALSE(fs::exists(dir.path() / "out"));
  const Result collect = shell(kExe + " sweep --collect " + dir.file("nowhere"));
  CHECK(collect.status == 1);
  CHECK_THAT(collect.out, Catch::Contains("no plan.yaml"));
}

namespace {
// (record interval, extra root keys) => the sweep tests' pendulum scene in DIR with that record
// interval (`record:` takes no parameter: every case records at the scene's), and a sweep file
// over VARY ("{dt: [...]}", "{speed_deg: [...]}")
fs::path ceilingSweep(yardsim::testing::SceneDir& dir, const std::string& vary,
                      const std::string& interval = "0.05", const std::string& extra = "") {
  std::ifstream in(std::string(YARDSIM_SOURCE_DIR) +
                   "/tests/studies/data/pendulum_sweep/scene.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string record = "  interval: 0.05\n";
  REQUIRE(text.find(record) != std::string::npos);
  text.replace(text.find(record), record.size(), "  interval: " + interval + "\n");
  dir.write("scene.yaml", text + extra);
  return dir.write("sweep.yaml", "sweep:\n  scene: scene.yaml\n  vary: " + vary +
                                     "\n  collect: [max(pendulum.joint0.q)]\n");
}
}  // namespace

TEST_CASE("A sweep whose case would step more than the ceiling is refused at the door") {
  // (dt = 1e-9 s over until = 6 s) => 6e9 steps, above the 1e8 ceiling: exit 1 before any case
  yardsim::testing::SceneDir dir;
  const fs::path sweep = ceilingSweep(dir, "{dt: [1.0e-9, 0.002]}");
  const Result r = shell(kExe + " sweep " + sweep.string() + " -o " + dir.file("out"));
  INFO(r.out);
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Catch::Contains("error: components.pendulum.params.dt: a step of 1e-09 s over "
                                    "until = 6 s is 6e+09 steps, above the ceiling of 1e+08") &&
                        Catch::Contains("`limits: {steps: 6e+09}`") &&
                        Catch::Contains("no case was run"));
  CHECK_THAT(r.out,
             Catch::Matches("(.|\n)*scene.yaml:[0-9]+:[0-9]+: error: components.pendulum(.|\n)*"));
  CHECK_FALSE(fs::exists(dir.path() / "out/cases"));
}

TEST_CASE(
    "A sweep whose case would record more rows than the ceiling is refused at the door unless the "
    "scene opts in") {
  // (record.interval = 1e-6 s over 6 s) => 6e6 rows, above the 1e6 ceiling
  yardsim::testing::SceneDir dir;
  const fs::path sweep = ceilingSweep(dir, "{speed_deg: [4, 6]}", "1.0e-6");
  const Result r = shell(kExe + " sweep " + sweep.string() + " -o " + dir.file("out"));
  INFO(r.out);
  CHECK(r.status == 1);
  CHECK_THAT(r.out,
             Catch::Matches("(.|\n)*scene.yaml:[0-9]+:[0-9]+: error: record.interval: a record "
                            "interval of 1e-06 s over until = 6 s is 6e\\+06 recorded rows, above "
                            "the ceiling of 1e\\+06(.|\n)*"));
  CHECK_FALSE(fs::exists(dir.path() / "out/cases"));
  // (the scene's `limits: {rows: 1.0e7}`) => the door lets it through (a Slurm array is only
  // written, nothing is run)
  yardsim::testing::SceneDir opted;
  const fs::path raised =
      ceilingSweep(opted, "{speed_deg: [4, 6]}", "1.0e-6", "limits: {rows: 1.0e7}\n");
  const Result ok =
      shell(kExe + " sweep " + raised.string() + " -o " + opted.file("out") + " --slurm-array");
  INFO(ok.out);
  CHECK(ok.status == 0);
  CHECK(fs::exists(opted.path() / "out/sweep.sbatch"));
}
