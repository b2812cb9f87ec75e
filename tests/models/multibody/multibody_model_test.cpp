#include "models/multibody/multibody_model.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>

#include "devs/coupled.hpp"
#include "devs/simulator.hpp"
#include "models/multibody/mechanics_spec.hpp"
#include "support/record_collector.hpp"
#include "support/test_models.hpp"

using namespace yardsim;
using models::MultibodyModel;

namespace {

// (YAML of the multibody params) => the params as a scene would give them
models::Params params(const std::string& yaml) {
  models::Params p;
  const YAML::Node n = YAML::Load(yaml);
  for (const char* key : {"bodies", "loops", "ropes", "equalizers", "gravity"})
    p.set(key, n[key] ? n[key] : YAML::Load(key == std::string("gravity") ? "[0, 0, -9.81]" : "{}"), {});
  return p;
}

models::BuiltMechanics build(const std::string& yaml) {
  return models::buildMechanics(models::parseMechanics(
      params(yaml), [](const std::string& param, const YAML::Node&, const std::string& key,
                       const std::string& msg) { FAIL(param + "." + key + ": " + msg); }));
}

// A compound pendulum: a 1 kg, 1 m rod about a horizontal axis at one end.
const char* kRod = R"(bodies:
  rod:
    parent: world
    joint: {name: hinge, type: revolute, axis: [0, 1, 0], q0_deg: 90}
    mass: 1.0
    com: [0, 0, -0.5]
    inertia: [0.0833333333333333, 0.0833333333333333, 0.001]
)";

}  // namespace

TEST_CASE("a free compound pendulum keeps its energy and swings at the closed-form period") {
  devs::Coupled root("root");
  models::MultibodyOptions opt;
  opt.dt = 1e-3;
  auto& mb = root.add<MultibodyModel>("pendulum", build(kRod), opt);
  devs::Simulator sim(root);
  const double e0 = mb.energy();
  sim.runUntil(10.0);
  CHECK(mb.energy() == Approx(e0).margin(1e-9 * 9.81 * 0.5));  // E0 = 0: the rod starts level

  // small amplitude: T = 2 pi sqrt(I_O / (m g d)), I_O = m L^2 / 3, d = L / 2
  auto small = build(std::string(kRod).replace(std::string(kRod).find("q0_deg: 90"), 10, "q0_deg: 1 "));
  devs::Coupled root2("root");
  auto& mb2 = root2.add<MultibodyModel>("pendulum", std::move(small), opt);
  devs::Simulator sim2(root2);
  const double T = 2.0 * M_PI * std::sqrt((1.0 / 3.0) / (9.81 * 0.5));
  sim2.runUntil(T);  // one period later the angle is back at its start
  CHECK(mb2.state().x.q[0] == Approx(M_PI / 180.0).epsilon(1e-4));
  sim2.runUntil(1.5 * T);  // half a period after that, at the other extreme
  CHECK(mb2.state().x.q[0] == Approx(-M_PI / 180.0).epsilon(1e-4));
}

