#include "collision/body_collision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace yardsim::collision {

namespace {

// (shape, kinematics) => its world pose X_WS = X_WB X_BS (the world's shapes: X_BS)
Transform poseOf(const BodyShape& s, const dynamics::Data& kin) {
  return s.body == 0 ? s.X_BS : kin.X_WB[static_cast<std::size_t>(s.body)] * s.X_BS;
}

}  // namespace

BodyCollision::BodyCollision(BodyCollisionSpec spec, const dynamics::Data& kin)
    : spec_(std::move(spec)) {
  const int nb = spec_.bodyCount;
  auto ropeOwner = [nb](std::size_t r) { return nb + static_cast<int>(r); };
  // (rope r, world) => the rope never tested against the bodies it is attached to
  auto ignoreAttached = [&](std::size_t r, CollisionWorld& w) {
    for (const auto& [body, p] : spec_.ropes[r].path) w.filter().ignoreOwners(ropeOwner(r), body);
  };
  // (shapes) => the contact world
  for (const BodyShape& s : spec_.shapes) {
    contactIds_.push_back(
        spec_.contact ? contact_.add(s.shape, poseOf(s, kin), {s.name, {s.body, s.group, s.mask}})
                      : -1);
    // (shape) => the points of it that can touch the ground, in its frame
    std::vector<Vector3> points;
    const Vector3 h = s.shape.size / 2;
    switch (s.shape.kind) {
      case ShapeKind::kBox:
        for (int k = 0; k < 8; ++k)
          points.emplace_back(k & 1 ? h.x() : -h.x(), k & 2 ? h.y() : -h.y(),
                              k & 4 ? h.z() : -h.z());
        break;
      case ShapeKind::kMesh:
        points = s.shape.mesh->vertices;
        break;
      case ShapeKind::kCylinder:
        for (int k = 0; k < 32; ++k) {
          const double a = 2 * M_PI * (k % 16) / 16.0;
          points.emplace_back(s.shape.radius * std::cos(a), s.shape.radius * std::sin(a),
                              (k < 16 ? -0.5 : 0.5) * s.shape.length);
        }
        break;
      default:
        break;
    }
    // (ignore list) => no ground contact for a body ignored with the world (a body fixed to it)
    bool ignored = s.body == 0;
    for (const auto& [a, b] : spec_.ignore)
      ignored = ignored || (a == s.body && b == 0) || (a == 0 && b == s.body);
    if (ignored) points.clear();
    groundPoints_.push_back(std::move(points));
    touchesGround_.push_back(!ignored);
  }
  for (const auto& [a, b] : spec_.ignore) {
    contact_.filter().ignoreOwners(a, b);
    clearance_.filter().ignoreOwners(a, b);
  }
  // (watches) => the shapes and ropes they name, once each, in the clearance world
  clearanceShapeIds_.assign(spec_.shapes.size(), -1);
  clearanceRopeIds_.resize(spec_.ropes.size());
  for (const ClearanceSpec& w : spec_.watches) {
    for (const auto* list : {&w.shapesA, &w.shapesB})
      for (const int i : *list) {
        auto& id = clearanceShapeIds_[static_cast<std::size_t>(i)];
        if (id >= 0) continue;
        const BodyShape& s = spec_.shapes[static_cast<std::size_t>(i)];
        id = clearance_.add(s.shape, poseOf(s, kin), {s.name, {s.body, s.group, s.mask}});
        clearanceOwnerName_.push_back(i);
      }
    for (const auto* list : {&w.ropesA, &w.ropesB})
      for (const int r : *list) {
        const auto k = static_cast<std::size_t>(r);
        if (!clearanceRopeIds_[k].empty()) continue;
        const RopeShape& rope = spec_.ropes[k];
        clearanceRopeIds_[k] =
            clearance_.addRope(ropePath(rope, kin.X_WB), rope.diameter,
                               {rope.name, {ropeOwner(k), rope.group, rope.mask}});
        clearanceOwnerName_.resize(static_cast<std::size_t>(clearance_.size()), -1 - r);
        ignoreAttached(k, clearance_);
      }
  }
  // (watch sets) => the world's watches, margin the threshold
  for (const ClearanceSpec& w : spec_.watches) {
    std::vector<ObjectId> a, b;
    auto collect = [&](const std::vector<int>& shapes, const std::vector<int>& ropes,
                       std::vector<ObjectId>& out) {
      for (const int i : shapes) out.push_back(clearanceShapeIds_[static_cast<std::size_t>(i)]);
      for (const int r : ropes) {
        const auto& ids = clearanceRopeIds_[static_cast<std::size_t>(r)];
        out.insert(out.end(), ids.begin(), ids.end());
      }
    };
    collect(w.shapesA, w.ropesA, a);
    collect(w.shapesB, w.ropesB, b);
    watchIds_.push_back(
        clearance_.addWatch(std::move(a), std::move(b), std::max(w.below, w.margin)));
  }
}

