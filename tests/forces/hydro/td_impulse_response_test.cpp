// The impulse responses of a floating hemisphere (a = 1 m) from the time-domain solver, checked
// against the same solver's forced oscillation (a different route: one steady sine per frequency)
// and against each other:
//   B(w) = int_0^inf K(t) cos(w t) dt,  A(w) = A_inf - (1/w) int_0^inf K(t) sin(w t) dt  (Ogilvie
//   1964) Haskind (deep water, Newman 1962): B_jj = w^3 / (4 pi rho g^3) int_0^2pi |X_j(beta)|^2
//   dbeta, i.e. heave B33 = w^3 |X3|^2 / (2 rho g^3), surge B11 = w^3 |X1(0)|^2 / (4 rho g^3),
// with X(w) = int h(t) e^(-i w t) dt / W(w) from the excitation response of the incident
// impulse wave. And the cache key: the same inputs give the same key, any change another. And the
// two paths' radiation force histories for one transient motion: the march against the Cummins
// convolution of its responses.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>

#include "forces/airy_waves.hpp"
#include "forces/hydro/emp_scheme.hpp"
#include "forces/hydro/forced_oscillation.hpp"
#include "forces/hydro/frequency_domain.hpp"
#include "forces/hydro/incident_kinematics.hpp"
#include "forces/hydro/radiation_memory.hpp"
#include "forces/hydro/td_impulse_response.hpp"
#include "td_fixtures.hpp"

using namespace yardsim::forces::hydro;
using namespace yardsim::forces::hydro::test;

namespace {

constexpr double kKa = 1.0;
const double kOmega = std::sqrt(kG * kKa);

// (hull divisions) => a model whose free surface and damping zone are sized for ka = 0.4 (an
// impulse radiates long waves too), with panels of ka = 1 / 10 of its wavelength far out
RankineTdSettings impulseSettings() {
  return hemisphereSettings(0.4, 3.0, 25.0);
}

ImpulseResponseSettings settings(const RankineTdModel& model) {
  ImpulseResponseSettings s;
  s.solver = model.settings();
  s.dt = std::min(0.9 * empLimit(model, 60).dtMax, 2.0 * std::numbers::pi / kOmega / 40.0);
  s.memory = 12.0;
  // (the raw K rings at about 7 rad/s, waves the mesh does not resolve; band-limited above)
  s.bandStart = 1.3 * kOmega;
  s.bandEnd = 2.0 * kOmega;
  return s;
}

// (K, dt, w, i, j) => B_ij and A_ij - A_inf,ij by the trapezoidal rule
std::pair<double, double> fromRetardation(const ImpulseResponse& r, double w, int i, int j) {
  double c = 0.0, s = 0.0;
  for (std::size_t k = 0; k < r.radiation.size(); ++k) {
    const double t = static_cast<double>(k) * r.dt,
                 weight = (k == 0 || k + 1 == r.radiation.size() ? 0.5 : 1.0) * r.dt;
    c += weight * r.radiation[k](i, j) * std::cos(w * t);
    s += weight * r.radiation[k](i, j) * std::sin(w * t);
  }
  return {c, -s / w};
}

}  // namespace

