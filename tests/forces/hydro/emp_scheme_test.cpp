// The emp scheme's stability limit g lambda_max dt^2 <= 4, checked by running it: from the same
// disturbed free surface a step 3 % below the computed limit stays bounded and a step 3 % above
// it grows without bound. The largest eigenvalue is about 3/h for the smallest panel size h (the
// issue's 3.44/h is for a uniform grid of square panels). And the damping zone absorbs an
// outgoing ring wave: the energy that comes back from it is measured.
#include <catch2/catch.hpp>

#include <cmath>

#include "forces/hydro/emp_scheme.hpp"
#include "td_fixtures.hpp"

using namespace yardsim::forces::hydro;
using namespace yardsim::forces::hydro::test;

namespace {

// (model, dt, steps) => largest |zeta| over the run divided by the initial largest |zeta|
double growth(const RankineTdModel& model, double dt, int steps) {
  FreeSurfaceState state = quietSurface(model);
  for (Eigen::Index k = 0; k < state.zeta.size(); ++k)
    state.zeta[k] = 1e-3 * std::sin(0.37 * static_cast<double>(k * k));
  EmpScratch scratch = makeEmpScratch(model);
  const Eigen::VectorXd still = Eigen::VectorXd::Zero(model.problem().bodyCount()), none;
  const double start = state.zeta.cwiseAbs().maxCoeff();
  double largest = start;
  for (int n = 0; n < steps; ++n) {
    empStep(model, dt, still, none, state, scratch);
    largest = std::max(largest, state.zeta.cwiseAbs().maxCoeff());
    if (!(largest < 1e6 * start)) break;
  }
  return largest / start;
}

}  // namespace

TEST_CASE("the emp step limit separates bounded from growing runs") {
  RankineTdSettings s = hemisphereSettings(1.0, 2.0, 8.0);
  const RankineTdModel model(cubeSphere(1.0, 6), yardsim::dynamics::Transform{}, s);
  const EmpLimit limit = empLimit(model);
  INFO("lambda_max " << limit.lambdaMax << " 1/m, h " << limit.smallestPanel << " m, lambda h "
                     << limit.lambdaMax * limit.smallestPanel << ", dt_max " << limit.dtMax
                     << " s");
  CHECK(limit.lambdaMax * limit.smallestPanel > 2.5);
  CHECK(limit.lambdaMax * limit.smallestPanel < 3.6);
  CHECK(limit.dtMax == Approx(2.0 / std::sqrt(kG * limit.lambdaMax)));
  const double below = growth(model, 0.97 * limit.dtMax, 600),
               above = growth(model, 1.03 * limit.dtMax, 600);
  INFO("growth at 0.97 dt_max " << below << ", at 1.03 dt_max " << above);
  CHECK(below < 10.0);
  CHECK(above > 1e4);
}

TEST_CASE("the damping zone absorbs an outgoing ring wave") {
  // a hemisphere heaved once (a smooth pulse of period T) sends out a ring wave; the free-surface
  // energy E = (rho g / 2) sum zeta^2 A + (rho / 2) phi phi_n A is measured inside the inner
  // region (r < R - width) once the pulse has left it and again after the time the reflection
  // would need to come back. Without a zone the wave reflects off the truncation edge.
  const double ka = 1.0, period = 2.0 * std::numbers::pi / std::sqrt(kG * ka);
  const auto energyLeft = [&](double strength) {
    RankineTdSettings s = hemisphereSettings(ka, 3.0, 8.0);
    s.freeSurface.dampingStrength *= strength;
    const RankineTdModel model(cubeSphere(1.0, 6), yardsim::dynamics::Transform{}, s);
    const double dt = std::min(0.9 * empLimit(model, 60).dtMax, period / 30.0);
    const double inner = s.freeSurface.truncationRadius - s.freeSurface.dampingWidth;
    FreeSurfaceState state = quietSurface(model);
    EmpScratch scratch = makeEmpScratch(model);
    const Eigen::VectorXd heave = model.modes().col(2), none;
    Eigen::VectorXd a(heave.size());
    // (state) => potential energy in the inner region, J per (m of amplitude)^2
    const auto innerEnergy = [&]() {
      double e = 0.0;
      for (int k = 0; k < model.problem().surfaceCount(); ++k) {
        const Panel& p = model.problem().surface()[static_cast<std::size_t>(k)];
        if (p.centroid.head<2>().norm() < inner)
          e += 0.5 * kRho * kG * state.zeta[k] * state.zeta[k] * p.area;
      }
      return e;
    };
    double peak = 0.0, late = 0.0;
    const double group = 0.5 * std::sqrt(kG / ka);  // deep-water group velocity
    const double back = 2.0 * s.freeSurface.truncationRadius / group;
    const int steps = static_cast<int>((period + 1.2 * back) / dt);
    for (int n = 0; n < steps; ++n) {
      const double t = n * dt;
      const double v = t < period ? std::sin(2.0 * std::numbers::pi * t / period) *
                                        std::sin(std::numbers::pi * t / period)
                                  : 0.0;
      a = v * heave;
      empStep(model, dt, a, none, state, scratch);
      peak = std::max(peak, innerEnergy());
      if (t > 1.0 * back) late = std::max(late, innerEnergy());
    }
    return late / peak;
  };
  const double with = energyLeft(1.0), without = energyLeft(0.0);
  INFO("energy back in the inner region / peak: with the zone " << with << ", without " << without);
  CHECK(with < 0.05);
  CHECK(without > 5.0 * with);
}
