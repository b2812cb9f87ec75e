#include "forces/contact.hpp"

#include <stdexcept>

#include "dynamics/kinematics.hpp"

namespace yardsim::forces {

namespace {
// m: a point touching less deep than this is not yet pressing for the regime. A contact onset is
// located as a state event to 1e-9 s (dtss/atomic.hpp), so 1e-9 m deep or less at up to 1 m/s
// and 1e-8 m at 10 m/s: the step from there is the one that closes the contact
constexpr double kPressingDepth = 1e-8;
}  // namespace

ContactForce::ContactForce(std::string name, ContactSource source, NormalLaw law,
                           FrictionLaw friction, std::size_t reserve)
    : ContactForce(std::move(name), std::move(source), {ContactMaterial{law, friction}}, reserve) {}

ContactForce::ContactForce(std::string name, ContactSource source,
                           std::vector<ContactMaterial> materials, std::size_t reserve)
    : ForceProvider(std::move(name)),
      source_(std::move(source)),
      materials_(std::move(materials)),
      reserve_(reserve) {
  if (!source_) throw std::invalid_argument("contact '" + this->name() + "': no contact source");
  if (materials_.empty()) throw std::invalid_argument("contact '" + this->name() + "': no material");
  for (const ContactMaterial& m : materials_) {
    if (!(m.law.stiffness >= 0.0) || !(m.law.damping >= 0.0) || !(m.law.exponent > 0.0)) {
      throw std::invalid_argument("contact '" + this->name() +
                                  "': stiffness and damping must be >= 0, the exponent > 0");
    }
    if (!(m.friction.mu >= 0.0) || !(m.friction.slipSpeed > 0.0)) {
      throw std::invalid_argument("contact '" + this->name() +
                                  "': friction needs mu >= 0 and a slip speed > 0");
    }
  }
}

std::unique_ptr<ProviderScratch> ContactForce::makeScratch() const {
  auto s = std::make_unique<Scratch>();
  s->points.reserve(reserve_);
  s->responses.reserve(reserve_);
  return s;
}

// (stage) => the source's points and the law's response at each
void ContactForce::collect(const Stage& s, Scratch& out) const {
  out.points.clear();
  out.responses.clear();
  source_(s, out.points);
  for (const ContactPoint& c : out.points) {
    const auto velocity = [&](int body) {
      if (body == 0) return dynamics::Vector3::Zero().eval();
      return dynamics::pointVelocity(s.data, body, s.data.X_WB[body].invActPoint(c.p_W));
    };
    const dynamics::Vector3 v = velocity(c.bodyB) - velocity(c.bodyA);
    const double vn = v.dot(c.n_W);
    const ContactMaterial& m = materials_[static_cast<std::size_t>(c.material)];
    out.responses.push_back(contactResponse(m.law, m.friction, c.depth, -vn, v - vn * c.n_W));
  }
}

// (stage) => F = F_n n + F_t on B at p_W, -F on A
void ContactForce::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                              Eigen::VectorXd&) const {
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& at = scratchOf<Scratch>(s, temporary);
  collect(s, at);
  for (std::size_t i = 0; i < at.points.size(); ++i) {
    const ContactPoint& c = at.points[i];
    const dynamics::Vector3 F =
        at.responses[i].normalForce * c.n_W + at.responses[i].tangentialForce;
    if (c.bodyB != 0) f.addPointForceWorld(c.bodyB, c.p_W, F);
    if (c.bodyA != 0) f.addPointForceWorld(c.bodyA, c.p_W, -F);
  }
}

// (stage) => sum of k delta^(n+1) / (n+1)
double ContactForce::doPotentialEnergy(const Stage& s) const {
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& at = scratchOf<Scratch>(s, temporary);
  collect(s, at);
  double e = 0.0;
  for (const ContactResponse& r : at.responses) e += r.potentialEnergy;
  return e;
}

// (stage) => sum of the law's non-conservative power
double ContactForce::doPower(const Stage& s) const {
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& at = scratchOf<Scratch>(s, temporary);
  collect(s, at);
  double p = 0.0;
  for (const ContactResponse& r : at.responses) p += r.power;
  return p;
}

// (stage) => (count of points pressing: F_n > 0, deeper than kPressingDepth) + 2^20 x (sum of a
// hash of their body pairs and materials): independent of the order the source lists its points in
std::uint64_t ContactForce::doRegime(const Stage& s) const {
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& at = scratchOf<Scratch>(s, temporary);
  collect(s, at);
  std::uint64_t count = 0, pairs = 0;
  for (std::size_t i = 0; i < at.points.size(); ++i) {
    const ContactPoint& c = at.points[i];
    if (!(at.responses[i].normalForce > 0.0) || !(c.depth > kPressingDepth)) continue;
    ++count;
    pairs += (static_cast<std::uint64_t>(c.bodyA) * 0x9E3779B97F4A7C15ULL) ^
             (static_cast<std::uint64_t>(c.bodyB) * 0xC2B2AE3D27D4EB4FULL) ^
             static_cast<std::uint64_t>(c.material);
  }
  return count + (pairs << 20);
}

}  // namespace yardsim::forces
