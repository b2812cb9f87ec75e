#include "mechanics/stiffness_estimate.hpp"

#include <cmath>
#include <complex>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "dynamics/configuration.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/multibody_system.hpp"
#include "forces/provider_stiffness.hpp"
#include "mechanics/data.hpp"
#include "mechanics/largest_mode.hpp"
#include "mechanics/providers.hpp"
#include "mechanics/stage.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

namespace {

constexpr double kTautStrain = 1e-4;  // strain given to a rope that is slack at the start
constexpr double kStep = 1e-7;        // finite-difference step, m or rad

// (mechanics) => the same mechanics with every slack rope and equalizer just taut at q0
BuiltMechanics tautened(const BuiltMechanics& mech) {
  BuiltMechanics m = mech;
  Providers p = makeProviders(m, m.model);
  dynamics::Data data(m.model);
  dynamics::forwardKinematics(m.model, data, m.q0, m.v0);
  const forces::Stage s{0.0, m.model, data, m.q0, m.v0};
  auto tighten = [](MechanicsSpec::Material& mat, double length) {
    mat.l0 = std::min(mat.l0, length / (1.0 + kTautStrain));
    mat.minLength = std::min(mat.minLength, mat.l0);
  };
  const std::size_t nw = m.ropes.size();  // (ropes) => the wire ropes, then the equalizers
  for (std::size_t i = 0; i < p.ropes.size(); ++i)
    tighten(i < nw ? m.ropes[i].material : m.equalizers[i - nw].material, p.ropes[i]->length(s));
  return m;
}

// (kernel, q0, v0) => J = [0 I; A_q A_v] by central differences of the accelerations, dense,
// and its eigenvalue of largest modulus with its mode's q part
void denseLargestMode(dynamics::MultibodySystem& kernel, const dynamics::Model& model,
                      const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                      std::complex<double>& lambda, Eigen::VectorXcd& shape) {
  const int nv = model.nv;
  // (q0 (+) theta, v0 + dv) => central differences of the accelerations: J = [0 I; A_q A_v]
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(2 * nv, 2 * nv);
  J.topRightCorner(nv, nv).setIdentity();
  Eigen::VectorXd q(model.nq), v(nv), ap(nv), am(nv), d(nv);
  for (int j = 0; j < nv; ++j) {
    for (int side = 0; side < 2; ++side) {
      const double sign = side == 0 ? 1.0 : -1.0;
      d.setZero();
      d[j] = sign * kStep;
      dynamics::integrate(model, q0, d, 1.0, q);
      kernel.acceleration(0.0, q, v0, side == 0 ? ap : am);
    }
    J.block(nv, j, nv, 1) = (ap - am) / (2.0 * kStep);
    for (int side = 0; side < 2; ++side) {
      v = v0;
      v[j] += (side == 0 ? 1.0 : -1.0) * kStep;
      kernel.acceleration(0.0, q0, v, side == 0 ? ap : am);
    }
    J.block(nv, nv + j, nv, 1) = (ap - am) / (2.0 * kStep);
  }
  // (J) => the eigenvalue of largest modulus and its mode shape
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(J, true);
  Eigen::Index top = 0;
  eig.eigenvalues().cwiseAbs().maxCoeff(&top);
  lambda = eig.eigenvalues()[top];
  shape = eig.eigenvectors().col(top).head(nv);
}

}  // namespace

