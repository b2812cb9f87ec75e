#include "mechanics/blowup.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "dynamics/kinematics.hpp"
#include "dynamics/loop_constraints.hpp"
#include "mechanics/energy.hpp"
#include "mechanics/step_verdict.hpp"
#include "mechanics/stiffness_estimate.hpp"

namespace yardsim::mechanics {

double energyScale(const System& s, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  // (initial state) => total weight x the system's size, plus its kinetic and strain energy
  const auto& m = s.model();
  const dynamics::Data& kin = d.scratchKinematics(s, q, v);
  std::vector<dynamics::Vector3> points;
  for (int i = 1; i < m.nbodies; ++i) points.push_back(kin.X_WB[i].p);
  const forces::Stage stage{0.0, m, kin, q, v};
  double stored = 0.0;
  for (const auto& r : s.ropes()) {  // (every branch's points) => the system's extent
    for (int j = 0; j < r->branchCount(); ++j)
      for (const auto& a : r->branch(j).points())
        points.push_back(dynamics::pointPosition(kin, a.body, a.p_B));
    stored += r->potentialEnergy(stage);
  }
  double size = 1.0;
  for (const auto& a : points)
    for (const auto& b : points) size = std::max(size, (a - b).norm());
  double kinetic = 0.0;
  for (int i = 1; i < m.nbodies; ++i)
    kinetic += 0.5 * kin.V_B[i].dot(m.inertias[i].apply(kin.V_B[i]));
  return m.totalMass() * std::max(m.gravity.norm(), 1.0) * size + kinetic + stored;
}

std::string likelyCause(const System& s, const std::string& method, double dt) {
  // (mechanics at the start) => omega_max against the method's limit at this step
  StiffnessEstimate e;
  try {
    e = estimateStiffness(s.description(), s.servo());
  } catch (const std::exception&) {
    return "a smaller dt, or an implicit integrator";
  }
  const StepVerdict v = judgeStep(e, method, dt);
  if (!v.stable) return v.suggestion + " (" + v.problem + ")";
  std::ostringstream o;
  o.precision(3);
  o << describe(e) << ", omega_max dt = " << v.omegaDt << " is within " << method
    << "'s stability limit, so energy is being created by a "
    << "force element or by a step too long for accuracy: try dt/4, check rope damping and "
       "drive bandwidths, or an implicit integrator";
  return o.str();
}

double checkBlowUp(const System& s, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                   double work, double t, const BlowUpLimits& limits) {
  const auto& m = s.model();
  // (non-finite state) => the first body whose joint went bad
  if (!q.allFinite() || !v.allFinite()) {
    int bad = 1;
    for (int i = 1; i < m.nbodies; ++i)
      if (!q.segment(m.idxQ[i], m.jointNq[i]).allFinite() ||
          !v.segment(m.idxV[i], m.jointNv[i]).allFinite()) {
        bad = i;
        break;
      }
    throw BlowUp(", body '" + m.names[bad] + "' (joint '" + s.description().jointNames[bad] + "')",
                 "its state became NaN or infinite", likelyCause(s, limits.method, limits.dt));
  }
  // (energy balance) => a rise beyond the bound, naming the most energetic body and element
  dynamics::Data& kin = d.scratchKinematics(s, q, v);
  const double energy = energyAfterKinematics(s, d, kin, q, v, t);
  const double rise = energy - work - limits.balance0;
  if (rise > limits.energyBound) {
    int body = 1;
    double most = -1.0;
    for (int i = 1; i < m.nbodies; ++i) {
      const double k = 0.5 * kin.V_B[i].dot(m.inertias[i].apply(kin.V_B[i]));
      if (k > most) most = k, body = i;
    }
    std::string element;
    double strain = 0.0;
    const forces::Stage stage{t, m, kin, q, v};
    for (const auto& r : s.ropes())
      if (const double u = r->potentialEnergy(stage); u > strain)
        strain = u, element = (r->branchCount() > 1 ? "equalizer '" : "rope '") + r->name() + "'";
    std::ostringstream what;
    what.precision(3);
    what << "the energy balance rose by " << rise << " J (bound " << limits.energyBound
         << " J): the integration is unstable; most kinetic energy in body '" << m.names[body]
         << "'";
    if (!element.empty()) what << ", most strain energy in " << element;
    throw BlowUp(", body '" + m.names[body] + "'", what.str(),
                 likelyCause(s, limits.method, limits.dt));
  }
  // (loops) => the loop with the largest residual, if beyond the bound
  if (m.nc == 0) return energy;
  d.scratchWritten();  // (the residual places the bodies in scratch)
  const Eigen::VectorXd& r = dynamics::loopResidual(m, d.scratch, q);
  for (const auto& loop : m.loops) {
    const double g = r.segment(loop.row, loop.dim).norm();
    if (g <= limits.loopResidualLimit) continue;
    std::ostringstream what;
    what.precision(3);
    what << "loop '" << loop.name << "' opened: residual " << g << " (bound "
         << limits.loopResidualLimit << ")";
    throw BlowUp(", loop '" + loop.name + "'", what.str(),
                 limits.projectLoops
                     ? "a smaller dt, or an implicit integrator"
                     : "turn loop projection on (project_loops: true), or a smaller dt");
  }
  return energy;
}

}  // namespace yardsim::mechanics
