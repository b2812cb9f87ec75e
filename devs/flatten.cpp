#include "devs/flatten.hpp"

#include "devs/coupled.hpp"

namespace yardsim::devs {

FlatModel flatten(Model& root) {
  FlatModel flat;
  // (hierarchy) => how many atomics and atomic output ports: every list below takes one block of
  // its final size (a list that doubles its way up touches twice its size in fresh pages)
  std::size_t atomics = 0, outPorts = 0;
  std::vector<Model*> stack{&root};
  while (!stack.empty()) {
    Model* m = stack.back();
    stack.pop_back();
    if (m->isAtomic()) {
      ++atomics;
      outPorts += m->outPorts().size();
    } else {
      for (const auto& child : static_cast<Coupled*>(m)->components()) stack.push_back(child.get());
    }
  }
  flat.atomics.reserve(atomics);
  flat.outBegin.reserve(atomics + 1);
  flat.outPorts.reserve(outPorts);
  flat.destBegin.reserve(outPorts + 1);
  flat.dests.reserve(outPorts);  // a guess: one destination per output port

  // (hierarchy) => atomics in depth-first order
  stack.push_back(&root);
  while (!stack.empty()) {
    Model* m = stack.back();
    stack.pop_back();
    if (m->isAtomic()) {
      flat.atomics.push_back(static_cast<AtomicBase*>(m));
    } else {
      const auto& children = static_cast<Coupled*>(m)->components();
      for (auto it = children.rbegin(); it != children.rend(); ++it) stack.push_back(it->get());
    }
  }
  for (std::uint32_t i = 0; i < flat.atomics.size(); ++i) flat.atomics[i]->simIndex_ = i;

  // (atomic output ports, couplings) => atomic input ports reached through any depth
  std::vector<PortBase*> frontier;
  for (AtomicBase* a : flat.atomics) {
    flat.outBegin.push_back(static_cast<std::uint32_t>(flat.outPorts.size()));
    for (PortBase* out : a->outPorts()) {
      flat.destBegin.push_back(static_cast<std::uint32_t>(flat.dests.size()));
      flat.outPorts.push_back(out);
      frontier.assign(out->links().begin(), out->links().end());
      while (!frontier.empty()) {
        PortBase* p = frontier.back();
        frontier.pop_back();
        Model& owner = p->owner();
        if (owner.isAtomic()) {
          flat.dests.push_back({p, static_cast<AtomicBase&>(owner).simIndex()});
        } else {
          frontier.insert(frontier.end(), p->links().begin(), p->links().end());
        }
      }
    }
  }
  flat.outBegin.push_back(static_cast<std::uint32_t>(flat.outPorts.size()));
  flat.destBegin.push_back(static_cast<std::uint32_t>(flat.dests.size()));
  return flat;
}

}  // namespace yardsim::devs
