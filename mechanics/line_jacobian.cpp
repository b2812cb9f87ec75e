#include "mechanics/line_jacobian.hpp"

#include <vector>

#include "mechanics/jacobian_pattern.hpp"

namespace yardsim::mechanics {

LineJacobian lineJacobian(const System& s, const Data& d) {
  const dynamics::Model& m = s.model();
  const std::vector<char> node = lineNodes(s);
  // per line: its provider, its node blocks' workspace, and per block of the matrix its slot
  struct Line {
    const forces::ForceProvider* provider;
    const forces::LumpedLineProvider* line;
    std::vector<dynamics::Matrix3> dadr, dadv;
    std::vector<std::size_t> block, slot;
  };
  auto lines = std::make_shared<std::vector<Line>>();
  auto blocks = std::make_shared<dynamics::JacobianBlocks>();
  // (every inner node the pattern keeps a node) => its blocks with its node neighbours
  for (const auto& p : s.contributed()) {
    const forces::LumpedLineProvider* line = lumpedLine(*p);
    if (line == nullptr) continue;
    const int n = line->line().properties().segments;
    const int b = line->line().jacobianBandwidth();  // (1, or 2 with bending)
    Line l{p.get(),
           line,
           std::vector<dynamics::Matrix3>(static_cast<std::size_t>((2 * b + 1) * (n + 1))),
           std::vector<dynamics::Matrix3>(static_cast<std::size_t>((2 * b + 1) * (n + 1))),
           {},
           {}};
    auto isNode = [&](int i) {
      return i >= 1 && i < n && node[static_cast<std::size_t>(line->nodeBody(i))] != 0;
    };
    for (int i = 1; i < n; ++i)
      for (int j = i - b; j <= i + b; ++j) {
        if (!isNode(i) || !isNode(j)) continue;
        l.block.push_back(blocks->at.size());
        l.slot.push_back(static_cast<std::size_t>((2 * b + 1) * i + j - i + b));
        blocks->at.push_back({m.idxV[line->nodeBody(i)], m.idxV[line->nodeBody(j)]});
      }
    if (!l.block.empty()) lines->push_back(std::move(l));
  }
  if (blocks->at.empty()) return {};
  // (t, q, v, kinematics) => every line's node blocks, copied to the matrix's order; the lines'
  // switch signatures combined
  auto evaluate = [&s, &d, lines](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                  const dynamics::Data& kin, std::vector<Eigen::Matrix3d>& dq,
                                  std::vector<Eigen::Matrix3d>& dv) {
    std::uint64_t signature = 0;
    for (Line& l : *lines) {
      forces::Stage stage = d.stage(s, t, kin, q, v);
      stage.scratch = d.scratchOf(s, *l.provider);
      signature =
          signature * 1099511628211ull + l.line->accelerationJacobian(stage, l.dadr, l.dadv);
      for (std::size_t k = 0; k < l.block.size(); ++k) {
        dq[l.block[k]] = l.dadr[l.slot[k]];
        dv[l.block[k]] = l.dadv[l.slot[k]];
      }
    }
    return signature;
  };
  return {blocks, evaluate};
}

}  // namespace yardsim::mechanics
