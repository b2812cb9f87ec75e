#pragma once
// The motion of a run's bodies as the report's 3D replay and replay.glb show it: per body its
// shape (resolved: never Auto) and its world pose at every frame, and the ropes as polylines
// through points fixed on bodies (or the world): wire ropes through their paths, lines with mass
// through their nodes (bodies), catenary lines through markers (bodies without a shape) that
// follow their profile. Models that have bodies implement Replayable; the replay recorder samples
// them on the record grid.
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/spatial.hpp"
#include "mechanics/description.hpp"

namespace yardsim::models {

using mechanics::MechanicsSpec;

struct ReplayBody {
  std::string name;  // full path
  // a point that lines are drawn through (a catenary line's profile point): no shape, and only
  // its translation per frame (rotation stays empty)
  bool marker = false;
  MechanicsSpec::Visual::Shape shape = MechanicsSpec::Visual::Shape::Box;
  dynamics::Vector3 size = dynamics::Vector3::Ones();  // as MechanicsSpec::Visual::size
  dynamics::Transform X_BG;                             // shape frame in the body frame
  std::shared_ptr<const forces::TriangleMesh> mesh;     // shape Mesh: its triangles
  // per frame: position of the body origin in the world (m) and orientation as a unit
  // quaternion in glTF order x, y, z, w
  std::vector<std::array<float, 3>> translation;
  std::vector<std::array<float, 4>> rotation;
};

struct ReplayRope {
  std::string name;
  std::vector<std::pair<int, dynamics::Vector3>> points;  // (body index in Replay::bodies or
                                                          // -1 for the world, point in it)
};

struct Replay {
  std::vector<float> times;  // s, one per frame
  std::vector<ReplayBody> bodies;
  std::vector<ReplayRope> ropes;
};

// A model whose bodies the replay shows.
class Replayable {
 public:
  virtual ~Replayable() = default;
  // (replay) => this model's bodies and ropes appended (no frames yet); body indices in ropes
  // are offset by the bodies already there
  virtual void replayBodies(Replay& out) const = 0;
  // (replay, index of this model's first body) => one pose appended to each of its bodies, from
  // the committed state
  virtual void replayFrame(Replay& out, std::size_t firstBody) const = 0;
};

// (body visual, mass, centre of mass, inertia about it) => the shape the replay draws: the given
// one, placed on the centre of mass unless posed; Auto becomes the uniform box with that mass
// and those principal moments
ReplayBody replayShape(const MechanicsSpec::Visual& visual, double mass,
                       const dynamics::Vector3& com, const dynamics::Matrix3& inertia);

}  // namespace yardsim::models
