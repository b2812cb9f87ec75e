// The checked builder: valid trees are ordered parent-first; bad input is refused with a message
// naming the body or loop.
#include <catch2/catch.hpp>

#include "dynamics/added_mass.hpp"
#include "dynamics/model_builder.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;
using Catch::Matchers::Contains;

namespace {
const SpatialInertia kUnit = boxInertia(1.0, Vector3(1, 1, 1));
}

TEST_CASE("bodies may be declared before their parents — the model orders parents first") {
  ModelBuilder b;
  b.addBody("tip", "arm", Joint::revolute(), Transform::translation(Vector3(1, 0, 0)), kUnit);
  b.addBody("arm", "base", Joint::revolute(), {}, kUnit);
  b.addBody("base", "world", Joint::free(), {}, kUnit, "base.stl");
  const Model m = b.build();
  REQUIRE(m.nbodies == 4);
  CHECK(m.names[1] == "base");
  CHECK(m.names[2] == "arm");
  CHECK(m.names[3] == "tip");
  CHECK(m.nq == 9);
  CHECK(m.nv == 8);
  CHECK(m.geometry[1] == "base.stl");
  for (int i = 1; i < m.nbodies; ++i) CHECK(m.parent[i] < i);
  CHECK(m.bodyIndex("tip") == 3);
  CHECK(m.bodyIndex("nope") == -1);
}

TEST_CASE("bad models are rejected naming the body") {
  auto build = [](auto&& edit) {
    ModelBuilder b;
    b.addBody("hull", "world", Joint::free(), {}, kUnit);
    edit(b);
    return b.build();
  };
  CHECK_THROWS_WITH(build([](ModelBuilder& b) { b.addBody("boom", "hull", Joint::revolute(), {}, makeInertia(0.0, Vector3::Zero(), Matrix3::Identity())); }),
                    Contains("body 'boom'") && Contains("mass must be positive"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) { b.addBody("boom", "hull", Joint::revolute(), {}, makeInertia(-2.0, Vector3::Zero(), Matrix3::Identity())); }),
                    Contains("body 'boom'") && Contains("mass"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) {
                      b.addBody("jib", "hull", Joint::revolute(), {}, makeInertia(1.0, Vector3::Zero(), Vector3(1, 1, -1).asDiagonal()));
                    }),
                    Contains("body 'jib'") && Contains("positive definite"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) {
                      b.addBody("jib", "hull", Joint::revolute(), {}, makeInertia(1.0, Vector3::Zero(), Vector3(1, 1, 3).asDiagonal()));
                    }),
                    Contains("body 'jib'") && Contains("triangle inequality"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) {
                      Matrix3 I = Matrix3::Identity();
                      I(0, 1) = 0.5;
                      b.addBody("jib", "hull", Joint::revolute(), {}, makeInertia(1.0, Vector3::Zero(), I));
                    }),
                    Contains("body 'jib'") && Contains("symmetric"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) { b.addBody("hook", "trolley", Joint::prismatic(), {}, kUnit); }),
                    Contains("body 'hook'") && Contains("unknown parent 'trolley'"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) { b.addBody("hull", "world", Joint::free(), {}, kUnit); }),
                    Contains("body 'hull'") && Contains("twice"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) {
                      b.addBody("a", "c", Joint::revolute(), {}, kUnit);
                      b.addBody("c", "a", Joint::revolute(), {}, kUnit);
                    }),
                    Contains("body 'a'") && Contains("cycle") && Contains("a -> c -> a"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) { b.addBody("self", "self", Joint::revolute(), {}, kUnit); }),
                    Contains("body 'self'") && Contains("own parent"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) { b.addBody("pin", "hull", Joint::revolute(Vector3::Zero()), {}, kUnit); }),
                    Contains("body 'pin'") && Contains("axis"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) {
                      b.addBody("cardan", "hull", Joint::universal(Vector3::UnitX(), Vector3(1, 1, 0)), {}, kUnit);
                    }),
                    Contains("body 'cardan'") && Contains("orthogonal"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) {
                      b.addBody("skewed", "hull", Joint::revolute(), Transform{2.0 * Matrix3::Identity(), Vector3::Zero()}, kUnit);
                    }),
                    Contains("body 'skewed'") && Contains("placement"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) { b.addLoop("stay", "hull", {}, "mast", {}, kPointConstraint); }),
                    Contains("loop 'stay'") && Contains("unknown body 'mast'"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) { b.addLoop("stay", "hull", {}, "hull", {}, kPointConstraint); }),
                    Contains("loop 'stay'"));
  CHECK_THROWS_WITH(build([](ModelBuilder& b) { b.addLoop("stay", "hull", {}, "world", {}, kRotX | kTransX); }),
                    Contains("loop 'stay'") && Contains("rotational"));
}

