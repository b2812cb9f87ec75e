#include "dynamics/integrators/chart_newton_system.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dynamics/joint.hpp"

namespace yardsim::dynamics {

namespace {

bool rotational(JointType t) {
  return t == JointType::Spherical || t == JointType::Free;
}

// (model, pattern) => the pattern with every rotational joint's columns holding the union of
// their rows and the joint's own dofs: F_q M then stays on it
JacobianPattern grouped(const Model& m, const JacobianPattern& pattern) {
  JacobianPattern out = pattern;
  if (pattern.n != m.nv || static_cast<int>(pattern.rows.size()) != m.nv) return out;
  for (int i = 1; i < m.nbodies; ++i) {
    if (!rotational(m.joints[static_cast<std::size_t>(i)].type)) continue;
    const int first = m.idxV[static_cast<std::size_t>(i)],
              k = m.jointNv[static_cast<std::size_t>(i)];
    std::vector<int> rows;
    for (int c = first; c < first + k; ++c) {
      const auto& r = pattern.rows[static_cast<std::size_t>(c)];
      rows.insert(rows.end(), r.begin(), r.end());
      rows.push_back(c);
    }
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (int c = first; c < first + k; ++c) out.rows[static_cast<std::size_t>(c)] = rows;
  }
  return out;
}

}  // namespace

ChartNewtonSystem::ChartNewtonSystem(const Model& model, const JacobianPattern& pattern,
                                     const JacobianBlocks* blocks, bool kinematicImplicit)
    : model_(model),
      kinematic_(kinematicImplicit),
      sparse_(model, grouped(model, pattern), blocks) {
  // (rotational joints) => their groups of columns, K = 0, G = P = I until formed
  for (int i = 1; i < model.nbodies && kinematic_; ++i) {
    if (!rotational(model.joints[static_cast<std::size_t>(i)].type)) continue;
    Group g;
    g.joint = i;
    g.first = model.idxV[static_cast<std::size_t>(i)];
    g.k = model.jointNv[static_cast<std::size_t>(i)];
    g.K.setZero();
    g.G.setIdentity();
    g.P.setIdentity();
    if (!sparse_.groupColumns(g.first, g.k))
      throw std::invalid_argument("ChartNewtonSystem: a rotational joint's columns differ in rows");
    groups_.push_back(g);
  }
  maps_.assign(groups_.size(), Eigen::Matrix<double, 6, 6>::Identity());
  for (Eigen::VectorXd* x : {&theta_, &v_, &f_, &u_, &r_, &xv_}) x->setZero(model.nv);
}

int ChartNewtonSystem::form(AccelerationSource& source, double t, const Eigen::VectorXd& origin,
                            const double* y, const Eigen::VectorXd& q, const Eigen::VectorXd& a) {
  const int n = model_.nv;
  theta_ = Eigen::Map<const Eigen::VectorXd>(y, n);
  v_ = Eigen::Map<const Eigen::VectorXd>(y + n, n);
  f_ = a;
  // (colours) => F_q through the chart at q*, F_v, by forward differences (the forces with an
  // analytic linearisation taking it about (q, v))
  const LinearisedScope linearised(source, t, q, v_);
  const int evaluations =
      sparse_.form([&](const Eigen::VectorXd& qs, const Eigen::VectorXd& vs, bool,
                       Eigen::VectorXd& out) { source.acceleration(t, qs, vs, out); },
                   origin, theta_, q, v_, f_);
  refreshBlocks(source, t, q, v_);
  // (per rotational joint, theta, v) => G = d(G v)/dv (the rate is linear in v: its columns at
  // the unit vectors) and K = d(G v)/d theta by central differences
  for (Group& g : groups_) {
    const Joint& joint = model_.joints[static_cast<std::size_t>(g.joint)];
    double th[6], unit[6], plus[6], minus[6];
    for (int c = 0; c < g.k; ++c) th[c] = theta_[g.first + c];
    for (int c = 0; c < g.k; ++c) {
      for (int e = 0; e < g.k; ++e) unit[e] = e == c ? 1.0 : 0.0;
      jointChartRate(joint, th, unit, plus);
      for (int e = 0; e < g.k; ++e) g.G(e, c) = plus[e];
      const double h = 1e-6 * std::max(1.0, std::abs(th[c])), saved = th[c];
      th[c] = saved + h;
      jointChartRate(joint, th, v_.data() + g.first, plus);
      th[c] = saved - h;
      jointChartRate(joint, th, v_.data() + g.first, minus);
      th[c] = saved;
      for (int e = 0; e < g.k; ++e) g.K(e, c) = (plus[e] - minus[e]) / (2.0 * h);
    }
  }
  return evaluations;
}

void ChartNewtonSystem::refreshBlocks(AccelerationSource& source, double t,
                                      const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  if (!sparse_.hasBlocks()) return;
  sparse_.applyBlocks(source.blockJacobian(t, q, v, sparse_.blockDq(), sparse_.blockDv()));
}

bool ChartNewtonSystem::factorise(double gamma) {
  gamma_ = gamma;
  if (!kinematic_) return ok_ = sparse_.factorise(0.0, gamma);
  // (gamma, K, G) => P = (I - gamma K)^-1 and M = P G per rotational joint (identity beyond k)
  for (std::size_t i = 0; i < groups_.size(); ++i) {
    Group& g = groups_[i];
    const Eigen::Matrix<double, 6, 6> IK = Eigen::Matrix<double, 6, 6>::Identity() - gamma * g.K;
    g.P = IK.partialPivLu().inverse();
    maps_[i] = g.P * g.G;
  }
  return ok_ = sparse_.factorise(gamma * gamma, gamma, maps_);
}

void ChartNewtonSystem::solve(const double* b, double* x) {
  const int n = model_.nv;
  const Eigen::Map<const Eigen::VectorXd> bTheta(b, n), bV(b + n, n);
  // (b_theta) => u = P b_theta; (b_v, u) => r = b_v + gamma F_q u
  u_ = bTheta;
  if (kinematic_)
    for (const Group& g : groups_)
      u_.segment(g.first, g.k).noalias() =
          g.P.topLeftCorner(g.k, g.k) * bTheta.segment(g.first, g.k);
  r_ = bV;
  sparse_.addFq(gamma_, u_, r_);
  // (r) => x_v by the reduced matrix's LU
  sparse_.solve(r_, xv_);
  // (u, x_v) => x_theta = u + gamma M x_v (explicit kinematics: b_theta)
  Eigen::Map<Eigen::VectorXd> xTheta(x, n), xV(x + n, n);
  if (!kinematic_) {
    xTheta = u_;
  } else {
    xTheta = u_ + gamma_ * xv_;
    for (std::size_t i = 0; i < groups_.size(); ++i) {
      const Group& g = groups_[i];
      xTheta.segment(g.first, g.k) =
          u_.segment(g.first, g.k) +
          gamma_ * maps_[i].topLeftCorner(g.k, g.k) * xv_.segment(g.first, g.k);
    }
  }
  xV = xv_;
}

}  // namespace yardsim::dynamics
