#pragma once
// Test support for mechanics/: a System built from the multibody type's YAML (bodies, ropes,
// equalizers), as a scene would build it.
#include <yaml-cpp/yaml.h>
#include <catch2/catch.hpp>
#include <string>

#include "mechanics/build.hpp"
#include "models/params.hpp"
#include "scene/mechanics_reader.hpp"

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

}  // namespace yardsim::testing
