#include "forces/rotational_spring_damper.hpp"

#include <cmath>
#include <stdexcept>

namespace yardsim::forces {

namespace {
// (model, body, coordinate, owner) => the joint's coordinate is a plain one, or
// std::invalid_argument
void checkCoordinate(const dynamics::Model& model, int body, int coordinate,
                     const std::string& owner) {
  auto bad = [&](const std::string& what) {
    throw std::invalid_argument("joint spring '" + owner + "': " + what);
  };
  if (body < 1 || body >= model.nbodies)
    bad("body " + std::to_string(body) + " is not a moving body of the model");
  const dynamics::JointType t = model.joints[body].type;
  if (t == dynamics::JointType::Spherical || t == dynamics::JointType::Free)
    bad("a spherical or free joint has no plain coordinate (use a bushing)");
  if (coordinate < 0 || coordinate >= model.jointNv[body])
    bad("coordinate " + std::to_string(coordinate) + " is outside the joint's " +
        std::to_string(model.jointNv[body]));
}
// (properties, owner) => properties, checked
const JointSpringProperties& checked(const JointSpringProperties& p, const std::string& owner) {
  if (!(std::isfinite(p.damping) && p.damping >= 0.0) || !std::isfinite(p.neutral) ||
      !std::isfinite(p.preload))
    throw std::invalid_argument("joint spring '" + owner +
                                "': neutral and preload must be finite, damping finite and >= 0");
  return p;
}
}  // namespace

RotationalSpringDamper::RotationalSpringDamper(std::string name, const dynamics::Model& model,
                                               int body, int coordinate,
                                               const JointSpringProperties& properties)
    : ForceProvider(std::move(name)), p_(checked(properties, this->name())) {
  checkCoordinate(model, body, coordinate, this->name());
  iq_ = model.idxQ[body] + coordinate;
  iv_ = model.idxV[body] + coordinate;
}

double RotationalSpringDamper::generalizedForce(const Stage& s) const {
  const double x = s.q[iq_] - p_.neutral;
  return -(p_.preload + p_.curve.force(x) + p_.damping * s.v[iv_]);
}

void RotationalSpringDamper::doEvaluate(const Stage& s, dynamics::ExternalForces& /*f*/,
                                        Eigen::VectorXd& tau) const {
  tau[iv_] += generalizedForce(s);
}

double RotationalSpringDamper::doPotentialEnergy(const Stage& s) const {
  const double x = s.q[iq_] - p_.neutral;
  return p_.preload * x + p_.curve.energy(x);
}

double RotationalSpringDamper::doPower(const Stage& s) const {
  return -p_.damping * s.v[iv_] * s.v[iv_];
}

}  // namespace yardsim::forces
