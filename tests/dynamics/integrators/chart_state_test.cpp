// The flat state y = [theta; v] for SUNDIALS: gather/scatter round trip, unit quaternions for any
// theta, and dy/dt equal to the joints' velocities and the accelerations.
#include <catch2/catch.hpp>

#include "dynamics/integrators/chart_state.hpp"
#include "integrator_cases.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("chart state: gather then scatter returns q and v, and any theta gives unit quaternions") {
  std::mt19937 rng(5);
  const Model m = randomTree(rng, 9);
  ChartState chart(m);
  const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv);
  Eigen::VectorXd y(chart.size()), q1(m.nq), v1(m.nv), d(m.nv);
  chart.gather(q, v, y.data());
  chart.scatter(y.data(), q1, v1);
  difference(m, q, q1, d);  // (a quaternion may come back as its negative: the same rotation)
  CHECK(d.norm() < 1e-15);
  CHECK(v1 == v);
  y.head(m.nv) = randomVectorX(rng, m.nv, 3.0);
  chart.scatter(y.data(), q1, v1);
  for (int i = 1; i < m.nbodies; ++i) {
    const JointType t = m.joints[i].type;
    if (t == JointType::Spherical) CHECK(q1.segment<4>(m.idxQ[i]).norm() == Approx(1.0).epsilon(1e-15));
    if (t == JointType::Free) CHECK(q1.segment<4>(m.idxQ[i] + 3).norm() == Approx(1.0).epsilon(1e-15));
  }
  CHECK(chart.rotationExtent(y.data()) > 0.0);
  CHECK(chart.rotationExtent(y.data()) <= std::sqrt(3.0) * 3.0);
}

TEST_CASE("chart state: the rate at the origin is (v, a), and scatter moves along it to first order") {
  std::mt19937 rng(6);
  const Model m = randomTree(rng, 6);
  ChartState chart(m);
  const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv), a = randomVectorX(rng, m.nv);
  Eigen::VectorXd y(chart.size()), ydot(chart.size());
  chart.gather(q, v, y.data());
  chart.kinematicRate(y.data(), ydot.data());
  chart.dynamicRate(a, ydot.data());
  CHECK((ydot.head(m.nv) - v).norm() < 1e-15);
  CHECK(ydot.tail(m.nv) == a);
  // (y + eps ydot) => q (+) eps v, to O(eps^2)
  const double eps = 1e-6;
  Eigen::VectorXd q1(m.nq), v1(m.nv), q2(m.nq), d(m.nv);
  const Eigen::VectorXd y1 = y + eps * ydot;
  chart.scatter(y1.data(), q1, v1);
  integrate(m, q, v, eps, q2);
  difference(m, q2, q1, d);
  CHECK(d.norm() < 1e-11);
}
