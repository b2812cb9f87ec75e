#pragma once
// A translational spring-damper between a point on body A and a point on body B (either may be
// the world, body 0) that pushes as well as pulls, along the line between the points. With L the
// distance between the points (m), L0 the free length, x = L - L0 and L' = dL/dt, the force
// that pulls the points together (> 0 tension, < 0 compression), N, is
//   f = preload + curve(x) + c L' + kStop (L - maxLength)   when L > maxLength
//                                 + kStop (L - minLength)   when L < minLength
// A pulls toward B by f u and B toward A by -f u (u the unit vector from A to B, world frame).
// Potential energy preload x + V_curve(x) + kStop/2 (overshoot)^2, J; power -c L'^2 <= 0, W.
// At L = 0 the direction is undefined and no force is applied. Conventions: docs/forces.md.
#include <limits>
#include <string>

#include "forces/force_provider.hpp"
#include "forces/rope_path.hpp"
#include "forces/spring_curve.hpp"

namespace yardsim::forces {

struct SpringDamperProperties {
  double freeLength = 0.0;                       // L0, m (>= 0)
  SpringCurve curve = SpringCurve::linear(0.0);  // force of x = L - L0, N
  double preload = 0.0;                          // tension at the free length, N (< 0: pushes)
  double damping = 0.0;                          // c, N s/m (>= 0)
  double minLength = 0.0;                        // a stop: stiff below this length, m (0: none)
  double maxLength = std::numeric_limits<double>::infinity();  // a stop above this length, m
  double stopStiffness = 0.0;                                  // kStop of both stops, N/m (>= 0)
};

// The state of a spring-damper at one stage: length L (m), rate L' (m/s), the force f (N, > 0
// pulls the ends together) and its elastic part (without damping).
struct SpringState {
  double length = 0.0;
  double rate = 0.0;
  double force = 0.0;
  double elasticForce = 0.0;
};

class SpringDamper final : public ForceProvider {
 public:
  // (name, model (checks only), end A, end B, properties) => the element; throws
  // std::invalid_argument naming it for bodies outside the model, a non-finite point, a
  // negative length, damping or stop stiffness, or minLength > maxLength
  SpringDamper(std::string name, const dynamics::Model& model, const Attachment& a,
               const Attachment& b, const SpringDamperProperties& properties);

  // (stage) => length, rate and force
  SpringState state(const Stage& s) const;
  // (stage) => df/dL, the axial stiffness at the current length (curve slope plus an engaged
  // stop), N/m; the damping c is properties().damping
  double axialStiffness(const Stage& s) const;
  const SpringDamperProperties& properties() const { return p_; }
  const Attachment& endA() const { return a_; }
  const Attachment& endB() const { return b_; }

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPotentialEnergy(const Stage& s) const override;
  double doPower(const Stage& s) const override;

 private:
  // (stage) => the world points, the unit vector from A to B and the state
  struct Geometry {
    dynamics::Vector3 pA, pB, u;
    SpringState st;
  };
  Geometry geometry(const Stage& s) const;

  Attachment a_, b_;
  SpringDamperProperties p_;
};

}  // namespace yardsim::forces
