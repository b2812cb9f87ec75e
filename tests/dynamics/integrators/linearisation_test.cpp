// The linearisation scope of the finite-difference Jacobians (AccelerationSource::
// beginLinearisation, dynamics/integrators/integrator.hpp): every implicit method (HHT,
// generalized-alpha, CVODE BDF and Adams, ARKODE DIRK and IMEX), on its dense path and with a
// Jacobian pattern, opens one scope per Jacobian it forms, at the state it linearises about, and
// closes it before the Newton iterations evaluate their residuals; the explicit methods open none.
// The source is a hardening spring a = -k q - b q^3 whose linearised evaluation is its tangent.
#include <catch2/catch.hpp>
#include <cmath>

#include "dynamics/integrators/factory.hpp"
#include "dynamics/model_builder.hpp"
#include "integrator_cases.hpp"

using namespace yardsim::dynamics;

namespace {

// a unit mass on a hardening spring; inside a scope its tangent at the scope's base
struct HardeningSpring final : AccelerationSource {
  Model model;
  double k = 4.0, b = 40.0;
  JacobianPattern pattern{1, {{0}}};
  bool withPattern = false;
  bool open = false;
  double q0 = 0.0, a0 = 0.0, slope = 0.0;
  long begins = 0, ends = 0, inside = 0, outside = 0;
  double farthest = 0.0;  // largest |q - q0| evaluated inside a scope
  HardeningSpring() {
    ModelBuilder mb;
    mb.addBody("mass", "world", Joint::prismatic(Vector3::UnitX()), {},
               boxInertia(1.0, Vector3(1, 1, 1)));
    model = mb.build();
  }
  double force(double q) const { return -k * q - b * q * q * q; }
  void acceleration(double, const Eigen::VectorXd& q, const Eigen::VectorXd&,
                    Eigen::VectorXd& a) override {
    if (open) {
      ++inside;
      farthest = std::max(farthest, std::abs(q[0] - q0));
      a[0] = a0 + slope * (q[0] - q0);
    } else {
      ++outside;
      a[0] = force(q[0]);
    }
  }
  const JacobianPattern* jacobianPattern() const override {
    return withPattern ? &pattern : nullptr;
  }
  void beginLinearisation(double, const Eigen::VectorXd& q, const Eigen::VectorXd&) override {
    CHECK_FALSE(open);  // (scopes do not nest)
    ++begins;
    open = true;
    q0 = q[0];
    a0 = force(q0);
    slope = -k - 3.0 * b * q0 * q0;
  }
  void endLinearisation() override {
    if (!open) return;
    ++ends;
    open = false;
  }
  bool linearises() const override { return true; }
};

}  // namespace

TEST_CASE("every implicit method opens one linearisation per Jacobian and closes it") {
  for (const MethodInfo& method : integratorMethods()) {
    for (bool withPattern : {false, true}) {
      INFO(method.name << (withPattern ? ", with a Jacobian pattern" : ", dense"));
      HardeningSpring spring;
      spring.withPattern = withPattern;
      IntegratorSpec spec = testing::specOf(std::string(method.name));
      spec.dt = 0.01;
      spec.rtol = 1e-9;
      spec.atol = 1e-11;
      const auto integ = makeIntegrator(spec, spring.model);
      Eigen::VectorXd q = Eigen::VectorXd::Constant(1, 0.5), v = Eigen::VectorXd::Zero(1);
      double t = 0.0;
      for (int n = 0; n < 300; ++n) integ->step(spring, t, q, v, spec.dt);
      const IntegratorStats& s = integ->stats();
      INFO(s.jac_evals << " Jacobians, " << spring.begins << " scopes, " << spring.inside
                       << " evaluations inside, " << spring.outside << " outside");
      CHECK_FALSE(spring.open);
      CHECK(spring.ends == spring.begins);
      if (!method.implicit) {
        CHECK(spring.begins == 0);
        continue;
      }
      // (each Jacobian) => one scope, its columns inside it at a difference's distance from its
      // base, the residuals outside
      CHECK(s.jac_evals > 0);
      CHECK(spring.begins == s.jac_evals);
      CHECK(spring.inside >= s.jac_evals);
      CHECK(spring.farthest < 1e-6);
      CHECK(spring.outside > spring.inside);
      // (energy of the undamped spring, 1/2 v^2 + 2 q^2 + 10 q^4) => kept by the solution to the
      // method's accuracy: the residuals saw the spring, not its tangents
      const double e0 = 2.0 * 0.25 + 10.0 * 0.0625;
      const double e = 0.5 * v[0] * v[0] + 2.0 * q[0] * q[0] + 10.0 * std::pow(q[0], 4);
      CHECK(e == Approx(e0).epsilon(0.05));
    }
  }
}
