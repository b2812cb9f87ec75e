// The rankine_td provider: (1) driven by a prescribed heave it returns exactly the emp march's
// memory force, held between panel steps; (2) its carried state restores a run bit for bit;
// (3) a floating hemisphere (mass rho (2/3) pi a^3, A_inf on the left-hand side, a linear
// hydrostatic spring C33 = rho g pi a^2) released 5 cm high decays with the damping ratio
// B / (2 (M + A) w) and the period of the solver's own A(w), B(w) at the natural frequency
// (forced oscillation of the same panel model); without the provider it does not decay; (4) in a
// two-component sea its marched excitation is the sum of the single-component runs, and in an
// irregular sea it agrees with the convolution of the same panels' excitation response.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "dynamics/added_mass.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/model_builder.hpp"
#include "dynamics/multibody_system.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/hydro/forced_oscillation.hpp"
#include "forces/hydro/impulse_response_force.hpp"
#include "forces/hydro/irregular_sea.hpp"
#include "forces/hydro/rankine_td_provider.hpp"
#include "forces/hydro/td_impulse_response.hpp"
#include "td_fixtures.hpp"

using namespace yardsim;
using namespace yardsim::forces::hydro;
using namespace yardsim::forces::hydro::test;

namespace {

// (with A_inf) => a hemisphere's body on a vertical prismatic joint, origin at the waterline
dynamics::Model heaveBody(const dynamics::Matrix6& aInf) {
  dynamics::ModelBuilder b;
  const double m = kHemisphereMass;
  b.setGravity(
      Vector3::Zero());  // weight and buoyancy balance at the mean pose: only the spring acts
  b.addBody(
      "float", "world", dynamics::Joint::prismatic(Vector3::UnitZ()),
      dynamics::Transform::identity(),
      dynamics::makeInertia(m, Vector3(0.0, 0.0, -0.375), 0.4 * m * Eigen::Matrix3d::Identity()));
  b.setAddedMass("float", dynamics::addedMassAboutOrigin(aInf, Vector3::Zero()));
  return b.build();
}

std::shared_ptr<const RankineTdModel> panels() {
  return std::make_shared<const RankineTdModel>(cubeSphere(1.0, 6), dynamics::Transform{},
                                                hemisphereSettings(1.0));
}

// (provider, model, q, v, t, scratch) => the heave force it adds at the first stage of a step at t
double heaveForce(const RankineTdProvider& p, const dynamics::Model& model, dynamics::Data& d,
                  double z, double w, double t, forces::ProviderScratch& scratch) {
  Eigen::VectorXd q(1), v(1), tau = Eigen::VectorXd::Zero(1);
  q[0] = z;
  v[0] = w;
  dynamics::forwardKinematics(model, d, q, v);
  dynamics::ExternalForces f(model);
  const forces::Stage s{t, model, d, q, v, &scratch, t};
  p.evaluate(s, f, tau);
  return f.bodyFrame(1).tail<3>().z();  // body axes = world axes here
}

}  // namespace

TEST_CASE(
    "driven in heave the provider returns the emp march's force and holds it between panel steps") {
  const auto pm = panels();
  const double panelStep = 0.1, h = 0.05;
  const dynamics::Model model = heaveBody(pm->aInf());
  const RankineTdProvider p("radiation", model, 1, pm, panelStep);
  dynamics::Data d(model);
  auto scratch = p.makeScratch();
  // the same march by hand
  FreeSurfaceState state = quietSurface(*pm);
  EmpScratch emp = makeEmpScratch(*pm);
  const Eigen::VectorXd heave = pm->modes().col(2), none;
  double held = 0.0;
  for (int n = 0; n < 80; ++n) {
    const double t = n * h, w = 0.3 * std::sin(2.5 * t) * std::min(1.0, t);
    if (n % 2 == 0) {
      const Eigen::VectorXd a = w * heave;
      held = empStep(*pm, panelStep, a, none, state, emp)[2];
    }
    CHECK(heaveForce(p, model, d, 0.0, w, t, *scratch) == held);
  }
  CHECK(held != 0.0);
}

