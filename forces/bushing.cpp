#include "forces/bushing.hpp"

#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "dynamics/kinematics.hpp"
#include "dynamics/rotation.hpp"

namespace yardsim::forces {

using dynamics::Matrix3;
using dynamics::Matrix6;
using dynamics::Vector3;
using dynamics::Vector6;

namespace {
// (model, bodies, frames, properties, owner) => nothing, or std::invalid_argument
void check(const dynamics::Model& model, int bodyA, const dynamics::Transform& X_AF, int bodyB,
           const dynamics::Transform& X_BG, const BushingProperties& p, const std::string& owner) {
  auto bad = [&](const std::string& what) {
    throw std::invalid_argument("bushing '" + owner + "': " + what);
  };
  for (int b : {bodyA, bodyB})
    if (b < 0 || b >= model.nbodies)
      bad("body " + std::to_string(b) + " is outside the model's " + std::to_string(model.nbodies) +
          " bodies");
  if (!X_AF.R.allFinite() || !X_AF.p.allFinite() || !X_BG.R.allFinite() || !X_BG.p.allFinite())
    bad("a frame is not finite");
  if (!p.stiffness.allFinite() || !p.damping.allFinite()) bad("K or C is not finite");
  const double scaleK = p.stiffness.cwiseAbs().maxCoeff();
  const double scaleC = p.damping.cwiseAbs().maxCoeff();
  if ((p.stiffness - p.stiffness.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scaleK)
    bad("the stiffness matrix must be symmetric (a potential exists only then)");
  if ((p.damping - p.damping.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scaleC)
    bad("the damping matrix must be symmetric");
  if (scaleC > 0.0) {
    const Eigen::SelfAdjointEigenSolver<Matrix6> eig(p.damping, Eigen::EigenvaluesOnly);
    if (eig.eigenvalues().minCoeff() < -1e-12 * scaleC)
      bad("the damping matrix must be positive semidefinite (it would feed energy in)");
  }
}
}  // namespace

Bushing::Bushing(std::string name, const dynamics::Model& model, int bodyA,
                 const dynamics::Transform& X_AF, int bodyB, const dynamics::Transform& X_BG,
                 const BushingProperties& properties)
    : ForceProvider(std::move(name)),
      bodyA_(bodyA),
      bodyB_(bodyB),
      X_AF_(X_AF),
      X_BG_(X_BG),
      p_(properties) {
  check(model, bodyA, X_AF, bodyB, X_BG, properties, this->name());
}

Bushing::Frames Bushing::frames(const Stage& s) const {
  // (X_WA, X_WB, V) => X_WF, X_WG; theta = log(R_FG), d = p_FG in F; their rates; Q
  Frames fr;
  fr.X_WF = s.data.X_WB[bodyA_] * X_AF_;
  fr.X_WG = s.data.X_WB[bodyB_] * X_BG_;
  const Matrix3 R_FG = fr.X_WF.R.transpose() * fr.X_WG.R;
  const Vector3 theta = dynamics::logSO3(R_FG);
  const Vector3 r_W = fr.X_WG.p - fr.X_WF.p;
  const Vector3 w_A = s.data.X_WB[bodyA_].R * s.data.V_B[bodyA_].head<3>();
  const Vector3 w_B = s.data.X_WB[bodyB_].R * s.data.V_B[bodyB_].head<3>();
  const Vector3 vF = dynamics::pointVelocity(s.data, bodyA_, X_AF_.p);
  const Vector3 vG = dynamics::pointVelocity(s.data, bodyB_, X_BG_.p);
  fr.JrInv = dynamics::rightJacobianInverse(theta);
  fr.st.displacement.head<3>() = theta;
  fr.st.displacement.tail<3>() = fr.X_WF.R.transpose() * r_W;
  fr.st.rate.head<3>() = fr.JrInv * (fr.X_WG.R.transpose() * (w_B - w_A));
  fr.st.rate.tail<3>() = fr.X_WF.R.transpose() * (vG - vF - w_A.cross(r_W));
  fr.st.generalizedForce = p_.stiffness * fr.st.displacement + p_.damping * fr.st.rate;
  return fr;
}

BushingState Bushing::state(const Stage& s) const {
  return frames(s).st;
}

void Bushing::doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& /*tau*/) const {
  // (Q) => the wrench on B at G's origin, world frame, and its opposite on A at the same point
  const Frames fr = frames(s);
  const Vector6& Q = fr.st.generalizedForce;
  const Vector3 m_W = -(fr.X_WG.R * (fr.JrInv.transpose() * Q.head<3>()));
  const Vector3 f_W = -(fr.X_WF.R * Q.tail<3>());
  const Vector3& p = fr.X_WG.p;
  dynamics::Force F;  // about the world origin: [m + p x f; f]
  F.head<3>() = m_W + p.cross(f_W);
  F.tail<3>() = f_W;
  if (bodyB_ != 0) f.addWorldFrame(bodyB_, F);
  if (bodyA_ != 0) f.addWorldFrame(bodyA_, -F);
}

double Bushing::doPotentialEnergy(const Stage& s) const {
  const Vector6 d = frames(s).st.displacement;
  return 0.5 * d.dot(p_.stiffness * d);
}

double Bushing::doPower(const Stage& s) const {
  const Vector6 r = frames(s).st.rate;
  return -r.dot(p_.damping * r);
}

}  // namespace yardsim::forces
