// The growth of the marched free surface's own short waves (issue 16): the estimate from the
// eigenvalues of L: phi -> phi_z against an independent eigenvalue solve of the whole
// continuous emp system with its beach, the uniform surface damping lowering every rate by
// itself (phi = e^(-nu0 t) psi), a long march that grows at the estimated rate without it and
// stays bounded with it, forced heave of the hemisphere against Hulme (1982) with and without it,
// and the door's message.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "forces/hydro/emp_scheme.hpp"
#include "forces/hydro/forced_oscillation.hpp"
#include "forces/hydro/surface_growth.hpp"
#include "forces/hydro/td_checks.hpp"
#include "td_fixtures.hpp"

using namespace yardsim::forces::hydro;
using namespace yardsim::forces::hydro::test;
using Catch::Matchers::Contains;

namespace {

// (box barge's mesh at w = 2 rad/s, uniform damping nu0) => the model (580 free-surface panels)
RankineTdModel bargeModel(double nu0) {
  RankineTdSettings s = BoxBarge::settings(2.0);
  s.freeSurface.surfaceDamping = nu0;
  return RankineTdModel(BoxBarge{}.hull(), yardsim::dynamics::Transform{}, s);
}

// (model) => the largest real part of the eigenvalues of d/dt [zeta; phi] = [-2 nu, L + nu^2/g;
// -g, 0] [zeta; phi], the beach and the uniform damping in nu (order 2 Nf)
double fullSystemRate(const RankineTdModel& model) {
  const MixedProblem& pb = model.problem();
  const int nb = pb.bodyCount(), nf = pb.surfaceCount();
  const double g = model.settings().g;
  const Eigen::MatrixXd u =
      pb.solve(Eigen::MatrixXd::Zero(nb, nf), Eigen::MatrixXd::Identity(nf, nf));
  const Eigen::ArrayXd nu = model.damping().array();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * nf, 2 * nf);
  a.topRightCorner(nf, nf) = -u.bottomRows(nf);
  a.topLeftCorner(nf, nf).diagonal() = -2.0 * nu.matrix();
  a.topRightCorner(nf, nf).diagonal() += (nu * nu / g).matrix();
  a.bottomLeftCorner(nf, nf).diagonal().setConstant(-g);
  return Eigen::EigenSolver<Eigen::MatrixXd>(a, false).eigenvalues().real().maxCoeff();
}

// (model, dt, end time, window) => largest |zeta| per window of the hull-held march from a
// disturbed surface
std::vector<double> marchPeaks(const RankineTdModel& model, double dt, double end, double window) {
  FreeSurfaceState state = quietSurface(model);
  for (Eigen::Index k = 0; k < state.zeta.size(); ++k)
    state.zeta[k] = 1e-3 * std::sin(0.37 * static_cast<double>(k * k));
  EmpScratch scratch = makeEmpScratch(model);
  const Eigen::VectorXd still = Eigen::VectorXd::Zero(model.problem().bodyCount()), none;
  std::vector<double> peaks(static_cast<std::size_t>(std::lround(end / window)), 0.0);
  const int steps = static_cast<int>(std::lround(end / dt));
  for (int n = 0; n < steps; ++n) {
    empStep(model, dt, still, none, state, scratch);
    const auto w = std::min(peaks.size() - 1, static_cast<std::size_t>(n * dt / window));
    peaks[w] = std::max(peaks[w], state.zeta.cwiseAbs().maxCoeff());
  }
  return peaks;
}

}  // namespace

TEST_CASE("the barge mesh grows and the surface damping lowers every rate by itself") {
  const RankineTdModel plain = bargeModel(0.0), damped = bargeModel(0.01);
  const SurfaceGrowth g0 = surfaceGrowth(plain), g1 = surfaceGrowth(damped);
  const SurfaceGrowth s0 = surfaceGrowth(plain, 0.1), s1 = surfaceGrowth(damped, 0.1);
  INFO("continuous " << g0.rate << " 1/s at " << g0.frequency << " rad/s, with nu0 = 0.01: "
                     << g1.rate << "; per 0.1 s step " << s0.rate << " and " << s1.rate);
  // (the defect) => short waves (about 5 rad/s) grow at some 0.007 1/s on this mesh
  CHECK(g0.rate > 0.005);
  CHECK(g0.frequency > 4.0);
  // (phi = e^(-nu0 t) psi) => every continuous rate lowered by nu0
  CHECK(std::abs(g1.rate - (g0.rate - 0.01)) < 1e-12);
  // (the emp step at 0.1 s, well below its 0.27 s limit) => near the continuous rates
  CHECK(s0.rate == Approx(g0.rate).epsilon(0.1));
  CHECK(s1.rate < 0.0);
}

