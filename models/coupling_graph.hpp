#pragma once
// Checks of the assembled coupling graph (Boost.Graph), after a scene's couplings are valid:
// zero-delay algebraic loops (a cycle of models that each answer an input at the same time)
// are errors naming the cycle's models; atomic input ports that nothing feeds are warnings.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "models/diagnostics.hpp"
#include "models/scene.hpp"

namespace yardsim::models {

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

// (scene) => an error for every mechanical element an actor names (through the model its
// `setpoint` port reaches) that this model does not have, with "did you mean"; and for an actor
// whose set-points reach no model that has elements
void checkElementReferences(const Instance& root, Diagnostics& diags);

}  // namespace yardsim::models
