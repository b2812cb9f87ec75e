#pragma once
// Checks of the assembled coupling graph (Boost.Graph), after a scene's couplings are valid:
// zero-delay algebraic loops (a cycle of models that each answer an input at the same time)
// are errors naming the cycle's models; atomic input ports that nothing feeds are warnings.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "models/diagnostics.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/scene.hpp"

namespace yardsim::scene {

using models::Diagnostics;

// The scene's couplings as port-to-port edges, and where an atomic output port's messages end.
class CouplingIndex {
 public:
  using PortKey = std::pair<const Instance*, std::string>;
  explicit CouplingIndex(const Instance& root);
  const std::vector<const Instance*>& atomics() const { return atomics_; }
  std::size_t id(const Instance* atomic) const { return atomicId_.at(atomic); }
  // (atomic, output port) => the atomic input ports its messages reach, through any level
  std::vector<PortKey> reach(const Instance* atomic, const std::string& port) const;

 private:
  void collect(const Instance& inst);
  std::vector<const Instance*> atomics_;
  std::map<const Instance*, std::size_t> atomicId_;
  std::map<PortKey, std::vector<PortKey>> links_;
};

void checkCouplingGraph(const Instance& root, Diagnostics& diags);

// (scene) => every mechanical element an actor names, checked: through the model its `setpoint`
// port reaches when it is coupled, otherwise resolved in the scene's mechanical systems from
// where the actor sits (the actor is then bound to that system and its reference rewritten to
// the element's full path). Errors with "did you mean" for names that exist nowhere.
void checkElementReferences(Scene& scene, Diagnostics& diags);

// (scene) => every actor whose `trigger` port is not coupled listens to the actors its start
// rule names (`after_all` / `after_any`), resolved from where it sits like element names (a
// sibling first, then the enclosing models, then the root); the names are rewritten to full paths
// and the assembler couples their `finished` ports to its `trigger`. Unknown names are errors, and
// so is a cycle of actors waiting for each other (checkStartRuleCycles).
void bindStartRules(Scene& scene, Diagnostics& diags);

// (resolved start rules) => an error at the first actor of a cycle of waiting, naming the cycle
// (a self-reference is a cycle of one)
void checkStartRuleCycles(const CouplingIndex& index, Diagnostics& diags);

}  // namespace yardsim::scene
