// The yardsim command, run as a process: every subcommand and every exit status.
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sys/wait.h>

#include "support/csv_file.hpp"
#include "support/scene_files.hpp"
#include "support/shell_command.hpp"
#include "support/test_paths.hpp"

namespace {

using Result = yardsim::testing::ShellResult;

// (arguments) => exit status and output of `yardsim arguments`, killed after 120 s
Result runYardsim(const std::string& args) {
  return yardsim::testing::shell(std::string(YARDSIM_EXE) + " " + args);
}

const std::string kGpt = std::string(YARDSIM_SOURCE_DIR) + "/examples/gpt/scene.yaml";

}  // namespace

TEST_CASE("yardsim run writes the time series and the traces asked for (exit 0)") {
  yardsim::testing::SceneDir dir;
  const auto r = runYardsim("run " + kGpt + " -o " + dir.file("out") + " --trace jsonl,csv --quiet");
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK(std::filesystem::exists(dir.path() / "out/trace.jsonl"));
  CHECK(std::filesystem::exists(dir.path() / "out/trace.csv"));
  CHECK_FALSE(std::filesystem::exists(dir.path() / "out/trace.json"));  // --trace replaced the scene's list
  const yardsim::testing::CsvFile csv(dir.file("out/timeseries.csv"));
  CHECK(csv.header.front() == "time[s]");
  CHECK(csv.column("ef.transd.solved[-]") > 0);
  CHECK(csv.meta.at("scene_sha256").size() == 64);
  CHECK(csv.rows.back()[0] == 21.5);  // runs until no event is left

  const auto limited = runYardsim("run " + kGpt + " -o " + dir.file("short") + " --until 5 --quiet");
  CHECK(limited.status == 0);
  CHECK(yardsim::testing::CsvFile(dir.file("short/timeseries.csv")).rows.back()[0] == 5.0);
}

TEST_CASE("yardsim run --profile prints the time of every phase and the share of output") {
  yardsim::testing::SceneDir dir;
  const auto r = runYardsim("run " + kGpt + " -o " + dir.file("out") + " --trace jsonl --quiet --profile");
  INFO(r.out);
  CHECK(r.status == 0);
  for (const char* phase : {"profile: read ", ", validation ", ", stiffness guard ", ", build ", ", simulate ",
                            ", output ", " % of the run), total "})
    CHECK(r.out.find(phase) != std::string::npos);
  CHECK(runYardsim("run " + kGpt + " -o " + dir.file("out2") + " --quiet").out.find("profile:") == std::string::npos);
}

TEST_CASE("yardsim run and validate refuse a bad scene with exit 1 and every error") {
  yardsim::testing::SceneDir dir;
  const auto bad = dir.write("bad.yaml", "schema_version: 1\ncomponents:\n  p: {type: procesor}\n"
                                         "  q: {type: processor, params: {processing_time: x}}\n");
  for (const std::string cmd : {"run", "validate"}) {
    const auto r = runYardsim(cmd + " " + bad.string() + (cmd == "run" ? " -o " + dir.file("out") : ""));
    INFO(r.out);
    CHECK(r.status == 1);
    CHECK_THAT(r.out, Catch::Contains("bad.yaml:3:13: error: components.p.type"));
    CHECK_THAT(r.out, Catch::Contains("bad.yaml:4:50: error: components.q.params.processing_time"));
    CHECK_THAT(r.out, Catch::Contains("2 error(s)"));
  }
  CHECK_FALSE(std::filesystem::exists(dir.path() / "out"));  // nothing simulated
  CHECK(runYardsim("run").status == 1);                          // missing argument
}

TEST_CASE("yardsim run exits 2 on a numerical failure and keeps the samples") {
  yardsim::testing::SceneDir dir;
  const auto scene = dir.write("blow.yaml", R"(schema_version: 1
components:
  s: {type: spring_mass, params: {mass: 1, stiffness: 1, x0: 1, dt: 3.0, blowup_limit: 100}}
record: {interval: 3.0}
until: 1000
)");
  const auto r = runYardsim("run " + scene.string() + " -o " + dir.file("out") + " --quiet");
  INFO(r.out);
  CHECK(r.status == 2);
  CHECK_THAT(r.out, Catch::Contains("numerical failure") && Catch::Contains("suggestion"));
  CHECK(yardsim::testing::CsvFile(dir.file("out/timeseries.csv")).rows.size() >= 2);
}

