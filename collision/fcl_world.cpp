// The FCL side of CollisionWorld (the module libyardsim_fcl.so, collision/world_backend.hpp):
// objects, poses and the broad phase; the queries are in world_queries.cpp.
#include "collision/world_backend.hpp"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/halfspace.h>
#include <fcl/geometry/shape/sphere.h>

#include <cmath>
#include <stdexcept>

#include "collision/detail/world_impl.hpp"

namespace yardsim::collision {

using detail::Record;

namespace {

// (X_WB) => the same as an FCL transform
fcl::Transform3d toFcl(const Transform& X) {
  fcl::Transform3d t = fcl::Transform3d::Identity();
  t.linear() = X.R;
  t.translation() = X.p;
  return t;
}

// (name, X_WB) => CollisionError unless finite with R a proper rotation (1e-6)
void checkPose(const std::string& name, const Transform& X_WB) {
  if (!X_WB.R.allFinite() || !X_WB.p.allFinite()) {
    throw CollisionError("collision: object '" + name +
                         "': non-finite pose (NaN or inf); FCL's broad phase cannot take it");
  }
  const double err =
      (X_WB.R.transpose() * X_WB.R - dynamics::Matrix3::Identity()).cwiseAbs().maxCoeff();
  if (err > 1e-6 || X_WB.R.determinant() < 0.0) {
    throw CollisionError(
        "collision: object '" + name +
        "': pose rotation is not a rotation (|R^T R - I| = " + std::to_string(err) + ")");
  }
}

// (p0, p1) => pose of a capsule between them: origin at the middle, z_B along p1 - p0
Transform segmentPose(const Vector3& p0, const Vector3& p1) {
  Transform X;
  X.p = 0.5 * (p0 + p1);
  const Vector3 d = p1 - p0;
  const double len = d.norm();
  const Vector3 z = len > 0.0 ? Vector3(d / len) : Vector3::UnitZ();
  const Vector3 helper = std::abs(z.x()) < 0.9 ? Vector3::UnitX() : Vector3::UnitY();
  const Vector3 x = helper.cross(z).normalized();
  X.R.col(0) = x;
  X.R.col(1) = z.cross(x);
  X.R.col(2) = z;
  return X;
}

}  // namespace

// (record) => FCL transform, geometry length of a segment and world box
void CollisionWorld::Impl::refresh(Record& r) const {
  if (r.segment) {
    r.X_WB = segmentPose(r.p0_W, r.p1_W);
    r.shape.length = (r.p1_W - r.p0_W).norm();
    auto& cap = static_cast<fcl::Capsuled&>(*r.geometry);
    cap.lz = r.shape.length;
    if (!options.tightAabb) cap.computeLocalAABB();
  }
  r.object->setTransform(toFcl(r.X_WB));
  // a half-space keeps our finite box even in the loose mode: FCL's spans +-DBL_MAX, whose
  // volume overflows in the tree's balancing
  if (options.tightAabb || r.shape.kind == ShapeKind::kHalfSpace) {
    r.box = r.segment ? segmentAabb(r.p0_W, r.p1_W, r.shape.radius)
                      : worldAabb(r.shape, r.bound, r.X_WB);
    r.object->setAabb(r.box);
  } else {
    r.object->computeAABB();
    r.box = {r.object->getAABB().min_, r.object->getAABB().max_};
  }
  // (world box) => finite and within 1e12 m of the origin: FCL's tree balancing crashed on a box
  // of 1e300 m (a size or a centre of mass of 1e300 in a scene: tests/fuzz/mutate.py)
  constexpr double kFar = 1e12;
  if (!(r.box.min.array().abs() <= kFar).all() || !(r.box.max.array().abs() <= kFar).all())
    throw CollisionError("collision: object '" + r.name +
                         "': its bounding box reaches beyond 1e12 m of the origin (a size or a "
                         "position of that order); FCL's broad phase cannot take it");
}

Record& CollisionWorld::Impl::at(ObjectId id) {
  if (id < 0 || id >= static_cast<ObjectId>(records.size())) {
    throw std::out_of_range("collision: no object with id " + std::to_string(id));
  }
  return records[static_cast<std::size_t>(id)];
}

namespace {
// () => the counts now
FclCounts countsNow() {
  return {detail::worldTally.made, detail::worldTally.alive, detail::objectTally.made,
          detail::objectTally.alive};
}

// (options) => a world on FCL's side
std::unique_ptr<WorldBackend> makeFclWorld(const WorldOptions& options) {
  return std::make_unique<FclWorld>(options);
}
}  // namespace

FclWorld::FclWorld(const WorldOptions& options) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
  impl_->probe = std::make_unique<detail::FclObject>(std::make_shared<fcl::Sphered>(1.0));
  impl_->probe->setUserData(reinterpret_cast<void*>(std::intptr_t{-1}));
  const auto gjk = options.independentGjk ? fcl::GST_INDEP : fcl::GST_LIBCCD;
  impl_->request.gjk_solver_type = gjk;
  impl_->distanceRequest.gjk_solver_type = gjk;
  impl_->distanceRequest.enable_nearest_points = true;
  impl_->distanceRequest.enable_signed_distance = true;
}

