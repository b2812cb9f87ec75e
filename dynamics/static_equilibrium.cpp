#include "dynamics/static_equilibrium.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dynamics/configuration.hpp"
#include "dynamics/crba.hpp"
#include "dynamics/data.hpp"

namespace yardsim::dynamics {

namespace {

// (J, relative tolerance) => V of J's singular value decomposition (stiff directions first) and
// the number of singular values above tolerance x the largest, and above tolerance x 1 s^-2 (a J
// of finite-difference noise alone, a body in free fall, has rank 0)
int stiffSubspace(const Eigen::MatrixXd& J, double rankTolerance, Eigen::MatrixXd& V) {
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  V = svd.matrixV();
  int rank = 0;
  const double floor = rankTolerance * std::max(1.0, s.size() ? s[0] : 0.0);  // 1/s^2
  while (rank < s.size() && s[rank] > floor) ++rank;
  return rank;
}

// (q, a) => r: a with the angular (spherical, free) and linear (free) accelerations of every
// quaternion joint turned from the child frame into the joint frame, r = R_JC(q) a. r vanishes
// where a does, but its Jacobian sees no stiffness in turning a body under a net force: the
// body-frame components of a force fixed in space change as the body turns, and would make the
// roll of a barge pushed up by too much buoyancy look stiff away from equilibrium
void jointFrameAccelerations(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& a,
                             Eigen::VectorXd& r) {
  r = a;
  for (int i = 1; i < model.nbodies; ++i) {
    const JointType type = model.joints[static_cast<std::size_t>(i)].type;
    if (type != JointType::Spherical && type != JointType::Free) continue;
    const int iq = model.idxQ[static_cast<std::size_t>(i)] + (type == JointType::Free ? 3 : 0);
    const int iv = model.idxV[static_cast<std::size_t>(i)];
    const Eigen::Matrix3d R_JC =
        Eigen::Quaterniond(q[iq], q[iq + 1], q[iq + 2], q[iq + 3]).normalized().toRotationMatrix();
    r.segment<3>(iv) = R_JC * a.segment<3>(iv);
    if (type == JointType::Free) r.segment<3>(iv + 3) = R_JC * a.segment<3>(iv + 3);
  }
}

// (null space V0 of J, q, a) => the net generalized force (M a) along each direction without
// stiffness, in a basis of V0 aligned with the tangent coordinates that span it best (a column
// pivoted QR of V0^T picks them): what keeps the system from rest where nothing resists
std::vector<UnbalancedDirection> unbalancedDirections(const Model& model, const Eigen::MatrixXd& V0,
                                                      const Eigen::VectorXd& q,
                                                      const Eigen::VectorXd& a, double tolerance) {
  std::vector<UnbalancedDirection> out;
  const Eigen::Index n0 = V0.cols();
  if (n0 == 0) return out;
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(V0.transpose());
  Eigen::MatrixXd S(n0, n0);  // rows of V0 at the pivot coordinates
  for (Eigen::Index j = 0; j < n0; ++j) S.row(j) = V0.row(qr.colsPermutation().indices()[j]);
  const Eigen::MatrixXd B = V0 * S.inverse();  // B(p_j, i) = delta_ij
  Data data(model);
  const Eigen::MatrixXd& M = crba(model, data, q);
  const Eigen::VectorXd f = M * a;  // N or N m per tangent coordinate
  // (forces) => those whose acceleration |force| / M_kk passes the tolerance and a thousandth of
  // the largest (a 0.02 N rounding residue beside a 111 kN wind is not what keeps it moving)
  Eigen::VectorXd force(n0), accel(n0);
  for (Eigen::Index j = 0; j < n0; ++j) {
    const int dof = qr.colsPermutation().indices()[j];
    force[j] = B.col(j).dot(f);
    accel[j] = std::abs(force[j]) / M(dof, dof);
  }
  const double floor = std::max(tolerance, 1e-3 * accel.maxCoeff());
  for (Eigen::Index j = 0; j < n0; ++j)
    if (accel[j] > floor) out.push_back({qr.colsPermutation().indices()[j], force[j]});
  return out;
}

}  // namespace

std::string_view jointDirectionName(JointType type, int k) {
  // (type, k) => the name of one column of S, in the order jointMotionSubspace uses
  static constexpr std::string_view free[6] = {"roll (rx)", "pitch (ry)", "yaw (rz)",
                                               "surge (x)", "sway (y)",   "heave (z)"};
  static constexpr std::string_view xyz[3] = {"x", "y", "z"};
  static constexpr std::string_view sphere[3] = {"rotation about x", "rotation about y",
                                                 "rotation about z"};
  static constexpr std::string_view planar[3] = {"x", "y", "rotation"};
  switch (type) {
    case JointType::Fixed:
      return "?";
    case JointType::Revolute:
      return "rotation";
    case JointType::Prismatic:
      return "translation";
    case JointType::Cylindrical:
      return k == 0 ? "rotation" : "translation";
    case JointType::Universal:
      return k == 0 ? "rotation about the first axis" : "rotation about the second axis";
    case JointType::Spherical:
      return sphere[k];
    case JointType::Planar:
      return planar[k];
    case JointType::Free:
      return free[k];
    case JointType::Translation:
      return xyz[k];
  }
  return "?";
}

bool jointDirectionIsRotation(JointType type, int k) {
  switch (type) {
    case JointType::Revolute:
    case JointType::Universal:
    case JointType::Spherical:
      return true;
    case JointType::Cylindrical:
      return k == 0;
    case JointType::Planar:
      return k == 2;
    case JointType::Free:
      return k < 3;
    default:
      return false;
  }
}

EquilibriumResult solveStaticEquilibrium(const Model& model, AccelerationSource& system, double t,
                                         Eigen::VectorXd& q, const EquilibriumOptions& options) {
  const Eigen::Index nv = model.nv;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(nv), a(nv), aTrial(nv), dx(nv), e(nv), qTrial(q.size());
  Eigen::VectorXd r(nv), rTrial(nv);
  Eigen::MatrixXd J(nv, nv), Jr(nv, nv), V(nv, nv);
  // (q) => max |a| at rest, after the system's own step hook (loop projection)
  auto residual = [&](Eigen::VectorXd& qq, Eigen::VectorXd& out) {
    v.setZero();
    system.afterStep(t, qq, v);
    v.setZero();
    system.acceleration(t, qq, v, out);
    return out.size() ? out.cwiseAbs().maxCoeff() : 0.0;
  };
  // (trial q) => its residual, +inf where the system cannot evaluate it (far from anything)
  auto trialResidual = [&](Eigen::VectorXd& qq, Eigen::VectorXd& out) {
    try {
      const double value = residual(qq, out);
      return std::isfinite(value) ? value : std::numeric_limits<double>::infinity();
    } catch (const std::runtime_error&) {
      return std::numeric_limits<double>::infinity();
    }
  };
  // (q, a at q) => J = da/dx and Jr = dr/dx, one tangent direction at a time; the rank of Jr and
  // its V
  auto jacobian = [&]() {
    jointFrameAccelerations(model, q, a, r);
    for (Eigen::Index k = 0; k < nv; ++k) {
      e.setZero();
      e[k] = options.step;
      integrate(model, q, e, 1.0, qTrial);
      if (std::isfinite(trialResidual(qTrial, aTrial))) {
        jointFrameAccelerations(model, qTrial, aTrial, rTrial);
      } else {  // no information there
        aTrial = a;
        rTrial = r;
      }
      J.col(k) = (aTrial - a) / options.step;
      Jr.col(k) = (rTrial - r) / options.step;
    }
    return stiffSubspace(Jr, options.rankTolerance, V);
  };
  // (rank-revealing or not, q) => q searched; without rank revealing every direction is taken as
  // stiff (the minimum-norm search of before, which may move directions without stiffness)
  auto search = [&](bool rankRevealing) {
    EquilibriumResult result;
    result.residual = residual(q, a);
    result.rank = static_cast<int>(nv);
    double sigma = 0.0;
    int neutral = 0;  // accepted moves in a row that did not lower the residual
    while (result.residual > options.tolerance && result.iterations < options.maxIterations) {
      ++result.iterations;
      const int revealed = jacobian();
      const int rank = result.rank = rankRevealing ? revealed : static_cast<int>(nv);
      const double scale = std::max(1.0, J.cwiseAbs().maxCoeff());  // 1/s^2
      // (J, a, sigma) => a step of (J - sigma I) dx = -a: Newton's when sigma = 0, a step along
      // the accelerations when J vanishes (a slack rope); sigma grows until the step is accepted,
      // then shrinks again (Levenberg-Marquardt on the residual). With directions without
      // stiffness (rank < nv) the step is dx = V_r y, y the least-squares solution of
      // (Jr - sigma I) V_r y = -r (the joint-frame accelerations), plus, with sigma > 0, a fall
      // V_0 V_0^T a / sigma along the net acceleration where it does not vanish: a free direction
      // without force never moves. With every direction stiff the step is the one above, as before
      const auto step = [&]() {
        if (rank == nv) {
          Eigen::MatrixXd A = J;
          A.diagonal().array() -= sigma;
          dx = A.completeOrthogonalDecomposition().solve(-a);
          return;
        }
        dx.setZero();
        if (rank > 0) {
          const auto Vr = V.leftCols(rank);
          const Eigen::MatrixXd A = Jr * Vr - sigma * Vr;
          dx = Vr * A.completeOrthogonalDecomposition().solve(-r);
        }
        const auto V0 = V.rightCols(nv - rank);
        const Eigen::VectorXd n = V0.transpose() * a;
        if (sigma > 0.0 && n.norm() > options.tolerance) dx += V0 * n / sigma;
      };
      bool accepted = false;
      for (int tries = 0; tries < 60 && !accepted; ++tries) {
        step();
        bool descent = false;
        if (dx.allFinite()) {
          integrate(model, q, dx, 1.0, qTrial);
          normalizeConfiguration(model, qTrial);
          const double trial = trialResidual(qTrial, aTrial);
          // a descent, or (with sigma > 0) a move that changes nothing yet: falling onto a slack
          // rope leaves the residual at g until the rope bites; such moves keep their size and
          // are limited in number (a body with nothing under it falls forever)
          descent = trial < result.residual;
          accepted = descent || (sigma > 0.0 && neutral < options.maxNeutralSteps &&
                                 trial <= result.residual * (1.0 + 1e-12));
        }
        if (accepted) {
          neutral = descent ? 0 : neutral + 1;
          if (descent) sigma = sigma * 0.1 < 1e-12 * scale ? 0.0 : sigma * 0.1;
        } else {
          sigma = sigma == 0.0 ? 1e-6 * scale : sigma * 10.0;
        }
      }
      if (!accepted) break;  // no descent: the best configuration found is kept
      q = qTrial;
      result.residual = residual(q, a);
    }
    result.converged = result.residual <= options.tolerance;
    return result;
  };
  const Eigen::VectorXd q0 = q;
  EquilibriumResult result = search(true);
  if (result.converged) return result;
  // (q0: the pose the search started from) => what has no stiffness and a force there. Not where
  // the search stopped: a body pushed along a direction without stiffness runs off (millions of
  // metres), where the moments' round-off turns it and the directions named depend on the
  // digits (the same push named as sway, or as surge and yaw)
  const Eigen::VectorXd stopped = q;
  q = q0;
  residual(q, a);
  result.rank = jacobian();
  result.unbalanced =
      unbalancedDirections(model, V.rightCols(nv - result.rank), q, a, options.tolerance);
  // (q0) => the minimum-norm search of before, when the rank-revealing one stalls where stiffness
  // appears only after a move (a barge pulled sideways by an inclined rope that is still slack)
  EquilibriumResult plain = search(false);
  if (plain.converged) {
    plain.minimumNorm = true;
    return plain;
  }
  q = stopped;
  return result;
}

}  // namespace yardsim::dynamics