TEST_CASE("a joint drive follows its ramp and reports the target as a located state event") {
  devs::Coupled root("root");
  models::MultibodyOptions opt;
  opt.dt = 1e-3;
  opt.driveTolerance = 1e-4;
  auto& mb = root.add<MultibodyModel>("pendulum", build(kRod), opt);
  // a test actor: one set-point at t = 0, while the rod is still level
  struct Driver final : devs::Atomic<bool> {
    Driver() : devs::Atomic<bool>("driver", false) {}
    devs::OutPort<models::SetPoint>& out = addOutPort<models::SetPoint>("out");
    devs::Time timeAdvance(const bool& sent) const override { return sent ? devs::kInfinity : 0.0; }
    void output(const bool&) const override {
      models::SetPoint s;
      s.element = "hinge";
      s.actor = "driver";
      s.target = 0.0;   // from 90 deg down to 0 at 0.5 rad/s
      s.speed = 0.5;
      out.add(s);
    }
    void internalTransition(bool& sent) const override { sent = true; }
    void externalTransition(bool&, devs::Time) const override {}
  };
  auto& driver = root.add<Driver>();
  root.couple(driver.out, mb.setpoint);
  devs::Simulator sim(root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  sim.runUntil(8.0);
  const auto outs = rec.ofKind("out");
  std::vector<testing::Record> reached;
  for (const auto& r : outs)
    if (r.port == "event") reached.push_back(r);
  REQUIRE(reached.size() == 1);
  // the ramp ends at (pi/2)/0.5 s; the servo settles within tolerance a little later
  const double rampEnd = (M_PI / 2) / 0.5;
  CHECK(reached[0].t > rampEnd - 0.05);
  CHECK(reached[0].t < rampEnd + 1.0);
  CHECK(std::abs(mb.state().x.q[0]) < 1e-4);  // held at the target afterwards
}

TEST_CASE("a body load on a free body changes its momentum by F dt") {
  const char* yaml = R"(gravity: [0, 0, 0]
bodies:
  block:
    parent: world
    joint: {type: free}
    mass: 4.0
    inertia: [1, 2, 3]
)";
  devs::Coupled root("root");
  models::MultibodyOptions opt;
  opt.dt = 0.01;
  auto& mb = root.add<MultibodyModel>("m", build(yaml), opt);
  struct Pusher final : devs::Atomic<int> {
    Pusher() : devs::Atomic<int>("pusher", 0) {}
    devs::OutPort<models::SetPoint>& out = addOutPort<models::SetPoint>("out");
    devs::Time timeAdvance(const int& s) const override { return s < 2 ? 1.0 : devs::kInfinity; }
    void output(const int& s) const override {
      models::SetPoint p;
      p.kind = models::SetPoint::Kind::BodyLoad;
      p.element = "block";
      p.force[0] = s == 0 ? 8.0 : 0.0;  // 8 N along x from t = 1 s to t = 2 s
      out.add(p);
    }
    void internalTransition(int& s) const override { ++s; }
    void externalTransition(int&, devs::Time) const override {}
  };
  auto& pusher = root.add<Pusher>();
  root.couple(pusher.out, mb.setpoint);
  devs::Simulator sim(root);
  sim.runUntil(3.0);
  // free joint: v = (omega_B, v_B) in the body frame; no rotation here
  CHECK(mb.state().x.v[3] == Approx(8.0 * 1.0 / 4.0).epsilon(1e-9));
  CHECK(mb.state().x.q[0] == Approx(0.5 * 2.0 * 1.0 + 2.0 * 1.0).epsilon(1e-9));  // x(3) = 1 + 2
}

TEST_CASE("a block on an equalizer rests where both branches carry m g l / (2 h)") {
  // anchors at x = +-a, the block's sheave h below them; L0 chosen so that this is equilibrium
  const double m = 500.0, g = 9.81, a = 2.0, h = 3.0, ea = 5.0e7;
  const double l = std::sqrt(a * a + h * h), T = m * g * l / (2.0 * h), L = 2.0 * l;
  const double l0 = L / (1.0 + T / ea);  // T = EA (L - L0) / L0
  std::ostringstream yaml;
  yaml.precision(17);
  yaml << "gravity: [0, 0, -9.81]\nbodies:\n  block:\n    parent: world\n"
       << "    joint: {type: prismatic, axis: [0, 0, 1], q0: " << -h << "}\n"
       << "    mass: " << m << "\n    inertia: [10, 10, 10]\n"
       << "equalizers:\n  eq:\n    sheave: {body: block, point: [0, 0, 0]}\n"
       << "    branches: [[{body: world, point: [" << -a << ", 0, 0]}], [{body: world, point: [" << a
       << ", 0, 0]}]]\n    EA: " << ea << "\n    L0: " << l0 << "\n    damping: 1.0e4\n";
  devs::Coupled root("root");
  models::MultibodyOptions opt;
  opt.dt = 1e-3;
  auto& mb = root.add<MultibodyModel>("m", build(yaml.str()), opt);
  devs::Simulator sim(root);
  sim.runUntil(2.0);
  CHECK(mb.state().x.q[0] == Approx(-h).margin(1e-9));
  std::vector<models::Channel> channels;
  mb.channels(channels);
  auto read = [&](const std::string& name) {
    for (const auto& c : channels)
      if (c.name == name) return c.read();
    FAIL("no channel " << name);
    return 0.0;
  };
  CHECK(read("eq.tension") == Approx(T).epsilon(1e-9));
  CHECK(read("eq.branch0.length") == Approx(l).epsilon(1e-9));
  CHECK(read("eq.length") == Approx(L).epsilon(1e-9));
}