TEST_CASE("the provider's carried state restores a run bit for bit") {
  const auto pm = panels();
  const dynamics::Model model = heaveBody(pm->aInf());
  const RankineTdProvider p("radiation", model, 1, pm, 0.1);
  dynamics::Data d(model);
  auto scratch = p.makeScratch();
  const auto w = [](double t) { return 0.2 * std::sin(3.0 * t); };
  for (int n = 0; n < 30; ++n) heaveForce(p, model, d, 0.0, w(n * 0.1), n * 0.1, *scratch);
  std::vector<double> saved;
  scratch->carried(saved);
  REQUIRE(saved.size() == 7 + 2 * static_cast<std::size_t>(pm->problem().surfaceCount()));
  std::vector<double> first, second;
  for (int n = 30; n < 50; ++n)
    first.push_back(heaveForce(p, model, d, 0.0, w(n * 0.1), n * 0.1, *scratch));
  auto fresh = p.makeScratch();
  fresh->restoreCarried(saved);
  for (int n = 30; n < 50; ++n)
    second.push_back(heaveForce(p, model, d, 0.0, w(n * 0.1), n * 0.1, *fresh));
  CHECK(first == second);
}

TEST_CASE("a panel step above the emp limit is refused with the numbers") {
  const auto pm = panels();
  const dynamics::Model model = heaveBody(pm->aInf());
  CHECK_THROWS_WITH(RankineTdProvider("radiation", model, 1, pm, 0.5),
                    Catch::Contains("above the emp limit") && Catch::Contains("radiation"));
}

TEST_CASE(
    "a floating hemisphere released in heave decays at the radiation damping of its natural "
    "frequency") {
  const auto pm = panels();
  const dynamics::Model model = heaveBody(pm->aInf());
  const double c33 =
      kRho * kG *
      std::numbers::pi;  // waterplane of the 24-gon is 1 % smaller; the same spring for both sides
  const auto run = [&](bool radiation) {
    // (RK4 at h, the provider at 2 h) => upward zero crossings and peaks of the heave
    const double h = 0.04;
    const RankineTdProvider p("radiation", model, 1, pm, 2 * h);
    auto scratch = p.makeScratch();
    dynamics::MultibodySystem system(model);
    double stepStart = 0.0;
    system.setForces([&](double ts, const Eigen::VectorXd& qs, const Eigen::VectorXd& vs,
                         const dynamics::Data& d, dynamics::ExternalForces& f,
                         Eigen::VectorXd& tau) {
      tau[0] -= c33 * qs[0];
      if (radiation)
        p.evaluate(forces::Stage{ts, model, d, qs, vs, scratch.get(), stepStart}, f, tau);
    });
    dynamics::Rk4 rk4(model);
    double t = 0.0;
    Eigen::VectorXd q(1), v(1);
    q[0] = 0.05;
    v[0] = 0.0;
    std::vector<double> peaks, ups;
    double prev = q[0], prevPrev = q[0];
    for (int n = 0; n < 400; ++n) {
      stepStart = t;
      rk4.step(system, t, q, v, h);
      if (prev > prevPrev && prev > q[0]) peaks.push_back(prev);
      if (prev < 0.0 && q[0] >= 0.0) ups.push_back(t - h * q[0] / (q[0] - prev));
      prevPrev = prev;
      prev = q[0];
    }
    return std::make_pair(peaks, ups);
  };
  const auto [peaks, ups] = run(true);
  REQUIRE(peaks.size() >= 3);
  REQUIRE(ups.size() >= 3);
  const double period = ups[2] - ups[1], omega = 2.0 * std::numbers::pi / period;
  const double decrement = std::log(peaks[1] / peaks[2]);
  const double zeta =
      decrement / std::sqrt(4.0 * std::numbers::pi * std::numbers::pi + decrement * decrement);
  // (the solver's own A and B at that frequency) => the expected damping ratio and period
  ForcedOscillationSettings f;
  f.omega = omega;
  f.dt = 0.04;
  const RadiationCoefficients r = forcedOscillation(*pm, 2, f);
  const double mass = kHemisphereMass + r.addedMass[2];
  const double zetaExpected = r.damping[2] / (2.0 * mass * std::sqrt(c33 / mass));
  const double periodExpected =
      2.0 * std::numbers::pi /
      (std::sqrt(c33 / mass) * std::sqrt(1.0 - zetaExpected * zetaExpected));
  INFO("period " << period << " s (expected " << periodExpected << "), damping ratio " << zeta
                 << " (expected " << zetaExpected << ")");
  CHECK(period == Approx(periodExpected).epsilon(0.03));
  CHECK(zeta == Approx(zetaExpected).epsilon(0.15));
  const auto [still, unused] = run(false);
  CHECK(still[2] / still[1] > 0.999);
}

