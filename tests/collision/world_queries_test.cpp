// Queries against hand computation: sphere-box and capsule-box distances with their witness
// points, a rope's clearance over a box edge (and the watch querying only nearby pairs), contact
// normals and depths, mesh boxes against primitive boxes, and the kernel driving the contact law
// (a sphere dropped on the ground, a box resting on it).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "collision/collision_world.hpp"
#include "dynamics/rotation.hpp"
#include "forces/contact_law.hpp"
#include "forces/geometry/primitive_meshes.hpp"

using namespace yardsim::collision;
using yardsim::dynamics::axisRotation;
using yardsim::dynamics::Matrix3;

namespace {

bool near(const Vector3& a, const Vector3& b, double tol) {
  return (a - b).norm() < tol;
}

}  // namespace

TEST_CASE("collision: sphere-box distances and witness points against hand computation") {
  CollisionWorld w;
  const ObjectId box = w.add(Shape::box(Vector3(2, 2, 2)), Transform::identity());
  const ObjectId s = w.add(Shape::sphere(0.5), Transform::translation(Vector3(2.0, 0.5, 0.3)));
  Distance d = w.distance(box, s);
  CHECK(d.distance == Approx(0.5).margin(1e-6));
  CHECK(near(d.pa_W, Vector3(1.0, 0.5, 0.3), 1e-5));
  CHECK(near(d.pb_W, Vector3(1.5, 0.5, 0.3), 1e-5));
  w.setPose(s, Transform::translation(Vector3(3, 3, 3)));  // off the corner (1, 1, 1)
  d = w.distance(s, box);
  CHECK(d.distance == Approx(2.0 * std::sqrt(3.0) - 0.5).margin(1e-6));
  CHECK(near(d.pb_W, Vector3(1, 1, 1), 1e-5));
  // the box turned 45 deg about z: its vertical edge at x = sqrt(2) faces the sphere
  w.setPose(box, Transform::rotation(axisRotation(Vector3::UnitZ(), M_PI / 4)));
  w.setPose(s, Transform::translation(Vector3(3, 0, 0)));
  CHECK(w.distance(box, s).distance == Approx(3.0 - std::sqrt(2.0) - 0.5).margin(1e-6));
}

TEST_CASE("collision: capsule-box distances against hand computation") {
  CollisionWorld w;
  const ObjectId box = w.add(Shape::box(Vector3(2, 2, 2)), Transform::identity());
  // a capsule along x, 2 m straight part, radius 0.2, 3 m above the centre: 3 - 1 - 0.2
  const ObjectId c = w.add(Shape::capsule(0.2, 2.0),
                           Transform{axisRotation(Vector3::UnitY(), M_PI / 2), Vector3(0, 0, 3)});
  CHECK(w.distance(box, c).distance == Approx(1.8).margin(1e-6));
  // a segment pointing away from the edge x = z = 1: its end (2, 0, 2) is closest, sqrt(2) - r
  const ObjectId r1 = w.addSegment(Vector3(2, 0, 2), Vector3(4, 0, 4), 0.2);
  CHECK(w.distance(box, r1).distance == Approx(std::sqrt(2.0) - 0.1).margin(1e-6));
  // a segment parallel to that edge, beyond both ends of it: the edge line, sqrt(2) - r
  const ObjectId r2 = w.addSegment(Vector3(2, -5, 2), Vector3(2, 5, 2), 0.2);
  const Distance d = w.distance(r2, box);
  CHECK(d.distance == Approx(std::sqrt(2.0) - 0.1).margin(1e-6));
  CHECK(std::abs(d.pb_W.x() - 1.0) < 1e-5);
  CHECK(std::abs(d.pb_W.z() - 1.0) < 1e-5);
  // moving the segment updates the capsule: 0.5 m above the top face
  w.setSegment(r2, Vector3(-0.5, -5, 1.6), Vector3(0.5, 5, 1.6));
  CHECK(w.distance(r2, box).distance == Approx(0.5).margin(1e-6));
}

