// The Jacobian pattern of a system with lumped-mass lines: it holds (what it leaves out is zero in
// the dense finite-difference Jacobian of the stage function), its colouring is valid and needs
// far fewer colours than dofs, only the nodes next to a body couple to the rigid dofs, a system
// without lines has none (the dense path), and a moored buoy stepped by HHT follows the same motion
// with the sparse and the dense Newton matrix, within the Newton tolerance.
#include "mechanics/jacobian_pattern.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "dynamics/integrators/factory.hpp"
#include "tests/mechanics/mechanics_fixture.hpp"

using namespace yardsim;
using testing::buildFromScene;
using testing::mooredBuoyScene;
using testing::StagedSystem;

namespace {

bool inPattern(const dynamics::JacobianPattern& p, int i, int j) {
  const auto& rows = p.rows[static_cast<std::size_t>(j)];
  return std::binary_search(rows.begin(), rows.end(), i);
}

}  // namespace

TEST_CASE("the pattern of a moored buoy holds and its colouring needs few colours") {
  // (without and with bending stiffness: EI 1e10 N m^2 on 39 m segments, a node then coupled to
  // the nodes two away and the two nodes nearest the buoy to the rigid dofs)
  for (const std::string keys : {"", ", EI: 1.0e10"}) {
    INFO("line keys '" << keys << "'");
    StagedSystem b(buildFromScene(mooredBuoyScene("", keys)));
    const auto& m = b.model();
    const dynamics::JacobianPattern* p = b.data.kernel.jacobianPattern();
    REQUIRE(p != nullptr);
    REQUIRE(p->n == m.nv);
    REQUIRE(m.nv == 2 + 4 * 7 * 3);
    const dynamics::ColumnColouring c = dynamics::colourColumns(*p);
    CHECK(dynamics::colouringConflict(*p, c) == -1);
    // 2 rigid dofs, 4 nodes next to the buoy (12 dofs), the rest of the chains in at most 9 more
    CHECK(c.count() >= 14);
    // (with bending: the two nodes nearest the buoy touch the rigid dofs, 24 dofs, and 15 more)
    CHECK(c.count() <= (keys.empty() ? 23 : 41));
    // (a moving state off equilibrium) => central differences of the stage's accelerations: every
    // entry the pattern leaves out is zero, and the chains' inner entries are not all zero
    Eigen::VectorXd q = b.system.description().q0, v = Eigen::VectorXd::Zero(m.nv);
    for (int i = 0; i < m.nv; ++i) v[i] = 0.3 * std::sin(1.0 + i);
    for (int i = 2; i < m.nv; ++i) q[i] += 0.5 * std::cos(2.0 * i);
    Eigen::VectorXd ap(m.nv), am(m.nv);
    int outside = 0, inside = 0;
    for (int j = 0; j < m.nv; ++j) {
      for (int which = 0; which < 2; ++which) {
        Eigen::VectorXd qp = q, qm = q, vp = v, vm = v;
        (which == 0 ? qp : vp)[j] += 1e-4;
        (which == 0 ? qm : vm)[j] -= 1e-4;
        b.data.kernel.acceleration(0.0, qp, vp, ap);
        b.data.kernel.acceleration(0.0, qm, vm, am);
        for (int i = 0; i < m.nv; ++i) {
          if (inPattern(*p, i, j))
            inside += ap[i] != am[i];
          else
            outside += ap[i] != am[i];
        }
      }
    }
    CHECK(outside == 0);
    CHECK(inside > 4 * 7 * 9);
    // (with bending) => node 1 moves node 3 (its angle at node 2), and node 6 (two from the buoy)
    // is coupled to the buoy's dofs, both in the pattern and in the differences
    const int node1 = m.idxV[static_cast<std::size_t>(m.bodyIndex("line0.node1"))];
    const int node3 = m.idxV[static_cast<std::size_t>(m.bodyIndex("line0.node3"))];
    const int node6 = m.idxV[static_cast<std::size_t>(m.bodyIndex("line0.node6"))];
    CHECK(inPattern(*p, node1, node3) == !keys.empty());
    CHECK(inPattern(*p, 0, node6) == !keys.empty());
    CHECK(inPattern(*p, node6, 0) == !keys.empty());
    if (!keys.empty()) {
      Eigen::VectorXd qp = q, qm = q;
      qp[node3] += 1e-4;
      qm[node3] -= 1e-4;
      b.data.kernel.acceleration(0.0, qp, v, ap);
      b.data.kernel.acceleration(0.0, qm, v, am);
      CHECK(std::abs(ap[node1] - am[node1]) > 0.0);
    }
  }
}

