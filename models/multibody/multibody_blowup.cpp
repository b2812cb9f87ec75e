// Blow-up diagnosis of the multibody model (docs/numerics.md): after every step the state must
// be finite, the energy balance (energy - work of the non-conservative forces, constant up to
// the integration error) must not rise beyond a bound, and the loops must stay closed. A
// failure stops the run with a NumericalError naming the time, the body or force element and
// the likely cause.
#include <cmath>
#include <sstream>

#include "dynamics/kinematics.hpp"
#include "dynamics/loop_constraints.hpp"
#include "models/multibody/multibody_model.hpp"
#include "mechanics/stiffness_estimate.hpp"
#include "models/numerical_error.hpp"
#include "mechanics/step_verdict.hpp"

namespace yardsim::models {

using mechanics::StepVerdict;
using mechanics::StiffnessEstimate;
using mechanics::estimateStiffness;
using mechanics::judgeStep;

double MultibodyModel::energyScale() const {
  // (initial state) => total weight x the system's size, plus its kinetic and strain energy
  const auto& m = mech_.model;
  const auto& x = state().x;
  dynamics::forwardKinematics(m, scratch_, x.q, x.v);
  std::vector<dynamics::Vector3> points;
  for (int i = 1; i < m.nbodies; ++i) points.push_back(scratch_.X_WB[i].p);
  const forces::Stage stage{0.0, m, scratch_, x.q, x.v};
  double stored = 0.0;
  for (const auto& r : ropes_) {
    for (const auto& a : r->path().points()) points.push_back(dynamics::pointPosition(scratch_, a.body, a.p_B));
    stored += r->potentialEnergy(stage);
  }
  for (const auto& e : equalizers_) stored += e->potentialEnergy(stage);
  double size = 1.0;
  for (const auto& a : points)
    for (const auto& b : points) size = std::max(size, (a - b).norm());
  double kinetic = 0.0;
  for (int i = 1; i < m.nbodies; ++i) kinetic += 0.5 * scratch_.V[i].dot(m.inertias[i].apply(scratch_.V[i]));
  return m.totalMass() * std::max(m.gravity.norm(), 1.0) * size + kinetic + stored;
}

std::string MultibodyModel::likelyCause() const {
  // (mechanics at the start) => omega_max against the method's limit at this step
  StiffnessEstimate e;
  try {
    e = estimateStiffness(mech_);
  } catch (const std::exception&) {
    return "a smaller dt, or an implicit integrator";
  }
  const StepVerdict v = judgeStep(e, opt_.integrator.method, opt_.dt);
  if (!v.stable) return v.suggestion + " (" + v.problem + ")";
  std::ostringstream s;
  s.precision(3);
  s << describe(e) << ", omega_max dt = " << v.omegaDt
    << " is within " << opt_.integrator.method << "'s stability limit, so energy is being created by a "
    << "force element or by a step too long for accuracy: try dt/4, check rope damping and "
       "drive bandwidths, or an implicit integrator";
  return s.str();
}

void MultibodyModel::checkBlowUp(const MultibodyState& x, double t) const {
  const auto& m = mech_.model;
  const std::string model = "multibody '" + path() + "'";
  // (non-finite state) => the first body whose joint went bad
  if (!x.q.allFinite() || !x.v.allFinite()) {
    int bad = 1;
    for (int i = 1; i < m.nbodies; ++i)
      if (!x.q.segment(m.idxQ[i], m.jointNq[i]).allFinite() ||
          !x.v.segment(m.idxV[i], m.jointNv[i]).allFinite()) {
        bad = i;
        break;
      }
    throw NumericalError(model + ", body '" + m.names[bad] + "' (joint '" + mech_.jointNames[bad] + "')",
                         t, "its state became NaN or infinite", likelyCause());
  }
  // (energy balance) => a rise beyond the bound, naming the most energetic body and element
  const double rise = energyOf(x, t, scratch_) - x.work - balance0_;
  if (rise > energyBound_) {
    int body = 1;
    double most = -1.0;
    for (int i = 1; i < m.nbodies; ++i) {
      const double k = 0.5 * scratch_.V[i].dot(m.inertias[i].apply(scratch_.V[i]));
      if (k > most) most = k, body = i;
    }
    std::string element;
    double strain = 0.0;
    const forces::Stage stage{t, m, scratch_, x.q, x.v};
    for (const auto& r : ropes_)
      if (const double u = r->potentialEnergy(stage); u > strain) strain = u, element = "rope '" + r->name() + "'";
    for (const auto& e : equalizers_)
      if (const double u = e->potentialEnergy(stage); u > strain)
        strain = u, element = "equalizer '" + e->name() + "'";
    std::ostringstream what;
    what.precision(3);
    what << "the energy balance rose by " << rise << " J (bound " << energyBound_
         << " J): the integration is unstable; most kinetic energy in body '" << m.names[body] << "'";
    if (!element.empty()) what << ", most strain energy in " << element;
    throw NumericalError(model + ", body '" + m.names[body] + "'", t, what.str(), likelyCause());
  }
  // (loops) => the loop with the largest residual, if beyond the bound
  if (m.nc == 0) return;
  const Eigen::VectorXd& r = dynamics::loopResidual(m, scratch_, x.q);
  for (const auto& loop : m.loops) {
    const double g = r.segment(loop.row, loop.dim).norm();
    if (g <= opt_.loopResidualLimit) continue;
    std::ostringstream what;
    what.precision(3);
    what << "loop '" << loop.name << "' opened: residual " << g << " (bound " << opt_.loopResidualLimit << ")";
    throw NumericalError(model + ", loop '" + loop.name + "'", t, what.str(),
                         opt_.projectLoops ? "a smaller dt, or an implicit integrator"
                                           : "turn loop projection on (project_loops: true), or a smaller dt");
  }
}

}  // namespace yardsim::models
