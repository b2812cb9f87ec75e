// After warm-up the step loop's own queries allocate nothing (every heap block counted): setPose,
// setSegment, candidatePairs, a clearance watch of a rope over primitive blocks and the rope-box
// distance. What FCL allocates inside is counted and reported: update() when FCL rebuilds its
// tree top-down (balanceTopdown collects the leaves in a vector), a rope against a mesh block
// (FCL's mesh-shape distance allocates the capsule's bound vertices), and contacts. A collision
// set of blocks on the ground (its own ground contacts, no FCL narrow phase) allocates nothing as
// a force provider, nor in its channels and event function.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "collision/collision_set.hpp"
#include "collision/collision_world.hpp"
#include "dynamics/configuration.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/model_builder.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "support/allocation_counter.hpp"

using namespace yardsim::collision;
using yardsim::testing::allocationCount;

namespace {

struct Scene {
  CollisionWorld world;
  std::vector<ObjectId> boxes, rope;
  int watch = -1;
  int meshWatch = -1;
};

// () => a row of blocks resting on the ground with a rope over them and a watch
Scene makeScene() {
  Scene s;
  auto mesh = std::make_shared<yardsim::forces::TriangleMesh>(
      yardsim::forces::boxMesh(Vector3(2, 2, 2), 2, 2, 2));
  s.world.add(Shape::halfSpace(Vector3::UnitZ(), 0.0), Transform::identity(), {"ground", {0}});
  for (int i = 0; i < 60; ++i) {
    const Transform X = Transform::translation(Vector3(3.0 * i, 0, 0.999));
    s.boxes.push_back(
        s.world.add(i % 4 == 3 ? Shape::triangleMesh(mesh) : Shape::box(Vector3(2, 2, 2)), X,
                    {"block", {i + 1}}));
  }
  std::vector<Vector3> path;
  for (int i = 0; i <= 30; ++i) path.push_back(Vector3(6.0 * i, 0.0, 2.3));
  s.rope = s.world.addRope(path, 0.05, {"rope", {1000}});
  std::vector<ObjectId> primitive;  // the blocks that are boxes
  for (std::size_t i = 0; i < s.boxes.size(); ++i)
    if (i % 4 != 3) primitive.push_back(s.boxes[i]);
  s.watch = s.world.addWatch(s.rope, primitive, 1.0);
  s.meshWatch = s.world.addWatch(s.rope, {s.boxes[3], s.boxes[7]}, 1.0);
  return s;
}

// (scene, t) => blocks rock, the rope sways
void move(Scene& s, double t) {
  for (std::size_t i = 0; i < s.boxes.size(); i += 3) {
    const double a = 0.01 * std::sin(t + static_cast<double>(i));
    Transform X =
        Transform::translation(Vector3(3.0 * static_cast<double>(i), 0, 0.999 + 0.001 * a));
    X.R = Eigen::AngleAxisd(a, Vector3::UnitX()).matrix();
    s.world.setPose(s.boxes[i], X);
  }
  for (std::size_t i = 0; i < s.rope.size(); ++i) {
    const double d = 0.1 * std::sin(t);
    s.world.setSegment(s.rope[i], Vector3(6.0 * static_cast<double>(i), d, 2.3),
                       Vector3(6.0 * static_cast<double>(i + 1), d, 2.3));
  }
}

}  // namespace

TEST_CASE("collision: moving, the broad phase, watches and rope distances do not allocate") {
  Scene s = makeScene();
  for (int k = 0; k < 5; ++k) {  // warm-up: the scratch vectors reach their sizes
    move(s, 0.1 * k);
    s.world.candidatePairs();
    s.world.clearance(s.watch);
    s.world.distance(s.rope[3], s.boxes[4]);
  }
  std::size_t n[5] = {0, 0, 0, 0, 0};
  for (int k = 5; k < 50; ++k) {
    std::size_t c = allocationCount();
    move(s, 0.1 * k);
    n[0] += allocationCount() - c;
    c = allocationCount();
    s.world.update();
    n[1] += allocationCount() - c;
    c = allocationCount();
    const bool pairs = !s.world.candidatePairs().empty();
    n[2] += allocationCount() - c;
    c = allocationCount();
    const bool within = s.world.clearance(s.watch).withinMargin;
    n[3] += allocationCount() - c;
    c = allocationCount();
    const double d = s.world.distance(s.rope[3], s.boxes[4]).distance;
    n[4] += allocationCount() - c;
    CHECK(pairs);
    CHECK(within);
    CHECK(d > 0.0);
  }
  INFO("update() " << n[1] << " heap blocks in 45 steps");
  CHECK(n[0] == 0);
  CHECK(n[2] == 0);
  CHECK(n[3] == 0);
  CHECK(n[4] == 0);
  CHECK(n[1] < 45 * 20);  // FCL's occasional top-down rebuild, not one per moved object
  WARN("update(): " << n[1] << " heap blocks in 45 steps (FCL's top-down rebuilds)");
  // FCL's mesh-capsule distance allocates: reported, not ours to fix
  const std::size_t c = allocationCount();
  CHECK(s.world.clearance(s.meshWatch).withinMargin);
  WARN("a rope against two mesh blocks: " << allocationCount() - c << " heap blocks");
}

