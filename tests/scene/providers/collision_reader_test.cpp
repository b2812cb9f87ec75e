// The `collision:` key of scene/providers/ in whole scenes, against closed forms: a box resting
// on the ground for 100 s (force = weight, sink m g / (4 k), no drift), a sphere dropped on it
// (restitution against the exact Hunt-Crossley relation, contact and release located in time),
// a block on an incline (slides at g (sin phi - mu cos phi) above tan phi = mu, creeps at the
// regularisation's closed-form speed below), a rope's clearance to a block moving towards it
// (distance, located clearance_below and touched with witness points), the stiffness guard's
// view of a contact, and bad input refused before the run.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

#include "forces/contact_law.hpp"
#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using Catch::Matchers::Contains;

namespace {

constexpr double kG = 9.81;

// (scene text, until) => its timeseries.csv after a run (trace.jsonl beside it)
testing::CsvFile simulate(const testing::SceneDir& dir, const std::string& text, double until) {
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", text));
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", until, {"jsonl"}, {}, 0.1});
  return testing::CsvFile((dir.path() / "out" / "timeseries.csv").string());
}

// (run directory) => the lines of its trace that mention `what`
std::vector<std::string> traced(const testing::SceneDir& dir, const std::string& what) {
  std::ifstream in(dir.path() / "out" / "trace.jsonl");
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);)
    if (line.find(what) != std::string::npos) out.push_back(line);
  return out;
}

// (trace line) => its time "t"
double timeOf(const std::string& line) {
  return std::stod(line.substr(line.find("\"t\":") + 4));
}

// (column) => its value in a row
double at(const testing::CsvFile& csv, std::size_t row, const char* name) {
  const int k = csv.column(name);
  REQUIRE(k >= 0);
  return csv.rows.at(row)[static_cast<std::size_t>(k)];
}

// a free body `box` of mass m with a box geometry, on the ground through the collision set floor
std::string boxScene(const std::string& gravity, const std::string& law, const std::string& q0,
                     const std::string& integrator, const std::string& extra = "") {
  return R"(schema_version: 1
integrator: )" +
         integrator + R"(
mechanics:
  gravity: )" +
         gravity + R"(
  bodies:
    box:
      parent: world
      joint: {name: box_free, type: free, q0: )" +
         q0 + R"(}
      mass: 1000
      inertia: [166.7, 166.7, 166.7]
      geometry: {box: [1, 1, 1]}
  collision:
    floor:
      bodies: [box]
      ground: 0
      contact:
        default: )" +
         law + "\n" + extra +
         R"(record: {interval: 0.5, channels: ["box.*", "floor.*", "mechanics.*"]}
trace: [jsonl]
)";
}

}  // namespace

TEST_CASE(
    "collision scene: a box resting on the ground carries its weight for 100 s without drift") {
  testing::SceneDir dir;
  const double m = 1000, k = 1e8;
  const auto csv = simulate(dir,
                            boxScene("[0, 0, -9.81]", "{law: linear, k: 1.0e8, c: 2.0e5, mu: 0.3}",
                                     "{xyz: [0, 0, 0.5]}", "{method: hht, dt: 0.01}"),
                            100);
  const std::size_t last = csv.rows.size() - 1, half = last / 2;
  REQUIRE(at(csv, last, "time[s]") == Approx(100));
  CHECK(at(csv, last, "floor.points[-]") == 4);
  CHECK(at(csv, last, "floor.box.fz[N]") == Approx(m * kG).epsilon(1e-9));
  CHECK(at(csv, last, "floor.normal_force[N]") == Approx(m * kG).epsilon(1e-9));
  CHECK(0.5 - at(csv, last, "box.z[m]") == Approx(m * kG / (4 * k)).epsilon(1e-6));  // 4 corners
  CHECK(std::abs(at(csv, last, "box.z[m]") - at(csv, half, "box.z[m]")) < 1e-12);
  CHECK(std::abs(at(csv, last, "box.x[m]")) < 1e-12);
  // the spring's energy k d^2 / 2 at each corner
  const double d = m * kG / (4 * k);
  CHECK(at(csv, last, "floor.energy[J]") == Approx(4 * 0.5 * k * d * d).epsilon(1e-6));
}