// (shape, X_WB, options) => FCL geometry (meshes shared), object, filter entry; pending insert
ObjectId FclWorld::add(const Shape& shape, const Transform& X_WB, const ObjectOptions& options) {
  Impl& m = *impl_;
  const auto id = static_cast<ObjectId>(m.records.size());
  Record r;
  r.name = options.name.empty() ? "object " + std::to_string(id) : options.name;
  checkShape(shape, r.name);
  checkPose(r.name, X_WB);
  r.shape = shape;
  r.bound = shapeBound(shape);
  r.X_WB = X_WB;
  switch (shape.kind) {
    case ShapeKind::kBox:
      r.geometry = std::make_shared<fcl::Boxd>(shape.size);
      break;
    case ShapeKind::kSphere:
      r.geometry = std::make_shared<fcl::Sphered>(shape.radius);
      break;
    case ShapeKind::kCylinder:
      r.geometry = std::make_shared<fcl::Cylinderd>(shape.radius, shape.length);
      break;
    case ShapeKind::kCapsule:
      r.geometry = std::make_shared<fcl::Capsuled>(shape.radius, shape.length);
      break;
    case ShapeKind::kHalfSpace:
      r.geometry = std::make_shared<fcl::Halfspaced>(shape.normal.normalized(),
                                                     shape.offset / shape.normal.norm());
      break;
    case ShapeKind::kMesh: {
      auto& bvh = m.meshes[shape.mesh.get()];
      if (!bvh) {
        bvh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
        std::vector<fcl::Vector3d> v(shape.mesh->vertices.begin(), shape.mesh->vertices.end());
        std::vector<fcl::Triangle> t;
        t.reserve(shape.mesh->triangles.size());
        for (const auto& tri : shape.mesh->triangles) {
          t.emplace_back(static_cast<std::size_t>(tri[0]), static_cast<std::size_t>(tri[1]),
                         static_cast<std::size_t>(tri[2]));
        }
        bvh->beginModel(static_cast<int>(t.size()), static_cast<int>(v.size()));
        bvh->addSubModel(v, t);
        bvh->endModel();
        bvh->computeLocalAABB();
      }
      r.geometry = bvh;
      break;
    }
  }
  r.geometry->computeLocalAABB();
  r.object = std::make_unique<detail::FclObject>(r.geometry, toFcl(X_WB));
  r.object->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(id)));
  m.records.push_back(std::move(r));
  m.filter.setEntry(id, options.filter);
  m.dirty.push_back(id);
  m.pending.push_back(id);
  return id;
}

// (p0, p1, d, options) => a capsule object of radius d / 2 marked as a segment
ObjectId FclWorld::addSegment(const Vector3& p0_W, const Vector3& p1_W, double diameter,
                              const ObjectOptions& options) {
  const std::string name = options.name.empty() ? "rope segment" : options.name;
  if (!p0_W.allFinite() || !p1_W.allFinite()) {
    throw CollisionError("collision: rope segment '" + name + "': non-finite end point");
  }
  const ObjectId id =
      add(Shape::capsule(0.5 * diameter, (p1_W - p0_W).norm()), segmentPose(p0_W, p1_W), options);
  Record& r = impl_->at(id);
  r.segment = true;
  r.p0_W = p0_W;
  r.p1_W = p1_W;
  return id;
}

