// The multibody model's readers of the committed state (models/multibody/multibody_committed.cpp):
// the joint reactions, accelerations and energy there are the committed state's own, whether they
// come from the look-ahead step (its first stage, the blow-up check's energy at a step's end) or
// are evaluated again.
#include <catch2/catch.hpp>
#include <string>

#include "devs/coupled.hpp"
#include "devs/listener.hpp"
#include "devs/simulator.hpp"
#include "dynamics/rnea.hpp"
#include "mechanics/build.hpp"
#include "mechanics/data.hpp"
#include "mechanics/energy.hpp"
#include "mechanics/stage.hpp"
#include "models/multibody/multibody_model.hpp"
#include "scene/mechanics_reader.hpp"

using namespace yardsim;
using models::MultibodyModel;

namespace {

// A 1 kg, 1 m rod on a hinge about y, held level at the start, with an elastic stay from the
// world to its tip: gravity, a rope (the providers whose stage may be shared) and the hinge's
// servo once a set-point arrives.
const char* kStayedRod = R"(bodies:
  rod:
    parent: world
    joint: {name: hinge, type: revolute, axis: [0, 1, 0], q0_deg: 90}
    mass: 1.0
    com: [0, 0, -0.5]
    inertia: [0.0833333333333333, 0.0833333333333333, 0.001]
ropes:
  stay:
    path: [{body: world, point: [-1.2, 0, 0.3]}, {body: rod, point: [0, 0, -1]}]
    EA: 200.0
    L0: 0.3
    damping: 20.0
)";

mechanics::BuiltMechanics build(const std::string& yaml) {
  models::Params p;
  const YAML::Node n = YAML::Load(yaml);
  for (const char* key : {"bodies", "ropes"}) p.set(key, n[key], {});
  for (const char* key : {"loops", "equalizers"}) p.set(key, YAML::Load("{}"), {});
  p.set("gravity", YAML::Load("[0, 0, -9.81]"), {});
  return mechanics::buildMechanics(scene::parseMechanics(
      p, [](const std::string& param, const YAML::Node&, const std::string& key,
            const std::string& msg) { FAIL(param + "." + key + ": " + msg); }));
}

// A test actor: one servo set-point for the hinge at time `at`, between two grid points.
struct Driver final : devs::Atomic<bool> {
  explicit Driver(devs::Time at) : devs::Atomic<bool>("driver", false), at_(at) {}
  devs::OutPort<models::SetPoint>& out = addOutPort<models::SetPoint>("out");
  devs::Time timeAdvance(const bool& sent) const override { return sent ? devs::kInfinity : at_; }
  void output(const bool&) const override {
    models::SetPoint s;
    s.element = "hinge";
    s.actor = "driver";
    s.target = 0.3;
    s.speed = 2.0;
    out.add(s);
  }
  void internalTransition(bool& sent) const override { sent = true; }
  void externalTransition(bool&, devs::Time) const override {}

 private:
  devs::Time at_;
};

// At every state the model records: its accelerations, joint reactions and energy against the
// stage and the energy evaluated anew at the committed state in a workspace of its own (the same
// providers, the set-points in force), bit for bit.
struct CommittedCheck final : devs::Listener {
  explicit CommittedCheck(const MultibodyModel& m) : mb(m), ref(m.system()) {
    mechanics::connectStage(m.system(), ref);
  }
  void onState(devs::Time, const devs::AtomicBase& m) override {
    if (&m != &mb) return;
    const auto& s = mb.state();
    const auto& model = mb.system().model();
    ref.setPoints = &s.x.setPoints;
    ref.stepStart = s.tx;  // (the stage at a step's start)
    Eigen::VectorXd a(model.nv);
    ref.kernel.acceleration(s.tx, s.x.q, s.x.v, a);
    dynamics::rneaWorld(model, ref.reaction, s.x.q, s.x.v, a, ref.kernel.stageExternalForces());
    dynamics::Data kin(model);
    const double e = mechanics::energy(mb.system(), ref, kin, s.x.q, s.x.v, s.tx);
    ++states;
    if (mb.jointForces()[1] != ref.reaction.F_W[1]) ++staleReactions;
    if (mb.acceleration() != a) ++staleAccelerations;
    if (mb.energy() != e) ++staleEnergies;
  }
  const MultibodyModel& mb;
  mechanics::Data ref;
  int states = 0, staleReactions = 0, staleAccelerations = 0, staleEnergies = 0;
};

}  // namespace

TEST_CASE(
    "the committed state's reactions, accelerations and energy are its own, for every method") {
  // rk4, ab2 and semi-implicit Euler evaluate each step's first stage at the committed state (the
  // kept stage is read); HHT evaluates the tree without the kept call (it is evaluated again);
  // ARKODE and CVODE continue their own history across steps, so their first evaluation in a step
  // is at a state of their own (a stage kept there must not be read). The set-point arrives
  // between grid points (a partial step) and changes the forces from then on.
  for (const char* method :
       {"rk4", "ab2", "semi_implicit_euler", "hht", "arkode_erk", "cvode_adams"}) {
    CAPTURE(method);
    devs::Coupled root("root");
    models::MultibodyOptions opt;
    opt.dt = 0.01;
    opt.integrator.method = method;
    auto& mb = root.add<MultibodyModel>("rod", build(kStayedRod), opt);
    auto& driver = root.add<Driver>(0.125);
    root.couple(driver.out, mb.setpoint);
    devs::Simulator sim(root);
    CommittedCheck check(mb);
    sim.addListener(check);
    sim.runUntil(0.6);
    CHECK(check.states > 60);
    CHECK(check.staleReactions == 0);
    CHECK(check.staleAccelerations == 0);
    CHECK(check.staleEnergies == 0);
    CHECK(mb.state().x.setPoints.drives[1].active);
  }
}
