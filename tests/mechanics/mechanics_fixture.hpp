#pragma once
// Test support for mechanics/: a System built from the multibody type's YAML (bodies, ropes,
// equalizers) or from a scene with one mechanical system, as a scene would build it, and the
// system with its workspace connected to the stage function.
#include <yaml-cpp/yaml.h>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "mechanics/build.hpp"
#include "mechanics/data.hpp"
#include "mechanics/stage.hpp"
#include "mechanics/system.hpp"
#include "models/params.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/mechanics_reader.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

namespace yardsim::testing {

// (YAML of bodies, ropes, equalizers) => the built mechanics
inline mechanics::BuiltMechanics buildFromYaml(const std::string& yaml) {
  models::Params p;
  const YAML::Node n = YAML::Load(yaml);
  for (const char* key : {"bodies", "loops", "ropes", "equalizers", "gravity"})
    p.set(key, n[key] ? n[key] : YAML::Load(key == std::string("gravity") ? "[0, 0, -9.81]" : "{}"),
          {});
  return mechanics::buildMechanics(scene::parseMechanics(
      p, [](const std::string& param, const YAML::Node&, const std::string& key,
            const std::string& msg) { FAIL(param + "." + key + ": " + msg); }));
}

// A 2 t block on a free joint under a 2-part hoist from the world, and a 500 kg hook on an
// equalizer hanging from the block: three providers besides gravity (none: gravity is the model's)
inline const char* kHoistAndEqualizer = R"(bodies:
  block:
    parent: world
    joint: {type: free, q0: {xyz: [0.3, -0.2, -10.0], rpy_deg: [4, -3, 10]}}
    mass: 2000.0
    inertia: [400, 500, 600]
  hook:
    parent: world
    joint: {type: free, q0: {xyz: [0.1, 0.2, -14.0]}}
    mass: 500.0
    inertia: [20, 20, 20]
ropes:
  hoist:
    path: [{body: world, point: [0, 0, 0]}, {body: block, point: [0, 0, 0.5]}]
    parts: 2
    EA: 1.0e8
    L0: 9.0
    damping: 1.0e4
  sling:
    path: [{body: world, point: [5, 0, 0]}, {body: world, point: [5, 0, -2]}, {body: block, point: [1, 0, 0.5]}]
    EA: 5.0e7
    L0: 8.0
equalizers:
  eq:
    sheave: {body: hook, point: [0, 0, 0]}
    branches: [[{body: block, point: [-1, 0, -0.5]}], [{body: block, point: [1, 0, -0.5]}]]
    EA: 2.0e7
    L0: 6.0
    damping: 1.0e3
)";

// (scene YAML with one mechanical system) => its mechanics, built as a run builds them
inline mechanics::BuiltMechanics buildFromScene(const std::string& yaml) {
  SceneDir dir;
  const auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", yaml).string());
  REQUIRE(scene->systems.size() == 1);
  return mechanics::buildMechanics(scene->systems[0]->spec);
}

// (system) => empty set-points of its size: no drive, load or winch job
inline mechanics::SetPoints noSetPoints(const mechanics::System& s) {
  const auto n = static_cast<std::size_t>(s.model().nbodies);
  return {std::vector<mechanics::JointDrive>(n), std::vector<mechanics::ActorLoad>(n),
          std::vector<mechanics::WinchJob>(s.ropes().size())};
}

// A system with its workspace connected to the stage function and no set-points: data.kernel is
// what an integrator steps.
struct StagedSystem {
  mechanics::System system;
  mechanics::Data data;
  mechanics::SetPoints sp;
  explicit StagedSystem(mechanics::BuiltMechanics built)
      : system(std::move(built), {}, "test"), data(system), sp(noSetPoints(system)) {
    mechanics::connectStage(system, data);
    data.setPoints = &sp;
  }
  const dynamics::Model& model() const { return system.model(); }
};

// (L0) => a scene: a 2 t block on a free joint hanging from (0, 0, 30) by a lumped rope of 8
// segments (10 kg/m, EA 5e7 N, EI 2e4 N m^2, undamped) whose winch a test may drive
inline std::string hangingRopeScene(double length) {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.001}
mechanics:
  bodies:
    block: {parent: world, joint: {type: free, q0: {xyz: [0.4, -0.3, 10.1]}}, mass: 2000,
            inertia: [100, 120, 140]}
  ropes:
    hoist: {model: lumped, path: [{body: world, point: [0, 0, 30]}, {body: block, point: [0, 0, 0.5]}],
            L0: )" +
         std::to_string(length) + R"(, segments: 8, EA: 5.0e7, EI: 2.0e4, mass_per_length: 10,
            diameter: 0.04, damping_ratio: 0}
until: 1
)";
}

// (extra lines of the mechanics block, extra keys of every line) => a scene: a 200 t buoy on a
// surge-sway slider at the fairlead height, moored by 4 lumped chain lines of 8 segments in still
// water, released at 0.5 m/s, stepped by HHT at 0.05 s
inline std::string mooredBuoyScene(const std::string& extra = "",
                                   const std::string& lineKeys = "") {
  std::string s = R"(schema_version: 1
integrator: {method: hht, dt: 0.05, stiffness_check: off}
mechanics:
  bodies:
    slide_x: {parent: world, joint: {type: prismatic, axis: [1, 0, 0], v0: 0.5}, mass: 1.0,
              inertia: [1, 1, 1]}
    buoy: {parent: slide_x, joint: {type: prismatic, axis: [0, 1, 0]},
           placement: {xyz: [0, 0, 39]}, mass: 2.0e5, inertia: [1, 1, 1]}
  mooring:
)";
  for (int k = 0; k < 4; ++k) {
    const double a = k * M_PI / 2.0 + 0.3;
    s += "    line" + std::to_string(k) + ": {model: lumped, anchor: [" +
         std::to_string(290.0 * std::cos(a)) + ", " + std::to_string(290.0 * std::sin(a)) +
         ", 0], fairlead: {body: buoy}, length: 314, EA: 1.2e9, mass: 282.21, diameter: 0.216, "
         "segments: 8" +
         lineKeys + "}\n";
  }
  return s + extra + "until: 1\n";
}

// (integrator line, surge q0, m) => a scene: a 1e5 kg buoy on a surge slider between two
// catenary chain lines (450 m, EA 1e9 N, 1000 N/m in water; anchors 400 m either side and 100 m
// down, on the sea bed), no gravity on the slider
inline std::string catenaryBuoyScene(const std::string& integrator, double q0) {
  return R"(schema_version: 1
integrator: )" +
         integrator +
         R"(
mechanics:
  gravity: [0, 0, 0]
  bodies:
    buoy:
      parent: world
      joint: {name: surge, type: prismatic, axis: [1, 0, 0], q0: )" +
         std::to_string(q0) + R"(}
      mass: 1.0e5
      inertia: [1, 1, 1]
  mooring:
    west: {anchor: [-400, 0, -100], fairlead: {body: buoy}, length: 450, EA: 1.0e9, weight: 1000}
    east: {anchor: [400, 0, -100], fairlead: {body: buoy}, length: 450, EA: 1.0e9, weight: 1000}
record: {interval: 0.5, channels: ["surge.q", "surge.v"]}
until: 1
)";
}

}  // namespace yardsim::testing
