// Pair filtering in scenes (docs/collision.md "Pairs"): a body never touches its parent body, and
// the pairs a scene lists under `ignore:` are never tested, in either order; two bodies on the
// world that overlap are a contact pair (zero force, counted in `collision.points`).
#include <catch2/catch.hpp>
#include <string>

#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {

// (scene text, until s) => its timeseries
testing::CsvFile simulate(const testing::SceneDir& dir, const std::string& text, double until) {
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", text));
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", until, {}, {}});
  return testing::CsvFile((dir.path() / "out" / "timeseries.csv").string());
}

// (column) => its value in a row
double at(const testing::CsvFile& csv, std::size_t row, const char* name) {
  const int k = csv.column(name);
  REQUIRE(k >= 0);
  return csv.rows.at(row)[static_cast<std::size_t>(k)];
}

}  // namespace

TEST_CASE("collision scene: a parent body and the pairs of ignore are never in contact") {
  // fixed 1 m boxes: a at the origin, b 0.9 m along x (0.1 m into a), c on a revolute joint to a,
  // 0.9 m along y (0.1 m into its parent); no gravity, nothing moves
  auto points = [](const std::string& bodies, const std::string& ignore) {
    testing::SceneDir dir;
    const std::string box = R"(
      mass: 1000
      inertia: [100, 100, 100]
      geometry: {box: [1, 1, 1]})";
    std::string text = R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  gravity: [0, 0, 0]
  bodies:
    a:
      parent: world
      joint: {name: a_fix, type: fixed})" +
                       box;
    if (bodies.find('b') != std::string::npos)
      text += R"(
    b:
      parent: world
      joint: {name: b_fix, type: fixed}
      placement: {xyz: [0.9, 0, 0]})" +
              box;
    if (bodies.find('c') != std::string::npos)
      text += R"(
    c:
      parent: a
      joint: {name: c_pin, type: revolute, axis: [0, 0, 1]}
      placement: {xyz: [0, 0.9, 0]})" +
              box;
    text += "\ncollision:\n  contact: {default: {law: linear, k: 1.0e8}}\n" + ignore +
            "record: {interval: 0.01, channels: [\"collision.points\"]}\n";
    const auto csv = simulate(dir, text, 0.02);
    return at(csv, csv.rows.size() - 1, "collision.points[-]");
  };
  CHECK(points("ab", "") > 0);                       // two boxes on the world overlap
  CHECK(points("ab", "  ignore: [[b, a]]\n") == 0);  // unless ignored (either order)
  CHECK(points("ac", "") == 0);                      // a body and its parent: by rule
}
