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

namespace {
// (the drive's lines 10 and 11 of the actor's params, the file's parameters) => a scene whose
// actor `haul` hoists a hook on the rope `hoist`
std::string withDrive(const std::string& line10, const std::string& line11 = "",
                      const std::string& params = "{}") {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
components:
  haul:
    type: wire_actor
    params:
      rope: hoist
      payout: -1
      speed: 0.1
      )" + line10 + "\n      " +
         line11 + R"(
mechanics:
  gravity: [0, 0, -9.81]
  bodies:
    hook:
      parent: world
      joint: {name: hook_z, type: prismatic, axis: [0, 0, 1], q0: -10}
      mass: 100
      inertia: [1, 1, 1]
  ropes:
    hoist: {path: [{point: [0, 0, 0]}, {body: hook, point: [0, 0, 0]}], EA: 1.0e6, L0: 10}
params: )" + params + "\n";
}
}  // namespace

// The door of a scene's wire_actor drive: a negative or NaN acceleration or jerk limit, and a
// jerk limit without an acceleration limit, are refused before the run, each at the value in the
// file (file:line:col), with the parameter's key path and what was expected; a sound drive
// passes.
TEST_CASE("a wire actor's bad accel or jerk is refused at the door with its place in the file") {
  using Catch::Matchers::Contains;
  testing::SceneDir dir;
  // (file name, lines 10 and 11, parameters) => the door's report, which must refuse the scene
  auto refused = [&](const std::string& name, const std::string& l10, const std::string& l11,
                     const std::string& params = "{}") {
    const auto r = scene::loadScene(dir.write(name, withDrive(l10, l11, params)));
    CHECK(r.diagnostics.hasErrors());
    CHECK_FALSE(r.scene);
    return r.diagnostics.report();
  };
  const std::string ok = "ok.yaml";
  const auto good = scene::loadScene(dir.write(ok, withDrive("accel: 0.02", "jerk: 0.1")));
  INFO(good.diagnostics.report());
  CHECK_FALSE(good.diagnostics.hasErrors());
  CHECK(good.scene);

  // (negative, NaN) accel: at line 10, the value's column 14
  const std::string negA = refused("neg_accel.yaml", "accel: -0.02", "jerk: 0");
  CHECK_THAT(negA, Contains("neg_accel.yaml:10:14") && Contains("components.haul.params.accel") &&
                       Contains("must be >= 0 m/s^2"));
  const std::string nanA = refused("nan_accel.yaml", "accel: .nan", "");
  CHECK_THAT(nanA, Contains("nan_accel.yaml:10:14") && Contains("components.haul.params.accel") &&
                       Contains("expected a number in m/s^2") && Contains(".nan"));
  // (negative, NaN) jerk: at line 11, column 13
  const std::string negJ = refused("neg_jerk.yaml", "accel: 0.02", "jerk: -0.1");
  CHECK_THAT(negJ, Contains("neg_jerk.yaml:11:13") && Contains("components.haul.params.jerk") &&
                       Contains("must be >= 0 m/s^3"));
  const std::string nanJ = refused("nan_jerk.yaml", "accel: 0.02", "jerk: .nan");
  CHECK_THAT(nanJ, Contains("nan_jerk.yaml:11:13") && Contains("components.haul.params.jerk") &&
                       Contains("expected a number in m/s^3") && Contains(".nan"));
  // a jerk limit without an acceleration limit: none given, or 0
  const std::string alone = refused("jerk_alone.yaml", "jerk: 0.01", "");
  CHECK_THAT(alone, Contains("jerk_alone.yaml:10:13") && Contains("components.haul.params.jerk") &&
                        Contains("needs an acceleration limit: give accel > 0"));
  const std::string zero = refused("jerk_zero_accel.yaml", "accel: 0", "jerk: 0.01");
  CHECK_THAT(zero, Contains("jerk_zero_accel.yaml:11:13") &&
                       Contains("needs an acceleration limit: give accel > 0"));
  // a drive given through the file's parameters (as the offshore scenes give $hoist_accel):
  // refused where the actor uses it
  const std::string viaParam = refused("param.yaml", "accel: $a", "", "{a: -0.02}");
  CHECK_THAT(viaParam, Contains("param.yaml:10:14") && Contains("components.haul.params.accel") &&
                           Contains("must be >= 0 m/s^2"));
}
