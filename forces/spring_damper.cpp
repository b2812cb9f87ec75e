#include "forces/spring_damper.hpp"

#include <cmath>
#include <stdexcept>

#include "dynamics/kinematics.hpp"

namespace yardsim::forces {

using dynamics::Vector3;

namespace {
// (model, end, its name, owner) => the end, checked
const Attachment& checkedEnd(const dynamics::Model& model, const Attachment& e, const char* which,
                             const std::string& owner) {
  if (e.body < 0 || e.body >= model.nbodies)
    throw std::invalid_argument("spring '" + owner + "': end " + which + " is on body " +
                                std::to_string(e.body) + ", outside the model's " +
                                std::to_string(model.nbodies) + " bodies");
  if (!e.p_B.allFinite())
    throw std::invalid_argument("spring '" + owner + "': end " + which + " is not finite");
  return e;
}
// (properties, owner) => properties, checked
const SpringDamperProperties& checked(const SpringDamperProperties& p, const std::string& owner) {
  auto bad = [&](const std::string& what) {
    throw std::invalid_argument("spring '" + owner + "': " + what);
  };
  if (!(std::isfinite(p.freeLength) && p.freeLength >= 0.0))
    bad("the free length must be finite and >= 0");
  if (!std::isfinite(p.preload)) bad("the preload must be finite");
  if (!(std::isfinite(p.damping) && p.damping >= 0.0)) bad("the damping must be finite and >= 0");
  if (!(std::isfinite(p.stopStiffness) && p.stopStiffness >= 0.0))
    bad("the stop stiffness must be finite and >= 0");
  if (!(p.minLength >= 0.0 && p.minLength <= p.maxLength) || std::isnan(p.maxLength))
    bad("the stops need 0 <= minLength <= maxLength");
  return p;
}
}  // namespace

SpringDamper::SpringDamper(std::string name, const dynamics::Model& model, const Attachment& a,
                           const Attachment& b, const SpringDamperProperties& properties)
    : ForceProvider(std::move(name)),
      a_(checkedEnd(model, a, "A", this->name())),
      b_(checkedEnd(model, b, "B", this->name())),
      p_(checked(properties, this->name())) {}

SpringDamper::Geometry SpringDamper::geometry(const Stage& s) const {
  // (X_WB, V) => points, u, L, L' and the force law
  Geometry g;
  g.pA = dynamics::pointPosition(s.data, a_.body, a_.p_B);
  g.pB = dynamics::pointPosition(s.data, b_.body, b_.p_B);
  const Vector3 d = g.pB - g.pA;
  const double len = d.norm();
  g.u = len > 0.0 ? Vector3(d / len) : Vector3::Zero();
  const Vector3 vA = dynamics::pointVelocity(s.data, a_.body, a_.p_B);
  const Vector3 vB = dynamics::pointVelocity(s.data, b_.body, b_.p_B);
  g.st.length = len;
  g.st.rate = g.u.dot(vB - vA);
  double fe = p_.preload + p_.curve.force(len - p_.freeLength);
  if (len > p_.maxLength) fe += p_.stopStiffness * (len - p_.maxLength);
  if (len < p_.minLength) fe += p_.stopStiffness * (len - p_.minLength);
  g.st.elasticForce = fe;
  g.st.force = fe + p_.damping * g.st.rate;
  return g;
}

SpringState SpringDamper::state(const Stage& s) const {
  return geometry(s).st;
}

double SpringDamper::axialStiffness(const Stage& s) const {
  const double len = geometry(s).st.length;
  double k = p_.curve.stiffness(len - p_.freeLength);
  if (len > p_.maxLength || len < p_.minLength) k += p_.stopStiffness;
  return k;
}

void SpringDamper::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                              Eigen::VectorXd& /*tau*/) const {
  // (f, u) => f u on A at its point, -f u on B at its point (the world takes nothing)
  const Geometry g = geometry(s);
  const Vector3 f_W = g.st.force * g.u;
  if (a_.body != 0) f.addPointForceWorld(a_.body, g.pA, f_W);
  if (b_.body != 0) f.addPointForceWorld(b_.body, g.pB, -f_W);
}

double SpringDamper::doPotentialEnergy(const Stage& s) const {
  // (L) => preload x + V_curve(x) + the stops' kStop/2 overshoot^2
  const double len = geometry(s).st.length;
  const double x = len - p_.freeLength;
  double v = p_.preload * x + p_.curve.energy(x);
  if (len > p_.maxLength) v += 0.5 * p_.stopStiffness * (len - p_.maxLength) * (len - p_.maxLength);
  if (len < p_.minLength) v += 0.5 * p_.stopStiffness * (len - p_.minLength) * (len - p_.minLength);
  return v;
}

double SpringDamper::doPower(const Stage& s) const {
  const double rate = geometry(s).st.rate;
  return -p_.damping * rate * rate;
}

}  // namespace yardsim::forces
