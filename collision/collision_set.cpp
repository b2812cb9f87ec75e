#include "collision/collision_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace yardsim::collision {

namespace {

// (point) => "(x, y, z)", mm resolution
std::string point(const Vector3& p) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// (contact points and the law's responses, body) => where the normal forces on the body act:
// their point of application, the force-weighted mean of its points (world, m); NaN without any
Vector3 applicationPoint(const forces::ContactForce::Scratch& got, int body) {
  Vector3 sum = Vector3::Zero();
  double weight = 0.0;
  for (std::size_t k = 0; k < got.points.size(); ++k) {
    const auto& p = got.points[k];
    if (p.bodyA != body && p.bodyB != body) continue;
    const double w = std::max(0.0, got.responses[k].normalForce);
    sum += w * p.p_W;
    weight += w;
  }
  if (!(weight > 0.0)) return Vector3::Constant(std::numeric_limits<double>::quiet_NaN());
  return sum / weight;
}

}  // namespace

CollisionSet::CollisionSet(std::string name, std::shared_ptr<BodyCollision> world,
                           std::vector<forces::ContactMaterial> materials,
                           const std::vector<std::pair<std::string, int>>& reactionBodies,
                           Options options)
    : ForceProvider(name), world_(std::move(world)), options_(options) {
  // (stage) => the world at the stage's poses, its contact points
  auto source = [w = world_](const forces::Stage& s, std::vector<forces::ContactPoint>& out) {
    w->update(s.data);
    w->contacts(out);
  };
  contact_ = std::make_unique<forces::ContactForce>(name, source, std::move(materials));
  unowned_ = contact_->makeScratch();
  if (options_.contact) addContactOutputs(reactionBodies);
  const auto& watches = world_->spec().watches;
  for (std::size_t w = 0; w < watches.size(); ++w) {
    const double below = watches[w].below;
    auto distance = [this, w](const forces::Stage& s) {
      world_->update(s.data);
      return world_->clearance(w).distance;
    };
    auto detail = [this, w](const forces::Stage& s) {
      world_->update(s.data);
      const WatchReading r = world_->clearance(w);
      if (r.a.empty()) return std::string("nothing within range");
      return r.a + " at " + point(r.pa_W) + ", " + r.b + " at " + point(r.pb_W);
    };
    const std::string element =
        options_.watchesAtTop ? watches[w].name : this->name() + "." + watches[w].name;
    outputs_.push_back({watches[w].name + ".distance", "m", distance, options_.watchesAtTop});
    events_.push_back({element, "clearance_below", "",
                       [distance, below](const forces::Stage& s) { return below - distance(s); },
                       distance, detail});
    events_.push_back({element, "touched", "",
                       [distance](const forces::Stage& s) { return -distance(s); }, distance,
                       detail});
  }
}

void CollisionSet::addContactOutputs(
    const std::vector<std::pair<std::string, int>>& reactionBodies) {
  outputs_.push_back({"points", "-", [this](const forces::Stage& s) {
                        return static_cast<double>(collected(s).points.size());
                      }});
  outputs_.push_back({"normal_force", "N", [this](const forces::Stage& s) {
                        double sum = 0.0;
                        for (const auto& r : collected(s).responses) sum += r.normalForce;
                        return sum;
                      }});
  for (const auto& [bodyName, body] : reactionBodies) {
    // (stage) => the world z component of the contact forces on the body, N
    outputs_.push_back({bodyName + ".fz", "N", [this, b = body](const forces::Stage& s) {
                          const auto& got = collected(s);
                          double fz = 0.0;
                          for (std::size_t k = 0; k < got.points.size(); ++k) {
                            const auto& p = got.points[k];
                            const auto& r = got.responses[k];
                            const double z = r.normalForce * p.n_W.z() + r.tangentialForce.z();
                            if (p.bodyB == b) fz += z;
                            if (p.bodyA == b) fz -= z;
                          }
                          return fz;
                        }});
    // (stage) => where the body's contact forces act, x, y, z (NaN without contact)
    for (int axis = 0; axis < 3; ++axis)
      outputs_.push_back(
          {bodyName + ".p" + "xyz"[axis], "m", [this, b = body, axis](const forces::Stage& s) {
             return applicationPoint(collected(s), b)[axis];
           }});
  }
  events_.push_back({this->name(), "contact", "release",
                     [this](const forces::Stage& s) { return penetration(s); },
                     [this](const forces::Stage& s) { return penetration(s); }, nullptr});
}

const forces::ContactForce::Scratch& CollisionSet::collected(const forces::Stage& s) const {
  forces::ProviderScratch* scratch = s.scratch != nullptr ? s.scratch : unowned_.get();
  const forces::Stage with{s.t, s.model, s.data, s.q, s.v, scratch, s.stepStart};
  contact_->potentialEnergy(with);  // collects the points and the law's responses
  return static_cast<const forces::ContactForce::Scratch&>(*scratch);
}

double CollisionSet::penetration(const forces::Stage& s) const {
  world_->update(s.data);
  const double ground = world_->groundPenetration();
  const auto& got = collected(s);
  double deepest = -std::numeric_limits<double>::infinity();
  for (const auto& p : got.points) deepest = std::max(deepest, p.depth);
  const double out = got.points.empty() ? (std::isfinite(ground) ? std::min(ground, -1e-9) : -1.0)
                                        : std::max(deepest, ground);
  return out;
}

forces::StiffnessHint CollisionSet::stiffnessHint(const dynamics::Model& model) const {
  forces::StiffnessHint out;
  if (!options_.contact) return out;
  const double g = model.gravity.norm();
  for (const BodyShape& s : world_->spec().shapes) {
    // (a body fixed to the world through fixed joints only) => it cannot move: no mode
    int up = s.body;
    while (up > 0 && model.jointNv[static_cast<std::size_t>(up)] == 0)
      up = model.parent[static_cast<std::size_t>(up)];
    if (up <= 0) continue;
    const double m = model.inertias[static_cast<std::size_t>(s.body)].mass;
    const bool flat = s.shape.kind == ShapeKind::kBox || s.shape.kind == ShapeKind::kMesh ||
                      s.shape.kind == ShapeKind::kCylinder;
    const double points = flat ? 4.0 : 1.0;
    for (const forces::ContactMaterial& c : contact_->materials()) {
      const auto& law = c.law;
      const double n = law.kind == forces::NormalLawKind::kLinear ? 1.0 : law.exponent;
      const double depth = std::pow(m * g / (points * law.stiffness), 1.0 / n);
      const double k = points * n * law.stiffness * std::pow(depth, n - 1.0);
      const auto consider = [&](double omega, const char* what) {
        if (omega <= out.omega) return;
        out = {omega, model.names[static_cast<std::size_t>(s.body)], what};
      };
      consider(std::sqrt(k / m), "contact normal");
      consider(c.friction.mu * g / c.friction.slipSpeed, "contact friction");
    }
  }
  return out;
}

}  // namespace yardsim::collision
