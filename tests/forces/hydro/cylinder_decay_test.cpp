// Free heave decay of a floating vertical cylinder (radius 1 m, draft 1 m, 24 sides) on both
// hydrodynamic paths of the same panel model: the time-domain Rankine solver marched with the run
// (rankine_td provider, its A_inf on the left-hand side) and the Cummins convolution of the
// impulse responses the same solver computes (ImpulseResponseForce, the response's A_inf on the
// left-hand side). Mass rho V (floating), a linear hydrostatic spring C33 = rho g A_wp, released
// 5 cm high. The two histories agree, and each has the period and damping ratio of a linear
// oscillator with the solver's own A(w_n) and B(w_n) (forced oscillation) at its frequency.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "dynamics/added_mass.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/model_builder.hpp"
#include "dynamics/multibody_system.hpp"
#include "forces/hydro/emp_scheme.hpp"
#include "forces/hydro/forced_oscillation.hpp"
#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/impulse_response_force.hpp"
#include "forces/hydro/rankine_td_provider.hpp"
#include "forces/hydro/td_impulse_response.hpp"
#include "td_fixtures.hpp"

using namespace yardsim;
using namespace yardsim::forces::hydro;
using namespace yardsim::forces::hydro::test;

namespace {

constexpr int kSides = 24;
const double kWaterplane = 0.5 * kSides * std::sin(2.0 * std::numbers::pi / kSides);  // m^2, R = 1
const double kMass = kRho * kWaterplane * 1.0;  // floating at 1 m draft
const double kC33 = kRho * kG * kWaterplane;

// (A_inf) => the cylinder's body on a vertical prismatic joint, origin on the waterline
dynamics::Model heaveBody(const dynamics::Matrix6& aInf) {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());  // weight and buoyancy balance at the mean pose: only the spring
  b.addBody("float", "world", dynamics::Joint::prismatic(Vector3::UnitZ()),
            dynamics::Transform::identity(),
            dynamics::makeInertia(kMass, Vector3(0.0, 0.0, -0.5),
                                  0.3 * kMass * Eigen::Matrix3d::Identity()));
  b.setAddedMass("float", dynamics::addedMassAboutOrigin(aInf, Vector3::Zero()));
  return b.build();
}

struct Decay {
  std::vector<double> z;  // heave at every step, m
  double period = 0.0;    // s, between the 2nd and 3rd upward zero crossings
  double zeta = 0.0;      // damping ratio from the log decrement of the 2nd and 3rd peaks
};

// (model, provider, step h, steps) => the heave history released 5 cm high, RK4
Decay release(const dynamics::Model& model, const forces::ForceProvider& p, double h, int steps) {
  auto scratch = p.makeScratch();
  dynamics::MultibodySystem system(model);
  double stepStart = 0.0;
  system.setForces([&](double ts, const Eigen::VectorXd& qs, const Eigen::VectorXd& vs,
                       const dynamics::Data& d, dynamics::ExternalForces& f, Eigen::VectorXd& tau) {
    tau[0] -= kC33 * qs[0];
    p.evaluate(forces::Stage{ts, model, d, qs, vs, scratch.get(), stepStart}, f, tau);
  });
  dynamics::Rk4 rk4(model);
  double t = 0.0;
  Eigen::VectorXd q(1), v(1);
  q[0] = 0.05;
  v[0] = 0.0;
  Decay out;
  std::vector<double> peaks, ups;
  double prev = q[0], prevPrev = q[0];
  for (int n = 0; n < steps; ++n) {
    stepStart = t;
    rk4.step(system, t, q, v, h);
    out.z.push_back(q[0]);
    if (prev > prevPrev && prev > q[0]) peaks.push_back(prev);
    if (prev < 0.0 && q[0] >= 0.0) ups.push_back(t - h * q[0] / (q[0] - prev));
    prevPrev = prev;
    prev = q[0];
  }
  REQUIRE(peaks.size() >= 3);
  REQUIRE(ups.size() >= 3);
  out.period = ups[2] - ups[1];
  const double decrement = std::log(peaks[1] / peaks[2]);
  out.zeta =
      decrement / std::sqrt(4.0 * std::numbers::pi * std::numbers::pi + decrement * decrement);
  return out;
}

}  // namespace

