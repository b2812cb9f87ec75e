// Projection onto the constraint manifold: positions to 1e-12 from an open four-bar, velocities
// to J v = 0 with an M-orthogonal correction.
#include <catch2/catch.hpp>

#include "dynamics/crba.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/projection.hpp"
#include "test_mechanisms.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("position projection closes an open four-bar and slider-crank") {
  std::mt19937 rng(29);
  const FourBar fb = makeFourBar(1.0, 3.0, 2.5, 3.0);
  Data d(fb.model);
  Eigen::VectorXd q = fb.closedConfiguration(0.8) + randomVectorX(rng, 3, 0.05);
  CHECK(loopResidualNorm(fb.model, d, q) > 1e-3);
  CHECK(projectPositions(fb.model, d, q) <= 1e-12);
  CHECK(loopResidualNorm(fb.model, d, q) <= 1e-12);
  CHECK((q - fb.closedConfiguration(q[0])).norm() < 1e-10);  // landed on the same branch
  const SliderCrank sc = makeSliderCrank(0.5, 1.5);
  Data ds(sc.model);
  Eigen::VectorXd qs = sc.closedConfiguration(2.0) + randomVectorX(rng, 3, 0.05);
  CHECK(projectPositions(sc.model, ds, qs) <= 1e-12);
  CHECK(qs[2] == Approx(sc.sliderPosition(qs[0])).epsilon(1e-11));
}

TEST_CASE("velocity projection gives J v = 0 and removes only an M-orthogonal part") {
  std::mt19937 rng(30);
  const FourBar fb = makeFourBar(1.0, 3.0, 2.5, 3.0);
  Data d(fb.model);
  const Eigen::VectorXd q = fb.closedConfiguration(0.4);
  Eigen::VectorXd v = randomVectorX(rng, 3), w = randomVectorX(rng, 3);
  const Eigen::VectorXd v0 = v;
  CHECK(projectVelocities(fb.model, d, q, v) < 1e-12);
  projectVelocities(fb.model, d, q, w);  // w is now an admissible velocity
  const Eigen::MatrixXd M = crba(fb.model, d, q);
  CHECK(std::abs((v0 - v).dot(M * w)) < 1e-10 * v0.norm() * w.norm() * M.norm());
}
