// Static equilibrium by Newton in the tangent space: checked against statics computed
// independently (force and moment sums) and against the closed form of a mass on a spring.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "dynamics/kinematics.hpp"
#include "dynamics/model_builder.hpp"
#include "dynamics/multibody_system.hpp"
#include "dynamics/static_equilibrium.hpp"

using namespace yardsim::dynamics;

namespace {
// Three zero-length linear springs from world anchors to points on the body.
struct Springs {
  std::array<Vector3, 3> anchor_W{Vector3(-3, -1, 10), Vector3(4, -2, 11), Vector3(0.5, 3, 9)};
  std::array<Vector3, 3> point_B{Vector3(-1, -0.5, 0.5), Vector3(1.2, -0.4, 0.5), Vector3(0, 0.8, 0.4)};
  std::array<double, 3> k{2.0e5, 3.0e5, 1.5e5};
  Vector3 point_W(const Transform& X_WB, int s) const { return X_WB.R * point_B[s] + X_WB.p; }
  Vector3 force_W(const Transform& X_WB, int s) const { return -k[s] * (point_W(X_WB, s) - anchor_W[s]); }
};
}  // namespace

TEST_CASE("a free body on three springs comes to rest where forces and moments balance") {
  ModelBuilder b;
  const double mass = 1000.0;
  const Vector3 com(0.1, -0.05, 0.2);
  b.addBody("block", "world", Joint::free(), Transform::identity(),
            makeInertia(mass, com, Vector3(300, 500, 700).asDiagonal()));
  const Model m = b.build();
  const Springs s;
  MultibodySystem sys(m);
  sys.setForces([&](double, const Eigen::VectorXd&, const Eigen::VectorXd&, const Data& d, ExternalForces& f,
                    Eigen::VectorXd&) {
    for (int k = 0; k < 3; ++k) f.addPointForceWorld(1, s.point_W(d.X_WB[1], k), s.force_W(d.X_WB[1], k));
  });
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nq);
  q[2] = 5.0;  // start 5 m below the anchors, unrotated: far from equilibrium
  q[3] = 1.0;  // quaternion (w, x, y, z)
  const EquilibriumResult r = solveStaticEquilibrium(m, sys, 0.0, q);
  REQUIRE(r.converged);
  CHECK(r.iterations < 20);
  CHECK(q.segment(3, 4).norm() == Approx(1.0).margin(1e-14));
  // (equilibrium pose) => force and moment sums about the centre of mass, computed here
  Data d(m);
  forwardKinematics(m, d, q, Eigen::VectorXd::Zero(m.nv));
  const Transform& X = d.X_WB[1];
  const Vector3 c_W = X.R * com + X.p;
  Vector3 force = Vector3(0, 0, -9.81 * mass), moment = Vector3::Zero();
  for (int k = 0; k < 3; ++k) {
    force += s.force_W(X, k);
    moment += (s.point_W(X, k) - c_W).cross(s.force_W(X, k));
  }
  CHECK(force.norm() < 1e-6 * 9.81 * mass);
  CHECK(moment.norm() < 1e-6 * 9.81 * mass);
}

TEST_CASE("a mass on a vertical spring settles at z = -m g / k, and a free slide stays put") {
  ModelBuilder b;
  b.addBody("slide", "world", Joint::prismatic(Vector3::UnitX()), Transform::identity(), boxInertia(50.0, Vector3::Ones()));
  b.addBody("mass", "slide", Joint::prismatic(Vector3::UnitZ()), Transform::identity(), boxInertia(200.0, Vector3::Ones()));
  const Model m = b.build();
  const double k = 4.0e4;
  MultibodySystem sys(m);
  sys.setForces([&](double, const Eigen::VectorXd& q, const Eigen::VectorXd&, const Data&, ExternalForces&,
                    Eigen::VectorXd& tau) { tau[1] = -k * q[1]; });
  Eigen::VectorXd q(2);
  q << 0.7, 0.3;
  const EquilibriumResult r = solveStaticEquilibrium(m, sys, 0.0, q);
  REQUIRE(r.converged);
  CHECK(q[1] == Approx(-200.0 * 9.81 / k).epsilon(1e-9));
  CHECK(q[0] == Approx(0.7).margin(1e-12));  // no stiffness along the slide: not moved
}

TEST_CASE("a body with nothing to rest on has no equilibrium: reported, not thrown, state finite") {
  ModelBuilder b;
  b.addBody("block", "world", Joint::free(), Transform::identity(), boxInertia(1000.0, Vector3::Ones()));
  const Model m = b.build();
  MultibodySystem sys(m);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nq);
  q[3] = 1.0;
  const EquilibriumResult r = solveStaticEquilibrium(m, sys, 0.0, q);
  CHECK_FALSE(r.converged);
  CHECK(r.residual == Approx(9.81));
  CHECK(q.allFinite());
}

