#include "mechanics/stage.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "dynamics/rnea.hpp"
#include "mechanics/follow_mass.hpp"
#include "mechanics/jacobian_pattern.hpp"
#include "mechanics/line_jacobian.hpp"
#include "mechanics/linearisation.hpp"

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
                    const Eigen::VectorXd& q, const Eigen::VectorXd& v, const dynamics::Data& kin,
                    dynamics::ExternalForces& f, Eigen::VectorXd& tau) {
  const auto& m = s.model();
  const ServoSettings& servo = s.servo();
  const double wc = servo.bandwidth;
  // (q, v, the placements in kin) => bias forces h(q, v) of the servo-driven joints, their
  // feedforward (gravity and velocity terms): RNEA over their subtrees and supports only
  // (drives) => the mask marked again only when the driven joints changed (between steps)
  bool changed = false;
  for (int i = 0; i < m.nbodies; ++i) {
    const JointDrive& j = sp.drives[static_cast<std::size_t>(i)];
    const char on = (i > 0 && j.active && !j.prescribed) ? 1 : 0;
    changed = changed || d.drivenJoints[static_cast<std::size_t>(i)] != on;
    d.drivenJoints[static_cast<std::size_t>(i)] = on;
  }
  if (changed) d.feedforwardMask.mark(m, d.drivenJoints);
  if (d.feedforwardMask.any)
    dynamics::biasForcesOfSubtrees(m, d.feedforward, kin, q, v, d.feedforwardMask);
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

namespace {
// (a stage whose forces f are not finite) => throws the ForceError of the first provider that
// makes them non-finite when evaluated again in order from zero (allocates: an error path), or
// one naming the body when only their sum is not finite
[[noreturn]] void diagnoseForces(const System& s, Data& d, const forces::Stage& stage,
                                 const dynamics::ExternalForces& f) {
  const auto& m = s.model();
  dynamics::ExternalForces again(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  forEachProvider(s, d, stage, [&](const forces::ForceProvider& p, const forces::Stage& st) {
    p.evaluate(st, again, tau);
  });
  std::string body = "a joint";
  for (int b = m.nbodies - 1; b >= 1; --b)
    if (!f.bodyFrame(b).allFinite() || (f.hasWorldFrame() && !f.worldFrame(b).allFinite()))
      body = "body '" + m.names[static_cast<std::size_t>(b)] + "'";
  throw forces::ForceError("the force providers' sum is not finite on " + body +
                           " at t = " + std::to_string(stage.t) + " s; take a smaller step");
}
}  // namespace

void stageForces(const System& s, Data& d, double t, const Eigen::VectorXd& q,
                 const Eigen::VectorXd& v, const dynamics::Data& kin, dynamics::ExternalForces& f,
                 Eigen::VectorXd& tau) {
  const SetPoints& sp = *d.setPoints;
  // (kinematics of the stage, t) => the masses that follow the draft or a winch, for the kernel's
  // ABA, the servos' bias forces and the reactions' RNEA (nothing without such a body)
  if (followsMass(s)) {
    followMass(s, t, kin, d.kernel.data());
    followMass(s, t, kin, d.feedforward);
    followMass(s, t, kin, d.reaction);
  }
  if (prescribedDofs(s, d, sp) || d.kernel.hybrid().any())
    d.kernel.prescribe(d.prescribedMask, d.prescribedAcc);
  // (stage) => every provider's forces, their sum checked once; not finite: evaluated again one
  // by one, each checked, from zero, so the error names the first provider that made it
  const forces::Stage stage = d.stage(s, t, kin, q, v);
  forEachProvider(s, d, stage, [&](const forces::ForceProvider& p, const forces::Stage& st) {
    p.evaluateUnchecked(st, f, tau);
  });
  if (!forces::forcesFinite(s.model(), f, tau)) diagnoseForces(s, d, stage, f);
  setPointForces(s, d, sp, t, q, v, kin, f, tau);
}

void connectStage(const System& s, Data& d) {
  d.kernel.setJacobianPattern(jacobianPattern(s));
  LineJacobian lines = lineJacobian(s, d);
  d.kernel.setJacobianBlocks(std::move(lines.blocks), std::move(lines.evaluate));
  connectLinearisation(s, d);
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
