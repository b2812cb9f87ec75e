#include "forces/contact.hpp"

#include <stdexcept>

#include "dynamics/kinematics.hpp"

namespace yardsim::forces {

ContactForce::ContactForce(std::string name, ContactSource source, NormalLaw law,
                           FrictionLaw friction, std::size_t reserve)
    : ForceProvider(std::move(name)), source_(std::move(source)), law_(law), friction_(friction) {
  if (!source_) throw std::invalid_argument("contact '" + this->name() + "': no contact source");
  if (!(law_.stiffness >= 0.0) || !(law_.damping >= 0.0) || !(law_.exponent > 0.0)) {
    throw std::invalid_argument("contact '" + this->name() +
                                "': stiffness and damping must be >= 0, the exponent > 0");
  }
  if (!(friction_.mu >= 0.0) || !(friction_.slipSpeed > 0.0)) {
    throw std::invalid_argument("contact '" + this->name() +
                                "': friction needs mu >= 0 and a slip speed > 0");
  }
  points_.reserve(reserve);
  responses_.reserve(reserve);
}

// (stage) => the source's points and the law's response at each
void ContactForce::collect(const Stage& s) const {
  points_.clear();
  responses_.clear();
  source_(s, points_);
  for (const ContactPoint& c : points_) {
    const auto velocity = [&](int body) {
      if (body == 0) return dynamics::Vector3::Zero().eval();
      return dynamics::pointVelocity(s.data, body, s.data.X_WB[body].invActPoint(c.p_W));
    };
    const dynamics::Vector3 v = velocity(c.bodyB) - velocity(c.bodyA);
    const double vn = v.dot(c.n_W);
    responses_.push_back(contactResponse(law_, friction_, c.depth, -vn, v - vn * c.n_W));
  }
}

// (stage) => F = F_n n + F_t on B at p_W, -F on A
void ContactForce::doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd&) {
  collect(s);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const ContactPoint& c = points_[i];
    const dynamics::Vector3 F = responses_[i].normalForce * c.n_W + responses_[i].tangentialForce;
    if (c.bodyB != 0) f.addPointForceWorld(c.bodyB, c.p_W, F);
    if (c.bodyA != 0) f.addPointForceWorld(c.bodyA, c.p_W, -F);
  }
}

// (stage) => sum of k delta^(n+1) / (n+1)
double ContactForce::doPotentialEnergy(const Stage& s) const {
  collect(s);
  double e = 0.0;
  for (const ContactResponse& r : responses_) e += r.potentialEnergy;
  return e;
}

// (stage) => sum of the law's non-conservative power
double ContactForce::doPower(const Stage& s) const {
  collect(s);
  double p = 0.0;
  for (const ContactResponse& r : responses_) p += r.power;
  return p;
}

}  // namespace yardsim::forces