TEST_CASE(
    "collision scene: a sphere hitting the ground rebounds with the Hunt-Crossley restitution") {
  testing::SceneDir dir;
  // no gravity (the exact relation has no other force during the impact): the ball arrives at
  // v0 = 4 m/s from 0.1 m; alpha = c / k
  const double alpha = 0.1, v0 = 4.0;
  const std::string text = R"(schema_version: 1
integrator: {method: rk4, dt: 1.0e-4}
mechanics:
  gravity: [0, 0, 0]
  bodies:
    ball:
      parent: world
      joint: {name: ball_free, type: free, q0: {xyz: [0, 0, 0.6]}, v0: [0, 0, 0, 0, 0, -4.0]}
      mass: 100
      inertia: [10, 10, 10]
      geometry: {sphere: 0.5}
  collision:
    floor:
      bodies: [ball]
      ground: 0
      contact:
        default: {law: hunt_crossley, n: 1.5, k: 1.0e8, c: 1.0e7}
record: {interval: 0.001, channels: ["ball.z", "floor.*", "mechanics.*"]}
)";
  const auto csv = simulate(dir, text, 0.1);
  const auto contact = traced(dir, "floor contact"), release = traced(dir, "floor release");
  REQUIRE(contact.size() == 1);
  REQUIRE(release.size() == 1);
  CHECK(timeOf(contact[0]) == Approx(0.1 / v0).epsilon(1e-6));
  // (two rows after the release) => the rebound speed
  const std::size_t last = csv.rows.size() - 1;
  REQUIRE(at(csv, last - 10, "time[s]") > timeOf(release[0]));
  const double v = (at(csv, last, "ball.z[m]") - at(csv, last - 10, "ball.z[m]")) /
                   (at(csv, last, "time[s]") - at(csv, last - 10, "time[s]"));
  CHECK(v / v0 == Approx(forces::huntCrossleyRestitution(alpha * v0)).margin(2e-4));
  // the energy balance over the impact: what the damping took is in the work
  const double lost = 0.5 * 100 * (v0 * v0 - v * v);
  CHECK(-at(csv, last, "mechanics.work[J]") == Approx(lost).epsilon(1e-3));
  CHECK(std::abs(at(csv, last, "mechanics.energy_balance[J]") -
                 at(csv, 0, "mechanics.energy_balance[J]")) < 1e-3 * lost);
}

TEST_CASE(
    "collision scene: a block on an incline slides at g (sin phi - mu cos phi) or creeps below tan "
    "phi = mu") {
  // the incline as tilted gravity: phi about y, the block slides along +x
  const double mu = 0.3, vs = 1e-3;
  auto run = [&](double phiDeg, double until) {
    testing::SceneDir dir;
    const double phi = phiDeg * M_PI / 180;
    const std::string gravity = "[" + std::to_string(kG * std::sin(phi)) + ", 0, " +
                                std::to_string(-kG * std::cos(phi)) + "]";
    return simulate(
        dir,
        boxScene(gravity, "{law: linear, k: 1.0e8, c: 2.0e5, mu: 0.3, slip_speed: 0.001}",
                 "{xyz: [0, 0, 0.49998]}", "{method: hht, dt: 0.002}"),
        until);
  };
  SECTION("above tan phi = mu it slides") {
    const double phi = 25 * M_PI / 180, a = kG * (std::sin(phi) - mu * std::cos(phi));
    const auto csv = run(25, 2.0);
    // (x at 1 s and 2 s) => the acceleration, free of the start transient: x2 - x1 = a (4 - 1) / 2
    const double x1 = at(csv, 2, "box.x[m]"), x2 = at(csv, 4, "box.x[m]");
    REQUIRE(at(csv, 4, "time[s]") == Approx(2.0));
    CHECK((x2 - x1) / 1.5 == Approx(a).epsilon(2e-3));
  }
  SECTION("below it creeps at the regularisation's speed") {
    const double phi = 10 * M_PI / 180, r = std::tan(phi) / mu;
    const auto csv = run(10, 4.0);
    const std::size_t last = csv.rows.size() - 1;
    const double v = (at(csv, last, "box.x[m]") - at(csv, last - 2, "box.x[m]")) / 1.0;
    CHECK(v == Approx(vs * r / std::sqrt(1 - r * r)).epsilon(2e-2));
  }
}