TEST_CASE("an output folder that cannot be made or written is a user error (exit 1)") {
  yardsim::testing::SceneDir dir;
  dir.write("file", "not a folder");
  const auto r = runYardsim("run " + kGpt + " -o " + dir.file("file/out") + " --quiet");
  INFO(r.out);
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Catch::Contains("-o: cannot create the output folder") &&
                        !Catch::Contains("internal error"));
  const auto empty = runYardsim("run " + kGpt + " -o '' --quiet");
  INFO(empty.out);
  CHECK(empty.status == 1);
  CHECK_THAT(empty.out, Catch::Contains("-o: expected an output folder"));
}

TEST_CASE("yardsim report on a damaged timeseries.csv names the file and line (exit 1)") {
  yardsim::testing::SceneDir dir;
  REQUIRE(runYardsim("run " + kGpt + " -o " + dir.file("out") + " --quiet").status == 0);
  std::ifstream in(dir.file("out/timeseries.csv"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const auto header = text.find("time[s]");
  const auto row = text.find('\n', text.find('\n', header) + 1) + 1;  // the second data row
  text.replace(row, text.find(',', row) - row, "abc");
  dir.write("out/timeseries.csv", text);
  const auto r = runYardsim("report " + dir.file("out"));
  INFO(r.out);
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Catch::Contains("out/timeseries.csv:") &&
                        Catch::Contains(": expected a number, got 'abc'") &&
                        !Catch::Contains("internal error"));
}

TEST_CASE("an --until beyond the step ceiling is refused before the run (exit 1)") {
  yardsim::testing::SceneDir dir;
  const auto scene = dir.write("s.yaml",
                               "schema_version: 1\ncomponents:\n  s: {type: spring_mass, params: "
                               "{mass: 1, stiffness: 1, x0: 1, dt: 0.01}}\nuntil: 5\n");
  const auto r =
      runYardsim("run " + scene.string() + " -o " + dir.file("out") + " --until 1e300 --quiet");
  INFO(r.out);
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Catch::Contains("s.yaml:3:") && Catch::Contains("components.s.params.dt") &&
                        Catch::Contains("over --until 1e+300 s"));
  CHECK_FALSE(std::filesystem::exists(dir.path() / "out"));  // nothing was simulated
}

TEST_CASE("yardsim validate --print-resolved lists exactly what will run") {
  const auto r = runYardsim("validate " + kGpt + " --print-resolved");
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("models: 3 atomic, 1 coupled"));
  CHECK_THAT(r.out, Catch::Contains("atomic  ef.genr  type=generator  period=1.0"));
  CHECK_THAT(r.out, Catch::Contains("ef.out -> proc.in"));
  CHECK_THAT(r.out, Catch::Contains("trace sinks: jsonl chrome"));
}

TEST_CASE("yardsim trace filters by model, port and time") {
  yardsim::testing::SceneDir dir;
  REQUIRE(runYardsim("run " + kGpt + " -o " + dir.file("out") + " --trace jsonl --quiet").status == 0);
  const auto r = runYardsim("trace " + dir.file("out/trace.jsonl") + " --model 'ef.*' --port out --from 2 --to 3");
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("ef.genr"));
  CHECK_THAT(r.out, !Catch::Contains("proc "));
  CHECK_THAT(r.out, Catch::Contains("2 of "));  // genr's outputs at t = 2 and t = 3
  CHECK(runYardsim("trace " + dir.file("missing.jsonl")).status == 1);
}

TEST_CASE("yardsim list-types and list-channels") {
  const auto types = runYardsim("list-types");
  CHECK(types.status == 0);
  CHECK_THAT(types.out, Catch::Contains("spring_mass") && Catch::Contains("param stiffness"));
  const auto ch = runYardsim("list-channels " + kGpt);
  CHECK(ch.status == 0);
  CHECK_THAT(ch.out, Catch::Contains("ef.transd.throughput[1/s]"));
}

