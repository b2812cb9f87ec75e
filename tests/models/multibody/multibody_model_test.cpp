#include "scene/mechanics_reader.hpp"
#include "mechanics/build.hpp"
#include "models/multibody/multibody_model.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>

#include "devs/coupled.hpp"
#include "devs/simulator.hpp"
#include "mechanics/description.hpp"
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
  for (const char* key : {"loads", "watch"})
    if (n[key]) p.set(key, n[key], {});
  return p;
}

mechanics::BuiltMechanics build(const std::string& yaml) {
  return mechanics::buildMechanics(scene::parseMechanics(
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

// A test actor: one set-point at time `at`.
struct Sender final : devs::Atomic<bool> {
  Sender(models::SetPoint s, devs::Time at) : devs::Atomic<bool>("driver", false), setPoint(std::move(s)), at_(at) {}
  devs::OutPort<models::SetPoint>& out = addOutPort<models::SetPoint>("out");
  devs::Time timeAdvance(const bool& sent) const override { return sent ? devs::kInfinity : at_; }
  void output(const bool&) const override { out.add(setPoint); }
  void internalTransition(bool& sent) const override { sent = true; }
  void externalTransition(bool&, devs::Time) const override {}
  models::SetPoint setPoint;

 private:
  devs::Time at_;
};

// (hinge set-point) => drive the joint `hinge` to `target` at `speed`, from `driver`
models::SetPoint driveHinge(double target, double speed, bool prescribed) {
  models::SetPoint s;
  s.element = "hinge";
  s.actor = "driver";
  s.target = target;
  s.speed = speed;
  s.prescribed = prescribed;
  return s;
}

// (model, channel name) => its current value
double channel(const MultibodyModel& mb, const std::string& name) {
  std::vector<models::Channel> channels;
  mb.channels(channels);
  for (const auto& c : channels)
    if (c.name == name) return c.read();
  FAIL("no channel " << name);
  return 0.0;
}

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
  // one set-point at t = 0, while the rod is still level: from 90 deg down to 0 at 0.5 rad/s
  auto& driver = root.add<Sender>(driveHinge(0.0, 0.5, false), 0.0);
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
      p.kind = models::SetPoint::Kind::ActorLoad;
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
  auto read = [&](const std::string& name) { return channel(mb, name); };
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

TEST_CASE("an equalizer is a rope: its peak tension and L0 are channels, and it raises over_mbl") {
  // the block released 0.05 m above its rest on the equalizer (branches slack): it falls and the
  // common tension rises through the MBL, 1.2 times the static tension, while it takes the load
  const double m = 500.0, g = 9.81, a = 2.0, h = 3.0, ea = 5.0e7;
  const double l = std::sqrt(a * a + h * h), T = m * g * l / (2.0 * h), L = 2.0 * l;
  const double l0 = L / (1.0 + T / ea);
  std::ostringstream yaml;
  yaml.precision(17);
  yaml << "gravity: [0, 0, -9.81]\nbodies:\n  block:\n    parent: world\n"
       << "    joint: {type: prismatic, axis: [0, 0, 1], q0: " << -h + 0.05 << "}\n"
       << "    mass: " << m << "\n    inertia: [10, 10, 10]\n"
       << "equalizers:\n  eq:\n    sheave: {body: block, point: [0, 0, 0]}\n"
       << "    branches: [[{body: world, point: [" << -a << ", 0, 0]}], [{body: world, point: [" << a
       << ", 0, 0]}]]\n    EA: " << ea << "\n    L0: " << l0 << "\n    damping: 1.0e4\n    mbl: "
       << 1.2 * T << "\n";
  devs::Coupled root("root");
  models::MultibodyOptions opt;
  opt.dt = 1e-3;
  auto& mb = root.add<MultibodyModel>("m", build(yaml.str()), opt);
  REQUIRE(mb.system().ropeIndex("eq") == 0);  // one rope list: a winch set-point can reach it
  devs::Simulator sim(root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  sim.runUntil(1.0);
  auto read = [&](const std::string& name) { return channel(mb, name); };
  CHECK(read("eq.unstretched_length") == Approx(l0).epsilon(1e-15));
  CHECK(read("eq.peak_tension") > 1.2 * T);
  CHECK(read("eq.peak_tension") >= read("eq.tension"));
  std::vector<testing::Record> warnings;
  for (const auto& r : rec.ofKind("out"))
    if (r.port == "event" && r.value.find("over_mbl") != std::string::npos) warnings.push_back(r);
  REQUIRE(!warnings.empty());
  const std::string& v = warnings.front().value;
  CHECK(v.find("eq") != std::string::npos);
  // (the damper acts the moment the branches go taut: the tension jumps past the MBL there) =>
  // the reported tension is at least the MBL
  CHECK(std::stod(v.substr(v.find("over_mbl ") + 9)) >= 1.2 * T);
}

TEST_CASE("a held joint stays where it starts until an actor drives it, a free one falls") {
  std::string held = kRod;
  held.replace(held.find("q0_deg: 90}"), 11, "q0_deg: 90, hold: true}");
  models::MultibodyOptions opt;
  opt.dt = 1e-3;
  devs::Coupled top("top");
  top.addComponent(std::make_unique<MultibodyModel>("brake", build(held), opt));
  top.addComponent(std::make_unique<MultibodyModel>("loose", build(kRod), opt));
  devs::Simulator sim(top);
  sim.runUntil(1.0);
  const auto& b = static_cast<const MultibodyModel&>(*top.findComponent("brake"));
  const auto& l = static_cast<const MultibodyModel&>(*top.findComponent("loose"));
  CHECK(b.state().x.q[0] == Approx(M_PI / 2).margin(1e-9));  // the servo's feedforward holds gravity
  CHECK(l.state().x.q[0] < M_PI / 2 - 0.5);                  // horizontal rod: falls freely
}

TEST_CASE("hold on a joint with more than one degree of freedom is refused") {
  std::string bad = kRod;
  bad.replace(bad.find("type: revolute, axis: [0, 1, 0], q0_deg: 90}"), 44, "type: spherical, hold: true}");
  std::vector<std::string> messages;
  scene::parseMechanics(params(bad), [&](const std::string& param, const YAML::Node&, const std::string& key,
                                         const std::string& msg) { messages.push_back(param + "." + key + ": " + msg); });
  REQUIRE(messages.size() == 1);
  CHECK_THAT(messages[0], Catch::Contains("rod.joint.hold") && Catch::Contains("only a 1-dof joint"));
}

TEST_CASE("a prescribed joint follows its ramp exactly, drags the free link, and locks at the target") {
  // a double pendulum: the upper hinge prescribed from 90 deg to 0 at 0.5 rad/s, the lower free
  const std::string yaml = std::string(kRod) + R"(  link:
    parent: rod
    joint: {name: elbow, type: revolute, axis: [0, 1, 0]}
    placement: {xyz: [0, 0, -1]}
    mass: 1.0
    com: [0, 0, -0.5]
    inertia: [0.0833333333333333, 0.0833333333333333, 0.001]
)";
  devs::Coupled root("root");
  models::MultibodyOptions opt;
  opt.dt = 1e-3;
  auto& mb = root.add<MultibodyModel>("pendulum", build(yaml), opt);
  auto& driver = root.add<Sender>(driveHinge(0.0, 0.5, true), 0.0);
  root.couple(driver.out, mb.setpoint);
  devs::Simulator sim(root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  auto read = [&](const std::string& n) { return channel(mb, n); };
  const double balance0 = read("energy_balance");  // at rest, level, before the set-point
  // (during the ramp) => the hinge angle is the ramp, to round-off; the elbow swings freely
  sim.runUntil(1.7);
  const double t1 = mb.state().tx;
  CHECK(mb.state().x.q[0] == Approx(M_PI / 2 - 0.5 * t1).margin(1e-12));
  CHECK(mb.state().x.v[0] == Approx(-0.5).margin(1e-12));
  CHECK(std::abs(mb.state().x.v[1]) > 0.01);
  sim.runUntil(6.0);
  // (ramp end) => "reached" exactly when the ramp ends, a time event; locked at 0 afterwards
  std::vector<testing::Record> reached;
  for (const auto& r : rec.ofKind("out"))
    if (r.port == "event") reached.push_back(r);
  REQUIRE(reached.size() == 1);
  CHECK(reached[0].t == Approx((M_PI / 2) / 0.5).epsilon(1e-12));
  CHECK(mb.state().x.q[0] == 0.0);
  CHECK(mb.state().x.v[0] == 0.0);
  // (energy) => kinetic + potential - work of the enforcing effort and the impulses is constant
  // (to the trapezoidal rule's error on the work; the energies are about 10 J)
  CHECK(std::abs(read("energy_balance") - balance0) < 1e-4);
  CHECK(std::abs(read("work")) > 1.0);  // the effort did work
}

TEST_CASE("a body load from a YAML time series: the momentum is its integral, its channels read it") {
  const char* yaml = R"(gravity: [0, 0, 0]
bodies:
  block: {parent: world, joint: {type: free}, mass: 4.0, inertia: [1, 2, 3]}
loads:
  push:                       # 0 -> 8 N over 1 s, held for 1 s, then off
    body: block
    series: [[0, 0, 0, 0, 0, 0, 0], [1, 8, 0, 0, 0, 0, 0], [2, 8, 0, 0, 0, 0, 0], [2, 0, 0, 0, 0, 0, 0]]
)";
  devs::Coupled root("root");
  models::MultibodyOptions opt;
  opt.dt = 0.01;
  auto& mb = root.add<MultibodyModel>("m", build(yaml), opt);
  auto read = [&](const std::string& n) { return channel(mb, n); };
  devs::Simulator sim(root);
  sim.runUntil(0.5);
  CHECK(read("push.fx") == Approx(4.0));
  sim.runUntil(3.0);
  // impulse 0.5 * 8 * 1 + 8 * 1 = 12 N s on 4 kg; x(t) integrates v: 1/3 + 2 + 3 (RK4 is exact on
  // these piecewise polynomials, whose kinks fall on grid points)
  CHECK(mb.state().x.v[3] == Approx(3.0).epsilon(1e-12));
  CHECK(mb.state().x.q[0] == Approx(16.0 / 3.0).epsilon(1e-12));
  CHECK(read("push.fx") == 0.0);
  // all of it became kinetic energy (to the trapezoidal rule the work is integrated with)
  CHECK(read("work") == Approx(0.5 * 4.0 * 9.0).epsilon(1e-4));
}

TEST_CASE("a set-point at a step's end is seen by the next step's event functions") {
  // the rod hangs at rest (q = v = 0 at every step), so each step starts where the last ended and
  // its event functions at the start are reused from there (multibody_model.cpp) unless the
  // set-points changed. A drive to the angle it already holds arrives on the grid (t = 0.25) or
  // between two steps (0.255): the drive's function is above zero from the moment it starts
  // either way, so both runs report the same "reached" events; a stale function from before the
  // set-point (-1: no drive) would make the first run see a crossing the second does not
  auto reachedEvents = [](double at) {
    std::string rod = kRod;
    rod.replace(rod.find("q0_deg: 90"), 10, "q0_deg: 0 ");
    devs::Coupled root("root");
    models::MultibodyOptions opt;
    opt.dt = 0.01;
    opt.driveTolerance = 1e-4;
    auto& mb = root.add<MultibodyModel>("pendulum", build(rod), opt);
    auto& driver = root.add<Sender>(driveHinge(0.0, 0.5, false), at);
    root.couple(driver.out, mb.setpoint);
    devs::Simulator sim(root);
    testing::RecordCollector rec(false);
    sim.addListener(rec);
    sim.runUntil(1.0);
    CHECK(mb.state().x.q[0] == 0.0);
    std::size_t n = 0;
    for (const auto& r : rec.ofKind("out"))
      if (r.port == "event") ++n;
    return n;
  };
  CHECK(reachedEvents(0.25) == reachedEvents(0.255));
}

TEST_CASE("a watched quantity crossing its threshold is a located state event, once per crossing") {
  const std::string yaml = std::string(kRod) + R"(watch:
  low: {channel: hinge.q, below: 1.0}
)";
  devs::Coupled root("root");
  models::MultibodyOptions opt;
  opt.dt = 0.01;
  root.add<MultibodyModel>("pendulum", build(yaml), opt);
  devs::Simulator sim(root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  // released level (90 deg), the rod swings through 1 rad on the way down, to -90 deg and back up
  // past 1 rad (not watched: rising) and down again: within 3 s (period about 2.4 s) two crossings
  sim.runUntil(3.0);
  std::vector<testing::Record> crossed;
  for (const auto& r : rec.ofKind("out"))
    if (r.port == "event") crossed.push_back(r);
  REQUIRE(crossed.size() == 2);
  for (const auto& r : crossed) {
    // "low crossed <value>" (6 digits): the angle at the located time is the threshold
    const auto at = r.value.find("low crossed ");
    REQUIRE(at != std::string::npos);
    CHECK(std::stod(r.value.substr(at + 12)) == Approx(1.0).margin(1e-5));
  }
  CHECK(crossed[1].t - crossed[0].t > 1.5);
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

TEST_CASE(
    "the state's trace text is what printf %g and a default ostream print for each coordinate") {
  // (coordinates across signs, magnitudes, rounding ties and non-finite values) => the trace's
  // JSON string, checked against snprintf "%g" and against the old ostream form
  models::MultibodyState x;
  x.q.resize(12);
  x.q << 0.0, -0.0, 1.0 / 3.0, -2.5e-7, 1234567.0, 999999.5, 1e-310, -1.7976931348623157e308,
      0.785398163397, std::nan(""), INFINITY, -INFINITY;
  std::string expected = "\"q=[";
  std::ostringstream old;
  old << "q=[";
  for (Eigen::Index i = 0; i < x.q.size(); ++i) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", x.q[i]);
    expected += (i ? "," : "") + std::string(buf);
    old << (i ? "," : "") << x.q[i];
  }
  expected += "]\"";
  old << "]";
  std::string out;
  devs::TraceFormat<models::MultibodyState>::write(out, x);
  CHECK(out == expected);
  CHECK(out == "\"" + old.str() + "\"");
  std::ostringstream streamed;
  streamed.precision(17);  // the stream's precision does not change the text
  streamed << x;
  CHECK("\"" + streamed.str() + "\"" == expected);
  CHECK(out.find("1e+06") != std::string::npos);  // 999999.5 rounds up to the next decade
}