TEST_CASE("collision scene: a rope's clearance to a block moving towards it") {
  // rope axis x = 0 (diameter 0.04 m), block face at x = q - 1 moving at -0.5 m/s from q = 3:
  // distance 1.98 - 0.5 t, below 1 m at t = 1.96 s, touching at t = 3.96 s
  testing::SceneDir dir;
  const std::string text = R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  gravity: [0, 0, 0]
  bodies:
    hook:
      parent: world
      joint: {name: hook_z, type: prismatic, axis: [0, 0, 1]}
      mass: 100
      inertia: [1, 1, 1]
    cart:                     # on the hook's frame: one mechanical system with the rope
      parent: hook
      joint: {name: cart_x, type: prismatic, axis: [1, 0, 0], q0: 3, v0: -0.5}
      mass: 1000
      inertia: [100, 100, 100]
      geometry: {box: [2, 2, 2]}
  ropes:
    hoist: {path: [{point: [0, 0, 10]}, {body: hook, point: [0, 0, 0]}], EA: 1.0e6, L0: 10.5}
  collision:
    near:
      bodies: [cart]
      rope_diameter: 0.04
      contact:
        default: {law: linear, k: 1.0e8}
      clearance:
        rope_cart: {between: [hoist, cart], below: 1.0, range: 3}
record: {interval: 0.5, channels: ["cart_x.q", "near.*"]}
trace: [jsonl]
)";
  const auto csv = simulate(dir, text, 4.2);
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const double t = at(csv, r, "time[s]");
    CHECK(at(csv, r, "near.rope_cart.distance[m]") == Approx(1.98 - 0.5 * t).margin(1e-6));
  }
  const auto below = traced(dir, "near.rope_cart clearance_below");
  const auto touched = traced(dir, "near.rope_cart touched");
  REQUIRE(below.size() == 1);
  REQUIRE(touched.size() == 1);
  CHECK(timeOf(below[0]) == Approx(1.96).margin(1e-6));
  CHECK(timeOf(touched[0]) == Approx(3.96).margin(1e-6));
  // the pair and the witness points: on the rope's axis shifted by its radius, on the face
  CHECK_THAT(below[0], Contains("hoist at (0.020,") && Contains("cart at (1.020,"));
}

TEST_CASE(
    "collision scene: the stiffness guard sees a contact open at the start and its step works") {
  // a 1000 kg box 1 cm above the ground on a contact stiff for rk4 at 0.01 s: omega = sqrt(4 k / m)
  // = 632 rad/s on its four corners, omega dt = 6.3 beyond rk4's 2.83
  const std::string law = "{law: linear, k: 1.0e8, c: 1.0e5, mu: 0.3, slip_speed: 0.01}";
  const std::string q0 = "{xyz: [0, 0, 0.51]}";
  testing::SceneDir dir;
  const auto refused = scene::loadScene(dir.write(
      "r.yaml",
      boxScene("[0, 0, -9.81]", law, q0, "{method: rk4, dt: 0.01, stiffness_check: refuse}")));
  CHECK_THAT(refused.diagnostics.report(),
             Contains("provider 'floor' (contact normal") && Contains("suggestion: dt <="));
  CHECK_THAT(refused.diagnostics.report(), Contains("omega_max = 632 rad/s"));
  // (the guard's suggested step, read from its message) => rk4 at that step rests at the weight
  const std::string report = refused.diagnostics.report();
  const double dt = std::stod(report.substr(report.find("suggestion: dt <= ") + 18));
  REQUIRE(dt > 0);
  REQUIRE(dt < 0.01);
  for (const std::string& integrator :
       {"{method: rk4, dt: " + std::to_string(dt) + "}", std::string("{method: hht, dt: 0.01}"),
        std::string("{method: generalized_alpha, dt: 0.01}")}) {
    testing::SceneDir run;
    const auto csv = simulate(run, boxScene("[0, 0, -9.81]", law, q0, integrator), 3.0);
    const std::size_t last = csv.rows.size() - 1;
    INFO(integrator);
    CHECK(at(csv, last, "floor.box.fz[N]") == Approx(1000 * kG).epsilon(1e-4));
    CHECK(0.5 - at(csv, last, "box.z[m]") == Approx(1000 * kG / 4e8).epsilon(1e-3));
  }
}