TEST_CASE("collision: rope clearance over a box edge, querying only the pairs within the margin") {
  CollisionWorld w;
  const ObjectId box = w.add(Shape::box(Vector3(2, 2, 2)), Transform::identity(), {"block", {1}});
  for (int i = 0; i < 50; ++i) {  // far away, must not be queried
    w.add(Shape::box(Vector3(2, 2, 2)), Transform::translation(Vector3(100.0 + 3 * i, 0, 0)));
  }
  // the rope runs at s = 0.3 from the edge E = (1, 0, 1) along the bisector n, in the plane
  // y = 0, at right angles to n: the edge is its closest point, clearance s - d/2
  const Vector3 E(1, 0, 1), n = Vector3(1, 0, 1).normalized(), t = Vector3(1, 0, -1).normalized();
  const double s = 0.3, dia = 0.04;
  const auto rope =
      w.addRope({E + s * n - 3 * t, E + s * n, E + s * n + 3 * t}, dia, {"hoist", {2}});
  const int watch = w.addWatch(rope, {box}, 1.0);
  const Clearance& c = w.clearance(watch);
  CHECK(c.withinMargin);
  CHECK(c.closest.distance == Approx(s - 0.5 * dia).margin(1e-6));
  // the rope-box distance is segmentBoxDistance: its minimiser along the segment is found to
  // about sqrt(machine epsilon) of the segment (the distance is quadratic near it)
  CHECK((c.closest.a == rope[0] || c.closest.a == rope[1]));  // both end at the apex
  CHECK(c.closest.b == box);
  CHECK(near(c.closest.pb_W, E, 1e-6));
  CHECK(near(c.closest.pa_W, E + (s - 0.5 * dia) * n, 1e-6));
  CHECK(c.pairsQueried == 2);  // two segments x one block, none of the 50 far boxes
  // a margin below the clearance whose grown boxes still overlap (the boxes of the diagonal
  // segments reach 0.19 m from the block's): queried, but nothing within the margin
  const int close = w.addWatch(rope, {box}, 0.25);
  CHECK_FALSE(w.clearance(close).withinMargin);
  CHECK(w.clearance(close).pairsQueried == 2);
  CHECK(w.clearance(close).closest.distance == 0.25);
  // a margin whose grown boxes stay apart: nothing is queried at all
  const int tight = w.addWatch(rope, {box}, 0.15);
  CHECK_FALSE(w.clearance(tight).withinMargin);
  CHECK(w.clearance(tight).pairsQueried == 0);
  // the rope attached to the block: the filter removes the pair from the watch too
  w.filter().ignoreOwners(1, 2);
  CHECK_FALSE(w.clearance(watch).withinMargin);
}

TEST_CASE("collision: contact normals point from the lower id to the higher, depth by hand") {
  for (bool boxFirst : {true, false}) {
    CollisionWorld w;
    const Transform Xs = Transform::translation(Vector3(0.2, -0.1, 1.9));  // 0.1 into the top
    ObjectId box, sph;
    if (boxFirst) {
      box = w.add(Shape::box(Vector3(2, 2, 2)), Transform::identity());
      sph = w.add(Shape::sphere(1.0), Xs);
    } else {
      sph = w.add(Shape::sphere(1.0), Xs);
      box = w.add(Shape::box(Vector3(2, 2, 2)), Transform::identity());
    }
    const auto& cs = w.contacts();
    REQUIRE(cs.size() == 1);
    const Contact& c = cs[0];
    CHECK(c.a == std::min(box, sph));
    CHECK(c.depth == Approx(0.1).margin(1e-6));
    const Vector3 boxToSphere = Vector3::UnitZ();
    CHECK(near(c.n_W, boxFirst ? boxToSphere : Vector3(-boxToSphere), 1e-6));
    CHECK(std::abs(c.p_W.x() - 0.2) < 1e-6);
    CHECK(c.p_W.z() >= 0.9 - 1e-9);
    CHECK(c.p_W.z() <= 1.0 + 1e-9);
    CHECK(w.anyInterference());
  }
}

TEST_CASE("collision: boxes from meshes agree with primitive boxes: interference and distance") {
  const Vector3 size(2.0, 1.0, 0.5);
  auto mesh =
      std::make_shared<yardsim::forces::TriangleMesh>(yardsim::forces::boxMesh(size, 2, 2, 2));
  CollisionWorld prim, meshes;
  const ObjectId a = prim.add(Shape::box(size), Transform::identity());
  const ObjectId b = prim.add(Shape::box(size), Transform::identity());
  meshes.add(Shape::triangleMesh(mesh), Transform::identity());
  meshes.add(Shape::triangleMesh(mesh), Transform::identity());
  std::mt19937 rng(21);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  int hits = 0, misses = 0;
  for (int k = 0; k < 300; ++k) {
    Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
    q.normalize();
    const Transform X{q.toRotationMatrix(), Vector3(u(rng), u(rng), u(rng))};
    prim.setPose(b, X);
    meshes.setPose(b, X);
    const bool hit = prim.intersects(a, b);
    CHECK(meshes.intersects(a, b) == hit);
    if (hit) {
      ++hits;
      // FCL's mesh-mesh contacts are triangle-pair intersections: found, with unit normals (their
      // points and depths are per triangle pair, not the solids' penetration: docs/collision.md)
      const auto& cs = meshes.contacts(8);
      CHECK(!cs.empty());
      for (const Contact& c : cs) CHECK(c.n_W.norm() == Approx(1.0));
    } else {
      ++misses;
      CHECK(meshes.distance(a, b).distance == Approx(prim.distance(a, b).distance).margin(1e-5));
    }
  }
  CHECK(hits > 30);
  CHECK(misses > 30);
}

