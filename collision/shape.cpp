#include "collision/shape.hpp"

#include <cmath>

namespace yardsim::collision {

Shape Shape::box(const Vector3& size) {
  Shape s;
  s.kind = ShapeKind::kBox;
  s.size = size;
  return s;
}

Shape Shape::sphere(double radius) {
  Shape s;
  s.kind = ShapeKind::kSphere;
  s.radius = radius;
  return s;
}

Shape Shape::cylinder(double radius, double length) {
  Shape s;
  s.kind = ShapeKind::kCylinder;
  s.radius = radius;
  s.length = length;
  return s;
}

Shape Shape::capsule(double radius, double length) {
  Shape s;
  s.kind = ShapeKind::kCapsule;
  s.radius = radius;
  s.length = length;
  return s;
}

Shape Shape::halfSpace(const Vector3& normal, double offset) {
  Shape s;
  s.kind = ShapeKind::kHalfSpace;
  s.normal = normal;
  s.offset = offset;
  return s;
}

Shape Shape::triangleMesh(std::shared_ptr<const forces::TriangleMesh> mesh) {
  Shape s;
  s.kind = ShapeKind::kMesh;
  s.mesh = std::move(mesh);
  return s;
}

namespace {

// (what, value, name) => CollisionError unless value is finite and > 0
void checkPositive(const char* what, double value, const std::string& name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw CollisionError("collision: object '" + name + "': " + what +
                         " must be positive and finite, got " + std::to_string(value));
  }
}

}  // namespace

// (shape, name) => throws on a size it cannot use
void checkShape(const Shape& shape, const std::string& name) {
  switch (shape.kind) {
    case ShapeKind::kBox:
      for (int i = 0; i < 3; ++i) checkPositive("box size", shape.size[i], name);
      break;
    case ShapeKind::kSphere:
      checkPositive("sphere radius", shape.radius, name);
      break;
    case ShapeKind::kCylinder:
      checkPositive("cylinder radius", shape.radius, name);
      checkPositive("cylinder length", shape.length, name);
      break;
    case ShapeKind::kCapsule:
      checkPositive("capsule radius", shape.radius, name);
      if (!(shape.length >= 0.0) || !std::isfinite(shape.length)) {
        throw CollisionError("collision: object '" + name +
                             "': capsule length must be >= 0 and finite");
      }
      break;
    case ShapeKind::kHalfSpace:
      if (!shape.normal.allFinite() || shape.normal.norm() < 1e-12 ||
          !std::isfinite(shape.offset)) {
        throw CollisionError("collision: object '" + name +
                             "': a half-space needs a finite non-zero normal and a finite offset");
      }
      break;
    case ShapeKind::kMesh: {
      if (!shape.mesh || shape.mesh->triangles.empty()) {
        throw CollisionError("collision: object '" + name + "': empty triangle mesh");
      }
      const int nv = static_cast<int>(shape.mesh->vertices.size());
      for (const auto& t : shape.mesh->triangles) {
        for (int v : t) {
          if (v < 0 || v >= nv) {
            throw CollisionError("collision: object '" + name + "': mesh '" + shape.mesh->source +
                                 "' has a vertex index out of range");
          }
        }
      }
      for (const auto& v : shape.mesh->vertices) {
        if (!v.allFinite()) {
          throw CollisionError("collision: object '" + name + "': mesh '" + shape.mesh->source +
                               "' has a non-finite vertex");
        }
      }
      break;
    }
  }
}

// (shape) => centre and half extents (a mesh: of its vertices' box; a box: 0 and size / 2)
ShapeBound shapeBound(const Shape& shape) {
  ShapeBound b;
  if (shape.kind == ShapeKind::kBox) {
    b.halfExtent_B = 0.5 * shape.size;
  } else if (shape.kind == ShapeKind::kMesh && shape.mesh && !shape.mesh->vertices.empty()) {
    Vector3 lo = shape.mesh->vertices.front(), hi = lo;
    for (const auto& v : shape.mesh->vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    b.center_B = 0.5 * (lo + hi);
    b.halfExtent_B = 0.5 * (hi - lo);
  }
  return b;
}

// (shape, bound, X_WB) => tight world box
Aabb worldAabb(const Shape& shape, const ShapeBound& bound, const Transform& X_WB) {
  const Vector3 c = X_WB.actPoint(bound.center_B);
  Vector3 e = Vector3::Zero();
  switch (shape.kind) {
    case ShapeKind::kBox:
    case ShapeKind::kMesh:
      e = X_WB.R.cwiseAbs() * bound.halfExtent_B;
      break;
    case ShapeKind::kSphere:
      e = Vector3::Constant(shape.radius);
      break;
    case ShapeKind::kCylinder: {
      const Vector3 a = X_WB.R.col(2);
      for (int i = 0; i < 3; ++i) {
        e[i] = 0.5 * shape.length * std::abs(a[i]) +
               shape.radius * std::sqrt(std::max(0.0, 1.0 - a[i] * a[i]));
      }
      break;
    }
    case ShapeKind::kCapsule:
      e = 0.5 * shape.length * X_WB.R.col(2).cwiseAbs() + Vector3::Constant(shape.radius);
      break;
    case ShapeKind::kHalfSpace: {
      const Vector3 n = X_WB.R * shape.normal.normalized();
      const double d = shape.offset / shape.normal.norm() + n.dot(X_WB.p);
      Aabb box{Vector3::Constant(-kWorldExtent), Vector3::Constant(kWorldExtent)};
      for (int i = 0; i < 3; ++i) {
        if (std::abs(std::abs(n[i]) - 1.0) < 1e-12) {  // n = +-e_i: the solid is n_i x_i <= d
          if (n[i] > 0.0)
            box.max[i] = d;
          else
            box.min[i] = -d;
        }
      }
      return box;
    }
  }
  return {c - e, c + e};
}

// (p0, p1, r) => box of the capsule
Aabb segmentAabb(const Vector3& p0_W, const Vector3& p1_W, double radius) {
  const Vector3 r = Vector3::Constant(radius);
  return {p0_W.cwiseMin(p1_W) - r, p0_W.cwiseMax(p1_W) + r};
}

}  // namespace yardsim::collision
