// Regression test of examples/double_pendulum (Ha et al. 2015, §4.1): the actor timeline and
// the final angles, against what the scenario implies (30 deg and 45 deg at 6 deg/s, then 90
// deg more).
#include <catch2/catch.hpp>
#include <cmath>
#include <map>

#include "devs/simulator.hpp"
#include "scene/assembler.hpp"
#include "models/multibody/multibody_model.hpp"
#include "scene/scene_loader.hpp"
#include "support/record_collector.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

TEST_CASE("double pendulum: actor 2 finishes first, actor 3 starts after both, 135 and 30 deg") {
  auto scene = scene::loadSceneOrThrow(std::string(YARDSIM_SOURCE_DIR) +
                                        "/examples/double_pendulum/scene.yaml");
  auto root = scene::assemble(*scene);
  devs::Simulator sim(*root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  sim.runUntil(scene->until);

  std::map<std::string, double> started, finished;
  for (const auto& r : rec.ofKind("out")) {
    if (r.port == "started") started[r.model] = r.t;
    if (r.port == "finished") finished[r.model] = r.t;
  }
  const double speed = 6.0;  // deg/s
  CHECK(started.at("actor1") == 0.0);
  CHECK(started.at("actor2") == 0.0);
  // each finishes when its ramp ends (travel / speed), within the servo's settling
  CHECK(finished.at("actor2") == Approx(30.0 / speed).margin(0.1));
  CHECK(finished.at("actor1") == Approx(45.0 / speed).margin(0.1));
  CHECK(finished.at("actor2") < finished.at("actor1"));
  CHECK(started.at("actor3") == finished.at("actor1"));  // both done: actor 1 was the last
  CHECK(finished.at("actor3") == Approx(finished.at("actor1") + 90.0 / speed).margin(0.1));

  const auto& mb = static_cast<const models::MultibodyModel&>(*root->findComponent("pendulum"));
  const double deg = M_PI / 180.0;
  CHECK(mb.state().x.q[0] == Approx(135.0 * deg).margin(2e-4));
  CHECK(mb.state().x.q[1] == Approx(30.0 * deg).margin(2e-4));
}