TEST_CASE("a multibody scene that blows up exits 2 naming the model, the body and the time") {
  yardsim::testing::SceneDir dir;
  // a 1 kg block on a 1e12 N rope: omega = 3e5 rad/s, far beyond RK4's limit at dt = 10 ms
  const auto scene = dir.write("stiff.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  bodies:
    block: {parent: world, joint: {name: drop, type: prismatic, axis: [0, 0, 1], q0: -10.001}, mass: 1, inertia: [1, 1, 1]}
  ropes:
    hoist: {path: [{body: world, point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}], EA: 1.0e12, L0: 10}
record: {interval: 0.01}
until: 10
)");
  const auto r = runYardsim("run " + scene.string() + " -o " + dir.file("out") + " --quiet");
  INFO(r.out);
  CHECK(r.status == 2);
  CHECK_THAT(r.out, Catch::Contains("numerical failure") && Catch::Contains("multibody 'mechanics'"));
  CHECK_THAT(r.out, Catch::Contains("block") && Catch::Contains("suggestion"));
  CHECK(yardsim::testing::CsvFile(dir.file("out/timeseries.csv")).rows.size() >= 1);
}

TEST_CASE("a scene asking for an equilibrium that does not exist exits 2 before the run, saying why") {
  yardsim::testing::SceneDir dir;
  // a free block with nothing to rest on: it would fall forever
  const auto scene = dir.write("fall.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  equilibrium: true
  bodies:
    block: {parent: world, joint: {type: free}, mass: 1000, inertia: [1, 1, 1]}
record: {interval: 0.1}
until: 1
)");
  const auto r = runYardsim("run " + scene.string() + " -o " + dir.file("out") + " --quiet");
  INFO(r.out);
  CHECK(r.status == 2);
  CHECK_THAT(r.out, Catch::Contains("no static equilibrium") && Catch::Contains("multibody 'mechanics'") &&
                        Catch::Contains("suggestion") && Catch::Contains("nothing was simulated"));
  // (run.json) => written anyway, with the status and the diagnosis
  std::ifstream json(dir.file("out/run.json"));
  const std::string summary((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  CHECK(summary.find("\"status\":\"failed\"") != std::string::npos);
  CHECK(summary.find("no static equilibrium") != std::string::npos);
}

TEST_CASE("yardsim run --report and yardsim report write report.html, and refuse a folder without a run") {
  yardsim::testing::SceneDir dir;
  const std::string pendulum = std::string(YARDSIM_SOURCE_DIR) + "/examples/double_pendulum/scene.yaml";
  auto r = runYardsim("run " + pendulum + " -o " + dir.file("out") + " --until 1 --trace csv --report --quiet");
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK(std::filesystem::file_size(dir.path() / "out/report.html") > 100000);  // the bundle is in it
  CHECK(std::filesystem::exists(dir.path() / "out/replay.glb"));
  CHECK(std::filesystem::exists(dir.path() / "out/trace.jsonl"));  // added for the timeline
  std::filesystem::remove(dir.path() / "out/report.html");
  r = runYardsim("report " + dir.file("out"));
  CHECK(r.status == 0);
  CHECK(std::filesystem::exists(dir.path() / "out/report.html"));
  r = runYardsim("report " + dir.file("nothing"));
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Catch::Contains("is not a folder"));
  std::filesystem::create_directories(dir.path() / "empty");
  r = runYardsim("report " + dir.file("empty"));
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Catch::Contains("has no timeseries.csv"));
}

