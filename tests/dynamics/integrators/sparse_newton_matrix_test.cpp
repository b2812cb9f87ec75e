// The sparse Newton matrix against the dense one on a chain of point masses (a lumped line: taut
// damped segments with drag, 3-dof nodes on translation joints) hung between a fixed anchor and
// the rocker of a four-bar (a closed loop): its F_q and F_v equal the dense finite differences,
// a pattern that leaves out a coupling is caught by that comparison, its solve equals the dense
// LU's, and generalized-alpha (with the loop's Schur complement) follows the same motion with the
// sparse and the dense matrix, within the Newton tolerance.
#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <memory>

#include "../test_mechanisms.hpp"
#include "dynamics/integrators/generalized_alpha.hpp"
#include "dynamics/integrators/sparse_newton_matrix.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/multibody_system.hpp"

using namespace yardsim::dynamics;
using yardsim::dynamics::testing::FourBar;
using yardsim::dynamics::testing::makeFourBar;

namespace {

constexpr int kNodes = 12;
constexpr double kA = 1.0, kB = 2.0, kC = 1.5, kG = 2.0;  // four-bar lengths, m
const Vector3 kAnchor(-4.0, 3.0, 0.5);                    // world, m

// The four-bar (3 dofs, a loop) and kNodes point masses of 0.2 kg on translation joints
Model chainModel() {
  ModelBuilder mb;
  mb.setGravity(Vector3(0, -9.81, 0));
  mb.addBody("crank", "world", Joint::revolute(), {}, rodInertia(1.0, kA));
  mb.addBody("coupler", "crank", Joint::revolute(), Transform::translation(Vector3(kA, 0, 0)),
             rodInertia(1.0, kB));
  mb.addBody("rocker", "world", Joint::revolute(), Transform::translation(Vector3(kG, 0, 0)),
             rodInertia(1.0, kC));
  mb.addLoop("coupler-rocker", "coupler", Transform::translation(Vector3(kB, 0, 0)), "rocker",
             Transform::translation(Vector3(kC, 0, 0)), kAxisConstraint);
  for (int i = 0; i < kNodes; ++i)
    mb.addBody("node" + std::to_string(i), "world", Joint::translation(), {},
               makeInertia(0.2, Vector3::Zero(), 1e-6 * Matrix3::Identity()));
  return mb.build();
}

// (rocker angle) => its tip (world, m)
Vector3 tip(double angle) {
  return Vector3(kG + kC * std::cos(angle), kC * std::sin(angle), 0.0);
}

// The chain's forces: segments anchor - node0 - ... - node(n-1) - rocker tip, tension-only with
// stiffness 2e3 N/m and damping 5 N s/m when taut, quadratic drag 0.3 N s^2/m^2 on each node
struct ChainForces {
  double l0;
  void operator()(double, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Data&,
                  ExternalForces&, Eigen::VectorXd& tau) const {
    const double angle = q[2], rate = v[2];
    auto r = [&](int k) {  // k = -1: anchor, kNodes: tip
      return k < 0 ? kAnchor : k == kNodes ? tip(angle) : Vector3(q.segment<3>(3 + 3 * k));
    };
    auto dr = [&](int k) {
      return k < 0         ? Vector3::Zero()
             : k == kNodes ? Vector3(-kC * std::sin(angle) * rate, kC * std::cos(angle) * rate, 0)
                           : Vector3(v.segment<3>(3 + 3 * k));
    };
    for (int k = -1; k < kNodes; ++k) {
      const Vector3 d = r(k + 1) - r(k);
      const double L = d.norm();
      const Vector3 u = d / L;
      const double T = L > l0 ? 2e3 * (L - l0) + 5.0 * u.dot(dr(k + 1) - dr(k)) : 0.0;
      if (k >= 0) tau.segment<3>(3 + 3 * k) += T * u;
      if (k + 1 < kNodes)
        tau.segment<3>(3 + 3 * (k + 1)) -= T * u;
      else
        tau[2] += (tip(angle) - Vector3(kG, 0, 0)).cross(-T * u).z();
    }
    for (int k = 0; k < kNodes; ++k) {
      const Vector3 w = v.segment<3>(3 + 3 * k);
      tau.segment<3>(3 + 3 * k) -= 0.3 * w.norm() * w;
    }
  }
};

// (with or without the last node's coupling to the rocker) => the chain's pattern: the rocker's
// three dofs dense with the last node, each node with its neighbours
JacobianPattern chainPattern(bool complete) {
  JacobianPattern p;
  p.n = 3 + 3 * kNodes;
  p.rows.resize(static_cast<std::size_t>(p.n));
  auto dofs = [](int k, std::vector<int>& out) {
    for (int d = 0; d < 3; ++d) out.push_back(3 + 3 * k + d);
  };
  std::vector<int> rigid{0, 1, 2};
  for (int j = 0; j < 3; ++j) {
    p.rows[static_cast<std::size_t>(j)] = rigid;
    if (complete) dofs(kNodes - 1, p.rows[static_cast<std::size_t>(j)]);
  }
  for (int k = 0; k < kNodes; ++k) {
    std::vector<int> rows;
    for (int o = std::max(0, k - 1); o <= std::min(kNodes - 1, k + 1); ++o) dofs(o, rows);
    if (complete && k == kNodes - 1) rows.insert(rows.end(), rigid.begin(), rigid.end());
    std::sort(rows.begin(), rows.end());
    for (int d = 0; d < 3; ++d) p.rows[static_cast<std::size_t>(3 + 3 * k + d)] = rows;
  }
  return p;
}

struct Setup {
  Model model = chainModel();
  Eigen::VectorXd q, v;
  double l0 = 0.0;
  Setup() {
    // (closed four-bar at crank 0.3) => nodes on the chord, bowed out of plane, moving
    FourBar fb = makeFourBar(kA, kB, kC, kG);
    q.setZero(model.nq);
    v.setZero(model.nv);
    q.head<3>() = fb.closedConfiguration(0.3);
    const Vector3 end = tip(q[2]);
    for (int k = 0; k < kNodes; ++k) {
      const double s = (k + 1.0) / (kNodes + 1.0);
      q.segment<3>(3 + 3 * k) =
          kAnchor + s * (end - kAnchor) + Vector3(0, -0.1, 0.2 * std::sin(M_PI * s));
      v.segment<3>(3 + 3 * k) = Vector3(0.3 * std::cos(3.0 * s), -0.2, 0.1 * s);
    }
    l0 = 0.9 * (end - kAnchor).norm() / (kNodes + 1.0);
  }
};

// (system, q, v) => F_q and F_v by forward differences, one column per dof (the dense path)
void denseJacobian(MultibodySystem& sys, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                   double eps, Eigen::MatrixXd& Fq, Eigen::MatrixXd& Fv, bool central) {
  const int n = static_cast<int>(v.size());
  Eigen::VectorXd f(n), fp(n), fm(n);
  sys.unconstrainedAcceleration(0.0, q, v, f);
  Fq.resize(n, n);
  Fv.resize(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd qp = q, qm = q, vp = v, vm = v;
    const double hq = eps * std::max(1.0, std::abs(q[j]) * 0.0),
                 hv = eps * std::max(1.0, std::abs(v[j]));
    qp[j] += hq;
    qm[j] -= hq;
    sys.unconstrainedAcceleration(0.0, qp, v, fp);
    sys.unconstrainedAcceleration(0.0, qm, v, fm);
    Fq.col(j) = central ? Eigen::VectorXd((fp - fm) / (2 * hq)) : Eigen::VectorXd((fp - f) / hq);
    vp[j] += hv;
    vm[j] -= hv;
    sys.unconstrainedAcceleration(0.0, q, vp, fp);
    sys.unconstrainedAcceleration(0.0, q, vm, fm);
    Fv.col(j) = central ? Eigen::VectorXd((fp - fm) / (2 * hv)) : Eigen::VectorXd((fp - f) / hv);
  }
}

// (pattern) => the sparse F_q, F_v at the setup's state (delta = 0: the chart at q itself)
std::unique_ptr<SparseNewtonMatrix> sparseAt(const Setup& s, MultibodySystem& sys,
                                             const JacobianPattern& p, bool band = true) {
  auto sparse = std::make_unique<SparseNewtonMatrix>(s.model, p, nullptr, band);
  Eigen::VectorXd f(s.model.nv), zero = Eigen::VectorXd::Zero(s.model.nv);
  sys.unconstrainedAcceleration(0.0, s.q, s.v, f);
  const int evals =
      sparse->form([&](const Eigen::VectorXd& qs, const Eigen::VectorXd& vs, bool,
                       Eigen::VectorXd& out) { sys.unconstrainedAcceleration(0.0, qs, vs, out); },
                   s.q, zero, s.q, s.v, f);
  CHECK(evals == 2 * sparse->colouring().count());
  return sparse;
}

}  // namespace