TEST_CASE("the impulse responses agree with forced oscillation and with the Haskind relation",
          "[long]") {
  // one model and one set of responses for both checks (the set-up is the slow part)
  const RankineTdModel model(cubeSphere(1.0, 6), yardsim::dynamics::Transform{}, impulseSettings());
  ImpulseResponseSettings s = settings(model);
  s.headings = {0.0};
  s.cutoff = 1.6 * kOmega;
  const ImpulseResponse r = computeImpulseResponse(model, s);
  REQUIRE(r.radiation.size() == static_cast<std::size_t>(std::lround(s.memory / s.dt)) + 1);
  // (with a band limit aInf carries the cut part's added mass: a few per cent)
  CHECK((r.aInf - model.aInf()).norm() < 0.3 * model.aInf().norm());
  CHECK((r.aInf - model.aInf()).norm() > 1e-6 * model.aInf().norm());

  {  // the retardation function decays and gives the forced-oscillation A and B
    // K decays: the last second holds less than 3 % of its peak
    for (const int j : {0, 2}) {
      double peak = 0.0, tail = 0.0;
      for (std::size_t k = 0; k < r.radiation.size(); ++k) {
        peak = std::max(peak, std::abs(r.radiation[k](j, j)));
        if (static_cast<double>(k) * r.dt > s.memory - 1.0)
          tail = std::max(tail, std::abs(r.radiation[k](j, j)));
      }
      CHECK(tail < 0.03 * peak);
    }
    ForcedOscillationSettings f;
    f.omega = kOmega;
    f.dt = s.dt;
    f.periods = 8;
    f.rampPeriods = 2;
    for (const int j : {0, 2}) {
      const RadiationCoefficients forced = forcedOscillation(model, j, f);
      const auto [b, dA] = fromRetardation(r, kOmega, j, j);
      INFO("mode " << j << ": B " << b << " (forced " << forced.damping[j] << "), A "
                   << r.aInf(j, j) + dA << " (forced " << forced.addedMass[j] << ")");
      CHECK(b == Approx(forced.damping[j]).epsilon(0.03));
      CHECK(r.aInf(j, j) + dA == Approx(forced.addedMass[j]).epsilon(0.03));
    }
    // surge-heave coupling vanishes by symmetry
    double coupling = 0.0, diagonal = 0.0;
    for (const auto& K : r.radiation) {
      coupling = std::max(coupling, std::abs(K(0, 2)));
      diagonal = std::max(diagonal, std::abs(K(2, 2)));
    }
    CHECK(coupling < 0.02 * diagonal);
  }

  {  // the excitation response satisfies the Haskind relation with the radiation damping
    REQUIRE(r.excitation.size() == 1);
    REQUIRE(r.excitationStart < 0.0);
    // (h) => X(w) = int h e^(-i w t) dt / W(w)
    std::complex<double> x1 = 0.0, x3 = 0.0;
    for (std::size_t k = 0; k < r.excitation[0].size(); ++k) {
      const double t = r.excitationStart + static_cast<double>(k) * r.dt;
      const std::complex<double> e = std::exp(std::complex<double>(0.0, -kOmega * t)) * r.dt;
      x1 += r.excitation[0][k][0] * e;
      x3 += r.excitation[0][k][2] * e;
    }
    const double window = std::exp(-(kOmega / s.cutoff) * (kOmega / s.cutoff));
    x1 /= window;
    x3 /= window;
    const double w3 = kOmega * kOmega * kOmega, g3 = kG * kG * kG;
    const double b33 = w3 * std::norm(x3) / (2.0 * kRho * g3),
                 b11 = w3 * std::norm(x1) / (4.0 * kRho * g3);
    const auto [b33k, unused3] = fromRetardation(r, kOmega, 2, 2);
    const auto [b11k, unused1] = fromRetardation(r, kOmega, 0, 0);
    INFO("Haskind B33 " << b33 << " vs radiation " << b33k << "; B11 " << b11 << " vs " << b11k
                        << "; |X3| " << std::abs(x3) << " |X1| " << std::abs(x1));
    CHECK(b33 == Approx(b33k).epsilon(0.03));
    CHECK(b11 == Approx(b11k).epsilon(0.03));
  }
}

TEST_CASE("the impulse-response key follows the mesh and the settings") {
  const PanelMesh hull = cubeSphere(1.0, 4);
  const yardsim::dynamics::Transform X_WB{};
  ImpulseResponseSettings s;
  s.solver = hemisphereSettings(kKa);
  s.dt = 0.05;
  const std::string key = impulseResponseKey(hull, X_WB, s);
  CHECK(key.rfind("rankine_td-", 0) == 0);
  CHECK(key.size() == 11 + 16);
  CHECK(impulseResponseKey(hull, X_WB, s) == key);
  ImpulseResponseSettings t = s;
  t.dt = 0.051;
  CHECK(impulseResponseKey(hull, X_WB, t) != key);
  t = s;
  t.solver.freeSurface.truncationRadius += 1.0;
  CHECK(impulseResponseKey(hull, X_WB, t) != key);
  PanelMesh moved = hull;
  moved.vertices[3].x() += 1e-9;
  CHECK(impulseResponseKey(moved, X_WB, s) != key);
}

TEST_CASE("a step above the emp limit is refused with the numbers") {
  const RankineTdModel model(cubeSphere(1.0, 4), yardsim::dynamics::Transform{},
                             hemisphereSettings(kKa, 2.0, 6.0));
  ImpulseResponseSettings s;
  s.solver = model.settings();
  s.dt = 1.2 * empLimit(model, 60).dtMax;
  CHECK_THROWS_WITH(computeImpulseResponse(model, s),
                    Catch::Contains("above the emp limit") && Catch::Contains("lambda_max"));
}

