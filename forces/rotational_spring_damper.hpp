#pragma once
// A spring-damper on one coordinate of a joint (a revolute angle in rad, a prismatic slide in m):
// with q that coordinate, v its rate and x = q - q0, the generalized force added to tau at the
// coordinate's velocity index is
//   tau -= preload + curve(x) + c v
// (N m for an angle, N for a slide). Potential energy preload x + V_curve(x), J; power -c v^2.
// Only for joints whose configuration and velocity coordinates coincide (revolute, prismatic,
// cylindrical, universal, planar), not for spherical or free joints (std::invalid_argument).
#include <string>

#include "forces/force_provider.hpp"
#include "forces/spring_curve.hpp"

namespace yardsim::forces {

struct JointSpringProperties {
  double neutral = 0.0;                          // q0, rad or m
  SpringCurve curve = SpringCurve::linear(0.0);  // of x = q - q0, N m (N)
  double preload = 0.0;                          // generalized force at q0, N m (N)
  double damping = 0.0;                          // c, N m s/rad (N s/m), >= 0
};

class RotationalSpringDamper final : public ForceProvider {
 public:
  // (name, model, body whose joint it acts on (>= 1), coordinate of that joint (0 for a 1-dof
  // joint), properties) => the element; throws std::invalid_argument naming it for a body
  // outside the model, a coordinate outside the joint, a spherical or free joint, or a
  // negative or non-finite damping, a non-finite neutral or preload
  RotationalSpringDamper(std::string name, const dynamics::Model& model, int body, int coordinate,
                         const JointSpringProperties& properties);

  // (stage) => the generalized force the element applies, N m (N): -(preload + curve(x) + c v)
  double generalizedForce(const Stage& s) const;
  // the velocity index it acts on (and the configuration index it reads)
  int velocityIndex() const { return iv_; }
  int configurationIndex() const { return iq_; }
  const JointSpringProperties& properties() const { return p_; }

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPotentialEnergy(const Stage& s) const override;
  double doPower(const Stage& s) const override;

 private:
  JointSpringProperties p_;
  int iq_ = 0;
  int iv_ = 0;
};

}  // namespace yardsim::forces
