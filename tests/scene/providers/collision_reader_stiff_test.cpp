// Stiff contact (k = 1e9 and 1e10) with the implicit integrators at a scene's usual step (0.01 s):
// a 1000 kg box set down from 1 mm (0.14 m/s at impact) on the ground through a Hertzian
// Hunt-Crossley law settles at its weight, HHT and generalized-alpha alike, and sinks the law's
// static depth (m g / (4 k))^(1/n). (The linear spring-damper does not: its damping force jumps
// from 0 to c ddelta/dt where the contact closes, docs/collision.md "Stiff contact".)
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>

#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {

// (law, integrator) => the last row's box.z and floor.box.fz after 5 s
std::pair<double, double> settle(const std::string& law, const std::string& method) {
  testing::SceneDir dir;
  const std::string text = R"(schema_version: 1
integrator: {method: )" + method +
                           R"(, dt: 0.01}
mechanics:
  gravity: [0, 0, -9.81]
  bodies:
    box:
      parent: world
      joint: {name: box_free, type: free, q0: {xyz: [0, 0, 0.501]}}
      mass: 1000
      inertia: [166.7, 166.7, 166.7]
      geometry: {box: [1, 1, 1]}
  collision:
    floor:
      bodies: [box]
      ground: 0
      contact:
        default: )" + law + R"(
record: {interval: 0.5, channels: ["box.z", "floor.*"]}
)";
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", text));
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", 5.0, {}, {}});
  const testing::CsvFile csv((dir.path() / "out" / "timeseries.csv").string());
  const auto& last = csv.rows.back();
  REQUIRE(last[0] == Approx(5.0));
  return {last[static_cast<std::size_t>(csv.column("box.z[m]"))],
          last[static_cast<std::size_t>(csv.column("floor.box.fz[N]"))]};
}

}  // namespace

TEST_CASE(
    "collision scene: stiff Hertzian contact settles with HHT and generalized-alpha at 0.01 s") {
  const double m = 1000, g = 9.81, n = 1.5;
  for (const double k : {1e9, 1e10}) {
    for (const std::string method : {"hht", "generalized_alpha"}) {
      INFO(method << " k = " << k);
      std::ostringstream law;
      law << "{law: hunt_crossley, n: 1.5, k: " << k
          << ", restitution: 0.5, impact_speed: 0.1, mu: 0.3, slip_speed: 0.01}";
      const auto [z, fz] = settle(law.str(), method);
      CHECK(fz == Approx(m * g).epsilon(1e-6));
      CHECK(0.5 - z == Approx(std::pow(m * g / (4 * k), 1 / n)).epsilon(1e-6));  // 4 corners
    }
  }
}
