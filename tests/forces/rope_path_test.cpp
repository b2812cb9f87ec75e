// The rope path: length as the sum of segments, the length rate by central differences along a
// motion, and the forces of a uniform tension doing power -T dL/dt on the bodies (virtual work).
#include <catch2/catch.hpp>

#include <random>
#include <stdexcept>

#include "dynamics/configuration.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/model_builder.hpp"
#include "forces/rope_path.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using dynamics::Vector3;

namespace {

// Two free bodies: a hook block and a load.
dynamics::Model twoFreeBodies() {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("hook", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(10.0, Vector3(1, 1, 1)));
  b.addBody("load", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(100.0, Vector3(3, 2, 1)));
  return b.build();
}

const std::vector<Attachment> kPoints{{0, Vector3(0.0, 0.0, 30.0)},
                                      {1, Vector3(0.2, 0.0, 0.3)},
                                      {0, Vector3(4.0, 1.0, 28.0)},
                                      {2, Vector3(1.0, 0.5, 0.5)}};

}  // namespace

TEST_CASE("the length is the sum of the segments and its rate the derivative along a motion") {
  const dynamics::Model m = twoFreeBodies();
  RopePath path(m, kPoints, "r");
  std::mt19937 rng(7);
  const Eigen::VectorXd q = dynamics::randomConfiguration(m, rng);
  Eigen::VectorXd v(m.nv);
  for (int i = 0; i < m.nv; ++i) v[i] = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
  dynamics::Data d(m);
  dynamics::forwardKinematics(m, d, q, v);
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < kPoints.size(); ++i)
    sum += (dynamics::pointPosition(d, kPoints[i + 1].body, kPoints[i + 1].p_B) -
            dynamics::pointPosition(d, kPoints[i].body, kPoints[i].p_B))
               .norm();
  const PathMeasure a = path.measure(d);
  CHECK(a.length == Approx(sum).epsilon(1e-14));
  PathPoints points = path.makePoints();
  const PathMeasure b = path.update(d, points);
  CHECK(b.length == a.length);
  CHECK(b.rate == a.rate);
  // (q moved by +-v dt on the manifold) => central difference of the length
  const double dt = 1e-6;
  Eigen::VectorXd qp(m.nq), qm(m.nq);
  dynamics::integrate(m, q, v, dt, qp);
  dynamics::integrate(m, q, v, -dt, qm);
  dynamics::forwardKinematics(m, d, qp);
  const double lp = path.measure(d).length;
  dynamics::forwardKinematics(m, d, qm);
  const double lm = path.measure(d).length;
  CHECK(a.rate == Approx((lp - lm) / (2 * dt)).epsilon(1e-7));
}

TEST_CASE("a uniform tension pulls each point along the rope and does power -T dL/dt") {
  const dynamics::Model m = twoFreeBodies();
  RopePath path(m, kPoints, "r");
  std::mt19937 rng(11);
  const Eigen::VectorXd q = dynamics::randomConfiguration(m, rng);
  Eigen::VectorXd v(m.nv);
  for (int i = 0; i < m.nv; ++i) v[i] = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
  dynamics::Data d(m);
  dynamics::forwardKinematics(m, d, q, v);
  PathPoints points = path.makePoints();
  const PathMeasure pm = path.update(d, points);
  const double T = 1234.5;
  dynamics::ExternalForces f(m);
  path.applyTension(T, points, f);
  // (hook, a sheave between two world points) => T (u_prev + u_next)
  const auto& p = points.p_W;
  const Vector3 onHook = T * ((p[0] - p[1]).normalized() + (p[2] - p[1]).normalized());
  CHECK((f.worldFrame(1).tail<3>() - onHook).norm() < 1e-10 * T);
  CHECK((f.worldFrame(1).head<3>() - p[1].cross(onHook)).norm() < 1e-9 * T);
  // (load, the last end) => T u toward the previous point
  CHECK((f.worldFrame(2).tail<3>() - T * (p[2] - p[3]).normalized()).norm() < 1e-10 * T);
  // (virtual work) => sum over bodies of F_W . V_W = -T dL/dt
  double power = 0.0;
  for (int b = 1; b < m.nbodies; ++b)
    power += f.worldFrame(b).dot(dynamics::bodyVelocityWorld(d, b));
  CHECK(power == Approx(-T * pm.rate).epsilon(1e-10));
  CHECK(points.u_W.size() == kPoints.size() - 1);
}

TEST_CASE("a path needs two points on bodies of the model") {
  const dynamics::Model m = twoFreeBodies();
  CHECK_THROWS_AS(RopePath(m, {{0, Vector3::Zero()}}, "r"), std::invalid_argument);
  CHECK_THROWS_AS(RopePath(m, {{0, Vector3::Zero()}, {3, Vector3::Zero()}}, "r"),
                  std::invalid_argument);
  CHECK_THROWS_AS(RopePath(m, {{-1, Vector3::Zero()}, {1, Vector3::Zero()}}, "r"),
                  std::invalid_argument);
  CHECK_THROWS_AS(RopePath(m, {{0, Vector3::Zero()}, {1, Vector3(std::nan(""), 0, 0)}}, "r"),
                  std::invalid_argument);
}