TEST_CASE("a rope passing its minimum breaking load raises one located warning event") {
  // a block released with the rope just slack: the tension rises through 0.9 m g as it takes
  // the load, which is above the rope's MBL
  const char* yaml = R"(bodies:
  block:
    parent: world
    joint: {name: lift, type: prismatic, axis: [0, 0, 1], q0: -10.0}
    mass: 1000.0
    inertia: [100, 100, 100]
ropes:
  hoist:
    path: [{body: world, point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}]
    EA: 1.0e8
    L0: 10.0
    damping: 2.0e5
    mbl: 8829.0
)";
  devs::Coupled root("root");
  models::MultibodyOptions opt;
  opt.dt = 1e-3;
  auto& mb = root.add<MultibodyModel>("m", build(yaml), opt);
  devs::Simulator sim(root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  sim.runUntil(2.0);
  std::vector<testing::Record> warnings;
  for (const auto& r : rec.ofKind("out"))
    if (r.port == "event" && r.value.find("over_mbl") != std::string::npos) warnings.push_back(r);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].t > 0.0);
  CHECK(warnings[0].t < 0.1);  // the rope takes the load within a few milliseconds
  // the event reports the tension at the located time: the MBL, to the location tolerance
  const std::string& v = warnings[0].value;
  CHECK(std::stod(v.substr(v.find("over_mbl ") + 9)) == Approx(8829.0).epsilon(1e-3));
  (void)mb;
}

TEST_CASE("a block dropped onto a slack rope: taut located at the free-fall time, slack again on the rebound") {
  // the rope (L0 = 10 m) from a point 10 m above the block's start... the block starts 0.5 m above
  // where the rope becomes taut, at rest: taut at sqrt(2 * 0.5 / g); with little damping it bounces
  const char* yaml = R"(bodies:
  block:
    parent: world
    joint: {type: prismatic, axis: [0, 0, 1], q0: 0.5}
    mass: 1000.0
    inertia: [100, 100, 100]
ropes:
  sling:
    path: [{body: world, point: [0, 0, 10]}, {body: block, point: [0, 0, 0]}]
    EA: 1.0e7
    L0: 10.0
    damping: 1.0e3
)";
  for (const char* method : {"rk4", "hht", "cvode_bdf"}) {
    INFO(method);
    devs::Coupled root("root");
    models::MultibodyOptions opt;
    opt.dt = 0.01;
    opt.integrator.method = method;
    root.add<MultibodyModel>("m", build(yaml), opt);
    devs::Simulator sim(root);
    testing::RecordCollector rec(false);
    sim.addListener(rec);
    sim.runUntil(1.5);
    std::vector<testing::Record> events;
    for (const auto& r : rec.ofKind("out"))
      if (r.port == "event" && (r.value.find("taut") != std::string::npos || r.value.find("slack") != std::string::npos))
        events.push_back(r);
    REQUIRE(events.size() >= 2);
    CHECK(events[0].value.find("taut") != std::string::npos);
    CHECK(events[0].t == Approx(std::sqrt(2 * 0.5 / 9.81)).epsilon(1e-6));
    CHECK(events[1].value.find("slack") != std::string::npos);
    // bouncing on k = EA / L0 = 1e6 N/m from v0 = sqrt(2 g 0.5) about the static stretch d = m g / k:
    // slack again after (pi + 2 atan(d omega / v0)) / omega (light damping: zeta = 0.016; HHT's
    // period error at omega dt = 0.32 is about 1 %)
    const double w = std::sqrt(1e6 / 1000.0), d = 1000.0 * 9.81 / 1e6, v0 = std::sqrt(2 * 9.81 * 0.5);
    CHECK(events[1].t - events[0].t == Approx((M_PI + 2 * std::atan(d * w / v0)) / w).epsilon(1.5e-2));
  }
}
