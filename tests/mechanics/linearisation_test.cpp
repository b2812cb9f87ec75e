// The catenary lines' analytic linearisation wired to the finite-difference Jacobians
// (mechanics/linearisation.hpp): inside a linearisation the kernel's accelerations are affine in
// the fairlead's position with the slope of the lines' analytic stiffness (k11 of the 2D
// solution, checked against a Richardson difference of independent solves), outside it they are
// the nonlinear catenary's again; the stiffness estimate of a moored buoy is sqrt(k/m); and the
// implicit methods (HHT, generalized-alpha, CVODE and ARKODE on their dense paths, whose Newton
// matrices use the linearisation) follow an RK4 reference of the buoy's free surge.
#include <catch2/catch.hpp>
#include <cmath>

#include "forces/lines/catenary.hpp"
#include "mechanics/linearisation.hpp"
#include "mechanics/stiffness_estimate.hpp"
#include "mechanics_fixture.hpp"
#include "support/scene_run.hpp"

using namespace yardsim;

namespace {

// (the chain: 450 m, EA 1e9 N, 1000 N/m in water; anchors 400 m either side, 100 m down)
const forces::CatenaryParameters kChain{450.0, 1.0e9, 1000.0, true, 0.0};
constexpr double kMass = 1.0e5;  // kg, the buoy

// (integrator line, q0) => the buoy between two chain lines (mechanics_fixture.hpp)
std::string mooredBuoy(const std::string& integrator, double q0) {
  return testing::catenaryBuoyScene(integrator, q0);
}

// (surge x) => dHF/dXF of both lines: the west line's span is 400 + x, the east's 400 - x
double surgeStiffness(double x) {
  const auto w = forces::solveCatenary(kChain, 400.0 + x, 100.0);
  const auto e = forces::solveCatenary(kChain, 400.0 - x, 100.0);
  REQUIRE(w.status == forces::CatenaryStatus::Converged);
  REQUIRE(e.status == forces::CatenaryStatus::Converged);
  return w.k11 + e.k11;
}

// (surge x) => the net horizontal tension on the buoy, -HF_west + HF_east, N
double surgeForce(double x) {
  return -forces::solveCatenary(kChain, 400.0 + x, 100.0).hf +
         forces::solveCatenary(kChain, 400.0 - x, 100.0).hf;
}

}  // namespace

TEST_CASE("the lines' k11 is the derivative of their tension: a Richardson difference agrees") {
  const double x = 3.0, h = 0.01;
  const double d1 = (surgeForce(x + h) - surgeForce(x - h)) / (2 * h);
  const double d2 = (surgeForce(x + 2 * h) - surgeForce(x - 2 * h)) / (4 * h);
  CHECK(-(4 * d1 - d2) / 3 == Approx(surgeStiffness(x)).epsilon(1e-7));
}

TEST_CASE("inside a linearisation the accelerations are affine with the analytic slope") {
  const double x0 = 3.0;
  testing::StagedSystem st(testing::buildFromScene(mooredBuoy("{method: hht, dt: 0.05}", x0)));
  auto& kernel = st.data.kernel;
  REQUIRE(kernel.linearises());
  const Eigen::VectorXd q0 = Eigen::VectorXd::Constant(1, x0), v0 = Eigen::VectorXd::Zero(1);
  Eigen::VectorXd a0(1), a(1);
  // (outside) => the nonlinear catenary's accelerations at x0 and x0 + dx
  kernel.acceleration(0.0, q0, v0, a0);
  CHECK(a0[0] * kMass == Approx(surgeForce(x0)).epsilon(1e-9));
  auto at = [&](double dx) {
    kernel.acceleration(0.0, Eigen::VectorXd::Constant(1, x0 + dx), v0, a);
    return a[0];
  };
  const double nonlinear2 = at(2.0), nonlinear05 = at(0.5);
  const double slope = -surgeStiffness(x0) / kMass;
  CHECK(std::abs((nonlinear2 - a0[0]) / 2.0 - slope) > 1e-4 * std::abs(slope));
  {
    // (inside) => the base value the full solve's, every secant the analytic slope
    const dynamics::LinearisedScope linearised(kernel, 0.0, q0, v0);
    const double base = at(0.0);
    CHECK(base == Approx(a0[0]).epsilon(1e-9));
    for (double dx : {-2.0, 0.5, 2.0, 1e-3})
      CHECK((at(dx) - base) / dx == Approx(slope).epsilon(1e-10));
  }
  // (released) => the nonlinear catenary again (its solve's tolerance apart: the warm start moved)
  CHECK(at(2.0) == Approx(nonlinear2).epsilon(1e-10));
  CHECK(at(0.5) == Approx(nonlinear05).epsilon(1e-10));
}

TEST_CASE("a moored buoy's stiffness estimate is sqrt(k/m) of the lines' analytic stiffness") {
  for (double x0 : {0.0, 3.0, -8.0}) {
    const auto e = mechanics::estimateStiffness(
        testing::buildFromScene(mooredBuoy("{method: rk4, dt: 0.01}", x0)));
    INFO("x0 = " << x0 << ": " << mechanics::describe(e));
    // (the estimate's 1e-7 m step on 400 m spans: the step itself is rounded to about 6e-14 m,
    // 2.3e-7 of K here; differencing the solve instead gave up to 7e-6)
    CHECK(e.omegaMax == Approx(std::sqrt(surgeStiffness(x0) / kMass)).epsilon(1e-6));
    CHECK(e.body == "buoy");
  }
}

TEST_CASE("the implicit methods with the linearised Newton matrices follow an RK4 reference") {
  // (released 8 m off its equilibrium) => the surge at 0.5 s intervals over 20 s
  const double until = 20.0;
  testing::SceneDir ref;
  const auto expected =
      testing::simulateScene(ref, mooredBuoy("{method: rk4, dt: 0.005}", 8.0), until);
  const int q = expected.column("surge.q[m]");
  REQUIRE(q > 0);
  double swing = 0.0;
  for (const auto& r : expected.rows) swing = std::max(swing, std::abs(r[q]));
  REQUIRE(swing > 7.9);
  for (const char* integrator : {"{method: hht, dt: 0.02}", "{method: generalized_alpha, dt: 0.02}",
                                 "{method: cvode_bdf, dt: 0.1, rtol: 1.0e-8, atol: 1.0e-9}",
                                 "{method: arkode_dirk, dt: 0.1, rtol: 1.0e-8, atol: 1.0e-9}"}) {
    testing::SceneDir dir;
    const auto got = testing::simulateScene(dir, mooredBuoy(integrator, 8.0), until);
    REQUIRE(got.rows.size() == expected.rows.size());
    double worst = 0.0;
    for (std::size_t k = 0; k < got.rows.size(); ++k)
      worst = std::max(worst, std::abs(got.rows[k][q] - expected.rows[k][q]));
    INFO(integrator << ": worst surge difference " << worst << " m");
    CHECK(worst < 2e-3 * swing);
  }
}
