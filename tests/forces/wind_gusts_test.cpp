// Gusts of the wind (forces/wind_gusts.hpp): the NPD spectrum against a hand value and its
// integral against the closed form (a Beta function), the components' variance against an
// independent quadrature of the spectrum over the band, the sampled speed's variance and its
// periodogram (FFT) against that quadrature band by band, the hour mean against U0, same seed
// same gust and another seed another, no repetition within three hours (autocorrelation), the
// ramp, and the refused inputs.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <functional>
#include <vector>

#include <unsupported/Eigen/FFT>

#include "forces/wind_profile.hpp"

using namespace yardsim::forces;

namespace {
constexpr double kU0 = 15.0;  // m/s, the 1-hour mean at 10 m

GustProperties gusty(int components = 200, std::uint64_t seed = 7) {
  GustProperties g;
  g.seed = seed;
  g.components = components;
  g.fMin = 1.0 / 3600.0;
  g.fMax = 0.8;
  return g;
}

// (S, band in Hz) => the integral of S over it: composite Simpson in ln f on 20,000 intervals
// (independent of the sampler's trapezoid table)
double integral(const std::function<double(double)>& S, double lo, double hi, int n = 20000) {
  const double a = std::log(lo), h = (std::log(hi) - a) / n;
  double sum = 0;
  for (int k = 0; k <= n; ++k) {
    const double f = std::exp(a + k * h);
    sum += (k == 0 || k == n ? 1.0 : k % 2 ? 4.0 : 2.0) * S(f) * f;
  }
  return sum * h / 3;
}

// (gusts, lag s) => the normalised autocorrelation sum a^2 cos(w lag) / sum a^2
double autocorrelation(const WindGusts& g, double lag) {
  double num = 0, den = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const double a2 = g.amplitude(i) * g.amplitude(i);
    num += a2 * std::cos(2 * M_PI * g.frequency(i) * lag);
    den += a2;
  }
  return num / den;
}
}  // namespace

TEST_CASE("NPD spectrum: a hand value and the integral of the closed form") {
  const NpdGustSpectrum S(kU0, 10.0);
  // (DNV-RP-C205 eq. 2.3.4.8 evaluated by hand, U0 = 15 m/s, z = 10 m)
  CHECK(S.density(0.0) == Approx(320 * 1.5 * 1.5));
  CHECK(S.density(0.01) == Approx(49.735887).epsilon(1e-7));
  CHECK(S.density(0.1) == Approx(4.0468053).epsilon(1e-7));
  // (integral over f >= 0) => 320 (U0/10)^2 (z/10)^0.45 / f~-scale * B(1/n, 2/(3n)) / n, the
  // f~-scale 172 (z/10)^(2/3) (U0/10)^-0.75; here at z = 25 m
  const double z = 25.0, n = 0.468;
  const NpdGustSpectrum high(kU0, z);
  const double scale = 320 * std::pow(kU0 / 10, 2) * std::pow(z / 10, 0.45);
  const double fs = 172 * std::pow(z / 10, 2.0 / 3.0) * std::pow(kU0 / 10, -0.75);
  const double beta = std::tgamma(1 / n) * std::tgamma(2 / (3 * n)) / std::tgamma(5 / (3 * n));
  const double closed = scale / fs * beta / n;
  const double quadrature =
      integral([&](double f) { return high.density(f); }, 1e-12, 1e12, 400000) +
      high.density(0.0) * 1e-12;
  CHECK(quadrature == Approx(closed).epsilon(1e-6));
  // (the turbulence intensity over the hour's band, U0 = 15 m/s) => near NPD's I_u = 0.099
  const double band = integral([&](double f) { return S.density(f); }, 1.0 / 3600, 1.0);
  CHECK(std::sqrt(band) / kU0 == Approx(0.1119).epsilon(2e-3));
}

