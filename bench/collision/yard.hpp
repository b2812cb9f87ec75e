#pragma once
// A generated shipyard for the collision benchmarks: a square of side 1 km holding work sites (a
// block, a box or (every third) a mesh, resting 1 mm deep on two supports, under a hoist rope of
// four segments whose hook hangs just above it) and container stacks (three boxes, 1 mm into each
// other), until the asked number of parts. Deterministic (fixed seed). A tenth of the parts move:
// the hanging ropes sway and the blocks under them rock by a few centimetres and a fraction of a
// degree around their base pose.
#include <vector>

#include "collision/collision_world.hpp"

namespace yardsim::bench {

struct Yard {
  collision::CollisionWorld world;
  struct Mover {
    collision::ObjectId id;
    bool segment;
    dynamics::Transform base;                          // rigid parts
    dynamics::Vector3 p0 = dynamics::Vector3::Zero();  // segments: the ends at rest
    dynamics::Vector3 p1 = dynamics::Vector3::Zero();
    double f0 = 0.0, f1 = 0.0;  // segments: the ends' fractions of the rope from its top
    double phase = 0.0;         // one per site: the rope's segments stay joined
  };
  std::vector<Mover> movers;                      // about 10 % of the parts
  std::vector<collision::ObjectId> ropeSegments;  // all of them
  std::vector<collision::ObjectId> blocks;        // one per site, the rope's load
  int parts = 0;
};

// (number of parts, tight boxes, every third block a 192-triangle mesh or all boxes, contacts of
// unmoved pairs reused) => the yard
Yard makeYard(int parts, bool tightAabb = true, bool meshBlocks = true, bool reuse = true);
// (yard, time s) => the moving parts set to their poses at time t (call update or a query after)
void moveYard(Yard& yard, double t);

}  // namespace yardsim::bench
