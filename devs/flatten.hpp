#pragma once
// Flattening: the hierarchy of coupled models is reduced once to its atomics and, for every
// atomic output port, the list of atomic input ports its messages reach (following EIC, IC
// and EOC couplings through every level). A message reaching one input port along two paths
// is delivered twice, as the hierarchical semantics would.
#include <cstdint>
#include <vector>

#include "devs/atomic.hpp"

namespace yardsim::devs {

struct FlatModel {
  struct Destination {
    PortBase* port;
    std::uint32_t atomic;
  };
  std::vector<AtomicBase*> atomics;    // depth-first order of the hierarchy
  std::vector<std::uint32_t> outBegin; // atomic i owns outPorts[outBegin[i] .. outBegin[i+1])
  std::vector<PortBase*> outPorts;
  std::vector<std::uint32_t> destBegin;  // out port j reaches dests[destBegin[j] .. [j+1])
  std::vector<Destination> dests;
};

// (root model) => flat atomics and direct routes; sets each atomic's simIndex
FlatModel flatten(Model& root);

}  // namespace yardsim::devs
