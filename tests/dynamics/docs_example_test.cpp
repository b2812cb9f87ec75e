// The usage examples of docs/multibody.md, compiled and run, so that the page stays true.
#include <catch2/catch.hpp>

#include "dynamics/configuration.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/model_builder.hpp"
#include "dynamics/multibody_system.hpp"

using namespace yardsim::dynamics;

TEST_CASE("docs/multibody.md: building a model and integrating it") {
  ModelBuilder b;
  b.setGravity({0, 0, -9.81});
  b.addBody("barge", "world", Joint::free(), {}, boxInertia(3.5e6, {60, 30, 6}));
  b.addBody("boom", "barge", Joint::revolute(Vector3::UnitY()), Transform::translation({20, 0, 8}),
            makeInertia(4.0e4, {15, 0, 0}, Vector3(1e5, 3e6, 3e6).asDiagonal()), "boom.stl");
  b.addLoop("stay", "boom", Transform::translation({30, 0, 0}), "barge", Transform::translation({50, 0, 8}),
            kPointConstraint);  // holds the boom's tip at its place on the barge
  const Model model = b.build();  // throws ModelError
  Data data(model);

  MultibodySystem sys(model);
  sys.setForces([](double, const Eigen::VectorXd&, const Eigen::VectorXd&, const Data& d, ExternalForces& f,
                   Eigen::VectorXd&) {
    f.addPointForceWorld(1, pointPosition(d, 1, {10, 0, 0}), {0, 0, 2.0e5});  // d holds FK(q, v)
  });
  sys.setProjection(true);  // only matters with loops
  Rk4 rk4(model);
  Eigen::VectorXd q = neutralConfiguration(model), v = Eigen::VectorXd::Zero(model.nv);
  double t = 0;
  for (int k = 0; k < 1000; ++k) rk4.step(sys, t, q, v, 1e-3);

  CHECK(t == Approx(1.0));
  CHECK(loopResidualNorm(model, data, q) <= 1e-10);
  CHECK(std::abs(q[model.idxQ[model.bodyIndex("boom")]]) < 1e-10);  // the stay holds the boom
  CHECK(q[2] < -4.0);  // no buoyancy here: the barge falls (about g t^2 / 2)
}