TEST_CASE("sparse F_q and F_v equal the dense finite differences on a lumped chain with a loop") {
  const Setup s;
  MultibodySystem sys(s.model);
  sys.setForces(ChainForces{s.l0});
  const JacobianPattern p = chainPattern(true);
  const auto sparse = sparseAt(s, sys, p);
  // 3 rigid + 3 for the last node + 9 for the chain at most: far fewer than 39 columns
  CHECK(sparse->colouring().count() <= 15);
  CHECK(colouringConflict(p, sparse->colouring()) == -1);
  Eigen::MatrixXd Fq, Fv, Fqc, Fvc;
  denseJacobian(sys, s.q, s.v, 1.4901161193847656e-08, Fq, Fv, false);
  denseJacobian(sys, s.q, s.v, 1e-5, Fqc, Fvc, true);
  const Eigen::MatrixXd Sq = sparse->denseFq(), Sv = sparse->denseFv();
  INFO("|Fq| " << Fq.norm() << ", |Fv| " << Fv.norm());
  // the same forward differences, column by column: equal up to round-off in f
  CHECK((Sq - Fq).norm() <= 1e-6 * Fq.norm());
  CHECK((Sv - Fv).norm() <= 1e-6 * Fv.norm());
  // and an independent central difference: equal to finite-difference precision
  CHECK((Sq - Fqc).norm() <= 1e-5 * Fqc.norm());
  CHECK((Sv - Fvc).norm() <= 1e-5 * Fvc.norm());
  // the pattern holds on this system: what it leaves out is zero in the dense Jacobian
  for (int j = 0; j < p.n; ++j)
    for (int i = 0; i < p.n; ++i)
      if (!std::binary_search(p.rows[j].begin(), p.rows[j].end(), i)) {
        CHECK(Fq(i, j) == 0.0);
        CHECK(Fv(i, j) == 0.0);
      }
}