TEST_CASE("a spring on the buoy keeps the nodes sparse - a system without lines has no pattern") {
  StagedSystem b(buildFromScene(mooredBuoyScene(R"(  springs:
    tug: {between: [{body: buoy}, {point: [0, 0, 60]}], k: 1.0e3, free_length: 1}
)")));
  const auto& m = b.model();
  const dynamics::JacobianPattern* p = b.data.kernel.jacobianPattern();
  REQUIRE(p != nullptr);
  const int node1 = m.idxV[static_cast<std::size_t>(m.bodyIndex("line0.node1"))];
  const int node7 = m.idxV[static_cast<std::size_t>(m.bodyIndex("line0.node7"))];
  // the node next to the buoy is coupled to the rigid dofs, the one next to the anchor is not
  CHECK(inPattern(*p, 0, node7));
  CHECK(inPattern(*p, node7, 1));
  CHECK(!inPattern(*p, 0, node1));
  CHECK(!inPattern(*p, node1, node7));
  StagedSystem plain(buildFromScene(R"(schema_version: 1
integrator: {method: hht, dt: 0.05}
mechanics:
  bodies:
    bob: {parent: world, joint: {type: revolute, axis: [0, 1, 0], q0: 0.1}, mass: 2.0,
          com: [0, 0, -4.0], inertia: [1, 1, 1]}
until: 1
)"));
  CHECK(plain.data.kernel.jacobianPattern() == nullptr);
}

TEST_CASE("HHT moves the moored buoy alike with the sparse and the dense Newton matrix") {
  struct Run {
    Eigen::VectorXd q, v;
    dynamics::IntegratorStats stats;
  };
  auto run = [](bool sparse, const std::string& keys) {
    StagedSystem b(buildFromScene(mooredBuoyScene("", keys)));
    if (!sparse) b.data.kernel.setJacobianPattern(nullptr);
    dynamics::IntegratorSpec spec;
    spec.method = "hht";
    spec.dt = 0.05;
    auto integrator = dynamics::makeIntegrator(spec, b.model());
    Run r{b.system.description().q0, b.system.description().v0, {}};
    double t = 0.0;
    for (int k = 0; k < 40; ++k) integrator->step(b.data.kernel, t, r.q, r.v, 0.05);
    r.stats = integrator->stats();
    return r;
  };
  // (and with bending stiffness on these chains lying on the bed, EI 1e8 N m^2: until 2026-11-29
  // the chains started off their rest, lumped_line_statics.cpp having stalled, and both paths
  // failed Newton often, 106 and 71 failed solves in 2 s, ending 3.5 cm apart)
  for (const std::string keys : {"", ", EI: 1.0e8"}) {
    INFO("line keys '" << keys << "'");
    const Run dense = run(false, keys), sparse = run(true, keys);
    INFO("dense: " << dense.stats.f_evals << " evaluations, " << dense.stats.jac_evals
                   << " matrices; sparse: " << sparse.stats.f_evals << ", "
                   << sparse.stats.jac_evals << "; steps " << dense.stats.steps << " and "
                   << sparse.stats.steps << ", failed solves " << dense.stats.err_fails << " and "
                   << sparse.stats.err_fails);
    // 2 s at 0.5 m/s: the buoy moves about a metre; nodes and buoy agree to the Newton tolerance
    // and, where the dense path's chord Newton fails and halves a step that the sparse one (the
    // lines' blocks re-evaluated at every iterate) takes whole, to that step's truncation error
    // (1.0e-5 m measured with one halving)
    CHECK(std::abs(sparse.q[0]) > 0.3);
    CHECK(sparse.stats.steps <= dense.stats.steps);
    CHECK((sparse.q - dense.q).lpNorm<Eigen::Infinity>() <
          (sparse.stats.steps == dense.stats.steps ? 1e-5 : 3e-5));
    CHECK((sparse.v - dense.v).lpNorm<Eigen::Infinity>() < 1e-4);
    CHECK(sparse.stats.f_evals < dense.stats.f_evals / 2);
  }
}