TEST_CASE("the growth estimate equals the full system's with its beach", "[long]") {
  const RankineTdModel plain = bargeModel(0.0), damped = bargeModel(0.01);
  const SurfaceGrowth g0 = surfaceGrowth(plain);
  const double full0 = fullSystemRate(plain), full1 = fullSystemRate(damped);
  INFO("estimate " << g0.rate << " 1/s, full system " << full0 << "; with nu0 = 0.01: " << full1);
  // (beach left out of the estimate) => the same rate as the whole system with its beach
  CHECK(std::abs(g0.rate - full0) < 1e-3 * g0.rate);
  // (phi = e^(-nu0 t) psi, the beach in nu too) => the whole system's rate lowered by nu0
  CHECK(std::abs(full1 - (full0 - 0.01)) < 1e-6);
  CHECK(full1 < 0.0);
}

TEST_CASE("a long march grows at the estimated rate and stays bounded with the surface damping",
          "[long]") {
  const RankineTdModel plain = bargeModel(0.0);
  const double dt = 0.25;  // (emp limit 0.27 s: the scheme adds growth, 0.0092 against 0.0070 1/s)
  const double rate = surfaceGrowth(plain, dt).rate;
  // (no damping, 1,600 s) => the growing mode dominates: its rate from the peaks of 1,100-1,200 s
  // and 1,500-1,600 s
  const std::vector<double> grow = marchPeaks(plain, dt, 1600.0, 100.0);
  const double measured = std::log(grow[15] / grow[11]) / 400.0;
  INFO("estimated " << rate << " 1/s, measured " << measured);
  CHECK(std::abs(measured - rate) < 0.15 * rate);
  // (uniform damping 20 % above the rate, 4,000 s) => no growth: every later peak below the start's
  const RankineTdModel damped = bargeModel(1.2 * rate);
  CHECK(surfaceGrowth(damped, dt).rate < 0.0);
  const std::vector<double> kept = marchPeaks(damped, dt, 4000.0, 500.0);
  INFO("peaks " << kept[0] << " ... " << kept.back());
  CHECK(*std::max_element(kept.begin() + 1, kept.end()) <= kept[0]);
  CHECK(kept.back() < 0.5 * kept[0]);
}

TEST_CASE("the door's growth check gives the numbers and the damping that stops it") {
  SurfaceGrowth g;
  g.rate = 0.005;
  g.frequency = 5.26;
  CHECK_FALSE(checkSurfaceGrowth(g, 0.0, 400.0));  // (e^2 = 7.4 at 400 s)
  const auto m = checkSurfaceGrowth(g, 0.0, 1000.0);
  REQUIRE(m);
  CHECK_THAT(*m, Contains("grow at 0.005 1/s (at 5.26 rad/s)") && Contains("factor 148.4") &&
                     Contains("surface_damping to at least 0.0055 1/s") &&
                     Contains("before 400 s"));
  g.rate = -0.001;  // (damped)
  CHECK_FALSE(checkSurfaceGrowth(g, 0.006, 1e5));
}

TEST_CASE("forced heave with the surface damping stays at Hulme's coefficients", "[long]") {
  // (nu0 = 0.01 1/s, ten times the growth it has to stop on the barge's meshes) => the forced
  // response is the undamped one at the complex frequency w - i nu0: A and B move by about
  // nu0 / w of their slope, well inside the tolerances of forced_oscillation_test (Hulme 1982
  // Table 1, K a, A33 / (rho 2/3 pi a^3), B33 / (rho 2/3 pi a^3 w))
  struct Row {
    double ka, a, b;
  };
  for (const Row row : {Row{0.6, 0.5381, 0.3271}, Row{2.0, 0.3884, 0.1031}}) {
    double coefficients[2][2];
    for (int damped = 0; damped < 2; ++damped) {
      RankineTdSettings s = hemisphereSettings(row.ka);
      s.freeSurface.surfaceDamping = damped ? 0.01 : 0.0;
      const RankineTdModel model(cubeSphere(1.0, 8), yardsim::dynamics::Transform{}, s);
      const double omega = std::sqrt(kG * row.ka), period = 2.0 * std::numbers::pi / omega;
      ForcedOscillationSettings f;
      f.omega = omega;
      f.dt = std::min(0.9 * empLimit(model, 60).dtMax, period / 40.0);
      const RadiationCoefficients r = forcedOscillation(model, 2, f);
      coefficients[damped][0] = r.addedMass[2] / kHemisphereMass;
      coefficients[damped][1] = r.damping[2] / (kHemisphereMass * omega);
    }
    INFO("ka " << row.ka << ": A " << coefficients[0][0] << " / " << coefficients[1][0]
               << " (Hulme " << row.a << "), B " << coefficients[0][1] << " / "
               << coefficients[1][1] << " (Hulme " << row.b << ")");
    CHECK(coefficients[1][0] == Approx(coefficients[0][0]).epsilon(0.005));
    CHECK(coefficients[1][1] == Approx(coefficients[0][1]).epsilon(0.01));
    CHECK(coefficients[1][0] == Approx(row.a).epsilon(0.02));
    CHECK(coefficients[1][1] == Approx(row.b).epsilon(0.05));
  }
}
