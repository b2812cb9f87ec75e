#pragma once
// Flattening: the hierarchy of coupled models is reduced once to its atomics and, for every
// atomic output port, the list of atomic input ports its messages reach (following EIC, IC
// and EOC couplings through every level). A message reaching one input port along two paths
// is delivered twice, as the hierarchical semantics would.
//
// Every list is sized once (the hierarchy is counted first) and lives in the model arena beside
// the models (devs/model_arena.hpp): set-up takes no fresh small pages per atomic.
#include <cstdint>

#include "devs/atomic.hpp"
#include "devs/model_arena.hpp"

namespace yardsim::devs {

struct FlatModel {
  // One atomic output port and the destinations its messages reach: the input ports
  // destPorts[destFirst, destLast) of the atomics destAtomics[destFirst, destLast)
  struct Out {
    PortBase* port;
    std::uint32_t destFirst, destLast;
  };
  ListVector<AtomicBase*> atomics;     // depth-first order of the hierarchy
  ListVector<std::uint32_t> outBegin;  // atomic i owns outs[outBegin[i] .. outBegin[i+1])
  ListVector<Out> outs;
  // two lists: a bag is copied along destPorts alone
  ListVector<PortBase*> destPorts;
  ListVector<std::uint32_t> destAtomics;
};

// (root model) => flat atomics and direct routes; sets each atomic's simIndex
FlatModel flatten(Model& root);

}  // namespace yardsim::devs
