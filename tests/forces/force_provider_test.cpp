#include "forces/force_provider.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "dynamics/configuration.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/model_builder.hpp"

using namespace yardsim;
using dynamics::Vector3;

namespace {

// A provider that adds one value to one coefficient of one body's force (body or world frame),
// or to one joint force: the check in evaluate() must find exactly what it planted.
class Planted final : public forces::ForceProvider {
 public:
  Planted(int body, bool world, int coefficient, double value, int joint = -1)
      : ForceProvider("planted"),
        body_(body),
        world_(world),
        c_(coefficient),
        value_(value),
        joint_(joint) {}

 protected:
  void doEvaluate(const forces::Stage& /*s*/, dynamics::ExternalForces& f,
                  Eigen::VectorXd& tau) const override {
    if (joint_ >= 0) {
      tau[joint_] += value_;
      return;
    }
    dynamics::Force F = dynamics::Force::Zero();
    F[c_] = value_;
    if (world_)
      f.addWorldFrame(body_, F);
    else
      f.addBodyFrame(body_, F);
  }

 private:
  int body_;
  bool world_;
  int c_;
  double value_;
  int joint_;
};

// A chain of three bodies on revolute joints.
dynamics::Model chain() {
  dynamics::ModelBuilder b;
  const auto I = dynamics::boxInertia(1.0, Vector3(0.1, 0.1, 1.0));
  b.addBody("a", "world", dynamics::Joint::revolute(Vector3::UnitY()),
            dynamics::Transform::identity(), I);
  b.addBody("b", "a", dynamics::Joint::revolute(Vector3::UnitY()), dynamics::Transform::identity(),
            I);
  b.addBody("c", "b", dynamics::Joint::revolute(Vector3::UnitY()), dynamics::Transform::identity(),
            I);
  return b.build();
}

}  // namespace

TEST_CASE("evaluate refuses a non-finite force in any coefficient of any body and names the body") {
  const dynamics::Model m = chain();
  dynamics::Data d(m);
  const Eigen::VectorXd q = dynamics::neutralConfiguration(m), v = Eigen::VectorXd::Zero(m.nv);
  dynamics::forwardKinematics(m, d, q, v);
  const forces::Stage s{1.5, m, d, q, v};
  const double bad[3] = {std::numeric_limits<double>::quiet_NaN(), INFINITY, -INFINITY};
  for (int body = 1; body < m.nbodies; ++body)
    for (bool world : {false, true})
      for (int c = 0; c < 6; ++c)
        for (double x : bad) {
          dynamics::ExternalForces f(m);
          Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
          // (a finite world-frame force elsewhere) => the world-frame check is on
          f.addWorldFrame(body == 1 ? 2 : 1, dynamics::Force::Constant(1.0));
          const Planted p(body, world, c, x);
          try {
            p.evaluate(s, f, tau);
            FAIL("no ForceError for body " << body << (world ? " (world)" : " (body)")
                                           << " coefficient " << c);
          } catch (const forces::ForceError& e) {
            CHECK(std::string(e.what()).find("on body '" + m.names[body] + "'") !=
                  std::string::npos);
            CHECK(std::string(e.what()).find("'planted'") != std::string::npos);
          }
        }
}

TEST_CASE("evaluate accepts finite forces at the ends of the double range") {
  const dynamics::Model m = chain();
  dynamics::Data d(m);
  const Eigen::VectorXd q = dynamics::neutralConfiguration(m), v = Eigen::VectorXd::Zero(m.nv);
  dynamics::forwardKinematics(m, d, q, v);
  const forces::Stage s{0.0, m, d, q, v};
  const double max = std::numeric_limits<double>::max();
  for (double x : {max, -max, 4.9e-324, -0.0}) {
    dynamics::ExternalForces f(m);
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
    for (int body = 1; body < m.nbodies; ++body)  // the sum of all of them would overflow
      for (int c = 0; c < 6; ++c) {
        Planted(body, false, c, x).evaluate(s, f, tau);
        Planted(body, true, c, x).evaluate(s, f, tau);
      }
    CHECK(f.bodyFrame(3)[5] == x);
  }
}

TEST_CASE("evaluate refuses a non-finite joint force") {
  const dynamics::Model m = chain();
  dynamics::Data d(m);
  const Eigen::VectorXd q = dynamics::neutralConfiguration(m), v = Eigen::VectorXd::Zero(m.nv);
  dynamics::forwardKinematics(m, d, q, v);
  const forces::Stage s{0.0, m, d, q, v};
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  CHECK_NOTHROW(Planted(1, false, 0, 1e300, 2).evaluate(s, f, tau));
  CHECK_THROWS_WITH(Planted(1, false, 0, NAN, 2).evaluate(s, f, tau),
                    Catch::Contains("'planted' produced a non-finite joint force"));
}
