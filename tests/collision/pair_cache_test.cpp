// The pair cache: its own record / reuse rules (versions, contact limit, growth past its first
// size), and a world reusing the contacts of unmoved pairs giving exactly what a world without
// the cache gives, step after step, while skipping most narrow phases.
#include "collision/pair_cache.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <random>
#include <tuple>

#include "forces/geometry/primitive_meshes.hpp"

using namespace yardsim::collision;

namespace {

Contact contactAt(ObjectId a, ObjectId b, double x) {
  Contact c;
  c.a = a;
  c.b = b;
  c.p_W = Vector3(x, 0, 0);
  c.depth = x;
  return c;
}

// (contacts) => sorted by pair, then point, for comparing two worlds
std::vector<Contact> sortedContacts(std::vector<Contact> v) {
  std::sort(v.begin(), v.end(), [](const Contact& l, const Contact& r) {
    return std::tie(l.a, l.b, l.p_W.x(), l.p_W.y(), l.p_W.z()) <
           std::tie(r.a, r.b, r.p_W.x(), r.p_W.y(), r.p_W.z());
  });
  return v;
}

}  // namespace

TEST_CASE("collision: pair cache reuses a pair only at the same versions and limit") {
  PairCache cache;
  std::vector<Contact> contacts;
  cache.begin(contacts);
  for (int i = 0; i < 3000; ++i) {  // past the first table size
    contacts.push_back(contactAt(i, i + 1, i));
    cache.record(i, i + 1, 7, 9, 4, contacts.size() - 1, 1);
  }
  cache.begin(contacts);  // the next query
  REQUIRE(contacts.empty());
  CHECK(cache.reuse(10, 11, 7, 9, 4, contacts));
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].p_W.x() == 10.0);
  CHECK(cache.reuse(2999, 3000, 7, 9, 4, contacts));
  CHECK_FALSE(cache.reuse(12, 13, 8, 9, 4, contacts));  // a moved
  CHECK_FALSE(cache.reuse(12, 13, 7, 9, 1, contacts));  // another limit
  CHECK_FALSE(cache.reuse(5, 7, 7, 9, 4, contacts));    // never seen
  CHECK(contacts.size() == 2);
  cache.begin(contacts);  // only what was reused or recorded in the last query survives
  CHECK(cache.reuse(10, 11, 7, 9, 4, contacts));
  CHECK_FALSE(cache.reuse(12, 13, 7, 9, 4, contacts));
}

TEST_CASE("collision: reusing unmoved pairs gives the contacts of a world without the cache") {
  auto mesh = std::make_shared<yardsim::forces::TriangleMesh>(
      yardsim::forces::boxMesh(Vector3(3, 2, 1), 2, 2, 2));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 25.0);
  std::normal_distribution<double> g;
  std::vector<Transform> poses;
  for (int i = 0; i < 300; ++i) {
    Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
    q.normalize();
    poses.push_back(Transform{q.toRotationMatrix(), Vector3(u(rng), u(rng), u(rng))});
  }
  CollisionWorld cached(WorldOptions{true, false, true}), plain(WorldOptions{true, false, false});
  for (CollisionWorld* w : {&cached, &plain}) {
    for (int i = 0; i < 300; ++i) {
      const Shape s = i % 3 == 0   ? Shape::box(Vector3(3, 2, 1))
                      : i % 3 == 1 ? Shape::capsule(0.4, 2.0)
                                   : Shape::triangleMesh(mesh);
      w->add(s, poses[static_cast<std::size_t>(i)]);
    }
  }
  std::uniform_int_distribution<int> pick(0, 299);
  int reused = 0;
  for (int step = 0; step < 12; ++step) {
    for (int k = 0; k < 30; ++k) {
      const int i = pick(rng);
      poses[static_cast<std::size_t>(i)].p += Vector3(0.3 * g(rng), 0.3 * g(rng), 0.3 * g(rng));
      cached.setPose(i, poses[static_cast<std::size_t>(i)]);
      plain.setPose(i, poses[static_cast<std::size_t>(i)]);
    }
    const int limit = step == 6 ? 1 : 4;  // a change of limit recomputes everything once
    const auto a = sortedContacts(cached.contacts(limit));
    const auto b = sortedContacts(plain.contacts(limit));
    INFO("step " << step);
    REQUIRE(a.size() == b.size());
    CHECK(a.size() > 20);
    for (std::size_t j = 0; j < a.size(); ++j) {
      CHECK(a[j].a == b[j].a);
      CHECK(a[j].b == b[j].b);
      CHECK(a[j].p_W == b[j].p_W);
      CHECK(a[j].n_W == b[j].n_W);
      CHECK(a[j].depth == b[j].depth);
    }
    const QueryStats& s = cached.stats();
    CHECK(s.narrowPhaseCalls + s.reusedPairs == s.candidatePairs);
    if (step == 0 || step == 6 || step == 7)
      CHECK(s.reusedPairs == 0);
    else
      CHECK(s.reusedPairs > s.narrowPhaseCalls);
    reused += s.reusedPairs;
  }
  CHECK(reused > 0);
}
