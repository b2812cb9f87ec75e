#include "devs/flatten.hpp"

#include <vector>

#include "devs/coupled.hpp"

namespace yardsim::devs {
namespace {

// (root, visit) => visit(atomic) for every atomic below root in depth-first order, components in
// the order they were added; the stack holds one entry per level, not one per pending model
template <class Visit>
void forEachAtomic(Model& root, Visit&& visit) {
  if (root.isAtomic()) {
    visit(static_cast<AtomicBase&>(root));
    return;
  }
  struct Level {
    const std::unique_ptr<Model>* next;
    const std::unique_ptr<Model>* end;
  };
  const auto& top = static_cast<Coupled&>(root).components();
  std::vector<Level> stack{{top.data(), top.data() + top.size()}};
  while (!stack.empty()) {
    Level& level = stack.back();
    if (level.next == level.end) {
      stack.pop_back();
      continue;
    }
    Model* m = (level.next++)->get();
    if (m->isAtomic()) {
      visit(static_cast<AtomicBase&>(*m));
    } else {
      const auto& children = static_cast<Coupled*>(m)->components();
      stack.push_back({children.data(), children.data() + children.size()});
    }
  }
}

// (output port, visit) => visit(input port) for every atomic input port its messages reach;
// frontier is scratch
template <class Visit>
void forEachDestination(const PortBase& out, std::vector<PortBase*>& frontier, Visit&& visit) {
  frontier.assign(out.links().begin(), out.links().end());
  while (!frontier.empty()) {
    PortBase* p = frontier.back();
    frontier.pop_back();
    if (p->owner().isAtomic())
      visit(*p);
    else
      frontier.insert(frontier.end(), p->links().begin(), p->links().end());
  }
}

}  // namespace

FlatModel flatten(Model& root) {
  FlatModel flat;
  // (hierarchy) => how many atomics, atomic output ports and destinations: every list below takes
  // one block of its final size
  std::size_t atomics = 0, outPorts = 0, dests = 0;
  std::vector<PortBase*> frontier;
  forEachAtomic(root, [&](AtomicBase& a) {
    ++atomics;
    outPorts += a.outPorts().size();
    for (const PortBase* out : a.outPorts())
      forEachDestination(*out, frontier, [&](PortBase&) { ++dests; });
  });
  flat.atomics.reserve(atomics);
  flat.outBegin.reserve(atomics + 1);
  flat.destBegin.reserve(outPorts + 1);
  flat.dests.reserve(dests);

  // (hierarchy) => atomics in depth-first order, each with its index
  forEachAtomic(root, [&](AtomicBase& a) {
    a.simIndex_ = static_cast<std::uint32_t>(flat.atomics.size());
    flat.atomics.push_back(&a);
  });

  // (atomic output ports, couplings) => atomic input ports reached through any depth
  for (AtomicBase* a : flat.atomics) {
    flat.outBegin.push_back(static_cast<std::uint32_t>(flat.destBegin.size()));
    for (const PortBase* out : a->outPorts()) {
      flat.destBegin.push_back(static_cast<std::uint32_t>(flat.dests.size()));
      forEachDestination(*out, frontier, [&](PortBase& p) {
        flat.dests.push_back({&p, static_cast<AtomicBase&>(p.owner()).simIndex()});
      });
    }
  }
  flat.outBegin.push_back(static_cast<std::uint32_t>(flat.destBegin.size()));
  flat.destBegin.push_back(static_cast<std::uint32_t>(flat.dests.size()));
  return flat;
}

}  // namespace yardsim::devs