TEST_CASE("collision: a mesh block on the ground: the same deepest contact as the primitive box") {
  const Vector3 size(4.0, 2.0, 1.0);
  auto mesh =
      std::make_shared<yardsim::forces::TriangleMesh>(yardsim::forces::boxMesh(size, 3, 3, 3));
  for (bool useMesh : {false, true}) {
    for (bool groundFirst : {true, false}) {
      CollisionWorld w;
      const Shape s = useMesh ? Shape::triangleMesh(mesh) : Shape::box(size);
      // tilted 10 deg about x and lowered: the deepest edge is 0.03 m below the ground
      const Matrix3 R = axisRotation(Vector3::UnitX(), 10.0 * M_PI / 180.0);
      const double lowest = (R.cwiseAbs() * (0.5 * size)).z();
      const Shape ground = Shape::halfSpace(Vector3::UnitZ(), 0.0);
      if (groundFirst) w.add(ground, Transform::identity());
      w.add(s, Transform{R, Vector3(0, 0, lowest - 0.03)});
      if (!groundFirst) w.add(ground, Transform::identity());
      const Vector3 up = groundFirst ? Vector3::UnitZ() : Vector3(-Vector3::UnitZ());
      double depth = 0.0;
      const auto& cs = w.contacts(16);
      for (const Contact& c : cs) {
        depth = std::max(depth, c.depth);
        CHECK(near(c.n_W, up, 1e-9));  // from the lower id to the higher
        CHECK(c.p_W.z() < 0.0);
      }
      INFO("mesh " << useMesh << ", ground first " << groundFirst);
      CHECK(depth == Approx(0.03).margin(1e-9));
      if (useMesh) CHECK(cs.size() == 4);  // the 4 mesh vertices of the lowest edge (3 x 3 grid)
    }
  }
}

TEST_CASE("collision: the kernel drives the Hunt-Crossley law: a sphere dropped on the ground") {
  using namespace yardsim::forces;
  CollisionWorld w;
  w.add(Shape::halfSpace(Vector3::UnitZ(), 0.0), Transform::identity(), {"ground", {}});
  const ObjectId ball = w.add(Shape::sphere(0.5), Transform::translation(Vector3(0, 0, 0.5)));
  const double m = 100.0, v0 = 2.0, k = 1e8, a = 0.4;
  const NormalLaw law{NormalLawKind::kHuntCrossley, k, k * a / v0, 1.5};
  // (z, vz) => acceleration, the depth from the kernel's contact (no gravity: a free impact)
  auto acc = [&](double z, double vz) {
    w.setPose(ball, Transform::translation(Vector3(0, 0, z)));
    const auto& cs = w.contacts(1);
    if (cs.empty()) return 0.0;
    return normalForce(law, cs[0].depth, -vz) / m;
  };
  double z = 0.5, v = -v0;
  const double h = 2e-6;
  while (true) {
    const double k1v = acc(z, v), k1z = v;
    const double k2v = acc(z + 0.5 * h * k1z, v + 0.5 * h * k1v), k2z = v + 0.5 * h * k1v;
    const double k3v = acc(z + 0.5 * h * k2z, v + 0.5 * h * k2v), k3z = v + 0.5 * h * k2v;
    const double k4v = acc(z + h * k3z, v + h * k3v), k4z = v + h * k3v;
    z += h / 6 * (k1z + 2 * k2z + 2 * k3z + k4z);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (z > 0.5) break;
  }
  CHECK(v / v0 == Approx(huntCrossleyRestitution(a)).margin(1e-3));
}

TEST_CASE(
    "collision: a box resting on the ground through the kernel carries its weight for 100 s") {
  using namespace yardsim::forces;
  CollisionWorld w;
  w.add(Shape::halfSpace(Vector3::UnitZ(), 0.0), Transform::identity(), {"ground", {}});
  const ObjectId block =
      w.add(Shape::box(Vector3(4, 2, 1)), Transform::translation(Vector3(0, 0, 0.5)));
  const double m = 5000.0, g = 9.81, k = 1e8;
  const NormalLaw law{NormalLawKind::kLinear, k, 2.0 * 0.8 * std::sqrt(k * m), 1.0};
  // (z, vz) => the deepest contact's depth, and the force of the law on it
  auto force = [&](double z, double vz) {
    w.setPose(block, Transform::translation(Vector3(0, 0, z)));
    double depth = 0.0;
    for (const Contact& c : w.contacts(4)) depth = std::max(depth, c.depth);
    return normalForce(law, depth, -vz);
  };
  double z = 0.5, v = 0.0, z50 = 0.0;
  const double h = 1e-3;
  for (int i = 1; i <= 100'000; ++i) {  // semi-implicit Euler is enough at omega h = 0.14
    v += h * (force(z, v) / m - g);
    z += h * v;
    if (i == 50'000) z50 = z;
  }
  CHECK(force(z, v) == Approx(m * g).epsilon(1e-9));
  CHECK(0.5 - z == Approx(m * g / k).epsilon(1e-6));
  CHECK(std::abs(z - z50) < 1e-12);
}