TEST_CASE("the components carry the integral of the spectrum over the band") {
  const NpdGustSpectrum S(kU0, 10.0);
  for (int n : {1, 50, 200, 1000}) {
    const WindGusts g(gusty(n), kU0);
    REQUIRE(g.size() == static_cast<std::size_t>(n));
    double variance = 0;
    for (std::size_t i = 0; i < g.size(); ++i) {
      variance += g.amplitude(i) * g.amplitude(i) / 2;
      CHECK(g.frequency(i) >= 1.0 / 3600);
      CHECK(g.frequency(i) <= 0.8);
    }
    CHECK(variance == Approx(g.variance()).epsilon(1e-12));
    CHECK(g.variance() ==
          Approx(integral([&](double f) { return S.density(f); }, 1.0 / 3600, 0.8)).epsilon(2e-6));
  }
  // (the spectrum at another height) => the variance of that height's spectrum
  GustProperties p = gusty();
  p.height = 40.0;
  const NpdGustSpectrum S40(kU0, 40.0);
  CHECK(WindGusts(p, kU0).variance() ==
        Approx(integral([&](double f) { return S40.density(f); }, 1.0 / 3600, 0.8)).epsilon(2e-6));
}

TEST_CASE("the sampled gust has the band's variance and the spectrum by its periodogram") {
  const NpdGustSpectrum S(kU0, 10.0);
  const WindGusts g(gusty(800), kU0);
  // (18 h at 0.5 s: Nyquist 1 Hz above f_max, the record long against the lowest beats)
  const double dt = 0.5;
  const int n = 1 << 17;
  std::vector<double> u(n);
  double mean = 0, variance = 0;
  for (int i = 0; i < n; ++i) {
    u[i] = g.speed(i * dt);
    mean += u[i] / n;
  }
  for (int i = 0; i < n; ++i) variance += (u[i] - mean) * (u[i] - mean) / n;
  const double target = integral([&](double f) { return S.density(f); }, 1.0 / 3600, 0.8);
  CHECK(variance == Approx(target).epsilon(0.03));
  // (periodogram) => one-sided energy per FFT bin, |X_k|^2 2/n^2, summed over bands of 8-16 %
  // of the energy each, against the quadrature of S over the band
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> X;
  fft.fwd(X, u);
  const double df = 1.0 / (n * dt);
  const double edges[] = {1.0 / 3600, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.3, 0.8};
  for (int b = 0; b + 1 < 9; ++b) {
    double energy = 0;
    for (int k = 1; k < n / 2; ++k)
      if (k * df >= edges[b] && k * df < edges[b + 1])
        energy += 2 * std::norm(X[static_cast<std::size_t>(k)]) / (double(n) * n);
    const double expected =
        integral([&](double f) { return S.density(f); }, edges[b], edges[b + 1]);
    INFO("band " << edges[b] << " to " << edges[b + 1] << " Hz: " << expected / target
                 << " of the energy");
    // (below 0.005 Hz the components lie about 1.5e-5 Hz apart, the record's resolution: their
    // beats do not average out over 18 h, and a band's sampled energy scatters by some 5 % from
    // seed to seed, where the components themselves carry the target to 1.3 %) => 8 % there, 4 %
    // above
    CHECK(energy == Approx(expected).epsilon(edges[b] < 0.005 ? 0.08 : 0.04));
  }
}

TEST_CASE("the hour mean of the gusty speed is U0") {
  WindProperties p;
  p.profile = WindProfileKind::Npd;
  p.speed = kU0;
  const double T = 3600.0, dt = 0.25;
  double ensemble = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    p.gusts = gusty(200, seed);
    const WindField w(p);
    double mean = 0;
    const int n = static_cast<int>(T / dt);
    for (int i = 0; i < n; ++i) mean += (w.speedAt(10.0) + w.gust((i + 0.5) * dt)) / n;
    // (each component's hour mean) => a cos of random phase averages to a sinc(pi f T) part of
    // its amplitude: the hour mean's standard deviation, here 3.5 % of the gust's
    const WindGusts& g = *w.gusts();
    double s2 = 0;
    for (std::size_t i = 0; i < g.size(); ++i) {
      const double x = M_PI * g.frequency(i) * T;
      s2 += g.amplitude(i) * g.amplitude(i) / 2 * std::pow(std::sin(x) / x, 2);
    }
    CHECK(std::sqrt(s2) < 0.05 * std::sqrt(g.variance()));
    CHECK(mean == Approx(kU0).margin(4 * std::sqrt(s2)));
    ensemble += mean / 20;
  }
  CHECK(ensemble == Approx(kU0).margin(0.1));
}