TEST_CASE("a pattern that leaves out a coupling gives a Jacobian the dense check refuses") {
  // the last node's coupling to the rocker dropped: its colour is then shared with a rigid dof,
  // and the rocker's row picks up the node's influence under the rigid column
  const Setup s;
  MultibodySystem sys(s.model);
  sys.setForces(ChainForces{s.l0});
  const auto sparse = sparseAt(s, sys, chainPattern(false));
  Eigen::MatrixXd Fq, Fv;
  denseJacobian(sys, s.q, s.v, 1.4901161193847656e-08, Fq, Fv, false);
  CHECK((sparse->denseFq() - Fq).norm() > 1e-3 * Fq.norm());
}

TEST_CASE("the sparse LU solves A x = b as the dense LU does, banded and by SparseLU") {
  // (the chain's pattern: a band once the rocker's dof is set aside) => both factorisations
  const bool band = GENERATE(true, false);
  const Setup s;
  MultibodySystem sys(s.model);
  sys.setForces(ChainForces{s.l0});
  const auto sparse = sparseAt(s, sys, chainPattern(true), band);
  CHECK(sparse->banded() == band);
  const double cq = 0.3 * 0.01 * 0.01, cv = 0.6 * 0.01;
  REQUIRE(sparse->factorise(cq, cv));
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(s.model.nv, s.model.nv) -
                            cq * sparse->denseFq() - cv * sparse->denseFv();
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(s.model.nv, -1.0, 2.0), x(s.model.nv);
  sparse->solve(b, x);
  CHECK((A * x - b).norm() <= 1e-12 * b.norm());
  CHECK((x - A.partialPivLu().solve(b)).norm() <= 1e-12 * x.norm());
  Eigen::MatrixXd B = Eigen::MatrixXd::Random(s.model.nv, 3), X(s.model.nv, 3);
  sparse->solve(B, X);
  CHECK((A * X - B).norm() <= 1e-12 * B.norm());
  // (refactorised for other c_q, c_v: Newton's later steps, up to c_q, c_v large enough for other
  // pivots; SparseLU in the first factorisation's storage) => each solves as the dense LU does
  for (const double scale : {2.0, 0.5, 1e3, 1e5, 1.0}) {
    INFO("c_q, c_v scaled by " << scale);
    REQUIRE(sparse->factorise(scale * cq, scale * cv));
    const Eigen::MatrixXd As = Eigen::MatrixXd::Identity(s.model.nv, s.model.nv) -
                               scale * cq * sparse->denseFq() - scale * cv * sparse->denseFv();
    sparse->solve(b, x);
    const Eigen::VectorXd y = As.partialPivLu().solve(b);
    CHECK((x - y).norm() <= 1e-10 * y.norm());
    CHECK((As * x - b).norm() <= 1e-10 * b.norm());
  }
  if (!band) CHECK(sparse->sparseLu().fullFactorisations() == 1);
}