TEST_CASE("a barge heaving in a regular beam wave moves alike on both paths", "[long]") {
  // (a 4 x 2 m box at 1 m draft on a heave joint, a linear spring C33 = rho g A_wp) in a regular
  // wave of 0.1 m travelling along the body's y axis (beam sea): the provider marching radiation
  // + diffraction + Froude-Krylov against the Cummins convolution with the excitation response
  // of the same panel model (Froude-Krylov + diffraction)
  const auto pm = std::make_shared<const RankineTdModel>(
      panelMesh(forces::boxMesh(Vector3(4.0, 2.0, 2.0), 8, 4, 4)), dynamics::Transform{},
      hemisphereSettings(0.4, 3.0, 25.0));
  const double mass = kRho * 8.0, c33 = kRho * kG * 8.0, omega = 2.0;
  forces::WaterProperties water;
  water.density = kRho;
  water.gravity = kG;
  water.ramp = 6.0;
  const auto sea = std::make_shared<const forces::AiryWaves>(
      water, std::vector<forces::WaveComponent>{
                 {0.1, 2.0 * std::numbers::pi / omega, 0.5 * std::numbers::pi, 0.3}});
  const double h = std::min(0.04, 0.45 * empLimit(*pm, 60).dtMax);
  const int steps = static_cast<int>(std::lround(30.0 / h));
  // (A_inf, provider) => the heave history, RK4 at h from rest
  const auto run = [&](const dynamics::Matrix6& aInf, auto makeProvider) {
    dynamics::ModelBuilder b;
    b.setGravity(Vector3::Zero());
    b.addBody(
        "barge", "world", dynamics::Joint::prismatic(Vector3::UnitZ()),
        dynamics::Transform::identity(),
        dynamics::makeInertia(mass, Vector3(0.0, 0.0, -0.5), mass * Eigen::Matrix3d::Identity()));
    // (the box's discrete A_inf is symmetric only to the panel error) => its symmetric part
    b.setAddedMass(
        "barge", dynamics::addedMassAboutOrigin(0.5 * (aInf + aInf.transpose()), Vector3::Zero()));
    const dynamics::Model model = b.build();
    const auto p = makeProvider(model);
    auto scratch = p->makeScratch();
    dynamics::MultibodySystem system(model);
    double stepStart = 0.0;
    system.setForces([&](double ts, const Eigen::VectorXd& qs, const Eigen::VectorXd& vs,
                         const dynamics::Data& d, dynamics::ExternalForces& f,
                         Eigen::VectorXd& tau) {
      tau[0] -= c33 * qs[0];
      p->evaluate(forces::Stage{ts, model, d, qs, vs, scratch.get(), stepStart}, f, tau);
    });
    dynamics::Rk4 rk4(model);
    double t = 0.0;
    Eigen::VectorXd q = Eigen::VectorXd::Zero(1), v = Eigen::VectorXd::Zero(1);
    std::vector<double> z;
    for (int n = 0; n < steps; ++n) {
      stepStart = t;
      rk4.step(system, t, q, v, h);
      z.push_back(q[0]);
    }
    return z;
  };
  const auto marched = run(pm->aInf(), [&](const dynamics::Model& m) {
    return std::make_unique<RankineTdProvider>("rankine_td", m, 1, pm, 2.0 * h, sea, true);
  });
  ImpulseResponseSettings s;
  s.solver = pm->settings();
  s.dt = 2.0 * h;
  s.memory = 10.0;
  s.bandStart = 1.3 * 2.5;
  s.bandEnd = 2.0 * 2.5;
  s.headings = {0.5 * std::numbers::pi};
  s.cutoff = 1.6 * omega;
  s.froudeKrylov = true;
  // (the excitation response's transfer function is X(w) W(w), W = exp(-(w/w_c)^2): the force
  // divides W out, ImpulseResponse::excitationWindow)
  const auto response = std::make_shared<const ImpulseResponse>(computeImpulseResponse(*pm, s));
  REQUIRE(response->excitationWindow == s.cutoff);
  const auto convolved = run(response->aInf, [&](const dynamics::Model& m) {
    return std::make_unique<ImpulseResponseForce>("impulse_response", m, 1, response, sea);
  });
  // (the steady state, after the ramp and the start's transient) => amplitudes and difference
  double amplitude = 0.0, other = 0.0, worst = 0.0;
  for (std::size_t n = marched.size() / 2; n < marched.size(); ++n) {
    amplitude = std::max(amplitude, std::abs(marched[n]));
    other = std::max(other, std::abs(convolved[n]));
    worst = std::max(worst, std::abs(marched[n] - convolved[n]));
  }
  INFO("heave amplitude " << amplitude << " m marched, " << other
                          << " m convolved; largest difference " << worst << " m");
  CHECK(amplitude > 0.02);  // (a 0.1 m wave lifts the barge by several cm)
  // (measured: amplitudes 0.0772 and 0.0805 m, 4.3 % apart, difference 7.9 % of the amplitude)
  CHECK(other == Approx(amplitude).epsilon(0.06));
  CHECK(worst < 0.12 * amplitude);
}

