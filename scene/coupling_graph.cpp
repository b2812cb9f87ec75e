#include "scene/coupling_graph.hpp"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/strong_components.hpp>
#include <functional>
#include <map>
#include <set>

namespace yardsim::scene {

using models::Diagnostics;
using models::PortSpec;
using models::didYouMean;
CouplingIndex::CouplingIndex(const Instance& root) { collect(root); }

// (instance tree) => atomics and the port-to-port coupling edges of every coupled model
void CouplingIndex::collect(const Instance& inst) {
  if (inst.atomic()) {
    atomicId_[&inst] = atomics_.size();
    atomics_.push_back(&inst);
    return;
  }
  for (const auto& c : inst.couplings) {
    const Instance* from = c.fromModel.empty() ? &inst : inst.child(c.fromModel);
    const Instance* to = c.toModel.empty() ? &inst : inst.child(c.toModel);
    links_[{from, c.fromPort}].push_back({to, c.toPort});
  }
  for (const auto& child : inst.children) collect(*child);
}

std::vector<CouplingIndex::PortKey> CouplingIndex::reach(const Instance* atomic,
                                                         const std::string& port) const {
  std::vector<PortKey> out, frontier{{atomic, port}};
  std::set<PortKey> seen;
  while (!frontier.empty()) {
    const PortKey k = frontier.back();
    frontier.pop_back();
    auto it = links_.find(k);
    if (it == links_.end()) continue;
    for (const PortKey& next : it->second) {
      if (!seen.insert(next).second) continue;
      (next.first->atomic() ? out : frontier).push_back(next);
    }
  }
  return out;
}

void checkCouplingGraph(const Instance& root, Diagnostics& diags) {
  const CouplingIndex index(root);
  const auto& atomics = index.atomics();
  const std::size_t n = atomics.size();

  // (port links) => atomic-to-atomic edges, and which atomic input ports are fed
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;
  Graph g(n);
  std::set<CouplingIndex::PortKey> fed;
  for (std::size_t a = 0; a < n; ++a)
    for (const auto& p : atomics[a]->ports) {
      if (p.input) continue;
      for (const auto& dst : index.reach(atomics[a], p.name)) {
        fed.insert(dst);
        boost::add_edge(a, index.id(dst.first), g);
      }
    }

  // (edges among feedthrough atomics) => strongly connected components = algebraic loops
  Graph ft(n);
  for (auto [e, end] = boost::edges(g); e != end; ++e) {
    const auto s = boost::source(*e, g), t = boost::target(*e, g);
    if (atomics[s]->feedthrough && atomics[t]->feedthrough)
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
    for (std::size_t v : cycle) names += atomics[v]->path + " -> ";
    names += atomics[cycle[0]]->path;
    diags.error(atomics[m[0]]->where, atomics[m[0]]->keyPath,
                "zero-delay algebraic loop: " + names +
                    "; each of these models answers an input at the same time, so the loop never "
                    "advances (give one of them a delay)");
  }

  for (const Instance* a : atomics)
    for (const auto& p : a->ports)
      if (p.input && !p.optional && !fed.count({a, p.name}))
        diags.warning(a->where, a->keyPath,
                      "input port '" + p.name + "' of '" + a->path + "' is not connected");
}

}  // namespace yardsim::scene

namespace yardsim::scene {

void checkElementReferences(Scene& scene, Diagnostics& diags) {
  const CouplingIndex index(scene.root);
  for (const Instance* ac : index.atomics()) {
    auto* a = const_cast<Instance*>(ac);  // the index only reads; references are rewritten here
    if (!a->type->references) continue;
    const auto refs = a->type->references(a->params);
    if (refs.empty()) continue;
    // (the atomics its set-points reach) => those that declare mechanical elements
    std::vector<const Instance*> targets;
    for (const auto& [dst, port] : index.reach(a, "setpoint"))
      if (dst->type->elements) targets.push_back(dst);
    if (targets.empty() && !scene.systems.empty()) {
      // (not coupled) => resolved in the scene's mechanical systems, from the actor's parent
      const auto dot = a->path.rfind('.');
      const std::string from = dot == std::string::npos ? "" : a->path.substr(0, dot);
      for (const auto& ref : refs) {
        std::vector<std::string> names;
        std::map<std::string, std::string> owner;
        for (const auto& s : scene.systems)
          for (const auto& e : systemElements(*s))
            if (e.kind == ref.kind) {
              names.push_back(e.name);
              owner[e.name] = s->name;
            }
        const std::string full = resolveName(from, ref.name, names);
        if (full.empty() && ref.kind == "rope") {
          // (a rope with model: lumped over a sheave, a provider of kind ropes without a
          // winch) => refused: its rope flows over the sheave within one segment only
          std::vector<std::string> lumped;
          for (const auto& s : scene.systems)
            for (const auto& e : systemElements(*s))
              if (e.kind == "ropes") lumped.push_back(e.name);
          if (!resolveName(from, ref.name, lumped).empty()) {
            diags.error(
                a->params.mark(ref.param), a->keyPath + ".params." + ref.param,
                "rope '" + ref.name +
                    "' has model: lumped over a sheave, which has no "
                    "winch (its rope flows over the sheave within one segment only); pay out "
                    "a lumped rope between two points or a massless rope (docs/lines.md, "
                    "crane ropes with mass)");
            continue;
          }
        }
        if (full.empty()) {
          diags.error(a->params.mark(ref.param), a->keyPath + ".params." + ref.param,
                      "no " + ref.kind + " '" + ref.name + "' in the scene's mechanics (seen from '" +
                          (from.empty() ? std::string("the scene root") : from) + "')",
                      didYouMean(ref.name, names));
          continue;
        }
        if (!a->boundSystem.empty() && a->boundSystem != owner[full])
          diags.error(a->where, a->keyPath, "an actor acts on one mechanical system only");
        a->boundSystem = owner[full];
        a->params.set(ref.param, YAML::Node(full), a->params.mark(ref.param));
      }
      continue;
    }
    if (targets.empty()) {
      diags.error(a->where, a->keyPath,
                  "'" + a->path + "' acts on mechanical elements, but its `setpoint` port reaches "
                  "no multibody model and the scene has no mechanics; couple it, e.g. {from: " +
                      a->name + ".setpoint, to: <model>.setpoint}");
      continue;
    }
    for (const auto& ref : refs)
      for (const Instance* t : targets) {
        std::vector<std::string> names;
        for (const auto& e : t->type->elements(t->params))
          if (e.kind == ref.kind) names.push_back(e.name);
        if (std::find(names.begin(), names.end(), ref.name) != names.end()) continue;
        diags.error(a->params.mark(ref.param), a->keyPath + ".params." + ref.param,
                    "'" + t->path + "' has no " + ref.kind + " '" + ref.name + "'",
                    didYouMean(ref.name, names));
      }
  }
}

}  // namespace yardsim::scene

