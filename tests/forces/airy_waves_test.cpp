// Airy waves: the dispersion relation and its limits, the surface, the kinematic and dynamic
// conditions, continuity, the acceleration as the time derivative of the velocity, the pressure
// vanishing on the surface, the ramp and the refused inputs.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "forces/airy_waves.hpp"

using namespace yardsim::forces;
using yardsim::dynamics::Vector3;

TEST_CASE("the wave number solves the dispersion relation, with its deep and shallow limits") {
  const double g = 9.81;
  for (double T : {4.0, 8.0, 15.0})
    for (double h : {2.0, 20.0, 200.0}) {
      const double w = 2 * M_PI / T, k = waveNumber(w, h, g);
      CHECK(g * k * std::tanh(k * h) == Approx(w * w).epsilon(1e-13));
    }
  CHECK(waveNumber(1.0, INFINITY, g) == Approx(1.0 / g));
  CHECK(waveNumber(2 * M_PI / 8, 1e4, g) == Approx(std::pow(2 * M_PI / 8, 2) / g).epsilon(1e-12));
  // shallow: w = k sqrt(g h) when kh -> 0
  CHECK(waveNumber(0.01, 5.0, g) == Approx(0.01 / std::sqrt(g * 5.0)).epsilon(1e-4));
}

TEST_CASE("surface, kinematics and pressure of a finite-depth oblique wave") {
  const WaterProperties water{1025.0, 9.81, 1.5, 30.0, 0.0};
  const AiryWaves sea(water, {{2.0, 9.0, 0.6, 0.3}});
  const double k = sea.wavenumber(0), w = sea.frequency(0);
  const Vector3 dir(std::cos(0.6), std::sin(0.6), 0.0);
  const double x = 7.0, y = -3.0, t = 2.2;
  const double th = k * (x * dir.x() + y * dir.y()) - w * t + 0.3;
  CHECK(sea.elevation(x, y, t) == Approx(1.5 + std::cos(th)));
  // (linear kinematic condition) => d eta/dt = w at the surface (stretched point z' = 0)
  const double h = 1e-5;
  const double detadt = (sea.elevation(x, y, t + h) - sea.elevation(x, y, t - h)) / (2 * h);
  const Vector3 surf(x, y, sea.elevation(x, y, t));
  CHECK(sea.velocity(surf, t).z() == Approx(detadt).epsilon(1e-6));
  // the horizontal velocity is along the direction of travel
  const Vector3 u = sea.velocity(Vector3(x, y, -5.0), t);
  CHECK(std::abs(u.x() * dir.y() - u.y() * dir.x()) < 1e-12);
  // (pressure) => zero on the surface, hydrostatic + dynamic below, nothing above
  CHECK(std::abs(sea.pressure(surf, t)) < 1e-9);
  CHECK(sea.pressure(surf + Vector3(0, 0, 0.1), t) == 0.0);
  CHECK(sea.velocity(surf + Vector3(0, 0, 0.1), t).norm() == 0.0);
  // the bottom: no vertical velocity
  CHECK(std::abs(sea.velocity(Vector3(x, y, 1.5 - 30.0), t).z()) < 1e-12);
}

TEST_CASE("small-amplitude deep-water kinematics: continuity and d u/dt") {
  const AiryWaves sea(WaterProperties{1025.0, 9.81, 0.0}, {{0.02, 8.0, 0.0, 0.0}});
  const Vector3 p(3.0, 1.0, -4.0);
  const double t = 1.3, h = 1e-4;
  // div u = 0
  double div = 0.0;
  for (int i = 0; i < 3; ++i) {
    Vector3 e = Vector3::Zero();
    e[i] = h;
    div += (sea.velocity(p + e, t)[i] - sea.velocity(p - e, t)[i]) / (2 * h);
  }
  const double scale = sea.velocity(p, t).norm() * sea.wavenumber(0);
  CHECK(std::abs(div) < 1e-3 * scale);
  const Vector3 dudt = (sea.velocity(p, t + h) - sea.velocity(p, t - h)) / (2 * h);
  CHECK((sea.acceleration(p, t) - dudt).norm() < 1e-3 * dudt.norm());
  // deep water: amplitude of u is a w e^{kz} (Wheeler stretching: e^{k(z - eta)}, k eta ~ 1e-3)
  const double a = 0.01, w = sea.frequency(0), k = sea.wavenumber(0);
  double umax = 0.0;
  for (int i = 0; i < 200; ++i) umax = std::max(umax, sea.velocity(p, i * 0.04).norm());
  CHECK(umax == Approx(a * w * std::exp(k * p.z())).epsilon(2e-3));
}

