#include "mechanics/energy.hpp"

#include "dynamics/energy.hpp"
#include "dynamics/kinematics.hpp"
#include "mechanics/follow_mass.hpp"
#include "mechanics/stage.hpp"

namespace yardsim::mechanics {

double energy(const System& s, const Data& d, dynamics::Data& kin, const Eigen::VectorXd& q,
              const Eigen::VectorXd& v, double t) {
  // (one kinematics pass) => kinetic + gravity potential of every body, then stored energy
  dynamics::forwardKinematics(s.model(), kin, q, v);
  return energyAfterKinematics(s, d, kin, q, v, t);
}

double energyAfterKinematics(const System& s, const Data& d, dynamics::Data& kin,
                             const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t) {
  const auto& m = s.model();
  // (pose, t) => the added mass of the kinetic energy, where it follows the draft or a winch
  followMass(s, t, kin, kin);
  double e = 0.0;
  for (int i = 1; i < m.nbodies; ++i) {
    e +=
        dynamics::bodyKineticEnergy(m, kin, i, kin.V_B[i]) -  // with the fluid's share (added mass)
        m.inertias[i].mass * m.gravity.dot(kin.X_WB[i].actPoint(m.inertias[i].com));
  }
  forEachProvider(s, d, d.stage(s, t, kin, q, v),
                  [&](const forces::ForceProvider& p, const forces::Stage& st) {
                    e += p.potentialEnergy(st);
                  });
  return e;
}

double nonConservativePower(const System& s, Data& d, const SetPoints& sp, const Eigen::VectorXd& q,
                            const Eigen::VectorXd& v, double t) {
  const auto& m = s.model();
  const dynamics::Data& kin = d.scratchKinematics(s, q, v);
  double p = 0.0;
  forEachProvider(
      s, d, d.stage(s, t, kin, q, v),
      [&](const forces::ForceProvider& f, const forces::Stage& st) { p += f.power(st); });
  // (drives, loads) => their forces at this state, and the power they deliver
  const SetPoints* saved = d.setPoints;
  d.setPoints = &sp;
  d.spForces.clear();
  d.spTau.setZero();
  setPointForces(s, d, sp, t, q, v, kin, d.spForces, d.spTau);
  p += d.spTau.dot(v);
  if (prescribedDofs(s, d,
                     sp)) {  // (prescribed dofs) => the power of the effort that enforces them
    d.kernel.acceleration(t, q, v, d.accelScratch);
    p += d.kernel.prescribedEffort().dot(v);
  }
  d.setPoints = saved;
  for (int b = 1; b < m.nbodies; ++b) p += d.spForces.inBodyFrame(kin, b).dot(kin.V_B[b]);
  return p;
}

}  // namespace yardsim::mechanics
