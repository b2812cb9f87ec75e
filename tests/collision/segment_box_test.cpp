// Segment-box signed distance against hand computation and against brute force (dense sampling
// of the segment with the point-box distance), outside and through the box; and capsule-box
// distances of the world against brute force on random poses, where FCL's GJK fails.
#include "collision/segment_box.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "collision/collision_world.hpp"

using namespace yardsim::collision;
using yardsim::dynamics::Vector3;

namespace {

// (p0, p1, h, samples) => min over samples of the box signed distance (independent of the search)
double brute(const Vector3& p0, const Vector3& p1, const Vector3& h, int n) {
  double best = 1e300;
  for (int i = 0; i <= n; ++i) {
    const Vector3 p = p0 + (p1 - p0) * (static_cast<double>(i) / n);
    const Vector3 q = p.cwiseAbs() - h;
    const double outside = q.cwiseMax(0.0).norm();
    best = std::min(best, outside > 0.0 ? outside : q.maxCoeff());
  }
  return best;
}

}  // namespace

TEST_CASE("collision: segment-box distance by hand") {
  const Vector3 h(1, 1, 1);
  // over the top face, parallel: 2 - 1
  CHECK(segmentBoxDistance(Vector3(-5, 0, 2), Vector3(5, 0, 2), h).distance == Approx(1.0));
  // off the edge x = z = 1, parallel to it: sqrt(2)
  auto r = segmentBoxDistance(Vector3(2, -5, 2), Vector3(2, 5, 2), h);
  CHECK(r.distance == Approx(std::sqrt(2.0)));
  CHECK(r.onBox.x() == Approx(1.0));
  CHECK(r.onBox.z() == Approx(1.0));
  // an end nearest the corner: (3, 3, 3) -> (1, 1, 1)
  r = segmentBoxDistance(Vector3(3, 3, 3), Vector3(9, 4, 5), h);
  CHECK(r.distance == Approx(2.0 * std::sqrt(3.0)));
  CHECK(r.s < 1e-12);
  // through the centre along x: deepest point at the centre, -1
  r = segmentBoxDistance(Vector3(-3, 0, 0), Vector3(3, 0, 0), Vector3(2, 1, 1.5));
  CHECK(r.distance == Approx(-1.0));
  // any point of |x| <= 1 is deepest; its nearest face is 1 m away
  CHECK((r.onBox - r.onSegment).norm() == Approx(1.0));
  CHECK(std::abs(boxSignedDistance(r.onBox, Vector3(2, 1, 1.5))) < 1e-12);
}

TEST_CASE("collision: segment-box distance agrees with brute force on random segments") {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  const Vector3 h(2.0, 1.0, 0.5);
  for (int k = 0; k < 300; ++k) {
    const Vector3 p0(u(rng), u(rng), u(rng)), p1(u(rng), u(rng), u(rng));
    const auto r = segmentBoxDistance(p0, p1, h);
    const double b = brute(p0, p1, h, 20000);
    // brute force samples every 1/20000 of <= 14 m: it may miss the minimum by 7e-4 m at most,
    // and only from above
    CHECK(r.distance <= b + 1e-12);
    CHECK(r.distance >= b - 1e-3);
    CHECK(boxSignedDistance(r.onSegment, h) == Approx(r.distance).margin(1e-12));
    CHECK(std::abs(boxSignedDistance(r.onBox, h)) < 1e-12);  // on the surface
  }
}

TEST_CASE("collision: the world's capsule-box distance against brute force where GJK fails") {
  // a pose set in which libccd returned 1.998 m for 1.186 m (bench_collision's rope query)
  CollisionWorld w;
  const Transform X_box = Transform::rotation(Eigen::AngleAxisd(0.35, Vector3::UnitZ()).matrix());
  const ObjectId box = w.add(Shape::box(Vector3(10, 8, 4)), X_box);
  const ObjectId seg = w.addSegment(Vector3(-6, 0, 3), Vector3(6, 1, 6), 0.05);
  double t = 0.0;
  for (int i = 0; i < 2000; ++i, t += 280.78) {  // far apart in the sway's phase
    const Vector3 sway(0.5 * std::sin(t), 0.5 * std::cos(1.3 * t), 0.0);
    const Vector3 p0 = Vector3(-6, 0, 3) + sway, p1 = Vector3(6, 1, 6) + 0.3 * sway;
    w.setSegment(seg, p0, p1);
    const Distance d = w.distance(box, seg);
    const double b =
        brute(X_box.invActPoint(p0), X_box.invActPoint(p1), Vector3(5, 4, 2), 20000) - 0.025;
    CHECK(d.distance <= b + 1e-12);
    CHECK(d.distance >= b - 1e-3);
    CHECK((d.pa_W - d.pb_W).norm() == Approx(d.distance).margin(1e-9));  // witness gap = distance
  }
}

TEST_CASE(
    "collision: a rope pressed onto a block: one exact contact, consistent with the distance") {
  CollisionWorld w;
  const ObjectId box = w.add(Shape::box(Vector3(2, 2, 2)), Transform::identity());
  // radius 0.05, axis 1.03 m above the centre: 0.02 m into the top face
  const ObjectId seg = w.addSegment(Vector3(-0.5, 0.2, 1.03), Vector3(0.5, 0.2, 1.03), 0.1);
  const auto& cs = w.contacts(4);
  REQUIRE(cs.size() == 1);
  CHECK(cs[0].a == box);
  CHECK(cs[0].depth == Approx(0.02).margin(1e-12));
  CHECK((cs[0].n_W - Vector3::UnitZ()).norm() < 1e-12);  // from the block (a) to the rope (b)
  CHECK(cs[0].p_W.z() == Approx(0.99).margin(1e-12));
  CHECK(cs[0].p_W.y() == Approx(0.2).margin(1e-12));
  CHECK(w.anyInterference());
  // random poses around the block: intersects, contacts and the signed distance agree
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  int hits = 0;
  for (int k = 0; k < 500; ++k) {
    const Vector3 p0(u(rng), u(rng), u(rng)), p1(u(rng), u(rng), u(rng));
    w.setSegment(seg, p0, p1);
    const double d = w.distance(seg, box).distance;
    CHECK(w.intersects(box, seg) == (d < 0.0));
    const auto& c = w.contacts(4);
    CHECK(c.size() == (d < 0.0 ? 1u : 0u));
    if (!c.empty()) {
      ++hits;
      CHECK(c[0].depth == Approx(-d).margin(1e-12));
    }
  }
  CHECK(hits > 50);
}