TEST_CASE("the ramp grows the waves from calm, and bad inputs are refused") {
  const AiryWaves sea(WaterProperties{1025.0, 9.81, 0.0, INFINITY, 10.0}, {{2.0, 8.0, 0.0, 0.0}});
  CHECK(sea.elevation(0, 0, 0.0) == 0.0);
  CHECK(sea.elevation(0, 0, 5.0) == Approx(0.5 * std::cos(-2 * M_PI / 8 * 5.0)));
  CHECK(sea.elevation(0, 0, 16.0) == Approx(std::cos(-2 * M_PI / 8 * 16.0)));
  CHECK_THROWS_AS(AiryWaves(WaterProperties{}, {{20.0, 3.0, 0.0, 0.0}}), std::invalid_argument);  // breaking
  CHECK_THROWS_AS(AiryWaves(WaterProperties{-1.0}), std::invalid_argument);
  CHECK_THROWS_AS(AiryWaves(WaterProperties{}, {{1.0, 0.0, 0.0, 0.0}}), std::invalid_argument);
  CHECK(AiryWaves(WaterProperties{}).calm());
  // (start) => calm until then, the ramp after it
  const AiryWaves later(WaterProperties{1025.0, 9.81, 0.0, INFINITY, 10.0, 60.0}, {{2.0, 8.0, 0.0, 0.0}});
  CHECK(later.elevation(0, 0, 59.0) == 0.0);
  CHECK(later.elevation(0, 0, 65.0) == Approx(0.5 * std::cos(-2 * M_PI / 8 * 65.0)));
  CHECK(later.elevation(0, 0, 75.0) == Approx(std::cos(-2 * M_PI / 8 * 75.0)));
}

TEST_CASE("the pressure of many components equals the surface and dynamic pressure summed apart") {
  // (200 components: each cos once, in the stack buffer; 300: computed twice) => the same pressure
  for (int n : {200, 300}) {
    std::vector<WaveComponent> waves;
    for (int i = 0; i < n; ++i) waves.push_back({0.02, 5.0 + 0.037 * i, 0.01 * i, 0.7 * i});
    WaterProperties water{1025.0, 9.81, 0.5, 40.0, 0.0};
    const AiryWaves sea(water, waves);
    for (const Vector3& p : {Vector3(3, -2, -1.5), Vector3(-7, 4, -10), Vector3(1, 1, 0.3)}) {
      for (double t : {0.0, 12.5}) {
        const double eta = sea.elevation(p.x(), p.y(), t);
        const double expected = p.z() > eta ? 0.0 : 1025.0 * 9.81 * (0.5 - p.z()) + sea.dynamicPressure(p, t);
        INFO("n = " << n << " z = " << p.z() << " eta = " << eta);
        CHECK(sea.pressure(p, t) == Approx(expected).epsilon(1e-12).margin(1e-9));
      }
    }
  }
}

TEST_CASE("before the waves start the sea is calm water exactly") {
  // (a finite-depth sea starting at 60 s with a ramp, points below, at and above the level) =>
  // before the start the elevation is the level and the pressure that of calm water, bit for bit;
  // once the ramp is under way neither is
  const WaterProperties water{1025.0, 9.81, 0.5, 30.0, 20.0, 60.0};
  const AiryWaves sea(water, {{1.5, 7.0, -M_PI / 2, 0.4}, {0.8, 5.0, 0.3, 1.1}});
  const AiryWaves calm(water);
  for (const double t : {0.0, 30.0, 59.999}) {
    CHECK(sea.elevation(3.0, -7.0, t) == water.level);
    for (const double z : {-12.0, -0.25, 0.5, 0.75})
      CHECK(sea.pressure(Vector3(3.0, -7.0, z), t) == calm.pressure(Vector3(3.0, -7.0, z), t));
  }
  // (the still water's pressure, inline for the hull clipping) => rho g (level - z) below the
  // level, 0 above, as the calm sea's pressure
  for (const double z : {-12.0, -0.25, 0.5, 0.75}) {
    const Vector3 p(3.0, -7.0, z);
    CHECK(calm.hydrostaticPressure(p) ==
          Approx(z < water.level ? 1025.0 * 9.81 * (water.level - z) : 0.0).epsilon(1e-15));
    CHECK(calm.hydrostaticPressure(p) == calm.pressure(p, 61.0));
    CHECK(sea.hydrostaticPressure(p) == sea.pressure(p, 30.0));
  }
  CHECK(sea.elevation(3.0, -7.0, 61.0) != water.level);
  CHECK(sea.pressure(Vector3(3.0, -7.0, -0.25), 61.0) !=
        calm.pressure(Vector3(3.0, -7.0, -0.25), 61.0));
}

