// Generalized-alpha: second order for every rho_inf (alpha_m != alpha_f, so the starting procedure
// matters), spectral radius rho_inf at high frequency, Newton on a reused factorisation, and the
// index-3 form on the four-bar: g(q) held at the Newton tolerance and multipliers that converge
// to the Schur-complement ones with the step.
#include <catch2/catch.hpp>

#include "dynamics/constrained_dynamics.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/integrators/generalized_alpha.hpp"
#include "dynamics/integrators/hht.hpp"
#include "dynamics/loop_constraints.hpp"
#include "../test_mechanisms.hpp"
#include "integrator_cases.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("Chung-Hulbert parameters: gamma = 1/2 + alpha_f - alpha_m, rho_inf = 1 is the trapezoidal rule") {
  const GeneralizedAlphaParameters p = chungHulbert(1.0);
  CHECK(p.alphaM == Approx(0.5));
  CHECK(p.alphaF == Approx(0.5));
  CHECK(p.gamma == Approx(0.5));
  CHECK(p.beta == Approx(0.25));
  const GeneralizedAlphaParameters z = chungHulbert(0.0);
  CHECK(z.alphaM == Approx(-1.0));
  CHECK(z.alphaF == Approx(0.0));
  CHECK(z.gamma == Approx(1.5));
}

TEST_CASE("generalized-alpha converges with order 2 on a tree with a free joint, for every rho_inf") {
  const SmoothTree p;
  for (double rho : {1.0, 0.8, 0.5, 0.0}) {
    IntegratorSpec s = specOf("generalized_alpha");
    s.rhoInf = rho;
    INFO("rho_inf " << rho);
    CHECK(p.observedOrder(s, 50) == Approx(2.0).margin(0.15));
  }
}

TEST_CASE("generalized-alpha damps the highest frequencies by rho_inf per step and reuses its factorisation") {
  for (double rho : {0.0, 0.5, 0.8}) {
    IntegratorSpec s = specOf("generalized_alpha");
    s.rhoInf = rho;
    Oscillator osc(1e4);
    // (double eigenvalue rho_inf at infinity: amplitude ~ n rho^n) => rho from steps 100 to 200
    // at omega h = 1e4
    const double a100 = osc.amplitude(s, 1.0, 100), a200 = osc.amplitude(s, 1.0, 200);
    INFO("rho_inf " << rho << ": " << a100 << " -> " << a200);
    if (rho == 0.0) CHECK(a100 < 1e-6);
    else CHECK(std::pow(a200 / a100 / 2.0, 1.0 / 100) == Approx(rho).epsilon(0.003));
  }
  // (a linear problem) => one Jacobian for the whole run, Newton converging in 2 iterations
  Oscillator osc(50.0);
  GeneralizedAlpha ga(osc.model, chungHulbert(0.8), "generalized_alpha");
  Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
  double t = 0.0;
  for (int k = 0; k < 100; ++k) ga.step(osc, t, q, v, 0.05);
  CHECK(ga.stats().jac_evals == 1);
  CHECK(ga.stats().newton_its <= 2 * 100);
  CHECK(std::hypot(q[0], v[0] / 50.0) < 1.0);
}

TEST_CASE("generalized-alpha on the four-bar: g(q) = 0 at the Newton tolerance, energy kept, multipliers of order 2") {
  const FourBar fb = makeFourBar(1.0, 2.0, 1.5, 2.0);
  const Model& m = fb.model;
  auto run = [&](double h, double T, double& worstResidual, double& energyError, Eigen::VectorXd& lambda) {
    MultibodySystem sys(m);
    IntegratorSpec s = specOf("generalized_alpha");
    s.dt = h;
    GeneralizedAlpha ga(m, chungHulbert(0.9), "generalized_alpha");
    Eigen::VectorXd q = fb.closedConfiguration(0.3), v = Eigen::VectorXd::Zero(3);
    Data d(m);
    const double E0 = kineticEnergy(m, d, q, v) + potentialEnergy(m, d, q);
    double t = 0.0;
    worstResidual = energyError = 0.0;
    const int n = static_cast<int>(std::lround(T / h));
    for (int k = 0; k < n; ++k) {
      ga.step(sys, t, q, v, h);
      worstResidual = std::max(worstResidual, loopResidualNorm(m, d, q));
      energyError = std::max(energyError, std::abs(kineticEnergy(m, d, q, v) + potentialEnergy(m, d, q) - E0));
    }
    lambda = ga.multipliers();
    CHECK(ga.stats().jac_evals < n / 2);  // the iteration matrix is reused over steps
    CHECK(ga.stats().newton_its < 7 * n);
    // (end state) => multipliers of the index-1 forward dynamics, for comparison
    Data dr(m);
    constrainedForwardDynamics(m, dr, q, v, Eigen::VectorXd::Zero(3));
    return Eigen::VectorXd(dr.lambda);
  };
  double res = 0, err1 = 0, err2 = 0;
  Eigen::VectorXd l1, l2, l3;
  const Eigen::VectorXd r1 = run(0.01, 1.0, res, err1, l1);
  CHECK(res < 1e-9);
  const Eigen::VectorXd r2 = run(0.005, 1.0, res, err2, l2);
  INFO("residual " << res << ", energy errors " << err1 << " " << err2);
  CHECK(res < 1e-9);
  CHECK(err1 < 1e-3 * 9.81 * 2.0);  // 1e-3 of the potential energy range (masses of 1 kg, about 2 m of travel)
  CHECK(err2 < err1 / 3.0);         // and of second order
  const Eigen::VectorXd r3 = run(0.0025, 1.0, res, err1, l3);
  const double e1 = (l1 - r1).norm(), e2 = (l2 - r2).norm(), e3 = (l3 - r3).norm();
  INFO("multiplier errors " << e1 << " " << e2 << " " << e3);
  CHECK(std::log2(e2 / e3) == Approx(2.0).margin(0.3));
}