TEST_CASE("yardsim run --report: a run that blows up still gets its report, and no record block is refused") {
  yardsim::testing::SceneDir dir;
  const auto blow = dir.write("blow.yaml", R"(schema_version: 1
components:
  s: {type: spring_mass, params: {mass: 1, stiffness: 1, x0: 1, dt: 3.0, blowup_limit: 100}}
record: {interval: 3.0}
until: 1000
)");
  auto r = runYardsim("run " + blow.string() + " -o " + dir.file("out") + " --quiet --report");
  INFO(r.out);
  CHECK(r.status == 2);
  CHECK(std::filesystem::exists(dir.path() / "out/report.html"));
  std::ifstream run(dir.path() / "out/run.json");
  const std::string json((std::istreambuf_iterator<char>(run)), std::istreambuf_iterator<char>());
  CHECK_THAT(json, Catch::Contains("\"status\":\"failed\"") && Catch::Contains("spring_mass 's'"));
  const auto quiet = dir.write("norecord.yaml", "schema_version: 1\ncomponents:\n  s: {type: spring_mass, "
                                                "params: {mass: 1, stiffness: 1, x0: 1, dt: 0.1}}\nuntil: 1\n");
  r = runYardsim("run " + quiet.string() + " -o " + dir.file("out2") + " --quiet --report");
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Catch::Contains("--report needs a `record:` block"));
  CHECK_FALSE(std::filesystem::exists(dir.path() / "out2"));  // nothing simulated
}

TEST_CASE("yardsim wp writes wp.csv, wp.html and summary.md, and refuses a scene without wp: (exit 1)") {
  yardsim::testing::SceneDir dir;
  const std::string head = R"(schema_version: 1
name: bounce
integrator: {method: rk4, dt: 0.01}
mechanics:
  bodies:
    block: {parent: world, joint: {type: prismatic, axis: [0, 0, 1], q0: -20.015}, mass: 1.0e4, inertia: [1, 1, 1]}
  ropes:
    rope: {path: [{body: world, point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}], EA: 2.0e8, L0: 20.0}
until: 1
)";
  const auto scene = dir.write("bounce.yaml", head + R"(wp:
  channels: [block.z]
  interval: 0.1
  methods:
    - {method: rk4, dt0: 0.1, levels: 3}
    - {method: semi_implicit_euler, dt0: 0.01, levels: 2}
  reference: {method: rk4, dt: 0.001}
  check: {method: semi_implicit_euler, dt: 0.0001}
)");
  const auto r = runYardsim("wp " + scene.string() + " -o " + dir.file("wp") + " --repeats 1 --quiet");
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("| rk4 |") && Catch::Contains("| semi_implicit_euler |"));
  std::ifstream csv(dir.path() / "wp" / "wp.csv");
  std::string line;
  std::getline(csv, line);
  CHECK(line ==
        "scene,method,param,omega_dt,steps,f_evals,jac_evals,newton_its,err_fails,E_final,E_rms,E_max,g_max,"
        "wall_median_s,status");
  int rows = 0;
  while (std::getline(csv, line)) rows += line.rfind("bounce,", 0) == 0;
  CHECK(rows == 5);
  CHECK(std::filesystem::exists(dir.path() / "wp" / "wp.html"));
  CHECK(std::filesystem::exists(dir.path() / "wp" / "summary.md"));
  const auto none = runYardsim("wp " + dir.write("plain.yaml", head).string() + " -o " + dir.file("wp2"));
  CHECK(none.status == 1);
  CHECK_THAT(none.out, Catch::Contains("no `wp:` block"));
}

