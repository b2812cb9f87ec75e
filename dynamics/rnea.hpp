#pragma once
// Inverse dynamics by the recursive Newton-Euler algorithm (Featherstone, table 5.1): rnea in each
// body's frame (where its inertia is constant), rneaWorld in the world frame (velocities,
// accelerations and forces in world coordinates, so a joint force passes to the parent by
// addition), and the bias forces h(q, v) = RNEA(q, v, 0) in the world frame.

#include <vector>

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

/// (q, v, ddq, external forces) => data.tau with M ddq + h = tau + sum J_i^T F_ext_i, computed in
/// each body's frame (Featherstone's table 5.1 as written). Also leaves data.X_PB, data.V_B (as
/// forwardKinematics), data.A_B (body frame, including -g) and in data.F_W the force transmitted
/// by joint i to body i **in body i's frame**, about its origin; data.X_WB only with external
/// forces in the world frame or added mass. The same torques as rneaWorld to round-off.
const Eigen::VectorXd& rnea(const Model& model, Data& data, const Eigen::VectorXd& q,
                            const Eigen::VectorXd& v, const Eigen::VectorXd& ddq,
                            const ExternalForces* fext = nullptr);

/// rnea written in the world frame (the bias forces' loop with ddq): data.tau, and data.X_WB,
/// data.S_W, data.V_W, data.A_W (world frame, including -g) and data.F_W, the force transmitted
/// by joint i to body i in the world frame (the joint reactions of a scene's channels).
const Eigen::VectorXd& rneaWorld(const Model& model, Data& data, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& v, const Eigen::VectorXd& ddq,
                                 const ExternalForces* fext = nullptr);

/// (q, v, external forces) => data.nle = h(q, v) - sum J_i^T F_ext_i, i.e. RNEA with ddq = 0.
const Eigen::VectorXd& biasForces(const Model& model, Data& data, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                  const ExternalForces* fext = nullptr);

/// Bodies of a model by index (world = 0): `subtree` marks the bodies of the subtrees of some
/// joints, `forward` those and their ancestors. Sized by mark(); assign() reuses the capacity,
/// so a mask marked again for the same model does not allocate.
struct SubtreeMask {
  std::vector<char> subtree, forward;
  bool any = false;  ///< the subtree is not empty
  /// every joint of `forward` is prismatic, a translation or fixed: nothing in it rotates
  bool translational = false;
  /// (roots[i] != 0: body i's joint is wanted, size nbodies) => subtree, forward, any
  void mark(const Model& model, const std::vector<char>& roots);
};

/// (q, v; placed: a Data holding forwardKinematics(q) (X_WB, S); the subtrees of the wanted
/// joints) => data.nle[iv] = h(q, v) for every joint of the mask's subtree, N or N m: the same
/// doubles as biasForces (no external forces), without placing the bodies again and without
/// the bodies outside the subtrees and their supports. The other entries of data.nle keep
/// their values. A translational mask on bodies without added mass (a crane's travel and
/// trolleys) takes a shorter path with the same meaning: nothing rotates, so h is the weight of
/// each joint's subtree along its axes, S^T sum m (-g) (equal to RNEA's to round-off: its
/// velocity-product and moment terms are exact zeros there).
const Eigen::VectorXd& biasForcesOfSubtrees(const Model& model, Data& data, const Data& placed,
                                            const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                            const SubtreeMask& mask);

}  // namespace yardsim::dynamics