TEST_CASE("generalized-alpha follows the same motion with the sparse and the dense Newton matrix") {
  const Setup s;
  struct Run {
    Eigen::VectorXd q, v;
    IntegratorStats stats;
    double residual = 0.0;
  };
  auto run = [&](bool sparse) {
    MultibodySystem sys(s.model);
    sys.setForces(ChainForces{s.l0});
    if (sparse) sys.setJacobianPattern(std::make_shared<JacobianPattern>(chainPattern(true)));
    GeneralizedAlpha ga(s.model, chungHulbert(0.8), "hht");
    Run r{s.q, s.v, {}, 0.0};
    Data d(s.model);
    double t = 0.0;
    for (int k = 0; k < 200; ++k) {
      ga.step(sys, t, r.q, r.v, 0.005);
      r.residual = std::max(r.residual, loopResidualNorm(s.model, d, r.q));
    }
    r.stats = ga.stats();
    return r;
  };
  const Run dense = run(false), sparse = run(true);
  INFO("dense: " << dense.stats.f_evals << " evaluations, " << dense.stats.jac_evals
                 << " matrices; sparse: " << sparse.stats.f_evals << ", "
                 << sparse.stats.jac_evals);
  CHECK(sparse.residual < 1e-9);  // the loop's Schur complement works on the sparse LU
  CHECK(dense.residual < 1e-9);
  // 1 s of motion: the nodes move by metres; equal within the Newton tolerance's reach
  CHECK((sparse.q - s.q).norm() > 0.1);
  CHECK((sparse.q - dense.q).lpNorm<Eigen::Infinity>() < 1e-6);
  CHECK((sparse.v - dense.v).lpNorm<Eigen::Infinity>() < 1e-5);
  CHECK(sparse.stats.f_evals < dense.stats.f_evals);
}