namespace {
// (provider, model of one body on a joint, panel step h, steps) => the force it adds, naval order
// in the body frame, at the start of each step of h with the body held at its mean pose (the
// excitation alone: no radiation)
std::vector<Vector6> heldAtRest(const forces::ForceProvider& p, const dynamics::Model& model,
                                double h, int steps) {
  dynamics::Data d(model);
  auto scratch = p.makeScratch();
  const Eigen::VectorXd q = Eigen::VectorXd::Zero(model.nq), v = Eigen::VectorXd::Zero(model.nv);
  dynamics::forwardKinematics(model, d, q, v);
  std::vector<Vector6> out;
  for (int n = 0; n < steps; ++n) {
    const double t = n * h;
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(model.nv);
    dynamics::ExternalForces f(model);
    p.evaluate(forces::Stage{t, model, d, q, v, scratch.get(), t}, f, tau);
    const dynamics::Force F = f.bodyFrame(1);  // [moment; force]
    out.push_back((Vector6() << F.tail<3>(), F.head<3>()).finished());
  }
  return out;
}

// (water, components) => the sea, shared
std::shared_ptr<const forces::AiryWaves> seaOf(const forces::WaterProperties& water,
                                               std::vector<forces::WaveComponent> c) {
  return std::make_shared<const forces::AiryWaves>(water, std::move(c));
}
}  // namespace