namespace {

// (k, depth h, draft T) => int_{-T}^0 z cosh k(z + h) dz / cosh kh, closed form
double sideMoment(double k, double h, double T) {
  const auto f = [&](double z) {
    return z * std::sinh(k * (z + h)) / k - std::cosh(k * (z + h)) / (k * k);
  };
  return (f(0.0) - f(-T)) / std::cosh(k * h);
}

// (k, h) => the Froude-Krylov pitch moment amplitude of the box barge per metre of wave in a
// head sea on depth h: p = rho g C(z) sin(k x) (the slope phase; the cos part has no pitch
// moment about the box's centre), bottom and end walls, C = cosh k(z + h) / cosh kh
double boxFroudeKrylovPitch(double k, double h) {
  const double L = BoxBarge::kLength, B = BoxBarge::kBeam, T = BoxBarge::kDraft;
  const double bottom = std::cosh(k * (h - T)) / std::cosh(k * h) * B * 2.0 *
                        (std::sin(0.5 * k * L) / (k * k) - 0.5 * L * std::cos(0.5 * k * L) / k);
  const double ends = 2.0 * B * std::sin(0.5 * k * L) * sideMoment(k, h, T);
  return kRho * kG * std::abs(bottom + ends);
}

}  // namespace

TEST_CASE("the long-wave pitch excitation tends to the Froude-Krylov limit on a finite depth") {
  // The box barge on 3 m of water in a head sea; the impulse response's pitch moment at long
  // waves (omega 0.3 and 0.5 rad/s: k h = 0.17 and 0.28, shallow) against the Froude-Krylov
  // closed form of the box (the slope term rho g k A (I_yy + V z_B) at k -> 0) and against the
  // frequency-domain solve of the same panels. A deep-water impulsive wave (the defect this
  // guards: the wave number w^2 / g instead of w^2 = g k tanh kh) gave 0.18 and 0.28 of it.
  const BoxBarge barge;
  RankineTdSettings set = BoxBarge::settings(2.0);
  set.depth = 3.0;
  const RankineTdModel model(barge.hull(), yardsim::dynamics::Transform{}, set);
  ImpulseResponseSettings s;
  s.solver = set;
  s.dt = std::min(0.9 * empLimit(model, 60).dtMax, 0.05);
  s.memory = 20.0;
  s.headings = {0.0};
  s.cutoff = 2.0;
  const ImpulseResponse r = computeImpulseResponse(model, s);
  const FrequencyDomainSolver fd(model);
  for (const double w : {0.3, 0.5}) {
    std::complex<double> x5 = 0.0;
    for (std::size_t n = 0; n < r.excitation[0].size(); ++n) {
      const double t = r.excitationStart + static_cast<double>(n) * r.dt;
      x5 += r.excitation[0][n][4] * std::exp(std::complex<double>(0.0, -w * t)) * r.dt;
    }
    x5 /= std::exp(-(w / s.cutoff) * (w / s.cutoff));
    const double k = yardsim::forces::waveNumber(w, set.depth, kG);
    const double fk = boxFroudeKrylovPitch(k, set.depth);
    const double zb = -0.5 * BoxBarge::kDraft,
                 slope = kRho * kG * k *
                         (BoxBarge::kBeam * std::pow(BoxBarge::kLength, 3) / 12.0 +
                          BoxBarge::kLength * BoxBarge::kBeam * BoxBarge::kDraft * zb);
    const FrequencyResponse x = fd.solve(w, {0.0});
    const double fdPitch = std::abs(x.excitation[0][4]), fdFk = std::abs(x.froudeKrylov[0][4]);
    INFO("w " << w << ": |X5| " << std::abs(x5) << " N m/m, frequency domain " << fdPitch
              << " (its Froude-Krylov part " << fdFk << "), Froude-Krylov closed form " << fk
              << ", slope limit " << slope);
    // the same discrete system by its two routes; the panels' Froude-Krylov against the closed
    // form (-2.2 %: the centroid rule on 1 m panels for the x^2 of the bottom moment); in
    // shallow water the diffraction keeps a share of the pitch moment as w -> 0 (the
    // horizontal velocity per metre of wave tends to sqrt(g / h), not to 0): 5 % here
    CHECK(std::abs(x5) == Approx(fdPitch).epsilon(0.03));
    CHECK(fdFk == Approx(fk).epsilon(0.03));
    CHECK(std::abs(x5) == Approx(fk).epsilon(0.08));
    CHECK(fk == Approx(slope).epsilon(0.05));
  }
}