namespace {
// A mass landing on a damped spring stop at q = 0: the damping force jumps when contact begins,
// like a damped rope going taut.
struct DampedStop final : AccelerationSource {
  void acceleration(double, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) override {
    a[0] = -9.81 + (q[0] < 0.0 ? -1e4 * q[0] - 100.0 * v[0] : 0.0);
  }
};
}  // namespace

TEST_CASE("generalized-alpha started exactly where a force jumps stays bounded and follows the motion") {
  const Oscillator unit(1.0);  // its model: one prismatic joint
  for (const double h : {0.05, 0.01}) {
    for (const double rho : {0.5, 0.9}) {
      INFO("h " << h << ", rho_inf " << rho);
      DampedStop stop;
      GeneralizedAlpha ga(unit.model, chungHulbert(rho), "generalized_alpha");
      Rk4 rk(unit.model);
      Eigen::VectorXd q = Eigen::VectorXd::Zero(1), v = Eigen::VectorXd::Constant(1, -3.0);
      Eigen::VectorXd qr = q, vr = v;
      double t = 0.0, tr = 0.0, worst = 0.0, fastest = 0.0;
      for (int k = 0; k < static_cast<int>(std::lround(0.5 / h)); ++k) {
        ga.step(stop, t, q, v, h);
        for (int j = 0; j < 100; ++j) rk.step(stop, tr, qr, vr, h / 100);
        worst = std::max(worst, std::abs(v[0] - vr[0]));
        fastest = std::max(fastest, std::abs(v[0]));
      }
      // never faster than the impact speed plus what gravity adds over 0.5 s (no energy from the
      // start at the jump); at omega h = 1 it also tracks a fine RK4 solution (at omega h = 5 the
      // 30 ms bounce is not resolved, by design)
      CHECK(fastest < 3.0 + 9.81 * 0.5);
      if (h == 0.01) {
        CHECK(worst < 1.5);
        CHECK(std::abs(q[0] - qr[0]) < 0.05);
      }
    }
  }
}

namespace {
// A unit mass dropped on a stiff unilateral stop at q = 0 (omega = 3000 rad/s, zeta = 0.05: a
// contact of 1 ms): a force that switches, reporting its regime (in contact or not) when asked to.
struct StiffStop final : AccelerationSource {
  bool reports = true;
  static constexpr double k = 9e6, c = 300.0, g = 9.81;
  void acceleration(double, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) override {
    a[0] = -g + (q[0] < 0.0 ? std::max(0.0, -k * q[0] - c * v[0]) : 0.0);
  }
  bool switches() const override { return reports; }
  std::uint64_t regime(double, const Eigen::VectorXd& q, const Eigen::VectorXd&) override { return q[0] < -1e-8; }
  // (q, v) => kinetic + gravity + spring energy per unit mass, J/kg
  static double energy(double q, double v) { return 0.5 * v * v + g * q + (q < 0.0 ? 0.5 * k * q * q : 0.0); }
};
}  // namespace

TEST_CASE("HHT and generalized-alpha at their defaults sub-step a step where a stiff stop closes or opens") {
  // dropped from 1 cm at omega h = 30: with the regime reported the energy is never above its start
  // and the mass ends at rest on the stop (m g / k deep); without it (a source that does not report
  // its switches, as before) the same drop gains energy
  const Oscillator unit(1.0);  // its model: one prismatic joint
  for (const GeneralizedAlphaParameters& p : {hhtParameters(-0.1), chungHulbert(0.8)}) {
    double gained[2] = {0.0, 0.0};
    for (const bool reports : {true, false}) {
      StiffStop stop;
      stop.reports = reports;
      GeneralizedAlpha ga(unit.model, p, "generalized_alpha");
      Eigen::VectorXd q = Eigen::VectorXd::Constant(1, 0.01), v = Eigen::VectorXd::Zero(1);
      const double e0 = StiffStop::energy(q[0], v[0]);
      double t = 0.0;
      for (int k = 0; k < 300; ++k) {
        ga.step(stop, t, q, v, 0.01);
        gained[reports] = std::max(gained[reports], StiffStop::energy(q[0], v[0]) - e0);
      }
      if (reports) CHECK(q[0] == Approx(-StiffStop::g / StiffStop::k).epsilon(1e-3));
    }
    INFO("alpha_f " << p.alphaF << ": gained " << gained[1] << " J/kg with the regime, " << gained[0] << " without");
    CHECK(gained[1] < 1e-9);
    CHECK(gained[0] > 1e-3);
  }
}
