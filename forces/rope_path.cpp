#include "forces/rope_path.hpp"

#include <stdexcept>

#include "dynamics/kinematics.hpp"

namespace yardsim::forces {

using dynamics::Vector3;

RopePath::RopePath(const dynamics::Model& model, std::vector<Attachment> points,
                   const std::string& owner)
    : points_(std::move(points)) {
  // (points) => at least two, on bodies of the model, finite
  if (points_.size() < 2)
    throw std::invalid_argument("rope '" + owner +
                                "': a path needs at least two points (its two ends)");
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const Attachment& a = points_[i];
    if (a.body < 0 || a.body >= model.nbodies)
      throw std::invalid_argument("rope '" + owner + "': path point " + std::to_string(i) +
                                  " is on body " + std::to_string(a.body) +
                                  ", outside the model's " + std::to_string(model.nbodies) +
                                  " bodies");
    if (!a.p_B.allFinite())
      throw std::invalid_argument("rope '" + owner + "': path point " + std::to_string(i) +
                                  " is not finite");
  }
}

PathPoints RopePath::makePoints() const {
  return {std::vector<Vector3>(points_.size(), Vector3::Zero()),
          std::vector<Vector3>(points_.size() - 1, Vector3::Zero())};
}

template <class Visit>
PathMeasure RopePath::walk(const dynamics::Data& data, Visit&& visit) const {
  // (X_WB, V of the bodies) => sum over segments of |p1 - p0| and u . (v1 - v0)
  PathMeasure m;
  Vector3 p0 = dynamics::pointPosition(data, points_[0].body, points_[0].p_B);
  Vector3 v0 = dynamics::pointVelocity(data, points_[0].body, points_[0].p_B);
  visit(0, p0, nullptr);
  for (std::size_t i = 1; i < points_.size(); ++i) {
    const Vector3 p1 = dynamics::pointPosition(data, points_[i].body, points_[i].p_B);
    const Vector3 v1 = dynamics::pointVelocity(data, points_[i].body, points_[i].p_B);
    const Vector3 d = p1 - p0;
    const double len = d.norm();
    const Vector3 u = len > 0.0 ? Vector3(d / len) : Vector3::Zero();
    m.length += len;
    m.rate += u.dot(v1 - v0);
    visit(i, p1, &u);
    p0 = p1;
    v0 = v1;
  }
  return m;
}

PathMeasure RopePath::measure(const dynamics::Data& data) const {
  return walk(data, [](std::size_t, const Vector3&, const Vector3*) {});
}

PathMeasure RopePath::update(const dynamics::Data& data, PathPoints& out) const {
  return walk(data, [&out](std::size_t i, const Vector3& p, const Vector3* u) {
    out.p_W[i] = p;
    if (u) out.u_W[i - 1] = *u;
  });
}

void RopePath::applyTension(double tension, const PathPoints& at,
                            dynamics::ExternalForces& f) const {
  // (T, u) => point i is pulled toward i + 1 by T u_i and toward i - 1 by -T u_(i-1)
  const std::size_t n = points_.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (points_[i].body == 0) continue;
    Vector3 f_W = Vector3::Zero();
    if (i + 1 < n) f_W += tension * at.u_W[i];
    if (i > 0) f_W -= tension * at.u_W[i - 1];
    f.addPointForceWorld(points_[i].body, at.p_W[i], f_W);
  }
}

}  // namespace yardsim::forces