TEST_CASE("collision scene: bad input is refused before the run with its place in the file") {
  testing::SceneDir dir;
  auto load = [&](const std::string& name, const std::string& collision,
                  const std::string& geometry = "{box: [1, 1, 1]}") {
    return scene::loadScene(dir.write(name, R"(schema_version: 1
integrator: {method: hht, dt: 0.01}
mechanics:
  bodies:
    box:
      parent: world
      joint: {name: box_free, type: free, q0: {xyz: [0, 0, 0.5]}}
      mass: 1000
      inertia: [166.7, 166.7, 166.7]
      geometry: )" + geometry + R"(
  collision:
    floor:
)" + collision + R"(
record: {interval: 1, channels: ["floor.*"]}
)"));
  };
  const std::string law = "      contact: {default: {law: linear, k: 1.0e8}}\n";
  const auto unknown =
      load("unknown.yaml", "      bodies: [box]\n" + law +
                               "      clearance: {near: {between: [box, crane*], below: 1}}");
  // (a problem found once the system is built) => at the node itself (the between list)
  CHECK_THAT(unknown.diagnostics.report(), Contains("unknown.yaml:15:36:") &&
                                               Contains("'crane*' matches no body") &&
                                               Contains("floor.clearance.near.between"));
  const auto body = load("body.yaml", "      bodies: [box, crate]\n" + law);
  CHECK_THAT(body.diagnostics.report(), Contains("body.yaml:") && Contains("unknown body 'crate'"));
  const auto size =
      load("size.yaml", "      bodies: [box]\n      shapes: {box: {box: [1, 0, 1]}}\n" + law);
  CHECK_THAT(size.diagnostics.report(),
             Contains("size.yaml:14:") && Contains("every edge must be > 0 m"));
  const auto radius =
      load("radius.yaml",
           "      bodies: [box]\n      shapes: {box: {capsule: {radius: -1, length: 2}}}\n" + law);
  CHECK_THAT(radius.diagnostics.report(),
             Contains("radius.yaml:14:") && Contains("capsule.radius: must be > 0 m"));
  // an open mesh (one triangle) as the body's geometry
  std::ofstream(dir.path() / "open.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const auto open = load("open.yaml", "      bodies: [box]\n" + law, "{mesh: open.obj}");
  CHECK_THAT(open.diagnostics.report(),
             Contains("open.yaml:") && Contains("its mesh cannot be used for contact"));
  const auto noLaw = load("nolaw.yaml", "      bodies: [box]");
  CHECK_THAT(noLaw.diagnostics.report(), Contains("nolaw.yaml:13:") && Contains("with a default"));
  CHECK(!load("good.yaml", "      bodies: [box]\n" + law).diagnostics.hasErrors());
  // the damping ramp: the linear law's only, never negative
  const auto rampHc = load("ramphc.yaml",
                           "      bodies: [box]\n      contact: {default: {law: hunt_crossley, k: "
                           "1.0e8, damping_depth: 1.0e-4}}");
  CHECK_THAT(rampHc.diagnostics.report(), Contains("ramphc.yaml:14:") &&
                                              Contains("contact.default.damping_depth") &&
                                              Contains("the linear law's damping ramp"));
  const auto rampNeg = load("rampneg.yaml",
                            "      bodies: [box]\n      contact: {default: {law: linear, k: "
                            "1.0e8, damping_depth: -1.0e-4}}");
  CHECK_THAT(rampNeg.diagnostics.report(),
             Contains("rampneg.yaml:14:") && Contains("contact.default.damping_depth"));
}

namespace {

// the rope-and-cart geometry of the clearance test above in the scene-level spelling: a rope of
// its own diameter 0.06 m on x = 0, the cart's face at x = q - 1 moving at -0.5 m/s from q = 3
// (distance 1.97 - 0.5 t, touching at 3.94 s); `actors` are the scene's components
std::string ropeCartScene(const std::string& actors) {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
)" + actors +
         R"(
mechanics:
  gravity: [0, 0, 0]
  bodies:
    hook:
      parent: world
      joint: {name: hook_z, type: prismatic, axis: [0, 0, 1]}
      mass: 100
      inertia: [1, 1, 1]
    cart:
      parent: hook
      joint: {name: cart_x, type: prismatic, axis: [1, 0, 0], q0: 3, v0: -0.5}
      mass: 1000
      inertia: [100, 100, 100]
      geometry: {box: [2, 2, 2]}
  ropes:
    hoist: {path: [{point: [0, 0, 10]}, {body: hook, point: [0, 0, 0]}], EA: 1.0e6, L0: 10.5,
            diameter: 0.06}
clearance:
  rope_cart: {between: [hoist, cart], below: 1.0, range: 3}
record: {interval: 0.5, channels: ["*"]}
trace: [jsonl]
)";
}

}  // namespace

