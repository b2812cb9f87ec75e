#pragma once
// Collision shapes, described without FCL: boxes, spheres, cylinders, capsules, half-spaces and
// closed triangle meshes, each in its own body frame B (centred on B's origin, the axis of a
// cylinder or capsule along z_B); and the tight world-frame bounding box of a shape at a pose
// X_WB, which the broad phase uses instead of FCL's loose default (a sphere around the local box:
// a rotated box's FCL AABB holds up to 5x more candidate pairs). Rope segments are capsules
// between two world points (collision_world.hpp). Units: m.
#include <memory>
#include <stdexcept>
#include <string>

#include "dynamics/spatial.hpp"
#include "forces/geometry/triangle_mesh.hpp"

namespace yardsim::collision {

using dynamics::Transform;
using dynamics::Vector3;

// A shape that cannot be used (non-positive size, empty mesh) or an object in a state FCL cannot
// take (a non-finite pose): the message names the object.
class CollisionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class ShapeKind { kBox, kSphere, kCylinder, kCapsule, kHalfSpace, kMesh };

// One shape in its body frame B. Fill it through the factory functions.
struct Shape {
  ShapeKind kind = ShapeKind::kSphere;
  Vector3 size = Vector3::Zero();     // box: full edge lengths along x_B, y_B, z_B, m
  double radius = 0.0;                // sphere, cylinder, capsule, m
  double length = 0.0;                // cylinder: height; capsule: length of the straight part, m
  Vector3 normal = Vector3::UnitZ();  // half-space {p_B : normal . p_B <= offset}, unit
  double offset = 0.0;                // m
  std::shared_ptr<const forces::TriangleMesh> mesh;  // vertices in B, m; shared between objects

  static Shape box(const Vector3& size);
  static Shape sphere(double radius);
  static Shape cylinder(double radius, double length);
  static Shape capsule(double radius, double length);
  // the solid below the plane normal . p_B = offset (the ground: normal +z, offset 0)
  static Shape halfSpace(const Vector3& normal, double offset);
  static Shape triangleMesh(std::shared_ptr<const forces::TriangleMesh> mesh);
};

// (shape, object name) => nothing, or CollisionError naming the object: a non-positive or
// non-finite size, a zero normal, an empty mesh or one with an index out of range
void checkShape(const Shape& shape, const std::string& name);

// An axis-aligned box, world frame, m.
struct Aabb {
  Vector3 min = Vector3::Zero();
  Vector3 max = Vector3::Zero();
  // (other) => whether the closed boxes share a point
  bool overlaps(const Aabb& o) const {
    return (min.array() <= o.max.array()).all() && (o.min.array() <= max.array()).all();
  }
  // (margin m) => the box grown by margin on every side
  Aabb inflated(double margin) const {
    return {min - Vector3::Constant(margin), max + Vector3::Constant(margin)};
  }
};

// Half the extent of everything: a half-space's box is cut at +-kWorldExtent, m.
inline constexpr double kWorldExtent = 1e6;

// The part of a shape its world box needs, computed once (a mesh: the centre and half extents
// of its vertices' local box, so that a pose costs O(1) and not O(vertices)).
struct ShapeBound {
  Vector3 center_B = Vector3::Zero();      // m
  Vector3 halfExtent_B = Vector3::Zero();  // m (box, mesh)
};

// (shape) => its precomputed bound
ShapeBound shapeBound(const Shape& shape);
// (shape, its bound, X_WB) => the tight world box: box and mesh c_W +- |R_WB| h; sphere
// p +- r; cylinder and capsule from the axis a_W: (L/2)|a_i| + r sqrt(1 - a_i^2) (capsule:
// (L/2)|a_i| + r); a half-space bounded on the side its normal points to when the normal is a
// world axis, otherwise +-kWorldExtent
Aabb worldAabb(const Shape& shape, const ShapeBound& bound, const Transform& X_WB);
// (p0_W, p1_W, radius) => the box of a capsule between two points: min/max of the ends -+ r
Aabb segmentAabb(const Vector3& p0_W, const Vector3& p1_W, double radius);

}  // namespace yardsim::collision