TEST_CASE("a bad added mass is rejected naming the body") {
  auto build = [](const std::string& body, const Matrix6& A) {
    ModelBuilder b;
    b.addBody("hull", "world", Joint::free(), {}, kUnit);
    b.setAddedMass(body, A);
    return b.build();
  };
  Matrix6 A = Matrix6::Identity();
  CHECK_NOTHROW(build("hull", A));
  CHECK(build("hull", A).hasAddedMass[1]);
  CHECK_FALSE(build("hull", Matrix6::Zero()).hasAddedMass[1]);
  CHECK_THROWS_WITH(build("pontoon", A), Contains("unknown body 'pontoon'"));
  A(0, 4) = 0.3;
  CHECK_THROWS_WITH(build("hull", A), Contains("body 'hull'") && Contains("not symmetric"));
  A(4, 0) = 0.3;
  CHECK_NOTHROW(build("hull", A));
  A(2, 2) = -0.5;
  CHECK_THROWS_WITH(build("hull", A), Contains("body 'hull'") && Contains("not positive semidefinite"));
  A(2, 2) = std::nan("");
  CHECK_THROWS_WITH(build("hull", A), Contains("body 'hull'") && Contains("non-finite"));
}

TEST_CASE("added mass given in the naval order about a point moves to [angular, linear] about the origin") {
  // a pure heave added mass a at R = (2, 0, -1): heave at the origin with a pitch lever arm
  Matrix6 naval = Matrix6::Zero();
  naval(2, 2) = 5.0;
  const Matrix6 A = addedMassAboutOrigin(naval, Vector3(2.0, 0.0, -1.0));
  // a unit upward velocity of the origin with no rotation: momentum 5 up, moment about the origin
  // R x (0, 0, 5) = (0, -10, 0)
  Vector6 v = Vector6::Zero();
  v[5] = 1.0;
  const Vector6 h = A * v;
  CHECK(h[5] == Approx(5.0));
  CHECK(h[1] == Approx(-10.0));
  CHECK(h[0] == Approx(0.0).margin(1e-14));
  CHECK((A - A.transpose()).norm() < 1e-14);
}

TEST_CASE("loops get consecutive rows") {
  ModelBuilder b;
  b.addBody("a", "world", Joint::revolute(), {}, kUnit);
  b.addBody("c", "a", Joint::revolute(), {}, kUnit);
  b.addLoop("l1", "c", {}, "world", {}, kAxisConstraint);
  b.addLoop("l2", "a", {}, "world", {}, kPlanarPointConstraint);
  const Model m = b.build();
  REQUIRE(m.loops.size() == 2);
  CHECK(m.loops[0].dim == 5);
  CHECK(m.loops[1].row == 5);
  CHECK(m.nc == 7);
}

TEST_CASE("joints about a coordinate axis are marked for the kernels' special case") {
  ModelBuilder b;
  b.addBody("x", "world", Joint::revolute(Vector3::UnitX()), {}, rodInertia(1.0, 1.0));
  b.addBody("y", "x", Joint::prismatic(Vector3(0.0, 2.0, 0.0)), {},
            rodInertia(1.0, 1.0));  // normalised
  b.addBody("negz", "y", Joint::revolute(-Vector3::UnitZ()), {}, rodInertia(1.0, 1.0));
  b.addBody("oblique", "negz", Joint::revolute(Vector3(1.0, 1.0, 0.0)), {}, rodInertia(1.0, 1.0));
  b.addBody("cyl", "oblique", Joint::cylindrical(Vector3::UnitZ()), {}, rodInertia(1.0, 1.0));
  b.addBody("z", "cyl", Joint::revolute(Vector3(-0.0, 0.0, 1.0)), {}, rodInertia(1.0, 1.0));
  const Model m = b.build();
  REQUIRE(m.jointAxis.size() == 7u);
  CHECK(m.jointAxis[static_cast<std::size_t>(m.bodyIndex("x"))] == 0);
  CHECK(m.jointAxis[static_cast<std::size_t>(m.bodyIndex("y"))] == 1);
  CHECK(m.jointAxis[static_cast<std::size_t>(m.bodyIndex("negz"))] == -1);
  CHECK(m.jointAxis[static_cast<std::size_t>(m.bodyIndex("oblique"))] == -1);
  CHECK(m.jointAxis[static_cast<std::size_t>(m.bodyIndex("cyl"))] == -1);
  CHECK(m.jointAxis[static_cast<std::size_t>(m.bodyIndex("z"))] == -1);  // -0: not the same doubles
}

TEST_CASE("diagonal body inertias are marked for the kernels' scaling shortcut") {
  ModelBuilder b;
  b.addBody("rod", "world", Joint::revolute(Vector3::UnitX()), {}, rodInertia(1.0, 1.0));
  Matrix3 J = Vector3(1.0, 2.0, 2.5).asDiagonal();
  J(0, 1) = J(1, 0) = 0.1;
  b.addBody("full", "rod", Joint::revolute(Vector3::UnitX()), {},
            makeInertia(1.0, Vector3::Zero(), J));
  const Model m = b.build();
  CHECK(m.inertiaDiagonal[static_cast<std::size_t>(m.bodyIndex("rod"))]);
  CHECK_FALSE(m.inertiaDiagonal[static_cast<std::size_t>(m.bodyIndex("full"))]);
}