TEST_CASE("collision scene: the scene-level collision takes every body with a geometry") {
  // the resting box of the first test without a list of bodies: force = weight, sink m g / (4 k)
  testing::SceneDir dir;
  const auto csv = simulate(dir, R"(schema_version: 1
integrator: {method: hht, dt: 0.01}
mechanics:
  bodies:
    box:
      parent: world
      joint: {name: box_free, type: free, q0: {xyz: [0, 0, 0.5]}}
      mass: 1000
      inertia: [166.7, 166.7, 166.7]
      geometry: {box: [1, 1, 1]}
    bare:                     # no geometry: takes no part
      parent: world
      joint: {name: bare_free, type: free, q0: {xyz: [0, 0, -5]}}
      mass: 10
      inertia: [1, 1, 1]
collision:
  ground: 0
  contact: {default: {law: linear, k: 1.0e8, c: 2.0e5, mu: 0.3}}
record: {interval: 0.5, channels: ["*"]}
trace: [jsonl]
)",
                            5.0);
  const std::size_t last = csv.rows.size() - 1;
  CHECK(at(csv, last, "collision.box.fz[N]") == Approx(1000 * kG).epsilon(1e-6));
  CHECK(0.5 - at(csv, last, "box.z[m]") == Approx(1000 * kG / 4e8).epsilon(1e-3));
  CHECK(csv.column("collision.bare.fz[N]") < 0);
  CHECK(at(csv, last, "collision.points[-]") == 4);
}

TEST_CASE("collision scene: a scene-level watch uses the rope's own diameter") {
  testing::SceneDir dir;
  const auto csv = simulate(dir, ropeCartScene(""), 4.2);
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const double t = at(csv, r, "time[s]");
    CHECK(at(csv, r, "rope_cart.distance[m]") == Approx(1.97 - 0.5 * t).margin(1e-6));
  }
  CHECK(csv.column("collision.points[-]") < 0);  // clearance only: no contact channels
  const auto touched = traced(dir, "\"value\":\"rope_cart touched");
  REQUIRE(touched.size() >= 1);
  CHECK(timeOf(touched[0]) == Approx(3.94).margin(1e-6));
  CHECK_THAT(touched[0], Contains("hoist at (0.030,"));
}

TEST_CASE("collision scene: an actor stops a winch when the rope touches the block edge") {
  // haul in 5 m at 0.1 m/s, stopped by rope_cart.touched at 3.94 s; then `after` (after_all:
  // the stopped actor) pays out 1 m at 0.5 m/s: the unstretched length is 10.5 - 0.1 t until
  // 3.94 s, 10.106 + 0.5 (t - 3.94) for 2 s, then 11.106
  testing::SceneDir dir;
  const auto csv = simulate(dir, ropeCartScene(R"(components:
  haul: {type: wire_actor, params: {rope: hoist, payout: -5, speed: 0.1, stop_on: [rope_cart.touched]}}
  after: {type: wire_actor, params: {rope: hoist, payout: 1, speed: 0.5, after_all: [haul]}})"),
                            8.0);
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const double t = at(csv, r, "time[s]");
    const double expected = t <= 3.94   ? 10.5 - 0.1 * t
                            : t <= 5.94 ? 10.106 + 0.5 * (t - 3.94)
                                        : 11.106;
    INFO("t = " << t);
    CHECK(at(csv, r, "hoist.unstretched_length[m]") == Approx(expected).margin(1e-9));
  }
  const auto touched = traced(dir,
                              "\"model\":\"mechanics\",\"kind\":\"out\",\"port\":\"event\","
                              "\"value\":\"rope_cart touched");
  const auto stopped = traced(dir,
                              "\"model\":\"haul\",\"kind\":\"out\",\"port\":\"setpoint\","
                              "\"value\":\"hoist stop\"");
  REQUIRE(touched.size() == 1);
  REQUIRE(stopped.size() == 1);
  CHECK(timeOf(touched[0]) == Approx(3.94).margin(1e-6));
  CHECK(timeOf(stopped[0]) == timeOf(touched[0]));  // at the located time, not a step later
}