TEST_CASE("same seed same gust and another seed another") {
  const WindGusts a(gusty(200, 7), kU0), b(gusty(200, 7), kU0), c(gusty(200, 8), kU0);
  bool same = true, differ = false;
  for (double t = 0; t < 600; t += 0.37) {
    same = same && a.speed(t) == b.speed(t);
    differ = differ || std::abs(a.speed(t) - c.speed(t)) > 0.1;
  }
  CHECK(same);
  CHECK(differ);
}

TEST_CASE("the gust does not repeat within a three-hour run") {
  const WindGusts g(gusty(200), kU0);
  double worst = 0;
  for (double lag = 60.0; lag <= 3 * 3600.0; lag += 0.5)
    worst = std::max(worst, std::abs(autocorrelation(g, lag)));
  CHECK(worst < 0.3);
  // (the check can fail) => the same amplitudes at equally spaced frequencies repeat after 1/df
  // (the autocorrelation of a sum with frequencies k df at lag 1/df is 1): a grid's sum comes
  // back where the gust's does not
  const double df = 1.0 / 1800;
  double num = 0;
  for (std::size_t i = 0; i < g.size(); ++i)
    num += std::cos(2 * M_PI * static_cast<double>(i + 1) * df * (1 / df));
  CHECK(num / static_cast<double>(g.size()) == Approx(1.0).epsilon(1e-9));
  CHECK(std::abs(autocorrelation(g, 1 / df)) < 0.3);
}

TEST_CASE("the gust is ramped in after its start") {
  GustProperties p = gusty();
  p.start = 10.0;
  p.ramp = 20.0;
  const WindGusts ramped(p, kU0), full(gusty(), kU0);
  CHECK(ramped.speed(5.0) == 0.0);
  CHECK(ramped.speed(10.0) == 0.0);
  CHECK(ramped.ramp(20.0) == Approx(0.5));
  CHECK(ramped.speed(20.0) == Approx(0.5 * full.speed(20.0)));
  CHECK(ramped.speed(45.0) == full.speed(45.0));
  CHECK(full.ramp(0.0) == 1.0);
}

TEST_CASE("bad gusts are refused, naming the property") {
  GustProperties p = gusty(0);
  CHECK_THROWS_WITH(WindGusts(p, kU0), Catch::StartsWith("components"));
  p = gusty();
  p.fMin = 0.0;
  CHECK_THROWS_WITH(WindGusts(p, kU0), Catch::StartsWith("f_min"));
  p = gusty();
  p.fMax = 1e-4;
  CHECK_THROWS_WITH(WindGusts(p, kU0), Catch::StartsWith("f_max"));
  p = gusty();
  p.fMax = std::nan("");
  CHECK_THROWS_WITH(WindGusts(p, kU0), Catch::StartsWith("f_max"));
  p = gusty();
  p.height = -1.0;
  CHECK_THROWS_WITH(WindGusts(p, kU0), Catch::StartsWith("height"));
  p = gusty();
  p.ramp = -1.0;
  CHECK_THROWS_WITH(WindGusts(p, kU0), Catch::StartsWith("ramp"));
  CHECK_THROWS_WITH(WindGusts(gusty(), 0.0), Catch::StartsWith("speed"));
  CHECK_THROWS_WITH(gustSpectrumKind("kaimal"), Catch::Contains("expected npd"));
}