TEST_CASE("half phases give the surface at a point and the pressure at a midpoint to round-off") {
  // (deep, finite and shallow seas, one and 200 components, points far apart and close, late
  // times, the ramp under way) => elevation(h) and pressureBetween agree with the direct forms;
  // before the waves start both are the calm values bit for bit
  std::vector<WaveComponent> many;
  for (int i = 0; i < 200; ++i) many.push_back({0.02, 5.0 + 0.037 * i, 0.01 * i, 0.7 * i});
  struct Case {
    WaterProperties water;
    std::vector<WaveComponent> waves;
  };
  const std::vector<Case> cases = {
      {{1025.0, 9.81, 0.5, INFINITY, 0.0}, {{1.5, 7.0, -M_PI / 2, 0.4}}},
      {{1025.0, 9.81, 0.5, 30.0, 20.0, 10.0}, {{1.5, 7.0, 0.3, 0.4}, {0.8, 4.0, 2.0, 1.1}}},
      {{1025.0, 9.81, -1.0, 3.0, 0.0}, {{0.3, 12.0, 1.0, 0.0}}},
      {{1025.0, 9.81, 0.5, 40.0, 0.0}, many}};
  const std::vector<std::pair<Vector3, Vector3>> ends = {
      {Vector3(3, -2, -1.5), Vector3(-7, 4, -10)},
      {Vector3(1, 1, 0.2), Vector3(1.3, 0.9, -0.4)},
      {Vector3(40, -25, -0.8), Vector3(-60, 30, -2.5)}};
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const AiryWaves sea(cases[c].water, cases[c].waves);
    std::vector<double> ha(2 * sea.size()), hb(2 * sea.size());
    double amplitude = 0.0;
    for (std::size_t i = 0; i < sea.size(); ++i) amplitude += 0.5 * sea.component(i).height;
    const double rg = 1025.0 * 9.81;
    for (const auto& [a, b] : ends)
      for (double t : {0.0, 15.0, 3600.0}) {
        INFO("case " << c << " t = " << t << " a = " << a.transpose() << " b = " << b.transpose());
        sea.halfPhases(a.x(), a.y(), t, ha.data());
        sea.halfPhases(b.x(), b.y(), t, hb.data());
        CHECK(sea.elevation(ha.data(), t) ==
              Approx(sea.elevation(a.x(), a.y(), t)).margin(1e-12 * amplitude));
        CHECK(sea.elevation(hb.data(), t) ==
              Approx(sea.elevation(b.x(), b.y(), t)).margin(1e-12 * amplitude));
        const Vector3 q = 0.5 * (a + b);
        const double p = sea.pressure(q, t);
        CHECK(sea.pressureBetween(q, ha.data(), hb.data(), t) ==
              Approx(p).epsilon(1e-12).margin(1e-9 * rg));
        if (sea.ramp(t) == 0.0) CHECK(sea.pressureBetween(q, ha.data(), hb.data(), t) == p);
      }
  }
}

TEST_CASE(
    "the finite-depth pressure with one exponential equals the hydrostatic plus dynamic pressure") {
  // (a shallow and an intermediate sea, points from the surface to near the bed) => pressure(p)
  // = rho g (level - z) + dynamicPressure(p) below the surface, 0 above it, the latter with cosh
  // k(z'+h) / cosh kh as e^{kz'} (1 + e^{-2k(z'+h)}) / (1 + e^{-2kh})
  for (double h : {2.0, 25.0}) {
    const WaterProperties water{1025.0, 9.81, 0.0, h, 0.0};
    const AiryWaves sea(water, {{0.2, 6.0, 0.5, 0.2}});
    for (double z : {-0.05, -0.5 * h, -0.99 * h})
      for (double t : {0.0, 1.1, 2.9}) {
        const Vector3 p(2.0, 1.0, z);
        INFO("h = " << h << " z = " << z << " t = " << t);
        const bool dry = z > sea.elevation(p.x(), p.y(), t);
        CHECK(sea.pressure(p, t) ==
              Approx(dry ? 0.0 : 1025.0 * 9.81 * (0.0 - z) + sea.dynamicPressure(p, t))
                  .epsilon(1e-13)
                  .margin(1e-10));
      }
  }
}
