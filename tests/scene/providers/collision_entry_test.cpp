// Reading a `collision:` entry at the door (scene/providers/collision_entry.cpp): problems of
// `contact`, `materials` and `shapes` in the scene-level form are reported under the keys as
// the user wrote them (`collision.…`, never the loader's `mechanics.collision.collision.…`) at
// their own line and column (map keys included), and every number of a contact law, a shape or a
// watch given as .nan, .inf or -.inf is refused there before anything runs.
#include <catch2/catch.hpp>
#include <string>

#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using Catch::Matchers::Contains;

namespace {

// (file name, keys of the scene-level collision) => the loader's diagnostics; line 12 is the
// first of `keys`
std::string problems(const testing::SceneDir& dir, const std::string& name,
                     const std::string& keys) {
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
)" + keys))
      .diagnostics.report();
}

const std::string kLaw = "  contact: {default: {law: linear, k: 1.0e8}}\n";

}  // namespace

TEST_CASE("collision entry: scene-level problems read collision keys at their place") {
  testing::SceneDir dir;
  // contact: a bad number, a pair that is no pair, a law without k; a place inside a mapping is
  // that of its first value (the loader's resolved copy keeps no place for keys and mappings)
  const std::string contact = problems(
      dir, "contact.yaml",
      "  contact: {default: {law: linear, k: -1}, steel: {k: 1}, a/b: {law: hunt_crossley}}\n");
  CHECK_THAT(contact,
             Contains("contact.yaml:12:39: error: collision.contact.default.k: must be > 0") &&
                 Contains("contact.yaml:12:55: error: collision.contact.steel: expected default "
                          "or a pair") &&
                 Contains("contact.yaml:12:70: error: collision.contact.a/b: missing required "
                          "key 'k'"));
  // materials and shapes: bad values, and names that are no body (found when the system is built)
  const std::string values = problems(
      dir, "values.yaml", kLaw + "  materials: {box: [steel]}\n  shapes: {box: {sphere: 0}}\n");
  CHECK_THAT(values, Contains("values.yaml:13:21: error: collision.materials.box: expected a "
                              "material name") &&
                         Contains("values.yaml:14:26: error: collision.shapes.box.sphere: must be "
                                  "> 0 m"));
  const std::string material =
      problems(dir, "material.yaml", kLaw + "  materials: {crate: steel}\n");
  CHECK_THAT(material, Contains("material.yaml:13:22: error: collision.materials.crate:") &&
                           Contains("'crate' is not a body with a geometry"));
  const std::string shape = problems(dir, "shape.yaml", kLaw + "  shapes: {crate: {sphere: 1}}\n");
  CHECK_THAT(shape, Contains("shape.yaml:13:28: error: collision.shapes.crate:") &&
                        Contains("'crate' is not a body with a geometry"));
  const std::string radius =
      problems(dir, "radius.yaml", kLaw + "  shapes: {box: {capsule: {length: 1}}}\n");
  CHECK_THAT(radius, Contains("radius.yaml:13:36: error: collision.shapes.box.capsule: missing "
                              "required key 'radius'"));
  for (const std::string* report : {&contact, &values, &material, &shape, &radius})
    CHECK_THAT(*report, !Contains("mechanics.collision"));
  CHECK(
      problems(dir, "good.yaml", kLaw + "  materials: {box: steel}\n  shapes: {box: {sphere: 1}}\n")
          .find("error") == std::string::npos);
}

TEST_CASE("collision entry: a named set's map keys are reported at their own place") {
  testing::SceneDir dir;
  const std::string report = scene::loadScene(dir.write("named.yaml", R"(schema_version: 1
integrator: {method: hht, dt: 0.01}
mechanics:
  bodies:
    box: {parent: world, joint: {name: box_free, type: free}, mass: 1, inertia: [1, 1, 1],
          geometry: {box: [1, 1, 1]}}
  collision:
    s:
      bodies: [box]
      contact: {default: {law: linear, k: 1.0e8}, steel: {k: 1}}
      materials: {crate: steel}
      shapes: {crate: {sphere: 1}}
)"))
                                 .diagnostics.report();
  CHECK_THAT(report,
             Contains("named.yaml:10:62: error: mechanics.collision.s.contact.steel") &&
                 Contains("named.yaml:11:26: error: mechanics.collision.s.materials.crate") &&
                 Contains("named.yaml:12:32: error: mechanics.collision.s.shapes.crate"));
}

TEST_CASE("collision entry: non-finite contact numbers are refused at the door") {
  testing::SceneDir dir;
  for (const std::string value : {".nan", ".inf", "-.inf", ".NaN"}) {
    // every number of a linear law, one at a time (k alone: the others beside a finite k)
    for (const std::string field : {"k", "c", "damping_depth", "mu", "slip_speed", "n"}) {
      INFO(field + ": " + value);
      const std::string law = field == "k"
                                  ? "{law: linear, k: " + value + "}"
                                  : "{law: linear, k: 1.0e8, " + field + ": " + value + "}";
      CHECK_THAT(problems(dir, "law.yaml", "  contact: {default: " + law + "}\n"),
                 Contains("law.yaml:12:") && Contains("error: collision.contact.default." + field +
                                                      ": expected a number, got '" + value + "'"));
    }
    INFO("the rest: " + value);
    const std::string hc = problems(dir, "hc.yaml",
                                    "  contact: {default: {law: hunt_crossley, k: 1.0e8, "
                                    "restitution: " +
                                        value + ", impact_speed: " + value + "}}\n");
    CHECK_THAT(hc, Contains("hc.yaml:12:") &&
                       Contains("collision.contact.default.restitution: expected a number") &&
                       Contains("collision.contact.default.impact_speed: expected a number"));
    // the set's other numbers: ground, points per pair, the ropes' diameter, a shape, a watch
    const std::string rest =
        problems(dir, "rest.yaml",
                 kLaw + "  ground: " + value + "\n  points_per_pair: " + value +
                     "\n  rope_diameter: " + value + "\n  shapes: {box: {box: [1, " + value +
                     ", 1]}}\nclearance:\n  w: {between: [box, box], below: " + value +
                     ", range: " + value + "}\n");
    CHECK_THAT(
        rest,
        Contains("rest.yaml:13:") && Contains("collision.ground: expected a number") &&
            Contains("rest.yaml:14:") && Contains("collision.points_per_pair: expected a number") &&
            Contains("rest.yaml:15:") && Contains("collision.rope_diameter: expected a number") &&
            Contains("rest.yaml:16:") && Contains("collision.shapes.box.box: expected a number") &&
            Contains("rest.yaml:18:") && Contains("clearance.w.below: expected a number") &&
            Contains("clearance.w.range: expected a number"));
  }
}
