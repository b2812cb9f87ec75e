#pragma once
// Mechanical composition (DESIGN.md, "Two kinds of composition"): every coupled model of a
// scene may contribute a fragment of mechanics (`mechanics:` — bodies, ropes, equalizers,
// loops), namespaced by its instance path (GOC201.upper_trolley) and placed by its instance's
// placement. The fragments are merged and grouped into mechanically connected systems — the
// connected components of the graph whose vertices are bodies and whose edges are joints, loop
// closures, ropes and equalizers (Boost.Graph) — and each system becomes one multibody model,
// stepped as one tree by one integrator. Names inside a fragment resolve like parameters: in
// the fragment's own namespace first, then in the enclosing ones, then at the scene root.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "models/diagnostics.hpp"
#include "mechanics/description.hpp"
#include "scene/scene.hpp"

namespace yardsim::scene {

using mechanics::MechanicsSpec;
using models::Diagnostics;
using models::ElementRef;
using models::SourceMark;

struct MechanicalSystem {
  std::string name;    // the multibody model's name at the scene root: mechanics, mechanics2, ...
  MechanicsSpec spec;  // bodies, joints, ropes, equalizers, loops with full path names
  // parallel to spec.loops: where each loop's key is written and its key path (mechanics.loops.x)
  std::vector<std::pair<SourceMark, std::string>> loopPlaces;
  // parallel to spec.hydrodynamics: where each entry's method is written and its key path
  std::vector<std::pair<SourceMark, std::string>> hydroPlaces;
  // the spec built once at validation (model, added mass from hulls, q0): shared by the stiffness
  // guard and the assembler; null when it could not be built (an error was reported)
  std::shared_ptr<const mechanics::BuiltMechanics> built;
};

// (scene with its instance tree) => its mechanical systems; every problem reported with its place
std::vector<std::shared_ptr<const MechanicalSystem>> mechanicalSystems(const Scene& scene,
                                                                       Diagnostics& diags);

// (element name as written at instance path `from`, names that exist) => the full name it
// refers to (from.name, then the enclosing paths, then the root), or "" when none exists
std::string resolveName(const std::string& from, const std::string& name,
                        const std::vector<std::string>& known);

// (system) => its elements, for actors' references: joints, ropes, equalizers, bodies
std::vector<ElementRef> systemElements(const MechanicalSystem& system);

}  // namespace yardsim::scene
