#include "mechanics/jacobian_pattern.hpp"

#include <algorithm>
#include <vector>

#include "forces/lines/lumped_line_provider.hpp"
#include "forces/provider_outputs.hpp"

namespace yardsim::mechanics {

const forces::LumpedLineProvider* lumpedLine(const forces::ForceProvider& p) {
  if (const auto* line = dynamic_cast<const forces::LumpedLineProvider*>(&p)) return line;
  if (const auto* observed =
          dynamic_cast<const forces::ObservedProvider<forces::LumpedLineProvider>*>(&p))
    return &observed->inner();
  return nullptr;
}

namespace {

// (system) => per body: named by something other than its own line's nodes (rigid, then)
std::vector<char> namedElsewhere(const System& s) {
  const dynamics::Model& m = s.model();
  const BuiltMechanics& d = s.description();
  std::vector<char> named(static_cast<std::size_t>(m.nbodies), 0);
  auto mark = [&](const std::string& body) {
    const int b = m.bodyIndex(body);
    if (b >= 0) named[static_cast<std::size_t>(b)] = 1;
  };
  for (const auto& r : d.ropes)
    for (const auto& p : r.path) mark(p.first);
  for (const auto& e : d.equalizers) {
    mark(e.sheave.first);
    for (const auto& branch : e.branches)
      for (const auto& p : branch) mark(p.first);
  }
  for (const auto& l : d.loads) mark(l.body);
  const MechanicsSpec& env = d.environment;
  for (const auto& h : env.hulls) mark(h.body);
  for (const auto& f : env.windLoads) mark(f.body);
  for (const auto& f : env.currentLoads) mark(f.body);
  for (const auto& f : env.dampers) mark(f.body);
  for (const auto& f : env.hydrodynamics) mark(f.body);
  for (const auto& p : d.providers)
    for (const auto& a : p.attachments) mark(a.first);
  for (const auto& loop : m.loops) {
    named[static_cast<std::size_t>(loop.bodyA)] = 1;
    named[static_cast<std::size_t>(loop.bodyB)] = 1;
  }
  for (int b = 1; b < m.nbodies; ++b) {
    if (m.parent[static_cast<std::size_t>(b)] > 0)
      named[static_cast<std::size_t>(m.parent[static_cast<std::size_t>(b)])] = 1;
    if (!m.geometry[static_cast<std::size_t>(b)].empty()) named[static_cast<std::size_t>(b)] = 1;
  }
  return named;
}

}  // namespace

std::vector<char> lineNodes(const System& s) {
  const dynamics::Model& m = s.model();
  const std::vector<char> named = namedElsewhere(s);
  std::vector<char> node(static_cast<std::size_t>(m.nbodies), 0);
  for (const auto& p : s.contributed())
    if (const forces::LumpedLineProvider* line = lumpedLine(*p))
      for (int i = 1; i + 1 < line->line().nodes(); ++i) {
        const auto b = static_cast<std::size_t>(line->nodeBody(i));
        node[b] = m.parent[b] == 0 && m.jointNv[b] == 3 && !named[b] ? 1 : 0;
      }
  return node;
}

std::shared_ptr<const dynamics::JacobianPattern> jacobianPattern(const System& s) {
  const dynamics::Model& m = s.model();
  const auto nb = static_cast<std::size_t>(m.nbodies);
  // (lumped lines) => per node body its chain neighbours within the line's bandwidth b (bodies;
  // 0: the world): the nodes and ends i - b .. i + b, b = 2 with bending stiffness (the angle at
  // node i - 1 moves with node i - 2)
  const std::vector<char> node = lineNodes(s);
  std::vector<std::vector<int>> neighbours(nb);
  for (const auto& p : s.contributed()) {
    const forces::LumpedLineProvider* line = lumpedLine(*p);
    if (line == nullptr) continue;
    std::vector<int> chain{line->anchor().body};
    for (int i = 1; i + 1 < line->line().nodes(); ++i) chain.push_back(line->nodeBody(i));
    chain.push_back(line->fairlead().body);
    const auto b = static_cast<std::size_t>(line->line().jacobianBandwidth());
    for (std::size_t k = 1; k + 1 < chain.size(); ++k) {
      std::vector<int>& around = neighbours[static_cast<std::size_t>(chain[k])];
      around.clear();
      for (std::size_t j = k > b ? k - b : 0; j <= std::min(chain.size() - 1, k + b); ++j)
        if (j != k) around.push_back(chain[j]);
    }
  }
  if (std::none_of(node.begin(), node.end(), [](char c) { return c != 0; })) return nullptr;
  // (node flags) => the rigid dofs; the nodes that touch a rigid dof (a body or a rigid node)
  auto dofsOf = [&](int b, std::vector<int>& out) {
    for (int k = 0; k < m.jointNv[static_cast<std::size_t>(b)]; ++k)
      out.push_back(m.idxV[static_cast<std::size_t>(b)] + k);
  };
  std::vector<int> rigid, touching;  // dofs
  for (int b = 1; b < m.nbodies; ++b)
    if (!node[static_cast<std::size_t>(b)]) dofsOf(b, rigid);
  std::vector<char> touchesRigid(nb, 0);
  for (int b = 1; b < m.nbodies; ++b) {
    if (!node[static_cast<std::size_t>(b)]) continue;
    for (int o : neighbours[static_cast<std::size_t>(b)])
      if (o > 0 && !node[static_cast<std::size_t>(o)])
        touchesRigid[static_cast<std::size_t>(b)] = 1;
    if (touchesRigid[static_cast<std::size_t>(b)]) dofsOf(b, touching);
  }
  // (couplings) => per column its rows; symmetric: a node's rows are its own, its node neighbours'
  // and, touching a rigid dof, the rigid ones; a rigid column's rows are the rigid dofs and the
  // touching nodes
  auto pattern = std::make_shared<dynamics::JacobianPattern>();
  pattern->n = m.nv;
  pattern->rows.resize(static_cast<std::size_t>(m.nv));
  for (int b = 1; b < m.nbodies; ++b) {
    std::vector<int> rows;
    const auto ub = static_cast<std::size_t>(b);
    if (node[ub]) {
      dofsOf(b, rows);
      for (int o : neighbours[ub])
        if (o > 0 && node[static_cast<std::size_t>(o)]) dofsOf(o, rows);
      if (touchesRigid[ub]) rows.insert(rows.end(), rigid.begin(), rigid.end());
    } else {
      rows = rigid;
      rows.insert(rows.end(), touching.begin(), touching.end());
    }
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (int k = 0; k < m.jointNv[ub]; ++k)
      pattern->rows[static_cast<std::size_t>(m.idxV[ub] + k)] = rows;
  }
  return pattern;
}

}  // namespace yardsim::mechanics