StiffnessEstimate estimateStiffness(const BuiltMechanics& original, const ServoSettings& servo) {
  const BuiltMechanics mech = tautened(original);
  const auto& model = mech.model;
  const int nv = model.nv;
  StiffnessEstimate out;
  if (nv == 0) return out;
  // (the system's one provider list and its held joints' servos) => the stage the run evaluates
  const System system(mech, servo, "stiffness estimate");
  Data data(system);
  SetPoints held{std::vector<JointDrive>(static_cast<std::size_t>(model.nbodies)),
                 std::vector<ActorLoad>(static_cast<std::size_t>(model.nbodies)),
                 std::vector<WinchJob>(system.ropes().size())};
  if (servo.bandwidth > 0)
    for (int i = 1; i < model.nbodies; ++i)
      if (mech.hold[static_cast<std::size_t>(i)]) {
        const double q = mech.q0[model.idxQ[i]];
        held.drives[static_cast<std::size_t>(i)] =
            JointDrive{true, true, q, q, 0.0, 0.0, "", false};
      }
  data.setPoints = &held;
  connectStage(system, data);
  dynamics::MultibodySystem& kernel = data.kernel;
  // (a structured system: lumped-line nodes) => J on its pattern and Arnoldi (largest_mode.hpp);
  // (any other) => J dense by central differences and every eigenvalue
  // (a catenary line) => its analytic linearisation about the initial state in the differences
  std::complex<double> lambda;
  Eigen::VectorXcd shape;
  const dynamics::LinearisedScope linearised(kernel, 0.0, mech.q0, mech.v0);
  if (const dynamics::JacobianPattern* pattern = kernel.jacobianPattern()) {
    const LargestMode mode = largestMode(kernel, model, mech.q0, mech.v0, *pattern, kStep);
    lambda = mode.lambda;
    shape = mode.shape;
  } else {
    denseLargestMode(kernel, model, mech.q0, mech.v0, lambda, shape);
  }
  out.omegaMax = std::abs(lambda);
  out.dampingRatio = out.omegaMax > 0 ? -lambda.real() / out.omegaMax : 0.0;
  Eigen::Index dof = 0;
  shape.cwiseAbs().maxCoeff(&dof);
  out.body = model.names[static_cast<std::size_t>(model.dofBody[static_cast<std::size_t>(dof)])];
  // (mode shape, phase-aligned to its largest entry) => strain energy of each element along it
  const Eigen::VectorXd phi =
      (shape * std::conj(shape[dof]) / std::abs(shape[dof])).real().normalized();
  dynamics::Data dp(model), dm(model);
  Eigen::VectorXd qp(model.nq), qm(model.nq);
  const double h = 1e-6;
  dynamics::integrate(model, mech.q0, phi, h, qp);
  dynamics::integrate(model, mech.q0, phi, -h, qm);
  dynamics::forwardKinematics(model, dp, qp, mech.v0);
  dynamics::forwardKinematics(model, dm, qm, mech.v0);
  const forces::Stage sp{0.0, model, dp, qp, mech.v0}, sm{0.0, model, dm, qm, mech.v0};
  double best = 0.0;
  auto consider = [&](const std::string& name, double stiffness, double dl) {
    const double energy = 0.5 * stiffness * dl * dl;
    if (energy > best) {
      best = energy;
      out.element = name;
    }
  };
  for (const auto& r : system.ropes())
    consider((r->branchCount() > 1 ? "equalizer '" : "rope '") + r->name() + "'",
             r->parts() * r->properties().ea / r->properties().l0,
             (r->length(sp) - r->length(sm)) / (2 * h));
  // (any other provider that stores energy) => its strain energy along the mode, by the second
  // difference of its potential energy
  dynamics::Data d0(model);
  dynamics::forwardKinematics(model, d0, mech.q0, mech.v0);
  const forces::Stage s0{0.0, model, d0, mech.q0, mech.v0};
  for (std::size_t k = system.ropes().size(); k < system.providers().size(); ++k) {
    const forces::ForceProvider& p = *system.providers()[k];
    const double curvature =
        (p.potentialEnergy(sp) - 2.0 * p.potentialEnergy(s0) + p.potentialEnergy(sm)) / (h * h);
    if (curvature > 0) consider("provider '" + p.name() + "'", curvature, 1.0);
  }
  // (providers that bring stiffness in later: contacts open at the start) => their hint when it
  // is higher than the linearisation's
  for (const forces::ForceProvider* p : system.providers())
    if (const auto* hinted = dynamic_cast<const forces::ProviderStiffness*>(p)) {
      const forces::StiffnessHint hint = hinted->stiffnessHint(model);
      if (hint.omega <= out.omegaMax) continue;
      out = {hint.omega, 0.0, hint.body,
             "provider '" + p->name() + "' (" + hint.what + ", once engaged)"};
    }
  return out;
}

std::string describe(const StiffnessEstimate& e) {
  std::ostringstream s;
  s.precision(3);
  s << "omega_max = " << e.omegaMax << " rad/s, damping ratio " << e.dampingRatio << " (body '"
    << e.body << "'";
  if (!e.element.empty()) s << ", " << e.element;
  s << ")";
  return s.str();
}

}  // namespace yardsim::mechanics