const std::vector<Vector3>& BodyCollision::ropePath(const RopeShape& r,
                                                    const std::vector<Transform>& X_WB) {
  scratch_.clear();
  for (const auto& [body, p_B] : r.path)
    scratch_.push_back(body == 0 ? p_B : X_WB[static_cast<std::size_t>(body)].actPoint(p_B));
  return scratch_;
}

namespace {

// (pose lists) => equal, exactly (the world's entry 0 is not compared)
bool samePoses(const std::vector<Transform>& a, const std::vector<Transform>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 1; i < a.size(); ++i)
    if (a[i].p != b[i].p || a[i].R != b[i].R) return false;
  return true;
}

}  // namespace

void BodyCollision::update(const dynamics::Data& kin) {
  // (poses) => nothing to do when no body moved since the last update
  if (posed_ && samePoses(kin.X_WB, X_WB_)) return;
  X_WB_.assign(kin.X_WB.begin(), kin.X_WB.end());
  posed_ = true;
  clearancePosed_ = false;
  slot_ = -1;
  for (int k = 0; k < 2; ++k)
    if (samePoses(slots_[k].X_WB, X_WB_)) slot_ = k;
  for (std::size_t i = 0; i < spec_.shapes.size(); ++i) {
    const BodyShape& s = spec_.shapes[i];
    if (s.body == 0 || contactIds_[i] < 0) continue;  // the world's shapes never move
    contact_.setPose(contactIds_[i], poseOf(s, kin));
  }
}

BodyCollision::ReadSlot& BodyCollision::readSlot() {
  if (slot_ < 0) {
    slot_ = 1 - lastRead_;
    ReadSlot& s = slots_[slot_];
    s.X_WB = X_WB_;
    s.valid.assign(spec_.watches.size(), 0);
    s.readings.resize(spec_.watches.size());
  }
  lastRead_ = slot_;
  return slots_[slot_];
}

void BodyCollision::groundContacts(const BodyShape& s, const Transform& X_WS,
                                   std::vector<forces::ContactPoint>& out) const {
  const int law = spec_.pairLaw[static_cast<std::size_t>(
      spec_.groundMaterial * spec_.materialCount + s.material)];
  const double top = spec_.groundHeight;
  // (lowest point of a sphere of radius r at c) => a contact when below the ground
  auto sphere = [&](const Vector3& c, double r) {
    const double depth = top - (c.z() - r);
    if (depth > 0)
      out.push_back({0, s.body, c - r * Vector3::UnitZ(), Vector3::UnitZ(), depth, law});
  };
  if (s.shape.kind == ShapeKind::kSphere) return sphere(X_WS.p, s.shape.radius);
  if (s.shape.kind == ShapeKind::kCapsule) {
    const Vector3 half = X_WS.R.col(2) * (s.shape.length / 2);
    sphere(X_WS.p + half, s.shape.radius);
    sphere(X_WS.p - half, s.shape.radius);
    return;
  }
  for (const Vector3& p_S : groundPoints_[static_cast<std::size_t>(&s - spec_.shapes.data())]) {
    const Vector3 p_W = X_WS.actPoint(p_S);
    const double depth = top - p_W.z();
    if (depth > 0) out.push_back({0, s.body, p_W, Vector3::UnitZ(), depth, law});
  }
}