TEST_CASE("the marched radiation force and the convolution of its impulse responses agree in history",
          "[long]") {
  // (the hemisphere of rankine_td_provider_test.cpp, a = 1 m, its free surface sized for ka = 1,
  // moved by a smooth transient in surge and heave: Gaussian displacements of 0.2 m and 0.1 m)
  // => the emp march's memory force F^M(t) against the Cummins memory force -int K(t - tau)
  // xi_dot(tau) dtau of the impulse responses of the same panels at 0.05 s (RadiationMemory, as
  // ImpulseResponseForce uses it), over 16 s, compared on the response's grid:
  //   march at the response's step, memory 20 s: the same history to round-off (the response is
  //     the march's own, and the march is linear and time-invariant);
  //   march at half the response's step: within a few per cent of the range (the emp scheme's
  //     time discretisation against the response's sampling);
  //   the memory cut to 10 s: the raw K still rings there (the mesh's unresolved short waves, about
  //     3 % of K(0)), and the convolution misses it after 10 s: a difference the test must see.
  const RankineTdModel model(cubeSphere(1.0, 6), yardsim::dynamics::Transform{}, hemisphereSettings(1.0));
  ImpulseResponseSettings s;
  s.solver = model.settings();
  s.dt = 0.05;
  s.memory = 20.0;
  REQUIRE(s.dt < 0.9 * empLimit(model, 60).dtMax);
  const ImpulseResponse ir = computeImpulseResponse(model, s);
  ImpulseResponse shortMemory = ir;
  shortMemory.radiation.resize(static_cast<std::size_t>(std::lround(10.0 / s.dt)));
  // (t) => [surge, sway, heave, roll, pitch, yaw] velocity of x = 0.2 exp(-((t - 3) / 0.7)^2) and
  // z = 0.1 exp(-((t - 2.5) / 0.5)^2)
  const auto velocity = [](double t) {
    Vector6 u = Vector6::Zero();
    u[0] = -2.0 * (t - 3.0) / (0.7 * 0.7) * 0.2 * std::exp(-std::pow((t - 3.0) / 0.7, 2));
    u[2] = -2.0 * (t - 2.5) / (0.5 * 0.5) * 0.1 * std::exp(-std::pow((t - 2.5) / 0.5, 2));
    return u;
  };
  const int samples = static_cast<int>(std::lround(16.0 / s.dt)) + 1;
  // (march step dt / k) => F^M at the response's grid t_n = n dt
  const auto marched = [&](int k) {
    FreeSurfaceState state = quietSurface(model);
    EmpScratch emp = makeEmpScratch(model);
    const Eigen::VectorXd none;
    std::vector<Vector6> out;
    for (int n = 0; n < k * (samples - 1) + 1; ++n) {
      const double t = n * s.dt / k;
      const Eigen::VectorXd a = model.modes() * velocity(t);  // (the pose is the identity: W = B)
      const Vector6 f = empStep(model, s.dt / k, a, none, state, emp);
      if (n % k == 0) out.push_back(f);
    }
    return out;
  };
  // (response) => -mu(t_n) with the velocity committed at every t_n
  const auto convolved = [&](const ImpulseResponse& response) {
    const RetardationKernel kernel(response);
    RadiationMemory memory(kernel);
    std::vector<Vector6> out;
    for (int n = 0; n < samples; ++n) {
      const double t = n * s.dt;
      memory.commit(t, velocity(t));
      out.push_back(-memory.convolution(t, velocity(t)));
    }
    return out;
  };
  const auto same = marched(1), half = marched(2), cummins = convolved(ir), cut = convolved(shortMemory);
  // (surge force, heave force) => the largest difference against the marched force's range
  for (const int i : {0, 2}) {
    double lo = 0.0, hi = 0.0, dSame = 0.0, dHalf = 0.0, dCut = 0.0;
    for (int n = 0; n < samples; ++n) {
      lo = std::min(lo, same[n][i]);
      hi = std::max(hi, same[n][i]);
      dSame = std::max(dSame, std::abs(same[n][i] - cummins[n][i]));
      dHalf = std::max(dHalf, std::abs(half[n][i] - cummins[n][i]));
      dCut = std::max(dCut, std::abs(same[n][i] - cut[n][i]));
    }
    const double range = hi - lo;
    INFO("row " << i << ": range " << range << " N; largest difference from the convolution: "
                << 100.0 * dSame / range << " % marched at the response's step, "
                << 100.0 * dHalf / range << " % at half of it; "
                << 100.0 * dCut / range << " % with the memory cut to 10 s");
    CHECK(range > 100.0);  // (N: a 0.2 m surge of a 2.1 t hemisphere in 1.4 s radiates kN)
    CHECK(dSame < 1e-9 * range);
    CHECK(dHalf < 0.03 * range);
    CHECK(dCut > 0.01 * range);
  }
}
