#pragma once
// The mutable workspace of the algorithms, made once from a Model: every buffer they need is
// allocated here, so the algorithms themselves never allocate.

#include <Eigen/Core>
#include <vector>

#include "dynamics/model.hpp"

namespace yardsim::dynamics {

struct Data {
  explicit Data(const Model& model);

  // kinematics (index 0 = world)
  std::vector<Transform> X_PB;  ///< pose of body i in its parent body
  std::vector<Transform> X_WB;  ///< pose of body i in the world
  std::vector<MotionSubspace> S;  ///< joint motion subspace of body i, body frame
  std::vector<Motion> V_B;  ///< forwardKinematics: spatial velocity of body i, body frame
  std::vector<Motion> A_B;  ///< forwardKinematics: spatial acceleration of body i, body frame,
                            ///< without gravity (rnea: with -g)
  std::vector<Motion> C_B;  ///< forwardKinematics: velocity-product acceleration c_J + V x S v_i, body frame

  // RNEA / ABA (world frame)
  std::vector<Force> F_W;     ///< RNEA: force transmitted by joint i to body i, world frame
                              ///< (rneaWorld, biasForces; rnea: body frame)
  std::vector<Matrix6> IA_W;  ///< articulated inertia, world frame
  std::vector<Motion> A_W;  ///< RNEA, ABA: spatial acceleration, world frame, including -g
  std::vector<Motion> C_W;  ///< ABA: velocity-product acceleration, world frame
  std::vector<Force> PA_W;  ///< ABA: articulated bias force, world frame
  std::vector<Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::ColMajor, 6, 6>> U;
  /// ABA: D^-1 = (S^T IA S)^-1 of joint i; for a free joint at the root, D's L D L^T factors
  /// instead (strict lower triangle L, diagonal D: aba.cpp solves with them)
  std::vector<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 6, 6>> Dinv;
  std::vector<Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 6, 1>> u;
  Eigen::VectorXd tau;  ///< RNEA output
  Eigen::VectorXd ddq;  ///< ABA output

  // CRBA, bias forces, Cholesky
  std::vector<Matrix6> IC_W;  ///< composite inertia of the subtree of i, world frame
  Eigen::Matrix<double, 6, Eigen::Dynamic> S_W;  ///< motion subspace columns, world frame (6 x nv)
  Eigen::Matrix<double, 6, Eigen::Dynamic> Fcrb;  ///< CRBA: IC_W S_W column by column (6 x nv)
  Eigen::MatrixXd M;   ///< joint-space mass matrix (upper and lower triangle)
  Eigen::VectorXd nle; ///< bias forces h(q, v) (Coriolis, centrifugal, gravity)
  Eigen::MatrixXd L;         ///< choleskyFactor: M = L^T L along the dof tree (lower triangle)
  Eigen::VectorXd cholWork;  ///< choleskyFactor scratch (nv)

  // loop constraints
  Eigen::MatrixXd J;        ///< nc x nv constraint Jacobian
  Eigen::VectorXd residual; ///< nc position residual
  Eigen::VectorXd cv;       ///< nc velocity residual J v
  Eigen::VectorXd kappa;    ///< nc acceleration bias: d/dt(J v) = J ddq + kappa
  Eigen::VectorXd lambda;   ///< nc multipliers: the generalized constraint force is J^T lambda
  Eigen::MatrixXd MinvJt;   ///< nv x nc
  Eigen::MatrixXd schur;    ///< nc x nc  J M^-1 J^T
  Eigen::VectorXd rhs;      ///< nc
  Eigen::VectorXd work;     ///< nc
  std::vector<int> perm;    ///< nc pivot order
  int schurRank = 0;
  std::vector<Motion> V_W;  ///< spatial velocity of body i, world frame (RNEA, ABA, loop Jacobians)
  std::vector<Motion> A0_W; ///< spatial acceleration with ddq = 0, world frame (no gravity)
  Eigen::VectorXd dv;       ///< nv scratch
  Eigen::VectorXd dq;       ///< nq scratch

  // added mass as the kernels use it (ABA, CRBA, RNEA, energy): per body, about the body origin
  // in the body frame, [angular; linear], kg, kg m, kg m^2; initialised from Model::addedMass.
  // A body whose added mass follows its state (its draft: forces/hydro/draft_added_mass.hpp)
  // gets it written here before the kernels run at each stage.
  std::vector<Matrix6> addedMass;
  std::vector<char> hasAddedMass;  ///< addedMass[i] is not zero (char, as Model's)
};

}  // namespace yardsim::dynamics