double BodyCollision::groundPenetration() const {
  double deepest = -std::numeric_limits<double>::infinity();
  if (!spec_.ground || !spec_.contact) return deepest;
  const double top = spec_.groundHeight;
  for (std::size_t i = 0; i < spec_.shapes.size(); ++i) {
    if (!touchesGround_[i]) continue;
    const BodyShape& s = spec_.shapes[i];
    const Transform& X_WS = contact_.pose(contactIds_[i]);
    if (s.shape.kind == ShapeKind::kSphere || s.shape.kind == ShapeKind::kCapsule) {
      const double reach =
          s.shape.kind == ShapeKind::kCapsule ? std::abs(X_WS.R(2, 2)) * s.shape.length / 2 : 0.0;
      deepest = std::max(deepest, top - (X_WS.p.z() - reach - s.shape.radius));
    }
    for (const Vector3& p_S : groundPoints_[i])
      deepest = std::max(deepest, top - X_WS.actPoint(p_S).z());
  }
  return deepest;
}

void BodyCollision::contacts(std::vector<forces::ContactPoint>& out) {
  if (spec_.shapes.empty() || !spec_.contact) return;
  if (spec_.ground)
    for (const BodyShape& s : spec_.shapes)
      if (touchesGround_[static_cast<std::size_t>(&s - spec_.shapes.data())])
        groundContacts(
            s, contact_.pose(contactIds_[static_cast<std::size_t>(&s - spec_.shapes.data())]), out);
  for (const Contact& c : contact_.contacts(spec_.maxPointsPerPair)) {
    const BodyShape& a = spec_.shapes[static_cast<std::size_t>(c.a)];
    const BodyShape& b = spec_.shapes[static_cast<std::size_t>(c.b)];
    const int law =
        spec_.pairLaw[static_cast<std::size_t>(a.material * spec_.materialCount + b.material)];
    out.push_back({a.body, b.body, c.p_W, c.n_W, c.depth, law});
  }
}

WatchReading BodyCollision::clearance(std::size_t watch) {
  ReadSlot& slot = readSlot();
  if (slot.valid[watch]) return slot.readings[watch];
  if (!clearancePosed_) {  // (poses of the last update) => the watched shapes and ropes there
    for (std::size_t i = 0; i < spec_.shapes.size(); ++i) {
      const BodyShape& s = spec_.shapes[i];
      if (s.body != 0 && clearanceShapeIds_[i] >= 0)
        clearance_.setPose(clearanceShapeIds_[i], X_WB_[static_cast<std::size_t>(s.body)] * s.X_BS);
    }
    for (std::size_t r = 0; r < spec_.ropes.size(); ++r)
      if (!clearanceRopeIds_[r].empty())
        clearance_.setRopePath(clearanceRopeIds_[r], ropePath(spec_.ropes[r], X_WB_));
    clearancePosed_ = true;
  }
  const Clearance& c = clearance_.clearance(watchIds_[watch]);
  slot.valid[watch] = 1;
  WatchReading& out = slot.readings[watch];
  out = {};
  out.distance = c.closest.distance;
  if (!c.withinMargin) return out;
  auto nameOf = [&](ObjectId id) -> const std::string& {
    const int k = clearanceOwnerName_[static_cast<std::size_t>(id)];
    return k >= 0 ? spec_.shapes[static_cast<std::size_t>(k)].name
                  : spec_.ropes[static_cast<std::size_t>(-1 - k)].name;
  };
  out.a = nameOf(c.closest.a);
  out.b = nameOf(c.closest.b);
  out.pa_W = c.closest.pa_W;
  out.pb_W = c.closest.pb_W;
  return out;
}

}  // namespace yardsim::collision
