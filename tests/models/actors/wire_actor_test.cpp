// A block hanging on a wire rope is hoisted by a wire actor: the winch job ends exactly at
// |payout| / speed after it starts, the block rises by the payout, the static tension is the
// weight before and after, and kinetic + potential - work of non-conservative forces stays
// constant.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>

#include "devs/simulator.hpp"
#include "dynamics/kinematics.hpp"
#include "scene/assembler.hpp"
#include "models/multibody/multibody_model.hpp"
#include "scene/scene_loader.hpp"
#include "support/record_collector.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

TEST_CASE("a wire actor hoists a hanging block by its payout, ending exactly on time") {
  testing::SceneDir dir;
  const double m = 1000.0, g = 9.81, ea = 1.0e8, l0 = 10.0;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", R"(schema_version: 1
components:
  rig:
    type: multibody
    params:
      dt: 0.002
      bodies:
        block:
          parent: world
          joint: {name: lift, type: prismatic, axis: [0, 0, 1], q0: -10.000981}
          mass: 1000.0
          inertia: [100, 100, 100]
      ropes:
        hoist:
          path: [{body: world, point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}]
          EA: 1.0e8
          L0: 10.0
          damping: 2.0e4
  winch:
    type: wire_actor
    params: {rope: hoist, payout: -1.0, speed: 0.1, start_at: 2.0}
couplings:
  - {from: winch.setpoint, to: rig.setpoint}
  - {from: rig.event, to: winch.event}
)"));
  auto root = scene::assemble(*scene);
  auto& rig = static_cast<models::MultibodyModel&>(*root->findComponent("rig"));
  devs::Simulator sim(*root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);

  // (static stretch) => T = m g and L - L0 = m g L0 / EA
  const double stretch = m * g * l0 / ea;
  sim.runUntil(2.0);
  const double z0 = rig.state().x.q[0];
  CHECK(z0 == Approx(-(l0 + stretch)).margin(1e-4));
  const double balance0 = rig.energy() - rig.state().x.work;

  sim.runUntil(20.0);
  std::map<std::string, double> at;
  for (const auto& r : rec.ofKind("out")) at[r.model + "." + r.port] = r.t;
  CHECK(at.at("winch.started") == 2.0);
  CHECK(at.at("winch.finished") == 12.0);  // |payout| / speed after the start, exactly
  CHECK(rig.state().x.q[0] - z0 == Approx(1.0).margin(1e-4));  // risen by the payout
  CHECK(rig.rope(0).unstretchedLength(20.0) == Approx(l0 - 1.0).margin(1e-12));
  // tension back to the weight once the block is at rest again
  const auto& x = rig.state().x;
  dynamics::Data data(rig.mechanics());
  dynamics::forwardKinematics(rig.mechanics(), data, x.q, x.v);
  CHECK(rig.rope(0).tension({20.0, rig.mechanics(), data, x.q, x.v}) == Approx(m * g).epsilon(1e-4));
  CHECK(rig.energy() - rig.state().x.work == Approx(balance0).epsilon(1e-6));
}
