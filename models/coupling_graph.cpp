#include "models/coupling_graph.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/strong_components.hpp>
#include <map>
#include <set>

namespace yardsim::models {
namespace {

using PortKey = std::pair<const Instance*, std::string>;

struct Index {
  std::vector<const Instance*> atomics;
  std::map<const Instance*, std::size_t> atomicId;
  std::map<PortKey, std::vector<PortKey>> links;  // coupling edges between ports
};

// (instance tree) => atomics and the port-to-port coupling edges of every coupled model
void collect(const Instance& inst, Index& ix) {
  if (inst.atomic()) {
    ix.atomicId[&inst] = ix.atomics.size();
    ix.atomics.push_back(&inst);
    return;
  }
  for (const auto& c : inst.couplings) {
    const Instance* from = c.fromModel.empty() ? &inst : inst.child(c.fromModel);
    const Instance* to = c.toModel.empty() ? &inst : inst.child(c.toModel);
    ix.links[{from, c.fromPort}].push_back({to, c.toPort});
  }
  for (const auto& child : inst.children) collect(*child, ix);
}

}  // namespace

void checkCouplingGraph(const Instance& root, Diagnostics& diags) {
  Index ix;
  collect(root, ix);
  const std::size_t n = ix.atomics.size();

  // (port links) => atomic-to-atomic edges, and which atomic input ports are fed
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;
  Graph g(n);
  std::set<PortKey> fed;
  for (std::size_t a = 0; a < n; ++a) {
    for (const auto& p : ix.atomics[a]->ports) {
      if (p.input) continue;
      std::vector<PortKey> frontier{{ix.atomics[a], p.name}};
      std::set<PortKey> seen;
      while (!frontier.empty()) {
        const PortKey k = frontier.back();
        frontier.pop_back();
        auto it = ix.links.find(k);
        if (it == ix.links.end()) continue;
        for (const PortKey& next : it->second) {
          if (!seen.insert(next).second) continue;
          if (next.first->atomic()) {
            fed.insert(next);
            boost::add_edge(a, ix.atomicId.at(next.first), g);
          } else {
            frontier.push_back(next);
          }
        }
      }
    }
  }

  // (edges among feedthrough atomics) => strongly connected components = algebraic loops
  Graph ft(n);
  for (auto [e, end] = boost::edges(g); e != end; ++e) {
    const auto s = boost::source(*e, g), t = boost::target(*e, g);
    if (ix.atomics[s]->feedthrough && ix.atomics[t]->feedthrough)
      boost::add_edge(s, t, ft);
  }
  std::vector<std::size_t> comp(n);
  const std::size_t ncomp = boost::strong_components(ft, comp.data());
  std::vector<std::vector<std::size_t>> members(ncomp);
  for (std::size_t v = 0; v < n; ++v) members[comp[v]].push_back(v);
  for (const auto& m : members) {
    if (m.empty()) continue;
    bool selfLoop = false;
    for (auto [e, end] = boost::out_edges(m[0], ft); e != end; ++e)
      selfLoop |= boost::target(*e, ft) == m[0];
    if (m.size() < 2 && !selfLoop) continue;
    // (component) => the shortest cycle through its first model (BFS back to it)
    const std::size_t head = m[0];
    std::map<std::size_t, std::size_t> parent;
    std::vector<std::size_t> queue{head};
    std::size_t last = head;
    for (std::size_t qi = 0; qi < queue.size() && last == head; ++qi) {
      const std::size_t v = queue[qi];
      for (auto [e, end] = boost::out_edges(v, ft); e != end; ++e) {
        const auto t = boost::target(*e, ft);
        if (t == head) {
          last = v;
          break;
        }
        if (comp[t] == comp[head] && !parent.count(t)) {
          parent[t] = v;
          queue.push_back(t);
        }
      }
    }
    std::vector<std::size_t> cycle;
    if (!selfLoop)
      for (std::size_t v = last; v != head; v = parent.at(v)) cycle.insert(cycle.begin(), v);
    cycle.insert(cycle.begin(), head);
    std::string names;
    for (std::size_t v : cycle) names += ix.atomics[v]->path + " -> ";
    names += ix.atomics[cycle[0]]->path;
    diags.error(ix.atomics[m[0]]->where, ix.atomics[m[0]]->keyPath,
                "zero-delay algebraic loop: " + names +
                    "; each of these models answers an input at the same time, so the loop never "
                    "advances (give one of them a delay)");
  }

  for (const Instance* a : ix.atomics)
    for (const auto& p : a->ports)
      if (p.input && !p.optional && !fed.count({a, p.name}))
        diags.warning(a->where, a->keyPath,
                      "input port '" + p.name + "' of '" + a->path + "' is not connected");
}

}  // namespace yardsim::models
