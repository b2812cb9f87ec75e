#pragma once
// The seam between CollisionWorld (libyardsim_collision.so, no FCL) and its FCL side, which lives
// in a module, libyardsim_fcl.so, installed beside libyardsim_collision.so and opened (dlopen) when
// the first world is made: a run without collision never loads FCL, libccd and octomap (about
// 5 ms of start-up; docs/performance.md). WorldBackend is CollisionWorld's interface, method for
// method (collision_world.hpp has what each does, the frames and units); FclModule is the
// module's one entry. Not part of the API: only collision/*.cpp include it.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "collision/collision_world.hpp"

namespace yardsim::collision {

class WorldBackend {
 public:
  virtual ~WorldBackend() = default;
  virtual ObjectId add(const Shape& shape, const Transform& X_WB, const ObjectOptions& options) = 0;
  virtual ObjectId addSegment(const Vector3& p0_W, const Vector3& p1_W, double diameter,
                              const ObjectOptions& options) = 0;
  virtual std::vector<ObjectId> addRope(const std::vector<Vector3>& path_W, double diameter,
                                        const ObjectOptions& options) = 0;
  virtual void setPose(ObjectId id, const Transform& X_WB) = 0;
  virtual void setSegment(ObjectId id, const Vector3& p0_W, const Vector3& p1_W) = 0;
  virtual void setRopePath(const std::vector<ObjectId>& ids,
                           const std::vector<Vector3>& path_W) = 0;
  virtual void update() = 0;
  virtual int size() const = 0;
  virtual const std::string& name(ObjectId id) const = 0;
  virtual const Shape& shape(ObjectId id) const = 0;
  virtual const Transform& pose(ObjectId id) const = 0;
  virtual Aabb aabb(ObjectId id) const = 0;
  virtual CollisionFilter& filter() = 0;
  virtual const CollisionFilter& filter() const = 0;
  virtual const std::vector<std::pair<ObjectId, ObjectId>>& candidatePairs() = 0;
  virtual bool anyInterference() = 0;
  virtual const std::vector<Contact>& contacts(int maxPerPair) = 0;
  virtual Distance distance(ObjectId a, ObjectId b) = 0;
  virtual bool intersects(ObjectId a, ObjectId b) = 0;
  virtual int addWatch(std::vector<ObjectId> a, std::vector<ObjectId> b, double margin) = 0;
  virtual const Clearance& clearance(int watch) = 0;
  virtual const QueryStats& stats() const = 0;
};

// The module's entry: a new world on FCL's side, and FCL's counts (fclCounts)
struct FclModule {
  std::unique_ptr<WorldBackend> (*makeWorld)(const WorldOptions& options);
  FclCounts (*counts)();
};

// () => the module this build loads: libyardsim_fcl.so in the folder libyardsim_collision.so was
// loaded from (build tree and install tree alike); empty in a static build (linked in)
std::string fclModulePath();

// (module file) => its entry `yardsim_fcl_module`, the module kept loaded for the process.
// Throws std::runtime_error naming the file and why (missing, not loadable, no entry).
const FclModule& loadFclModule(const std::string& file);

}  // namespace yardsim::collision

// () => the entry itself, defined by fcl_world.cpp (linked to FCL)
extern "C" const yardsim::collision::FclModule* yardsim_fcl_module();
