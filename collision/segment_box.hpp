#pragma once
// The signed distance between a segment and a box, exact to rounding, without GJK: the rope
// clearance query (a capsule of the rope's radius against a block) and any capsule-box distance.
// FCL 0.7's GJK is not reliable for this pair: libccd is off by up to 1e-3 m and, about once in
// 300,000 poses, by metres; FCL's own GJK returns wrong box-box distances (docs/collision.md).
// Method: the box's signed distance function is convex, so along the segment p(s), s in [0, 1],
// it is a convex function of s, minimised by golden-section search (80 steps: the bracket shrinks
// below 1e-16 of the segment). Frame: the box's own frame B (centre at the origin, edges along the
// axes); units m.
#include "dynamics/spatial.hpp"

namespace yardsim::collision {

struct SegmentBoxResult {
  double distance = 0.0;  // signed: > 0 apart, < 0 the segment runs inside the box, m
  double s = 0.0;         // the closest point's parameter on the segment, p0 + s (p1 - p0)
  dynamics::Vector3 onSegment = dynamics::Vector3::Zero();  // p(s), B
  dynamics::Vector3 onBox = dynamics::Vector3::Zero();      // the nearest point of the surface, B
};

// (p) => signed distance from p to the surface of the box of half extents h (< 0 inside), m
double boxSignedDistance(const dynamics::Vector3& p_B, const dynamics::Vector3& halfExtent);
// (p) => the nearest point of the box surface to p (inside: on the nearest face), B
dynamics::Vector3 boxSurfacePoint(const dynamics::Vector3& p_B,
                                  const dynamics::Vector3& halfExtent);
// (segment ends in B, half extents) => the signed distance and the closest points
SegmentBoxResult segmentBoxDistance(const dynamics::Vector3& p0_B, const dynamics::Vector3& p1_B,
                                    const dynamics::Vector3& halfExtent);

}  // namespace yardsim::collision
