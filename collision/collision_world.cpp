// CollisionWorld without FCL: each method forwards to the world made by the FCL module
// (world_backend.hpp), which the first world of the process opens.
#include "collision/collision_world.hpp"

#include <atomic>

#include "collision/world_backend.hpp"
#include "forces/module_loader.hpp"

namespace yardsim::collision {

namespace {
#ifndef YARDSIM_FCL_LINKED
// the module's entry once opened (fclCounts reads it without opening the module)
std::atomic<const FclModule*> opened{nullptr};
#endif

// () => the module's entry, opened by the first call of the process (a failure is thrown again
// at the next call)
const FclModule& fcl() {
#ifdef YARDSIM_FCL_LINKED
  return *yardsim_fcl_module();
#else
  static const FclModule& module = loadFclModule(fclModulePath());
  opened.store(&module);
  return module;
#endif
}
}  // namespace

std::string fclModulePath() {
#ifdef YARDSIM_FCL_LINKED
  return {};
#else
  return forces::moduleBeside(reinterpret_cast<const void*>(&fclModulePath), "libyardsim_fcl.so");
#endif
}

const FclModule& loadFclModule(const std::string& file) {
  using Entry = const FclModule* (*)();
  const auto entry = reinterpret_cast<Entry>(forces::openModuleEntry(
      file, "yardsim_fcl_module", "the collision module",
      "; the collision module is built and installed with yardsim and needs FCL (Debian package "
      "libfcl0.7; reinstall yardsim, or put the module back beside libyardsim_collision.so)"));
  return *entry();
}

FclCounts fclCounts() {
#ifdef YARDSIM_FCL_LINKED
  return yardsim_fcl_module()->counts();
#else
  const FclModule* module = opened.load();
  return module != nullptr ? module->counts() : FclCounts{};
#endif
}

CollisionWorld::CollisionWorld(WorldOptions options) : backend_(fcl().makeWorld(options)) {}
CollisionWorld::~CollisionWorld() = default;
CollisionWorld::CollisionWorld(CollisionWorld&&) noexcept = default;
CollisionWorld& CollisionWorld::operator=(CollisionWorld&&) noexcept = default;

ObjectId CollisionWorld::add(const Shape& shape, const Transform& X_WB,
                             const ObjectOptions& options) {
  return backend_->add(shape, X_WB, options);
}
ObjectId CollisionWorld::addSegment(const Vector3& p0_W, const Vector3& p1_W, double diameter,
                                    const ObjectOptions& options) {
  return backend_->addSegment(p0_W, p1_W, diameter, options);
}
std::vector<ObjectId> CollisionWorld::addRope(const std::vector<Vector3>& path_W, double diameter,
                                              const ObjectOptions& options) {
  return backend_->addRope(path_W, diameter, options);
}
void CollisionWorld::setPose(ObjectId id, const Transform& X_WB) {
  backend_->setPose(id, X_WB);
}
void CollisionWorld::setSegment(ObjectId id, const Vector3& p0_W, const Vector3& p1_W) {
  backend_->setSegment(id, p0_W, p1_W);
}
void CollisionWorld::setRopePath(const std::vector<ObjectId>& ids,
                                 const std::vector<Vector3>& path_W) {
  backend_->setRopePath(ids, path_W);
}
void CollisionWorld::update() {
  backend_->update();
}
int CollisionWorld::size() const {
  return backend_->size();
}
const std::string& CollisionWorld::name(ObjectId id) const {
  return backend_->name(id);
}
const Shape& CollisionWorld::shape(ObjectId id) const {
  return backend_->shape(id);
}
const Transform& CollisionWorld::pose(ObjectId id) const {
  return backend_->pose(id);
}
Aabb CollisionWorld::aabb(ObjectId id) const {
  return backend_->aabb(id);
}
CollisionFilter& CollisionWorld::filter() {
  return backend_->filter();
}
const CollisionFilter& CollisionWorld::filter() const {
  return static_cast<const WorldBackend&>(*backend_).filter();
}
const std::vector<std::pair<ObjectId, ObjectId>>& CollisionWorld::candidatePairs() {
  return backend_->candidatePairs();
}
bool CollisionWorld::anyInterference() {
  return backend_->anyInterference();
}
const std::vector<Contact>& CollisionWorld::contacts(int maxPerPair) {
  return backend_->contacts(maxPerPair);
}
Distance CollisionWorld::distance(ObjectId a, ObjectId b) {
  return backend_->distance(a, b);
}
bool CollisionWorld::intersects(ObjectId a, ObjectId b) {
  return backend_->intersects(a, b);
}
int CollisionWorld::addWatch(std::vector<ObjectId> a, std::vector<ObjectId> b, double margin) {
  return backend_->addWatch(std::move(a), std::move(b), margin);
}
const Clearance& CollisionWorld::clearance(int watch) {
  return backend_->clearance(watch);
}
const QueryStats& CollisionWorld::stats() const {
  return backend_->stats();
}

}  // namespace yardsim::collision
