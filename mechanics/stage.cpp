#include "mechanics/stage.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/rnea.hpp"
#include "mechanics/follow_draft.hpp"
#include "mechanics/jacobian_pattern.hpp"
#include "mechanics/line_jacobian.hpp"

namespace yardsim::mechanics {

bool prescribedDofs(const System& s, Data& d, const SetPoints& sp) {
  const auto& m = s.model();
  bool any = false;
  for (int i = 1; i < m.nbodies; ++i) {
    const bool on = sp.drives[i].active && sp.drives[i].prescribed;
    if (m.jointNv[i] == 1) d.prescribedMask[static_cast<std::size_t>(m.idxV[i])] = on ? 1 : 0;
    any = any || on;
  }
  return any;
}

void setPointForces(const System& s, Data& d, const SetPoints& sp, double t,
                    const Eigen::VectorXd& q, const Eigen::VectorXd& v, dynamics::ExternalForces& f,
                    Eigen::VectorXd& tau) {
  const auto& m = s.model();
  const ServoSettings& servo = s.servo();
  const double wc = servo.bandwidth;
  // (q, v) => bias forces h(q, v), the drives' feedforward (gravity and velocity terms)
  const bool driving =
      std::any_of(sp.drives.begin(), sp.drives.end(), [](auto& j) { return j.active; });
  if (driving) dynamics::biasForces(m, d.feedforward, q, v);
  for (int i = 1; i < m.nbodies; ++i) {
    // (ramp reference, servo, feedforward) => bounded joint force of a driven 1-dof joint
    const JointDrive& j = sp.drives[i];
    if (j.active && !j.prescribed) {
      const int iq = m.idxQ[i], iv = m.idxV[i];
      const double dir = j.target >= j.start ? 1.0 : -1.0;
      const double travel = std::abs(j.target - j.start);
      const double moved = std::min(travel, j.speed * std::max(0.0, t - j.t0));
      const double qRef = j.start + dir * moved;
      const double vRef = moved < travel ? dir * j.speed : 0.0;
      const double I = s.servoInertia()[static_cast<std::size_t>(i)];
      double u = I * (wc * wc * (qRef - q[iq]) + 2.0 * wc * (vRef - v[iv])) + d.feedforward.nle[iv];
      if (servo.maxEffort > 0) u = std::clamp(u, -servo.maxEffort, servo.maxEffort);
      tau[iv] += u;
    }
    const ActorLoad& l = sp.loads[i];
    if (!l.force.isZero() || !l.moment.isZero()) {
      dynamics::Force F_W;
      F_W << l.moment, l.force;
      f.addWorldFrame(i, F_W);
    }
  }
}

void stageForces(const System& s, Data& d, double t, const Eigen::VectorXd& q,
                 const Eigen::VectorXd& v, const dynamics::Data& kin, dynamics::ExternalForces& f,
                 Eigen::VectorXd& tau) {
  const SetPoints& sp = *d.setPoints;
  // (kinematics of the stage) => the draft-following added mass of the kernel's ABA, the servos'
  // bias forces and the reactions' RNEA (nothing without such a body)
  if (!s.draftAddedMass().empty()) {
    followDraft(s, kin, d.kernel.data());
    followDraft(s, kin, d.feedforward);
    followDraft(s, kin, d.reaction);
  }
  if (prescribedDofs(s, d, sp) || d.kernel.hybrid().any())
    d.kernel.prescribe(d.prescribedMask, d.prescribedAcc);
  forEachProvider(s, d, d.stage(s, t, kin, q, v),
                  [&](const forces::ForceProvider& p, const forces::Stage& st) { p.evaluate(st, f, tau); });
  setPointForces(s, d, sp, t, q, v, f, tau);
}

void connectStage(const System& s, Data& d) {
  d.kernel.setJacobianPattern(jacobianPattern(s));
  LineJacobian lines = lineJacobian(s, d);
  d.kernel.setJacobianBlocks(std::move(lines.blocks), std::move(lines.evaluate));
  d.kernel.setForces([&s, &d](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                              const dynamics::Data& kin, dynamics::ExternalForces& f,
                              Eigen::VectorXd& tau) { stageForces(s, d, t, q, v, kin, f, tau); });
  // (a provider whose law switches, e.g. a contact) => the kernel reports the providers' regimes
  const auto& providers = s.providers();
  if (std::none_of(providers.begin(), providers.end(), [](const auto& p) { return p->switches(); }))
    return;
  d.kernel.setRegime([&s, &d](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                              const dynamics::Data& kin) {
    // (stage) => the switching providers' signatures, combined in the list's order
    std::uint64_t r = 0;
    forEachProvider(s, d, d.stage(s, t, kin, q, v),
                    [&](const forces::ForceProvider& p, const forces::Stage& st) {
                      if (p.switches()) r = r * 0x100000001B3ULL + p.regime(st);
                    });
    return r;
  });
}

}  // namespace yardsim::mechanics
