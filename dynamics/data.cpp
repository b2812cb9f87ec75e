#include "dynamics/data.hpp"

namespace yardsim::dynamics {

Data::Data(const Model& m)
    : X_PB(m.nbodies),
      X_WB(m.nbodies),
      S(m.nbodies),
      V_B(m.nbodies, Motion::Zero()),
      A_B(m.nbodies, Motion::Zero()),
      C_B(m.nbodies, Motion::Zero()),
      F_W(m.nbodies, Force::Zero()),
      IA_W(m.nbodies, Matrix6::Zero()),
      A_W(m.nbodies, Motion::Zero()),
      C_W(m.nbodies, Motion::Zero()),
      PA_W(m.nbodies, Force::Zero()),
      U(m.nbodies),
      Dinv(m.nbodies),
      u(m.nbodies),
      tau(Eigen::VectorXd::Zero(m.nv)),
      ddq(Eigen::VectorXd::Zero(m.nv)),
      IC_W(m.nbodies, Matrix6::Zero()),
      S_W(Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, m.nv)),
      Fcrb(Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, m.nv)),
      M(Eigen::MatrixXd::Zero(m.nv, m.nv)),
      nle(Eigen::VectorXd::Zero(m.nv)),
      L(Eigen::MatrixXd::Zero(m.nv, m.nv)),
      cholWork(Eigen::VectorXd::Zero(m.nv)),
      J(Eigen::MatrixXd::Zero(m.nc, m.nv)),
      residual(Eigen::VectorXd::Zero(m.nc)),
      cv(Eigen::VectorXd::Zero(m.nc)),
      kappa(Eigen::VectorXd::Zero(m.nc)),
      lambda(Eigen::VectorXd::Zero(m.nc)),
      MinvJt(Eigen::MatrixXd::Zero(m.nv, m.nc)),
      schur(Eigen::MatrixXd::Zero(m.nc, m.nc)),
      rhs(Eigen::VectorXd::Zero(m.nc)),
      work(Eigen::VectorXd::Zero(m.nc)),
      perm(static_cast<std::size_t>(m.nc), 0),
      V_W(m.nbodies, Motion::Zero()),
      A0_W(m.nbodies, Motion::Zero()),
      dv(Eigen::VectorXd::Zero(m.nv)),
      dq(Eigen::VectorXd::Zero(m.nq)),
      addedMass(m.addedMass),
      hasAddedMass(m.hasAddedMass) {
  // (model) => S for constant joints, sized buffers for the rest
  Eigen::VectorXd q0(m.nq);
  for (int i = 1; i < m.nbodies; ++i) {
    jointNeutral(m.joints[i], q0.data() + m.idxQ[i]);
    jointMotionSubspace(m.joints[i], q0.data() + m.idxQ[i], S[i]);
    const int nv = m.jointNv[i];
    U[i].setZero(6, nv);
    Dinv[i].setZero(nv, nv);
    u[i].setZero(nv);
  }
  S[0].setZero(6, 0);
}

}  // namespace yardsim::dynamics
