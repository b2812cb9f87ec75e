// The queries of CollisionWorld: candidate pairs, interference, contacts, distances, watches.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "collision/collision_world.hpp"
#include "collision/detail/world_impl.hpp"
#include "collision/segment_box.hpp"

namespace yardsim::collision {

using detail::idOf;

namespace {

// (capsule record, box record) => segmentBoxDistance of the capsule's axis, in the box frame
SegmentBoxResult capsuleAxisToBox(const detail::Record& cap, const detail::Record& box) {
  Vector3 p0 = cap.p0_W, p1 = cap.p1_W;
  if (!cap.segment) {
    const Vector3 half = 0.5 * cap.shape.length * cap.X_WB.R.col(2);
    p0 = cap.X_WB.p - half;
    p1 = cap.X_WB.p + half;
  }
  return segmentBoxDistance(box.X_WB.invActPoint(p0), box.X_WB.invActPoint(p1),
                            box.bound.halfExtent_B);
}

// (capsule record, box record) => their signed distance and the closest (apart) or deepest
// (overlapping) points on each, world frame
void capsuleBoxDistance(const detail::Record& cap, const detail::Record& box, double& distance,
                        Vector3& onCapsule_W, Vector3& onBox_W) {
  const SegmentBoxResult r = capsuleAxisToBox(cap, box);
  const double radius = cap.shape.radius;
  distance = r.distance - radius;
  const Vector3 out = r.onSegment - r.onBox;  // from the surface to the axis point
  const double len = out.norm();
  Vector3 onCap = r.onSegment;
  if (len > 0.0) onCap -= (r.distance >= 0.0 ? radius : -radius) / len * out;
  onCapsule_W = box.X_WB.actPoint(onCap);
  onBox_W = box.X_WB.actPoint(r.onBox);
}

// (capsule record, box record) => whether they overlap; if so the contact: the point half-way
// between the deepest points, the unit normal from the box into the capsule, the depth
bool capsuleBoxContact(const detail::Record& cap, const detail::Record& box, Vector3& p_W,
                       Vector3& n_W, double& depth) {
  const SegmentBoxResult r = capsuleAxisToBox(cap, box);
  const double radius = cap.shape.radius;
  if (r.distance >= radius) return false;
  Vector3 n_B = r.onSegment - r.onBox;
  const double len = n_B.norm();
  if (len > 0.0) {
    n_B *= (r.distance >= 0.0 ? 1.0 : -1.0) / len;  // the axis inside: out through the near face
  } else {                                          // the axis on the surface: the face normal
    const Vector3 rel = r.onBox.cwiseQuotient(box.bound.halfExtent_B);
    int axis = 0;
    rel.cwiseAbs().maxCoeff(&axis);
    n_B = Vector3::Zero();
    n_B[axis] = rel[axis] >= 0.0 ? 1.0 : -1.0;
  }
  depth = radius - r.distance;
  n_W = box.X_WB.R * n_B;
  p_W = box.X_WB.actPoint(r.onBox - 0.5 * depth * n_B);
  return true;
}

// (world, a, b) => 1 when a is the capsule and b the box, -1 the other way, 0 for other kinds
int capsuleBoxOrder(const CollisionWorld::Impl& m, ObjectId a, ObjectId b) {
  const ShapeKind ka = m.records[static_cast<std::size_t>(a)].shape.kind;
  const ShapeKind kb = m.records[static_cast<std::size_t>(b)].shape.kind;
  if (ka == ShapeKind::kCapsule && kb == ShapeKind::kBox) return 1;
  if (ka == ShapeKind::kBox && kb == ShapeKind::kCapsule) return -1;
  return 0;
}

// What a broad-phase callback needs: the world, and for the narrow phase how many contacts.
struct PairContext {
  CollisionWorld::Impl* m;
  int maxContacts = 0;  // 0: interference only
  bool found = false;
};

// (o1, o2) => (a, b) with a < b
std::pair<ObjectId, ObjectId> ordered(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2) {
  const ObjectId i = idOf(o1), j = idOf(o2);
  return i < j ? std::pair{i, j} : std::pair{j, i};
}

// (o1, o2, context) => the pair recorded if the filter lets it through; never stops
bool collectPair(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  auto* c = static_cast<PairContext*>(data);
  const auto [a, b] = ordered(o1, o2);
  if (!c->m->boxesOverlap(a, b)) return false;
  ++c->m->stats.broadPhasePairs;
  if (!c->m->filter.canCollide(a, b)) return false;
  ++c->m->stats.candidatePairs;
  c->m->pairs.emplace_back(a, b);
  return false;
}

void narrowPhase(PairContext* c, ObjectId a, ObjectId b);

// (o1, o2, context) => narrow phase of a filtered pair: contacts appended (or found set and
// the traversal stopped when maxContacts == 0)
bool narrowPair(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  auto* c = static_cast<PairContext*>(data);
  CollisionWorld::Impl& m = *c->m;
  const auto [a, b] = ordered(o1, o2);
  if (!m.boxesOverlap(a, b)) return false;
  ++m.stats.broadPhasePairs;
  if (!m.filter.canCollide(a, b)) return false;
  ++m.stats.candidatePairs;
  const bool cached = c->maxContacts > 0 && m.options.reuseUnmovedPairs;
  const std::uint64_t va = m.records[static_cast<std::size_t>(a)].version;
  const std::uint64_t vb = m.records[static_cast<std::size_t>(b)].version;
  if (cached && m.pairCache.reuse(a, b, va, vb, c->maxContacts, m.contacts)) {
    ++m.stats.reusedPairs;
    return false;
  }
  ++m.stats.narrowPhaseCalls;
  const std::size_t first = m.contacts.size();
  narrowPhase(c, a, b);
  if (cached) m.pairCache.record(a, b, va, vb, c->maxContacts, first, m.contacts.size() - first);
  return c->found;
}

// (context, a < b) => the pair's contacts appended to m.contacts (or found set when
// maxContacts == 0)
void narrowPhase(PairContext* c, ObjectId a, ObjectId b) {
  CollisionWorld::Impl& m = *c->m;
  if (const int order = capsuleBoxOrder(m, a, b)) {  // a rope or capsule on a block: exact
    const auto& ra = m.records[static_cast<std::size_t>(a)];
    const auto& rb = m.records[static_cast<std::size_t>(b)];
    Contact ct;
    ct.a = a;
    ct.b = b;
    const bool hit = order > 0 ? capsuleBoxContact(ra, rb, ct.p_W, ct.n_W, ct.depth)
                               : capsuleBoxContact(rb, ra, ct.p_W, ct.n_W, ct.depth);
    if (!hit) return;
    if (c->maxContacts == 0) {
      c->found = true;
      return;
    }
    if (order > 0) ct.n_W = -ct.n_W;  // box -> capsule turned into a -> b
    m.contacts.push_back(ct);
    return;
  }
  const double sign = collideOrdered(m, a, b);
  if (!m.result.isCollision()) return;
  if (c->maxContacts == 0) {
    c->found = true;
    return;
  }
  const std::size_t first = m.contacts.size();
  for (std::size_t k = 0; k < m.result.numContacts(); ++k) {
    const auto& fc = m.result.getContact(k);
    // a mesh reports a vertex once per triangle around it: keep one
    bool seen = false;
    for (std::size_t j = first; j < m.contacts.size() && !seen; ++j) {
      seen = (m.contacts[j].p_W - fc.pos).squaredNorm() < 1e-18 * (1.0 + fc.pos.squaredNorm()) &&
             m.contacts[j].depth == fc.penetration_depth;
    }
    if (seen) continue;
    Contact ct;
    ct.a = a;
    ct.b = b;
    ct.p_W = fc.pos;
    ct.n_W = sign * fc.normal;
    ct.depth = fc.penetration_depth;
    m.contacts.push_back(ct);
  }
}

}  // namespace

// (world, a < b) => m.result of fcl::collide, and the sign that turns its normals into a -> b.
// FCL 0.7 returns the normal of a shape-mesh pair (shape first) pointing the wrong way (from the
// mesh to the shape; world_queries_test): a mesh is always passed first and the sign fixes it.
double collideOrdered(CollisionWorld::Impl& m, ObjectId a, ObjectId b) {
  const auto* oa = m.records[static_cast<std::size_t>(a)].object.get();
  const auto* ob = m.records[static_cast<std::size_t>(b)].object.get();
  m.result.clear();
  if (oa->getObjectType() == fcl::OT_GEOM && ob->getObjectType() == fcl::OT_BVH) {
    fcl::collide(ob, oa, m.request, m.result);
    return -1.0;
  }
  fcl::collide(oa, ob, m.request, m.result);
  return 1.0;
}

// () => filtered pairs whose boxes overlap
const std::vector<std::pair<ObjectId, ObjectId>>& FclWorld::candidatePairs() {
  update();
  Impl& m = *impl_;
  m.stats = {};
  m.pairs.clear();
  PairContext c{&m};
  m.manager.collide(&c, collectPair);
  return m.pairs;
}

// () => first intersecting candidate pair found
bool FclWorld::anyInterference() {
  update();
  Impl& m = *impl_;
  m.stats = {};
  m.request.num_max_contacts = 1;
  m.request.enable_contact = false;
  PairContext c{&m, 0};
  m.manager.collide(&c, narrowPair);
  return c.found;
}

// (max per pair) => contact points of all intersecting candidate pairs
const std::vector<Contact>& FclWorld::contacts(int maxPerPair) {
  update();
  Impl& m = *impl_;
  m.stats = {};
  if (m.options.reuseUnmovedPairs) {
    m.pairCache.begin(m.contacts);  // keeps last query's contacts for the pairs that did not move
  } else {
    m.contacts.clear();
  }
  m.request.num_max_contacts = static_cast<std::size_t>(std::max(1, maxPerPair));
  m.request.enable_contact = true;
  PairContext c{&m, std::max(1, maxPerPair)};
  m.manager.collide(&c, narrowPair);
  m.stats.contacts = static_cast<int>(m.contacts.size());
  return m.contacts;
}

// (a, b) => minimum distance with witness points: capsule-box by segmentBoxDistance, the rest by
// FCL (closed forms where it has them, libccd or its own GJK otherwise)
Distance FclWorld::distance(ObjectId a, ObjectId b) {
  update();
  Impl& m = *impl_;
  const detail::Record& ra = m.at(a);
  const detail::Record& rb = m.at(b);
  Distance d;
  d.a = a;
  d.b = b;
  if (ra.shape.kind == ShapeKind::kCapsule && rb.shape.kind == ShapeKind::kBox) {
    capsuleBoxDistance(ra, rb, d.distance, d.pa_W, d.pb_W);
    return d;
  }
  if (ra.shape.kind == ShapeKind::kBox && rb.shape.kind == ShapeKind::kCapsule) {
    capsuleBoxDistance(rb, ra, d.distance, d.pb_W, d.pa_W);
    return d;
  }
  const auto* oa = ra.object.get();
  const auto* ob = rb.object.get();
  m.distanceResult.clear();
  fcl::distance(oa, ob, m.distanceRequest, m.distanceResult);
  d.distance = m.distanceResult.min_distance;
  d.pa_W = m.distanceResult.nearest_points[0];
  d.pb_W = m.distanceResult.nearest_points[1];
  return d;
}

// (a, b) => whether they intersect
bool FclWorld::intersects(ObjectId a, ObjectId b) {
  update();
  Impl& m = *impl_;
  m.request.num_max_contacts = 1;
  m.request.enable_contact = false;
  const detail::Record& ra = m.at(a);
  const detail::Record& rb = m.at(b);
  if (const int order = capsuleBoxOrder(m, a, b)) {
    Vector3 p, n;
    double depth = 0.0;
    return order > 0 ? capsuleBoxContact(ra, rb, p, n, depth)
                     : capsuleBoxContact(rb, ra, p, n, depth);
  }
  collideOrdered(m, a, b);
  return m.result.isCollision();
}

// (sets, margin) => a watch
int FclWorld::addWatch(std::vector<ObjectId> a, std::vector<ObjectId> b, double margin) {
  Impl& m = *impl_;
  if (!(margin >= 0.0) || !std::isfinite(margin)) {
    throw CollisionError("collision: a watch margin must be finite and >= 0");
  }
  detail::Watch w;
  w.inB.assign(m.records.size(), 0);
  for (ObjectId id : a) m.at(id);
  for (ObjectId id : b) {
    m.at(id);
    w.inB[static_cast<std::size_t>(id)] = 1;
  }
  w.a = std::move(a);
  w.margin = margin;
  m.watches.push_back(std::move(w));
  return static_cast<int>(m.watches.size()) - 1;
}

namespace {

struct WatchContext {
  FclWorld* world;
  CollisionWorld::Impl* m;
  detail::Watch* w;
  ObjectId a;
  Aabb box;  // a's box grown by the margin
};

// (tree object, probe, context) => a nearby member of set b: its exact distance, kept if closer
bool watchPair(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  auto* c = static_cast<WatchContext*>(data);
  const ObjectId b = idOf(o1) >= 0 ? idOf(o1) : idOf(o2);
  if (b == c->a || !c->w->inB[static_cast<std::size_t>(b)]) return false;
  if (!c->box.overlaps(c->m->records[static_cast<std::size_t>(b)].box)) return false;
  if (!c->m->filter.canCollide(c->a, b)) return false;
  ++c->w->result.pairsQueried;
  const Distance d = c->world->distance(c->a, b);
  if (!c->w->result.withinMargin || d.distance < c->w->result.closest.distance) {
    c->w->result.withinMargin = d.distance <= c->w->margin;
    if (c->w->result.withinMargin) c->w->result.closest = d;
  }
  return false;
}

}  // namespace

// (watch) => the closest pair within the margin, querying only pairs whose grown boxes overlap
const Clearance& FclWorld::clearance(int watch) {
  update();
  Impl& m = *impl_;
  if (watch < 0 || watch >= static_cast<int>(m.watches.size())) {
    throw std::out_of_range("collision: no watch " + std::to_string(watch));
  }
  detail::Watch& w = m.watches[static_cast<std::size_t>(watch)];
  if (w.inB.size() < m.records.size()) w.inB.resize(m.records.size(), 0);
  w.result = {};
  w.result.closest.distance = w.margin;
  for (ObjectId a : w.a) {
    const Aabb grown = m.records[static_cast<std::size_t>(a)].box.inflated(w.margin);
    m.probe->setAabb(grown);
    WatchContext c{this, &m, &w, a, grown};
    m.manager.collide(m.probe.get(), &c, watchPair);
  }
  return w.result;
}

}  // namespace yardsim::collision
