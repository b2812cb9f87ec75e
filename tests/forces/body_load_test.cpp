// The body load: piecewise-linear time series and events at exact times, a ramped world force
// moving a free body by F t^3 / (6 m T), a moment spinning it up at M t / I, the world and body
// frames, the power F . v + M . omega closing the kinetic-energy balance, refused input.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "dynamics/rotation.hpp"
#include "force_rig.hpp"
#include "forces/body_load.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;
using Catch::Matchers::Contains;
using dynamics::Matrix3;

namespace {

constexpr double kMass = 50e3;
const Vector3 kBox(6.0, 4.0, 2.0);

// A free box with its centre of mass at the body origin.
dynamics::Model freeBox() {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("block", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(kMass, kBox));
  return b.build();
}

}  // namespace

TEST_CASE("the time series is linear between samples and held outside with steps at equal times") {
  const dynamics::Model m = freeBox();
  BodyLoad load("wind", m, 1, Vector3::Zero(), LoadFrame::World);
  CHECK(load.at(3.0).force.isZero(0.0));
  load.setTable({{0.0, 0, 0, 0, 0, 0, 0},
                 {10.0, 100, -50, 0, 0, 0, 20},
                 {10.0, 0, 0, 0, 0, 0, 0},
                 {20.0, 0, 0, 10, 0, 0, 0}});
  CHECK(load.at(-5.0).force.isZero(0.0));
  CHECK((load.at(2.5).force - Vector3(25.0, -12.5, 0.0)).norm() < 1e-12);
  CHECK((load.at(2.5).moment - Vector3(0.0, 0.0, 5.0)).norm() < 1e-12);
  CHECK((load.at(9.999).force - Vector3(99.99, -49.995, 0.0)).norm() < 1e-9);
  CHECK(load.at(10.0).force.isZero(0.0));  // right-continuous at the step
  CHECK((load.at(15.0).force - Vector3(0.0, 0.0, 5.0)).norm() < 1e-12);
  CHECK((load.at(99.0).force - Vector3(0.0, 0.0, 10.0)).norm() < 1e-12);
  // the left limit at the step is the value before it; elsewhere both agree
  CHECK((load.at(10.0, true).force - Vector3(100.0, -50.0, 0.0)).norm() < 1e-12);
  CHECK(load.at(2.5, true).force == load.at(2.5).force);
  CHECK(load.at(0.0, true).force.isZero(0.0));
  // the breaks to land on: every sample time after t
  CHECK(load.nextBreak(-1.0) == 0.0);
  CHECK(load.nextBreak(0.0) == 10.0);
  CHECK(load.nextBreak(10.0) == 20.0);
  CHECK(std::isinf(load.nextBreak(20.0)));
}

TEST_CASE("an event sets the load from its exact time on and overrides the rest of the series") {
  const dynamics::Model m = freeBox();
  BodyLoad load("wind", m, 1, Vector3::Zero(), LoadFrame::World);
  load.set(5.0, Vector3(1.0, 2.0, 3.0), Vector3(0.0, 0.0, 4.0));
  CHECK(load.at(4.999).force.isZero(0.0));
  CHECK(load.at(5.0).force == Vector3(1.0, 2.0, 3.0));
  CHECK(load.at(1e6).moment == Vector3(0.0, 0.0, 4.0));
  load.setTable({{0.0, 0, 0, 0, 0, 0, 0}, {10.0, 10, 0, 0, 0, 0, 0}});
  load.set(4.0, Vector3(-1.0, 0.0, 0.0), Vector3::Zero());
  CHECK((load.at(2.0).force - Vector3(2.0, 0.0, 0.0)).norm() <
        1e-12);  // the ramp before 4 s is kept
  CHECK((load.at(3.999).force - Vector3(3.999, 0.0, 0.0)).norm() < 1e-12);
  CHECK(load.at(4.0).force == Vector3(-1.0, 0.0, 0.0));
  CHECK(load.at(8.0).force == Vector3(-1.0, 0.0, 0.0));  // the rest is overridden
}

TEST_CASE("a ramped world force at the centre of mass moves a free body by F t^3 / (6 m T)") {
  const dynamics::Model m = freeBox();
  BodyLoad load("push", m, 1, Vector3::Zero(), LoadFrame::World);
  const Vector3 F(2e5, -1e5, 5e4);
  const double ramp = 2.0;
  load.setTimeSeries({{0.0, Vector3::Zero(), Vector3::Zero()}, {ramp, F, Vector3::Zero()}});
  Rig r(m, {&load});
  r.q << 1.0, 2.0, 3.0, 1.0, 0.0, 0.0, 0.0;
  dynamics::matrixToQuaternion(dynamics::axisRotation(Vector3(1, 1, 0).normalized(), 0.5),
                               r.q.data() + 3);
  const Vector3 p0(1.0, 2.0, 3.0);
  for (int k = 0; k < 2000; ++k) r.step(1e-3);  // t = 2 s = ramp
  const Vector3 expected = p0 + F * std::pow(r.t, 3) / (6.0 * kMass * ramp);
  CHECK((r.q.head<3>() - expected).norm() < 1e-10);
  CHECK(r.v.head<3>().norm() < 1e-12);  // no rotation
}

