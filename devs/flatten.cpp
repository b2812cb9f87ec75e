#include "devs/flatten.hpp"

#include <span>
#include <utility>
#include <vector>

#include "devs/coupled.hpp"

namespace yardsim::devs {
namespace {

// The atomics below a root in depth-first order, components in the order they were added; the
// stack holds one entry per level, not one per pending model.
class AtomicsInOrder {
 public:
  explicit AtomicsInOrder(Model& root) {
    if (root.isAtomic()) {
      single_ = static_cast<AtomicBase*>(&root);
    } else {
      const auto& top = static_cast<Coupled&>(root).components();
      stack_.push_back({top.data(), top.data() + top.size()});
    }
  }
  // () => the next atomic, or nullptr after the last
  AtomicBase* next() {
    if (single_) return std::exchange(single_, nullptr);
    while (!stack_.empty()) {
      Level& level = stack_.back();
      if (level.next == level.end) {
        stack_.pop_back();
        continue;
      }
      Model* m = (level.next++)->get();
      if (m->isAtomic()) return static_cast<AtomicBase*>(m);
      const auto& children = static_cast<Coupled*>(m)->components();
      stack_.push_back({children.data(), children.data() + children.size()});
    }
    return nullptr;
  }

 private:
  struct Level {
    const std::unique_ptr<Model>* next;
    const std::unique_ptr<Model>* end;
  };
  std::vector<Level> stack_;
  AtomicBase* single_ = nullptr;
};

// (output port, visit) => visit(input port) for every atomic input port its messages reach, in
// the order of a stack seeded with its links (the last link first; a coupled model's port
// replaced by its own links); frontier is scratch, used only when a link is a coupled model's
template <class Visit>
void forEachDestination(const PortBase& out, std::vector<PortBase*>& frontier, Visit&& visit) {
  const std::span<PortBase* const> links = out.links();
  std::size_t n = links.size();
  // (links) => from the last on, atomic ones visited and coupled models' ports coupled no further
  // passed over, until a coupled model's port with couplings of its own
  for (; n > 0; --n) {
    PortBase* p = links[n - 1];
    if (p->owner().isAtomic())
      visit(*p);
    else if (!p->links().empty())
      break;
  }
  if (n == 0) return;
  frontier.assign(links.begin(), links.begin() + static_cast<std::ptrdiff_t>(n));
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
  for (AtomicsInOrder it(root); AtomicBase* a = it.next();) {
    ++atomics;
    for (const PortBase* out : a->outPorts()) {
      ++outPorts;
      if (!out->links().empty()) forEachDestination(*out, frontier, [&](PortBase&) { ++dests; });
    }
  }
  flat.atomics.reserve(atomics);
  flat.outBegin.reserve(atomics + 1);
  flat.outs.reserve(outPorts);
  flat.destPorts.reserve(dests);
  flat.destAtomics.reserve(dests);

  // (hierarchy) => atomics in depth-first order, each with its index and its first output port
  std::uint32_t firstOut = 0;
  for (AtomicsInOrder it(root); AtomicBase* a = it.next();) {
    a->simIndex_ = static_cast<std::uint32_t>(flat.atomics.size());
    flat.atomics.push_back(a);
    flat.outBegin.push_back(firstOut);
    firstOut += static_cast<std::uint32_t>(a->outPorts().size());
  }
  flat.outBegin.push_back(firstOut);

  // (atomic output ports, couplings) => atomic input ports reached through any depth
  for (const AtomicBase* a : flat.atomics) {
    for (PortBase* out : a->outPorts()) {
      const auto first = static_cast<std::uint32_t>(flat.destPorts.size());
      if (!out->links().empty()) {
        forEachDestination(*out, frontier, [&](PortBase& p) {
          flat.destPorts.push_back(&p);
          flat.destAtomics.push_back(static_cast<AtomicBase&>(p.owner()).simIndex());
        });
      }
      flat.outs.push_back({out, first, static_cast<std::uint32_t>(flat.destPorts.size())});
    }
  }
  return flat;
}

}  // namespace yardsim::devs