namespace {
// A free 2000 kg body held only by a vertical spring k (z - z_a) at its centre of mass: heave is
// its one direction with stiffness; surge, sway, roll, pitch and yaw have none.
struct HeaveSpring {
  double mass = 2000.0, k = 5.0e4;
  Vector3 side = Vector3::Zero();  // a steady force (N, world frame) at the centre of mass
  Model model() const {
    ModelBuilder b;
    b.addBody("float", "world", Joint::free(), Transform::identity(),
              makeInertia(mass, Vector3::Zero(), Vector3(400, 600, 900).asDiagonal()));
    return b.build();
  }
  void attach(MultibodySystem& sys) const {
    sys.setForces([this](double, const Eigen::VectorXd&, const Eigen::VectorXd&, const Data& d, ExternalForces& f,
                         Eigen::VectorXd&) {
      const Vector3 p = d.X_WB[1].p;
      f.addPointForceWorld(1, p, Vector3(0, 0, -k * p.z()) + side);
    });
  }
  // (x, y, z, roll, pitch, yaw) => q of the free joint
  static Eigen::VectorXd pose(double x, double y, double z, double roll, double pitch, double yaw) {
    const Eigen::Quaterniond r = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
    Eigen::VectorXd q(7);
    q << x, y, z, r.w(), r.x(), r.y(), r.z();
    return q;
  }
};
}  // namespace

TEST_CASE("directions without stiffness stay exactly where they are: only heave moves") {
  const HeaveSpring s;
  const Model m = s.model();
  MultibodySystem sys(m);
  s.attach(sys);
  // (start) => 0.3 m below its rest height, displaced and turned in every free direction
  const Eigen::VectorXd q0 = HeaveSpring::pose(3.0, -2.0, -s.mass * 9.81 / s.k - 0.3, 0.0, 0.0, 0.35);
  Eigen::VectorXd q = q0;
  const EquilibriumResult r = solveStaticEquilibrium(m, sys, 0.0, q);
  REQUIRE(r.converged);
  CHECK(r.rank == 1);  // heave only
  CHECK(q[2] == Approx(-s.mass * 9.81 / s.k).epsilon(1e-12));  // z = -m g / k
  CHECK(std::abs(q[0] - q0[0]) < 1e-12);
  CHECK(std::abs(q[1] - q0[1]) < 1e-12);
  CHECK((q.segment(3, 4) - q0.segment(3, 4)).cwiseAbs().maxCoeff() < 1e-9);  // roll, pitch, yaw
}

TEST_CASE("a steady force along a direction without stiffness: no equilibrium, the direction and force named") {
  HeaveSpring s;
  s.side = Vector3(0, 1.23e4, 0);  // 12.3 kN sideways
  const Model m = s.model();
  MultibodySystem sys(m);
  s.attach(sys);
  Eigen::VectorXd q = HeaveSpring::pose(0.0, 0.0, 0.1, 0.0, 0.0, 0.0);
  const EquilibriumResult r = solveStaticEquilibrium(m, sys, 0.0, q);
  CHECK_FALSE(r.converged);
  CHECK(q.allFinite());
  for (const auto& u : r.unbalanced) UNSCOPED_INFO("dof " << u.dof << " force " << u.force);
  // (directions named) => translations of the body whose forces add up to the 12.3 kN push
  // (the search leaves the body turned, so the push may show on more than one body axis)
  REQUIRE_FALSE(r.unbalanced.empty());
  double sum = 0.0;
  for (const auto& u : r.unbalanced) {
    CHECK_FALSE(jointDirectionIsRotation(m.joints[1].type, u.dof - m.idxV[1]));
    sum += u.force * u.force;
  }
  CHECK(std::sqrt(sum) == Approx(1.23e4).epsilon(1e-6));
}

TEST_CASE("a free body between springs in every direction: every direction stiff (full rank)") {
  ModelBuilder b;
  b.addBody("block", "world", Joint::free(), Transform::identity(),
            makeInertia(1000.0, Vector3(0.1, -0.05, 0.2), Vector3(300, 500, 700).asDiagonal()));
  const Model m = b.build();
  const Springs s;
  MultibodySystem sys(m);
  sys.setForces([&](double, const Eigen::VectorXd&, const Eigen::VectorXd&, const Data& d, ExternalForces& f,
                    Eigen::VectorXd&) {
    for (int k = 0; k < 3; ++k) f.addPointForceWorld(1, s.point_W(d.X_WB[1], k), s.force_W(d.X_WB[1], k));
  });
  Eigen::VectorXd q = HeaveSpring::pose(0.0, 0.0, 9.0, 0.0, 0.0, 0.0);
  const EquilibriumResult r = solveStaticEquilibrium(m, sys, 0.0, q);
  REQUIRE(r.converged);
  CHECK(r.rank == 6);
}