TEST_CASE("a floating cylinder's heave decay agrees on both hydrodynamic paths", "[long]") {
  // (free surface sized for ka = 0.4: the decay's w_n is about 2.5 rad/s, ka 0.65)
  const auto pm = std::make_shared<const RankineTdModel>(
      verticalCylinder(1.0, -1.0, 0.5, kSides, 6, 2), dynamics::Transform{},
      hemisphereSettings(0.4, 3.0, 25.0));
  const double h = std::min(0.04, 0.45 * empLimit(*pm, 60).dtMax);
  const int steps = static_cast<int>(std::lround(12.0 / h));

  // the time-domain path: the provider every second step
  const dynamics::Model tdModel = heaveBody(pm->aInf());
  const RankineTdProvider td("rankine_td", tdModel, 1, pm, 2.0 * h);
  const Decay marched = release(tdModel, td, h, steps);

  // the impulse-response path: K(t) from the same solver, band-limited above the mesh's waves
  ImpulseResponseSettings s;
  s.solver = pm->settings();
  s.dt = 2.0 * h;
  s.memory = 10.0;
  s.bandStart = 1.3 * 2.5;
  s.bandEnd = 2.0 * 2.5;
  const auto response = std::make_shared<const ImpulseResponse>(computeImpulseResponse(*pm, s));
  const dynamics::Model irModel = heaveBody(response->aInf);
  const ImpulseResponseForce ir("impulse_response", irModel, 1, response, nullptr);
  const Decay convolved = release(irModel, ir, h, steps);

  double worst = 0.0;
  for (std::size_t n = 0; n < marched.z.size(); ++n)
    worst = std::max(worst, std::abs(marched.z[n] - convolved.z[n]));
  INFO("largest difference " << worst << " m of 0.05; periods " << marched.period << " and "
                             << convolved.period << " s; damping ratios " << marched.zeta << " and "
                             << convolved.zeta);
  // (measured: 4.3 % of the release after 12 s, periods 0.35 % and damping ratios 6 % apart; the
  // convolution's A_inf carries the band-limited part of K, its K is sampled every 80 ms)
  CHECK(worst < 0.05 * 0.05);
  CHECK(convolved.period == Approx(marched.period).epsilon(0.01));
  CHECK(convolved.zeta == Approx(marched.zeta).epsilon(0.1));

  // (the solver's own A and B at the decay's frequency) => the linear oscillator's period and
  // damping ratio
  ForcedOscillationSettings f;
  f.omega = 2.0 * std::numbers::pi / marched.period;
  f.dt = 2.0 * h;
  const RadiationCoefficients r = forcedOscillation(*pm, 2, f);
  const double mass = kMass + r.addedMass[2], omegaN = std::sqrt(kC33 / mass);
  const double zetaExpected = r.damping[2] / (2.0 * mass * omegaN);
  const double periodExpected =
      2.0 * std::numbers::pi / (omegaN * std::sqrt(1.0 - zetaExpected * zetaExpected));
  INFO("expected period " << periodExpected << " s, damping ratio " << zetaExpected << " (A33 "
                          << r.addedMass[2] << " kg, B33 " << r.damping[2] << " kg/s)");
  CHECK(marched.period == Approx(periodExpected).epsilon(0.02));
  CHECK(marched.zeta == Approx(zetaExpected).epsilon(0.1));
  CHECK(convolved.period == Approx(periodExpected).epsilon(0.02));
  CHECK(convolved.zeta == Approx(zetaExpected).epsilon(0.1));
}