TEST_CASE("collision: contacts after warm-up (the figure FCL's narrow phase costs)") {
  Scene s = makeScene();
  for (int k = 0; k < 5; ++k) {
    move(s, 0.1 * k);
    s.world.contacts(4);
  }
  const std::size_t before = allocationCount();
  std::size_t contacts = 0;
  for (int k = 5; k < 15; ++k) {
    move(s, 0.1 * k);
    contacts += s.world.contacts(4).size();
  }
  const std::size_t perStep = (allocationCount() - before) / 10;
  WARN("contacts: " << contacts / 10 << " per step, heap blocks per step: " << perStep);
  CHECK(contacts >= 10 * 60);  // every block touches the ground
}

TEST_CASE("collision set: blocks on the ground, forces, channels and events do not allocate") {
  // (two 2 x 2 x 1 m blocks on free joints resting tilted on the ground, which the set computes
  // itself: its points at every box vertex below it) => at moving stages the contact forces,
  // energy, power and regime with the set's scratch, its channels (points, normal force, each
  // block's fz and point of application) with it, and its contact event function without one,
  // as mechanics/events.cpp calls it
  using namespace yardsim;
  dynamics::ModelBuilder b;
  for (const char* name : {"a", "b"})
    b.addBody(name, "world", dynamics::Joint::free(), {},
              dynamics::boxInertia(1e3, Vector3(2, 2, 1)));
  const dynamics::Model m = b.build();
  BodyCollisionSpec spec;
  spec.bodyCount = 3;
  spec.shapes.push_back({1, "a", Shape::box(Vector3(2, 2, 1))});
  spec.shapes.push_back({2, "b", Shape::box(Vector3(2, 2, 1))});
  spec.pairLaw = {0};
  spec.ground = true;
  Eigen::VectorXd q = dynamics::neutralConfiguration(m);
  q.segment<7>(0) << 0.0, 0.0, 0.49, std::cos(0.002), std::sin(0.002), 0.0, 0.0;
  q.segment<7>(7) << 5.0, 0.0, 0.495, std::cos(0.002), 0.0, std::sin(0.002), 0.0;
  const Eigen::VectorXd v = Eigen::VectorXd::Constant(m.nv, 0.1);
  dynamics::Data kin(m);
  dynamics::forwardKinematics(m, kin, q, v);
  const forces::ContactMaterial steel{{forces::NormalLawKind::kHuntCrossley, 1e8, 1e8, 1.5, 0.0},
                                      {0.3, 1e-3, forces::FrictionForm::kTanh}};
  const CollisionSet set("contacts", std::make_shared<BodyCollision>(spec, kin), {steel},
                         {{"a", 1}, {"b", 2}});
  const auto scratch = set.makeScratch();
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  double sink = 0.0;
  std::size_t before = 0;
  for (int k = 0; k <= 11; ++k) {
    // (after two rounds of set-up: the first move grows the world's lists of moved objects)
    if (k == 2) before = allocationCount();
    q[2] = 0.49 - 1e-4 * k;  // (a sinks, b stays)
    dynamics::forwardKinematics(m, kin, q, v);
    const forces::Stage s{0.01 * k, m, kin, q, v, scratch.get()};
    set.evaluate(s, f, tau);
    sink += set.potentialEnergy(s) + set.power(s) + static_cast<double>(set.regime(s));
    for (const forces::ProviderOutput& o : set.outputs()) sink += o.read(s);
    const forces::Stage alone{0.01 * k, m, kin, q, v};
    for (const forces::ProviderEvent& e : set.events()) sink += e.g(alone);
  }
  CHECK(allocationCount() == before);
  CHECK(static_cast<const forces::ContactForce::Scratch&>(*scratch).points.size() == 8);
  CHECK(f.worldFrame(1)[5] > 0.0);
  CHECK(f.worldFrame(2)[5] > 0.0);
  CHECK(std::isfinite(sink));
}