TEST_CASE("the marched excitation in a two-component sea is the sum of its single-component runs") {
  // (the hemisphere held at rest, Froude-Krylov + diffraction marched every 0.1 s for 12 s) =>
  // the force of two components from different directions equals the sum of each alone to
  // round-off: the provider's incident tables and the march are linear in the sea
  const auto pm = panels();
  const dynamics::Model model = heaveBody(pm->aInf());
  forces::WaterProperties water;
  water.density = kRho;
  water.gravity = kG;
  water.ramp = 3.0;
  const forces::WaveComponent a{0.2, 3.0, 0.0, 0.3}, b{0.15, 2.2, 2.0, 1.1};
  const double h = 0.1;
  const int steps = 120;
  auto run = [&](std::vector<forces::WaveComponent> c) {
    const RankineTdProvider p("excitation", model, 1, pm, h, seaOf(water, std::move(c)), true);
    return heldAtRest(p, model, h, steps);
  };
  const auto both = run({a, b}), first = run({a}), second = run({b});
  double largest = 0.0, largestSecond = 0.0, worst = 0.0;
  for (int n = 0; n < steps; ++n) {
    largest = std::max(largest, both[n].cwiseAbs().maxCoeff());
    largestSecond = std::max(largestSecond, second[n].cwiseAbs().maxCoeff());
    worst = std::max(worst, (both[n] - first[n] - second[n]).cwiseAbs().maxCoeff());
  }
  INFO("largest force " << largest << " N, second component alone " << largestSecond
                        << " N; largest difference from the sum " << worst << " N");
  CHECK(largestSecond > 0.2 * largest);  // (both components matter)
  CHECK(worst < 1e-10 * largest);
}

TEST_CASE("in an irregular sea the marched excitation agrees with the convolution of its response",
          "[long]") {
  // (the hemisphere held at rest in a long-crested JONSWAP sea, Hs 0.3 m, peaking at half the
  // frequency the free surface resolves, cut at 0.8 of it) => the provider's marched Froude-Krylov +
  // diffraction force against ImpulseResponseForce's convolution of the excitation response of the
  // same panel model with the same elevation, after the 4 s ramp and the start's transient
  const auto pm = panels();
  const dynamics::Model model = heaveBody(pm->aInf());
  const double h = 0.05, wc = resolvedFrequency(*pm);
  // (a swell peaking at half the resolved frequency, cut at 0.8 of it: irregular_sea.hpp)
  forces::hydro::IrregularSea irregular;
  irregular.hs = 0.3;
  irregular.tp = 2.0 * std::numbers::pi / (0.5 * wc);
  irregular.cutoff = 0.8 * wc;
  irregular.seed = 16;
  irregular.components = 40;
  const std::vector<forces::WaveComponent> kept = irregularWaves(irregular);
  REQUIRE(kept.size() == 40);
  forces::WaterProperties water;
  water.density = kRho;
  water.gravity = kG;
  water.ramp = 4.0;
  const auto sea = seaOf(water, kept);
  const int steps = static_cast<int>(std::lround(30.0 / h));
  const RankineTdProvider marchedProvider("marched", model, 1, pm, h, sea, true);
  const auto marched = heldAtRest(marchedProvider, model, h, steps);
  ImpulseResponseSettings s;
  s.solver = pm->settings();
  s.dt = h;
  s.memory = 10.0;
  s.headings = {0.0};
  s.cutoff = wc;
  s.froudeKrylov = true;
  const auto response = std::make_shared<const ImpulseResponse>(computeImpulseResponse(*pm, s));
  const ImpulseResponseForce convolvedProvider("convolved", model, 1, response, sea);
  const auto convolved = heldAtRest(convolvedProvider, model, h, steps);
  // (after 10 s) => per force row surge, heave and pitch: the largest difference against the range
  for (const int i : {0, 2, 4}) {
    double lo = 0.0, hi = 0.0, worst = 0.0;
    for (int n = static_cast<int>(std::lround(10.0 / h)); n < steps; ++n) {
      lo = std::min(lo, marched[n][i]);
      hi = std::max(hi, marched[n][i]);
      worst = std::max(worst, std::abs(marched[n][i] - convolved[n][i]));
    }
    INFO("resolved " << wc << " rad/s; row " << i << ": range " << hi - lo << ", largest difference " << worst << " ("
                << 100.0 * worst / (hi - lo) << " % of the range)");
    CHECK(hi - lo > 0.0);
    CHECK(worst < 0.04 * (hi - lo));
  }
}
