// yardsim run, as a process, on scenes that start in static equilibrium (`equilibrium: true`):
// a box barge released off its draft settles at the draft of the hand formula without moving in
// surge, sway or yaw; an unmoored barge in a steady wind has no equilibrium, and the run says
// which body and direction (in the body's own frame, with its world direction), exits 2 and still
// writes run.json. The stiffness guard's warning is one alarm of kind warning (--fail-on). The
// options run_command checks against the scene: --checkpoint-every held to 1 ms and the
// checkpoint ceiling.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>

#include "support/csv_file.hpp"
#include "support/scene_files.hpp"
#include "support/shell_command.hpp"
#include "support/test_paths.hpp"

namespace {

// (arguments) => exit status and output of `yardsim arguments`
yardsim::testing::ShellResult runYardsim(const std::string& args) {
  return yardsim::testing::shell(std::string(YARDSIM_EXE) + " " + args);
}

// A 60 m x 20 m x 5 m box hull (examples/floating_barge) of 1500 t: its draft is
// m / (rho L B) = 1.5e6 / (1025 x 60 x 20) = 1.2195122 m. Started 0.3 m too high, 3 m forward,
// 2 m to port and turned 20 degrees; `extra` adds to the mechanics block.
std::string barge(const std::string& extra) {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  equilibrium: true
  water: {density: 1025.0, level: 0.0, depth: 30.0}
  bodies:
    hull:
      parent: world
      joint: {type: free, q0: {xyz: [3.0, 2.0, -0.9195121951219512], rpy_deg: [0, 0, 20]}}
      mass: 1.5e6
      com: [0, 0, 2.0]
      inertia: [5.3125e7, 4.53125e8, 5.0e8]
  hydrostatics:
    buoyancy: {body: hull, mesh: )" +
         std::string(YARDSIM_SOURCE_DIR) + R"(/examples/floating_barge/barge_hull.obj}
)" + extra + R"(record: {interval: 0.01, channels: ["hull.*"]}
until: 0.01
)";
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("an unmoored box barge off its draft settles at the hand draft: surge sway and yaw unmoved") {
  yardsim::testing::SceneDir dir;
  const auto scene = dir.write("barge.yaml", barge(""));
  const auto r = runYardsim("run " + scene.string() + " -o " + dir.file("out") + " --quiet");
  INFO(r.out);
  REQUIRE(r.status == 0);
  const yardsim::testing::CsvFile csv(dir.file("out/timeseries.csv"));
  REQUIRE(csv.rows.size() >= 1);
  const auto& row = csv.rows.front();  // t = 0: the equilibrium the run starts from
  REQUIRE(row[0] == 0.0);
  auto at = [&](const std::string& channel) { return row[static_cast<std::size_t>(csv.column(channel))]; };
  CHECK(std::abs(at("hull.z[m]") + 1.5e6 / (1025.0 * 60.0 * 20.0)) < 1e-9);  // keel at minus the draft
  CHECK(std::abs(at("hull.x[m]") - 3.0) < 1e-9);
  CHECK(std::abs(at("hull.y[m]") - 2.0) < 1e-9);
  CHECK(std::abs(at("hull.yaw[rad]") - 20.0 * M_PI / 180.0) < 1e-9);
  CHECK(std::abs(at("hull.roll[rad]")) < 1e-9);  // a symmetric box on an even keel stays upright
  CHECK(std::abs(at("hull.pitch[rad]")) < 1e-9);
}

TEST_CASE("an unmoored barge in a steady side force has no equilibrium: body and direction named and exit 2") {
  yardsim::testing::SceneDir dir;
  // a steady 12.3 kN push along the hull's y axis (body frame), at the centre of the waterplane
  const auto scene = dir.write(
      "push.yaml", barge("  loads:\n    push: {body: hull, point: [0, 0, 1.2], frame: body, series: [[0, 0, 1.23e4, 0, "
                         "0, 0, 0], [100, 0, 1.23e4, 0, 0, 0, 0]]}\n"));
  const auto r = runYardsim("run " + scene.string() + " -o " + dir.file("out") + " --quiet");
  INFO(r.out);
  CHECK(r.status == 2);
  CHECK_THAT(r.out, Catch::Contains("hull: sway (y) has no stiffness and a net force of 12.3 kN") &&
                        Catch::Contains("set equilibrium: false") && Catch::Contains("nothing was simulated"));
  // (run.json) => written anyway: status failed, the reason naming the body and the direction
  const std::string json = slurp(dir.file("out/run.json"));
  CHECK_THAT(json, Catch::Contains("\"status\":\"failed\"") &&
                       Catch::Contains("hull: sway (y) has no stiffness and a net force of 12.3 kN"));
}

TEST_CASE(
    "a --checkpoint-every below 1 ms or above the checkpoint ceiling is refused before the run "
    "(exit 1)") {
  yardsim::testing::SceneDir dir;
  const std::string scene =
      std::string(YARDSIM_SOURCE_DIR) + "/tests/report/data/over_mbl.yaml";  // dt 1 ms
  // (1e-300 s: found by tests/fuzz/mutate.py) => refused at once, not checkpoints without end
  const auto tiny =
      yardsim::testing::shell(std::string(YARDSIM_EXE) + " run " + scene + " -o " + dir.file("a") +
                                  " --quiet --checkpoint-every 1e-300",
                              20);
  INFO(tiny.out);
  CHECK(tiny.status == 1);
  CHECK_THAT(tiny.out,
             Catch::Contains("--checkpoint-every: expected a period of at least 0.001 s"));
  CHECK_FALSE(std::filesystem::exists(dir.path() / "a/checkpoints"));
  // (1 ms over 2000 s) => 2e6 checkpoints, above the rows ceiling of 1e6
  const auto many = runYardsim("run " + scene + " -o " + dir.file("b") +
                               " --quiet --until 2000 --checkpoint-every 0.001");
  INFO(many.out);
  CHECK(many.status == 1);
  CHECK_THAT(many.out, Catch::Contains("is 2e+06 checkpoints, above the ceiling of 1e+06"));
  // (0.25 s over 0.5 s) => runs, with the one checkpoint before the end
  const auto fine = runYardsim("run " + scene + " -o " + dir.file("c") +
                               " --quiet --until 0.5 --checkpoint-every 0.25");
  INFO(fine.out);
  CHECK(fine.status == 0);
  CHECK(std::filesystem::exists(dir.path() / "c/checkpoints/t000000.250.ckpt"));
}

TEST_CASE(
    "a catenary line that fails at the start of an equilibrium is a numerical failure (exit 2) not "
    "exit 3") {
  // (tests/fuzz/mutate.py: FC2's north-west fairlead moved from x = -56 m to -1 m in the
  // launching scene; the equilibrium's search then fails a catenary solve at t = 0, which was an
  // internal error)
  yardsim::testing::SceneDir dir;
  const std::filesystem::path examples = std::filesystem::path(YARDSIM_SOURCE_DIR) / "examples";
  for (const char* folder : {"launching_floating_cranes", "floating_crane"})
    std::filesystem::copy(examples / folder, dir.path() / folder,
                          std::filesystem::copy_options::recursive);
  std::string text = slurp((examples / "launching_floating_cranes/scene.yaml").string());
  const std::string from = "fairlead: {body: FC2.barge, point: [-56, 21, 1]}";
  REQUIRE(text.find(from) != std::string::npos);
  text.replace(text.find(from), from.size(), "fairlead: {body: FC2.barge, point: [-1, 21, 1]}");
  std::ofstream(dir.path() / "launching_floating_cranes/scene.yaml") << text;
  const auto r = runYardsim("run " + dir.file("launching_floating_cranes/scene.yaml") + " -o " +
                            dir.file("out") + " --quiet --until 1");
  INFO(r.out);
  CHECK(r.status == 2);
  CHECK_THAT(r.out, Catch::Contains("numerical failure before the run") &&
                        Catch::Contains("catenary line") && !Catch::Contains("internal error"));
  CHECK_THAT(slurp(dir.file("out/run.json")), Catch::Contains("\"status\":\"failed\""));
}

TEST_CASE(
    "the stiffness guard's warning is an alarm of kind warning: once on the console and in "
    "run.json and --fail-on alarm exits 4") {
  yardsim::testing::SceneDir dir;
  const std::string scene =
      std::string(YARDSIM_SOURCE_DIR) + "/tests/report/data/guard_warning.yaml";
  const auto r = runYardsim("run " + scene + " -o " + dir.file("a") + " --quiet");
  INFO(r.out);
  CHECK(r.status == 0);  // a warning does not stop the run
  // (console) => the guard's text once (at the door), then one summary line with its count and
  // omega_max dt: sqrt(g (m l + m_b l) cos(q0) / I_O) dt for the arm and its bob (the scene's
  // comment), linearised at the initial state
  std::size_t texts = 0;
  for (auto at = r.out.find("omega_max = "); at != std::string::npos;
       at = r.out.find("omega_max = ", at + 1))
    ++texts;
  CHECK(texts == 1);
  const double omegaDt = std::sqrt(9.81 * (1000.0 * 5.0 + 1.0 * 5.0) * std::cos(0.3) /
                                   (100.0 + 1000.0 * 25.0 + 0.1 + 1.0 * 25.0)) *
                         0.01;
  CHECK_THAT(r.out, Catch::Contains("warning: 'arm': 1 time(s) from t = 0 s, value 0.0136"));
  // (run.json) => one alarm of kind warning: the stiffest body, omega_max dt, the text
  const std::string json = slurp(dir.file("a/run.json"));
  const std::string head =
      "{\"model\":\"\",\"element\":\"arm\",\"kind\":\"warning\",\"severity\":\"warning\","
      "\"first\":0,"
      "\"count\":1,\"worst\":";
  const auto at = json.find(head);
  REQUIRE(at != std::string::npos);
  CHECK(std::stod(json.substr(at + head.size())) == Approx(omegaDt).epsilon(1e-4));
  CHECK_THAT(json, Catch::Contains("\"message\":\"" + scene + ":11:") &&
                       Catch::Contains("integrator.dt: mechanical system 'mechanics': "
                                       "explicit_euler at dt = 0.01 s"));
  // (--fail-on) => alarm counts warnings (exit 4, output kept); safety only the safety alarms
  const auto strict =
      runYardsim("run " + scene + " -o " + dir.file("b") + " --quiet --fail-on alarm");
  CHECK(strict.status == 4);
  CHECK(std::filesystem::exists(dir.path() / "b/timeseries.csv"));
  const auto safety =
      runYardsim("run " + scene + " -o " + dir.file("c") + " --quiet --fail-on safety");
  CHECK(safety.status == 0);
  // (the report's rope over its MBL) => a safety alarm: exit 4 under --fail-on safety too
  const auto mbl =
      runYardsim("run " + std::string(YARDSIM_SOURCE_DIR) + "/tests/report/data/over_mbl.yaml -o " +
                 dir.file("d") + " --quiet --fail-on safety");
  CHECK(mbl.status == 4);
}

TEST_CASE(
    "a barge turned 90 degrees in yaw pushed along world x names its sway in its own frame and the "
    "world direction") {
  yardsim::testing::SceneDir dir;
  // (yaw 90 degrees) => the hull's y axis is world -x: a push along world +x (frame: world) is a
  // sway force of -12.3 kN in the body's own frame
  std::string text = barge(
      "  loads:\n    push: {body: hull, point: [0, 0, 1.2], frame: world, series: [[0, 1.23e4, 0, "
      "0, "
      "0, 0, 0], [100, 1.23e4, 0, 0, 0, 0, 0]]}\n");
  text.replace(text.find("rpy_deg: [0, 0, 20]"), 19, "rpy_deg: [0, 0, 90]");
  const auto scene = dir.write("push.yaml", text);
  const auto r = runYardsim("run " + scene.string() + " -o " + dir.file("out") + " --quiet");
  INFO(r.out);
  CHECK(r.status == 2);
  CHECK_THAT(r.out,
             Catch::Contains(
                 "hull: sway (y) has no stiffness and a net force of 12.3 kN (along the body's "
                 "own y axis, world direction [+1.000, +0.000, +0.000] at the initial pose)"));
  CHECK_THAT(r.out, !Catch::Contains("surge"));  // not the world x axis's name
}