TEST_CASE("yardsim run shows a rope over its MBL on the console and in run.json, and --fail-on alarm exits 4") {
  yardsim::testing::SceneDir dir;
  const auto scene = dir.write("mbl.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.001}
until: 0.5
record: {interval: 0.01}
mechanics:
  bodies:
    block:
      parent: world
      joint: {type: prismatic, axis: [0, 0, 1], q0: -10.0}
      mass: 1000.0
      inertia: [100, 100, 100]
  ropes:
    hoist:
      path: [{body: world, point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}]
      EA: 1.0e8
      L0: 10.0
      damping: 2.0e5
      mbl: 8829.0
)");
  const auto plain = runYardsim("run " + scene.string() + " -o " + dir.file("a") + " --quiet");
  INFO(plain.out);
  CHECK(plain.status == 0);  // an alarm alone does not fail the run
  CHECK(plain.out.find("ALARM") != std::string::npos);
  CHECK(plain.out.find("'hoist' passed its minimum breaking load") != std::string::npos);
  std::ifstream json(dir.file("a/run.json"));
  const std::string summary((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  CHECK(summary.find("\"alarms\":[{\"model\":\"mechanics\",\"element\":\"hoist\",\"kind\":\"over_mbl\"") !=
        std::string::npos);
  const auto strict = runYardsim("run " + scene.string() + " -o " + dir.file("b") + " --quiet --fail-on alarm");
  INFO(strict.out);
  CHECK(strict.status == 4);
  CHECK(std::filesystem::exists(dir.path() / "b/timeseries.csv"));  // the output is kept
  const auto bad = runYardsim("run " + scene.string() + " -o " + dir.file("c") + " --fail-on alarms");
  CHECK(bad.status != 0);
  CHECK(bad.status != 4);
}

TEST_CASE(
    "the report's lift over MBL exits 4 with --fail-on alarm and --report writes the events trace "
    "only") {
  yardsim::testing::SceneDir dir;
  const std::string scene = std::string(YARDSIM_SOURCE_DIR) + "/tests/report/data/over_mbl.yaml";
  auto slurp = [](const std::filesystem::path& f) {
    std::ifstream in(f);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  const auto strict =
      runYardsim("run " + scene + " -o " + dir.file("a") + " --quiet --report --fail-on alarm");
  INFO(strict.out);
  CHECK(strict.status == 4);
  CHECK(
      std::filesystem::exists(dir.path() / "a/report.html"));  // the report is written all the same
  // (--report, the scene asks no trace) => trace.jsonl holds the outputs only: the event, the actor
  const std::string events = slurp(dir.path() / "a/trace.jsonl");
  CHECK(events.find("\"value\":\"hoist over_mbl ") != std::string::npos);
  CHECK(events.find("\"model\":\"haul\",\"kind\":\"out\",\"port\":\"finished\"") !=
        std::string::npos);
  CHECK(events.find("\"kind\":\"state\"") == std::string::npos);
  CHECK(events.find("\"kind\":\"int\"") == std::string::npos);
  // (--trace jsonl) => the full trace as before, with the same outputs in it
  const auto full =
      runYardsim("run " + scene + " -o " + dir.file("b") + " --quiet --report --trace jsonl");
  CHECK(full.status == 0);
  const std::string trace = slurp(dir.path() / "b/trace.jsonl");
  CHECK(trace.find("\"kind\":\"state\"") != std::string::npos);
  CHECK(trace.size() > 10 * events.size());
  const auto bad =
      runYardsim("run " + scene + " -o " + dir.file("c") + " --quiet --trace everything");
  CHECK(bad.status == 1);
  CHECK_THAT(bad.out, Catch::Contains("expected jsonl, events, chrome or csv"));
}

TEST_CASE("yardsim refuses a bad --until, --repeats or command with exit 1 and says why") {
  yardsim::testing::SceneDir dir;
  for (const std::string until : {"-5", "nan", "inf", "1e400", "x"}) {
    const auto r = runYardsim("run " + kGpt + " -o " + dir.file("out") + " --quiet --until=" + until);
    INFO(until << ": " << r.out);
    CHECK(r.status == 1);
    CHECK(r.out.find("--until: expected a") != std::string::npos);
  }
  const auto repeats = runYardsim("wp " + kGpt + " -o " + dir.file("wp") + " --repeats -1");
  CHECK(repeats.status == 1);
  CHECK(repeats.out.find("--repeats: expected a whole number >= 1") != std::string::npos);
  const auto bogus = runYardsim("rnu " + kGpt);
  CHECK(bogus.status == 1);
  CHECK(bogus.out.find("unknown command 'rnu' (did you mean 'run'?)") != std::string::npos);
}

TEST_CASE("yardsim validate checks a scene's wp: block as yardsim wp reads it") {
  yardsim::testing::SceneDir dir;
  std::ifstream in(std::string(YARDSIM_SOURCE_DIR) + "/examples/stiff/block_920t.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(runYardsim("validate " + dir.write("ok.yaml", text).string()).status == 0);
  text.replace(text.find("  methods:"), 10, "  metods:");
  const auto r = runYardsim("validate " + dir.write("bad.yaml", text).string());
  INFO(r.out);
  CHECK(r.status == 1);
  CHECK(r.out.find("wp.metods: unknown key 'metods'") != std::string::npos);
  CHECK(r.out.find("did you mean 'methods'?") != std::string::npos);
}

TEST_CASE("yardsim run refuses a report.static level of a channel the scene does not have") {
  yardsim::testing::SceneDir dir;
  const auto scene = dir.write("s.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.001}
until: 0.1
record: {interval: 0.01}
report:
  static: {hoist.tension: 9810, hoist.tensoin: 9810}
mechanics:
  bodies:
    block: {parent: world, joint: {type: prismatic, axis: [0, 0, 1], q0: -10.001}, mass: 1000, inertia: [1, 1, 1]}
  ropes:
    hoist: {path: [{point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}], EA: 1.0e8, L0: 10}
)");
  const auto r = runYardsim("run " + scene.string() + " -o " + dir.file("out") + " --quiet");
  INFO(r.out);
  CHECK(r.status == 1);
  CHECK(r.out.find("s.yaml:6:33: error: report.static.hoist.tensoin: no channel") != std::string::npos);
  CHECK(r.out.find("did you mean 'hoist.tension'?") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir.path() / "out/timeseries.csv"));
}

TEST_CASE("yardsim run --checkpoint-every and --restart continue a run, and another scene's checkpoint is exit 1") {
  yardsim::testing::SceneDir dir;
  const auto first = runYardsim("run " + kGpt + " -o " + dir.file("a") + " --checkpoint-every 5 --quiet");
  INFO(first.out);
  REQUIRE(first.status == 0);
  const std::string ckpt = dir.file("a/checkpoints/t000010.000.ckpt");
  REQUIRE(std::filesystem::exists(ckpt));
  const auto again = runYardsim("run " + kGpt + " -o " + dir.file("b") + " --restart " + ckpt + " --quiet");
  INFO(again.out);
  CHECK(again.status == 0);
  const yardsim::testing::CsvFile whole(dir.file("a/timeseries.csv"));
  const yardsim::testing::CsvFile rest(dir.file("b/timeseries.csv"));
  REQUIRE(!rest.rows.empty());
  CHECK(rest.rows.front()[0] > 10.0);
  CHECK(rest.rows.back() == whole.rows.back());

  const std::string pendulum = std::string(YARDSIM_SOURCE_DIR) + "/examples/double_pendulum/scene.yaml";
  const auto wrong = runYardsim("run " + pendulum + " -o " + dir.file("c") + " --restart " + ckpt + " --quiet");
  CHECK(wrong.status == 1);
  CHECK_THAT(wrong.out, Catch::Contains("written for another scene") && Catch::Contains("nothing was simulated"));
  const auto missing = runYardsim("run " + kGpt + " -o " + dir.file("d") + " --restart " + dir.file("none.ckpt"));
  CHECK(missing.status == 1);
  CHECK_THAT(missing.out, Catch::Contains("cannot open the checkpoint"));
}

TEST_CASE("yardsim run --format hdf5 writes timeseries.h5 with the columns of timeseries.csv") {
  yardsim::testing::SceneDir dir;
  const auto r = runYardsim("run " + kGpt + " -o " + dir.file("out") + " --until 5 --quiet --format hdf5");
  INFO(r.out);
  REQUIRE(r.status == 0);
  const yardsim::testing::CsvFile csv(dir.file("out/timeseries.csv"));
  const std::string cmd = "timeout -s KILL 60 " + std::string(YARDSIM_PYTHON3) + " -c 'import sys, h5py\n"
                          "g = h5py.File(sys.argv[1], \"r\")[\"series\"]\n"
                          "print(len(g.keys()), len(g[\"time\"]), float(g[\"time\"][-1]))' " +
                          dir.file("out/timeseries.h5") + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  char buf[256] = {};
  const std::size_t n = fread(buf, 1, sizeof buf - 1, p);
  pclose(p);
  CHECK(std::string(buf, n) == std::to_string(csv.header.size()) + " " + std::to_string(csv.rows.size()) + " 5.0\n");
  CHECK(runYardsim("run " + kGpt + " -o " + dir.file("x") + " --format xml").status == 1);
}