// (path, d, options) => one segment per span, named "<name>[i]"
std::vector<ObjectId> FclWorld::addRope(const std::vector<Vector3>& path_W, double diameter,
                                        const ObjectOptions& options) {
  if (path_W.size() < 2)
    throw CollisionError("collision: rope '" + options.name + "' needs 2 points");
  std::vector<ObjectId> ids;
  ids.reserve(path_W.size() - 1);
  for (std::size_t i = 0; i + 1 < path_W.size(); ++i) {
    ObjectOptions o = options;
    o.name = options.name + "[" + std::to_string(i) + "]";
    ids.push_back(addSegment(path_W[i], path_W[i + 1], diameter, o));
  }
  return ids;
}

// (id, X_WB) => checked, stored, dirty
void FclWorld::setPose(ObjectId id, const Transform& X_WB) {
  Record& r = impl_->at(id);
  checkPose(r.name, X_WB);
  if (r.segment)
    throw CollisionError("collision: '" + r.name + "' is a rope segment: use setSegment");
  r.X_WB = X_WB;
  if (!r.dirty) impl_->dirty.push_back(id);
  r.dirty = true;
}

// (id, p0, p1) => checked, stored, dirty
void FclWorld::setSegment(ObjectId id, const Vector3& p0_W, const Vector3& p1_W) {
  Record& r = impl_->at(id);
  if (!r.segment) throw CollisionError("collision: '" + r.name + "' is not a rope segment");
  if (!p0_W.allFinite() || !p1_W.allFinite()) {
    throw CollisionError("collision: rope segment '" + r.name +
                         "': non-finite end point (NaN or inf); FCL's broad phase cannot take it");
  }
  r.p0_W = p0_W;
  r.p1_W = p1_W;
  if (!r.dirty) impl_->dirty.push_back(id);
  r.dirty = true;
}

// (ids, path) => one setSegment per span
void FclWorld::setRopePath(const std::vector<ObjectId>& ids, const std::vector<Vector3>& path_W) {
  if (path_W.size() != ids.size() + 1) {
    throw CollisionError("collision: setRopePath needs one more point than segments");
  }
  for (std::size_t i = 0; i < ids.size(); ++i) setSegment(ids[i], path_W[i], path_W[i + 1]);
}

// () => dirty boxes recomputed, new objects inserted, moved leaves updated
void FclWorld::update() {
  Impl& m = *impl_;
  if (m.dirty.empty() && m.pending.empty()) return;
  m.moved.clear();
  for (ObjectId id : m.dirty) {
    Record& r = m.records[static_cast<std::size_t>(id)];
    m.refresh(r);
    r.dirty = false;
    ++r.version;
    if (r.registered) m.moved.push_back(r.object.get());
  }
  m.dirty.clear();
  if (!m.pending.empty()) {
    m.added.clear();
    for (ObjectId id : m.pending) {
      Record& r = m.records[static_cast<std::size_t>(id)];
      r.registered = true;
      m.added.push_back(r.object.get());
    }
    m.pending.clear();
    m.manager.registerObjects(m.added);
    m.manager.setup();
  }
  if (!m.moved.empty()) m.manager.update(m.moved);
}

int FclWorld::size() const {
  return static_cast<int>(impl_->records.size());
}
const std::string& FclWorld::name(ObjectId id) const {
  return impl_->at(id).name;
}
const Shape& FclWorld::shape(ObjectId id) const {
  return impl_->at(id).shape;
}
const Transform& FclWorld::pose(ObjectId id) const {
  return impl_->at(id).X_WB;
}
Aabb FclWorld::aabb(ObjectId id) const {
  return impl_->at(id).box;
}
CollisionFilter& FclWorld::filter() {
  return impl_->filter;
}
const CollisionFilter& FclWorld::filter() const {
  return impl_->filter;
}
const QueryStats& FclWorld::stats() const {
  return impl_->stats;
}

}  // namespace yardsim::collision

extern "C" const yardsim::collision::FclModule* yardsim_fcl_module() {
  static const yardsim::collision::FclModule entry{&yardsim::collision::makeFclWorld,
                                                   &yardsim::collision::countsNow};
  return &entry;
}