TEST_CASE("a body-frame moment about a principal axis spins the body up at M t / I") {
  const dynamics::Model m = freeBox();
  BodyLoad load("turn", m, 1, Vector3::Zero(), LoadFrame::Body);
  const double M = 3e4, Izz = kMass * (kBox.x() * kBox.x() + kBox.y() * kBox.y()) / 12.0;
  load.set(0.0, Vector3::Zero(), Vector3(0.0, 0.0, M));
  Rig r(m, {&load});
  for (int k = 0; k < 1000; ++k) r.step(1e-3);
  CHECK(r.v[2] == Approx(M * r.t / Izz).epsilon(1e-12));
  CHECK(r.v.head<2>().norm() < 1e-12);
  CHECK(r.v.tail<3>().norm() < 1e-12);
}

TEST_CASE("world and body frames: F and M turned by R_WB and the moment p x F + M") {
  const dynamics::Model m = freeBox();
  const Vector3 p_B(1.0, -2.0, 0.5), F(10.0, 20.0, -5.0), M(1.0, 2.0, 3.0);
  Rig r(m, {});
  r.q << 4.0, -1.0, 2.0, 1.0, 0.0, 0.0, 0.0;
  const Matrix3 R = dynamics::axisRotation(Vector3(0.3, -1.0, 2.0).normalized(), 1.1);
  dynamics::matrixToQuaternion(R, r.q.data() + 3);
  const Stage s = r.stage();
  const Vector3 p_W = Vector3(4.0, -1.0, 2.0) + R * p_B;
  for (LoadFrame frame : {LoadFrame::World, LoadFrame::Body}) {
    BodyLoad load("l", m, 1, p_B, frame);
    load.set(0.0, F, M);
    dynamics::ExternalForces f(m);
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
    load.evaluate(s, f, tau);
    const Vector3 f_W = frame == LoadFrame::World ? F : Vector3(R * F);
    const Vector3 m_W = frame == LoadFrame::World ? M : Vector3(R * M);
    CHECK((f.worldFrame(1).tail<3>() - f_W).norm() < 1e-12);
    CHECK((f.worldFrame(1).head<3>() - (p_W.cross(f_W) + m_W)).norm() < 1e-12);
    CHECK(load.potentialEnergy(s) == 0.0);
  }
}

TEST_CASE("the load's power closes the kinetic-energy balance") {
  const dynamics::Model m = freeBox();
  BodyLoad load("gust", m, 1, Vector3(2.5, 1.0, -0.8), LoadFrame::Body);
  load.setTable({{0.0, 0, 0, 0, 0, 0, 0},
                 {1.0, 4e5, -2e5, 1e5, 5e4, 0, -2e5},
                 {2.0, -1e5, 3e5, 0, 0, 1e5, 1e5},
                 {3.0, 0, 0, 0, 0, 0, 0}});
  Rig r(m, {&load});
  r.v << 0.1, -0.2, 0.3, 0.5, 0.0, -0.4;
  const Rig::Balance bal = r.energyBalance(1e-3, 3000);  // the kinks fall on step ends
  CHECK(bal.maxWork > 1e4);
  CHECK(bal.maxError / bal.maxWork < 1e-8);
}

TEST_CASE("a body load refuses the world and unknown bodies and bad series") {
  const dynamics::Model m = freeBox();
  CHECK_THROWS_WITH(BodyLoad("wind-3", m, 0, Vector3::Zero(), LoadFrame::World),
                    Contains("wind-3"));
  CHECK_THROWS_AS(BodyLoad("wind-3", m, 2, Vector3::Zero(), LoadFrame::World),
                  std::invalid_argument);
  CHECK_THROWS_AS(BodyLoad("wind-3", m, 1, Vector3(0, std::nan(""), 0), LoadFrame::World),
                  std::invalid_argument);
  BodyLoad load("wind-3", m, 1, Vector3::Zero(), LoadFrame::World);
  CHECK_THROWS_AS(load.setTable({}), std::invalid_argument);
  CHECK_THROWS_AS(load.setTable({{1.0, 0, 0, 0, 0, 0, 0}, {0.5, 0, 0, 0, 0, 0, 0}}),
                  std::invalid_argument);
  CHECK_THROWS_AS(load.setTable({{1.0, std::nan(""), 0, 0, 0, 0, 0}}), std::invalid_argument);
  CHECK_THROWS_AS(load.set(1.0, Vector3(INFINITY, 0, 0), Vector3::Zero()), std::invalid_argument);
}
