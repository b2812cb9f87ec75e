#include "mechanics/line_jacobian.hpp"

#include <algorithm>
#include <vector>

#include "dynamics/kinematics.hpp"
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
    // per 3 x 1 block (an end node's row, a rigid dof of the body at the line's end): its place
    // among the values, the node's slot (i, end), the joint and its dof, the end
    struct End {
      std::size_t value, slot;
      int joint, dof, end;
    };
    std::vector<End> ends;
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
    // (each end on a body that is no node) => its inner nodes within b of it, coupled to every
    // dof from the body down to the world through the end point
    for (int e : {0, n}) {
      const forces::Attachment& a = e == 0 ? line->anchor() : line->fairlead();
      if (a.body <= 0 || node[static_cast<std::size_t>(a.body)] != 0) continue;
      for (int i = std::max(1, e - b); i <= std::min(n - 1, e + b); ++i) {
        if (!isNode(i)) continue;
        for (int j = a.body; j > 0; j = m.parent[static_cast<std::size_t>(j)])
          for (int c = 0; c < m.jointNv[static_cast<std::size_t>(j)]; ++c) {
            l.ends.push_back({blocks->columns.size(),
                              static_cast<std::size_t>((2 * b + 1) * i + e - i + b), j, c, e});
            blocks->columns.push_back({m.idxV[line->nodeBody(i)], m.idxV[j] + c});
          }
      }
    }
    if (!l.block.empty()) lines->push_back(std::move(l));
  }
  if (blocks->at.empty()) return {};
  // (3 x 1 blocks) => their values after the square ones
  const std::size_t squares = blocks->at.size();
  for (Line& l : *lines)
    for (auto& end : l.ends) end.value += squares;
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
      // (end node rows, rigid dofs) => d a_i/d r_end times the end point's velocity per unit
      // dof, J_p = v_O + omega x p of the joint's world subspace column
      for (const auto& end : l.ends) {
        const forces::Attachment& a = end.end == 0 ? l.line->anchor() : l.line->fairlead();
        const dynamics::Vector3 p = dynamics::pointPosition(kin, a.body, a.p_B);
        const dynamics::Motion s6 = kin.X_WB[static_cast<std::size_t>(end.joint)].actMotion(
            kin.S[static_cast<std::size_t>(end.joint)].col(end.dof));
        const dynamics::Vector3 jp = s6.tail<3>() + s6.head<3>().cross(p);
        dq[end.value].col(0) = l.dadr[end.slot] * jp;
        dv[end.value].col(0) = l.dadv[end.slot] * jp;
      }
    }
    return signature;
  };
  return {blocks, evaluate};
}

}  // namespace yardsim::mechanics