namespace yardsim::scene {

void bindStartRules(Scene& scene, Diagnostics& diags) {
  const CouplingIndex index(scene.root);
  // (couplings) => fed trigger ports, and the atomics that announce `finished`
  std::set<CouplingIndex::PortKey> fed;
  std::vector<std::string> actors;
  for (const Instance* a : index.atomics())
    for (const auto& p : a->ports) {
      if (p.input) continue;
      if (p.name == "finished") actors.push_back(a->path);
      for (const auto& dst : index.reach(a, p.name)) fed.insert(dst);
    }
  for (const Instance* ac : index.atomics()) {
    auto* a = const_cast<Instance*>(ac);  // the index only reads; start rules are rewritten here
    const bool hasTrigger = std::any_of(a->ports.begin(), a->ports.end(),
                                        [](const PortSpec& p) { return p.input && p.name == "trigger"; });
    if (!hasTrigger || fed.count({ac, "trigger"})) continue;
    for (const char* rule : {"after_all", "after_any"}) {
      if (!a->params.has(rule) || a->params.node(rule).IsNull()) continue;
      const auto dot = a->path.rfind('.');
      const std::string from = dot == std::string::npos ? "" : a->path.substr(0, dot);
      YAML::Node rewritten(YAML::NodeType::Sequence);
      for (const std::string& name : a->params.strings(rule)) {
        const std::string full = resolveName(from, name, actors);
        if (full.empty()) {
          diags.error(a->params.mark(rule), a->keyPath + ".params." + rule,
                      "no actor '" + name + "' (seen from '" +
                          (from.empty() ? std::string("the scene root") : from) + "')",
                      didYouMean(name, actors));
          continue;
        }
        a->listensTo.push_back(full);
        rewritten.push_back(full);
      }
      a->params.set(rule, rewritten, a->params.mark(rule));
    }
  }
  checkStartRuleCycles(index, diags);
}

void checkStartRuleCycles(const CouplingIndex& index, Diagnostics& diags) {
  // (actor => the actors it waits for) => a cycle of waiting, by depth-first search: an actor in
  // it (or one that waits for itself) would never start, nor anything after it
  std::map<std::string, const Instance*> byPath;
  for (const Instance* a : index.atomics()) byPath[a->path] = a;
  std::map<std::string, int> color;  // 0 unseen, 1 on the current path, 2 done
  std::vector<std::string> stack;
  std::function<void(const std::string&)> visit = [&](const std::string& path) {
    color[path] = 1;
    stack.push_back(path);
    const auto it = byPath.find(path);
    if (it != byPath.end())
      for (const std::string& next : it->second->listensTo) {
        if (color[next] == 1) {  // (back edge) => the cycle from `next` to here
          std::string cycle;
          for (auto s = std::find(stack.begin(), stack.end(), next); s != stack.end(); ++s) cycle += *s + " -> ";
          const Instance* first = byPath.at(next);
          const char* rule = first->params.has("after_all") ? "after_all" : "after_any";
          diags.error(first->params.mark(rule), first->keyPath + ".params." + rule,
                      "actors wait for each other in a cycle and would never start: " + cycle + next,
                      "remove one of these start rules, or start one of them with start_at");
        } else if (color[next] == 0) {
          visit(next);
        }
      }
    stack.pop_back();
    color[path] = 2;
  };
  for (const auto& [path, actor] : byPath)
    if (color[path] == 0 && !actor->listensTo.empty()) visit(path);
}

}  // namespace yardsim::scene