TEST_CASE("collision scene: scene-level mistakes are refused at their place") {
  testing::SceneDir dir;
  auto load = [&](const std::string& name, const std::string& extra) {
    return scene::loadScene(dir.write(name, R"(schema_version: 1
integrator: {method: hht, dt: 0.01}
mechanics:
  bodies:
    box:
      parent: world
      joint: {name: box_free, type: free, q0: {xyz: [0, 0, 0.5]}}
      mass: 1000
      inertia: [166.7, 166.7, 166.7]
      geometry: {box: [1, 1, 1]}
collision:
  ground: 0
  contact: {default: {law: linear, k: 1.0e8}}
)" + extra));
  };
  const auto pattern =
      load("pattern.yaml", "clearance:\n  near: {between: [box, crane*], below: 1}\n");
  CHECK_THAT(pattern.diagnostics.report(),
             Contains("pattern.yaml:15:20:") &&
                 Contains("'crane*' matches no body with a geometry") &&
                 Contains("clearance.near.between"));
  const auto ignored = load("ignored.yaml", "  ignore: [[box, crate]]\n");
  CHECK_THAT(ignored.diagnostics.report(), Contains("ignored.yaml:14:") &&
                                               Contains("collision.ignore[0]") &&
                                               Contains("'crate' is not a body with a geometry"));
  // (problems found at read time) => the keys as written at the scene root
  const auto stiffness = load("stiffness.yaml", "  points_per_pair: 0\n");
  CHECK_THAT(stiffness.diagnostics.report(),
             Contains("stiffness.yaml:14:20: error: collision.points_per_pair: must be >= 1"));
  const auto below = load("below.yaml", "clearance:\n  near: {between: [box, box], below: -1}\n");
  CHECK_THAT(below.diagnostics.report(),
             Contains("below.yaml:15:") && Contains("error: clearance.near.below"));
  CHECK(!load("good.yaml", "clearance:\n  near: {between: [box, box], below: 1}\n")
             .diagnostics.hasErrors());
}

TEST_CASE("collision scene: an equalizer's branches are watched with its own diameter") {
  // branch from the sheave (0, 0, 10) to (2, 0, 0): the line 10 x + 2 z = 20; the post's nearest
  // edge (2.5, y, 4.5) lies 14 / sqrt(104) from it, minus the radius 0.025 m
  testing::SceneDir dir;
  const auto csv = simulate(dir, R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  gravity: [0, 0, 0]
  bodies:
    load:
      parent: world
      joint: {name: load_z, type: prismatic, axis: [0, 0, 1]}
      mass: 1000
      inertia: [100, 100, 100]
      geometry: {box: [0.5, 0.5, 0.5]}
    post:
      parent: world
      joint: {name: post_fix, type: fixed}
      placement: {xyz: [3, 0, 5]}
      mass: 100
      inertia: [10, 10, 10]
      geometry: {box: [1, 1, 1]}
  equalizers:
    eq1:
      sheave: {point: [0, 0, 10]}
      branches: [[{body: load, point: [-2, 0, 0]}], [{body: load, point: [2, 0, 0]}]]
      EA: 2.0e8
      L0: 21.0                  # slack: nothing moves
      diameter: 0.05
clearance:
  eq_post: {between: [eq1, post], below: 0.5, range: 5}
record: {interval: 0.5, channels: ["*"]}
trace: [jsonl]
)",
                            1.0);
  for (std::size_t r = 0; r < csv.rows.size(); ++r)
    CHECK(at(csv, r, "eq_post.distance[m]") == Approx(14 / std::sqrt(104.0) - 0.025).margin(1e-9));
}
