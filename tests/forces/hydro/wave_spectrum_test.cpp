// Wave spectra against closed forms: the Pierson-Moskowitz moments m0..m3 (5/64 Hs^2 wp^n
// 1.25^((n-4)/4) Gamma(1 - n/4)), m0 = Hs^2/16 for JONSWAP, the peak at 2 pi/Tp, JONSWAP with
// gamma = 1 equal to Pierson-Moskowitz, the JONSWAP normalisation against the DNV approximation
// 1 - 0.287 ln gamma, the cumulative and its inverse, and the cos-2s spreading (integral 1,
// E[cos] = s/(s+1)); bad parameters refused.
#include <catch2/catch.hpp>

#include <cmath>

#include "forces/hydro/wave_spectrum.hpp"

using namespace yardsim::forces::hydro;

TEST_CASE("Pierson-Moskowitz moments against their closed forms") {
  const double hs = 2.5, tp = 8.0, wp = 2 * M_PI / tp;
  const WaveSpectrum s(SpectrumKind::PiersonMoskowitz, hs, tp);
  CHECK(s.normalisation() == Approx(1.0).epsilon(1e-7));
  for (int n = 0; n <= 3; ++n) {
    const double exact = 5.0 / 64.0 * hs * hs * std::pow(wp, n) * std::pow(1.25, (n - 4) / 4.0) *
                         std::tgamma(1.0 - n / 4.0);
    INFO("n = " << n);
    CHECK(s.moment(n) == Approx(exact).epsilon(2e-6));
  }
  CHECK(s.moment(0) == Approx(hs * hs / 16).epsilon(1e-7));
  // the zero-crossing period Tz = 2 pi sqrt(m0/m2) = Tp 1.25^(-1/4) pi^(-1/4) by the closed forms
  const double tz = 2 * M_PI * std::sqrt(s.moment(0) / s.moment(2));
  CHECK(tz / tp == Approx(std::pow(1.25, -0.25) * std::sqrt(1.0 / std::sqrt(M_PI))).epsilon(1e-5));
  CHECK(tz / tp == Approx(0.710).margin(1e-3));  // the textbook Tz/Tp of a Pierson-Moskowitz sea
  // (the cumulative in closed form) => Hs^2/16 exp(-1.25 (wp/w)^4)
  for (double x : {0.8, 1.0, 1.7, 3.0})
    CHECK(s.cumulative(x * wp) ==
          Approx(hs * hs / 16 * std::exp(-1.25 / std::pow(x, 4))).margin(1e-6 * hs * hs / 16));
}

TEST_CASE("JONSWAP holds Hs and peaks at Tp") {
  for (double gamma : {1.0, 2.0, 3.3, 7.0}) {
    const double hs = 4.0, tp = 11.0, wp = 2 * M_PI / tp;
    const WaveSpectrum s(SpectrumKind::Jonswap, hs, tp, gamma);
    INFO("gamma = " << gamma);
    CHECK(s.moment(0) == Approx(hs * hs / 16).epsilon(1e-6));
    CHECK(s.cumulative(100 * wp) == Approx(hs * hs / 16).epsilon(1e-6));
    // (the peak) => S(wp) above S at 0.5 % on either side, and the largest of a fine scan
    CHECK(s.density(wp) > s.density(0.995 * wp));
    CHECK(s.density(wp) > s.density(1.005 * wp));
    double best = 0, at = 0;
    for (double w = 0.3 * wp; w < 3 * wp; w += 1e-4 * wp)
      if (s.density(w) > best) best = s.density(w), at = w;
    CHECK(at == Approx(wp).epsilon(2e-4));
    // DNV-RP-C205 3.5.5.2: A_gamma about 1 - 0.287 ln gamma
    CHECK(s.normalisation() == Approx(1.0 - 0.287 * std::log(gamma)).epsilon(0.02));
    // (quantile) => the inverse of the cumulative
    for (double f : {0.01, 0.3, 0.5, 0.9, 0.999, 0.99995})
      CHECK(s.cumulative(s.quantile(f)) / s.moment(0) == Approx(f).epsilon(1e-6));
  }
  // gamma = 1: the Pierson-Moskowitz spectrum
  const WaveSpectrum j(SpectrumKind::Jonswap, 3.0, 9.0, 1.0),
      p(SpectrumKind::PiersonMoskowitz, 3.0, 9.0);
  for (double w : {0.4, 0.7, 1.5}) CHECK(j.density(w) == Approx(p.density(w)).epsilon(1e-12));
  // a sharper peak: more of the energy within 10 % of wp
  const WaveSpectrum sharp(SpectrumKind::Jonswap, 3.0, 9.0, 7.0);
  const double wp = 2 * M_PI / 9.0;
  CHECK(sharp.cumulative(1.1 * wp) - sharp.cumulative(0.9 * wp) >
        p.cumulative(1.1 * wp) - p.cumulative(0.9 * wp) + 0.1 * 9.0 / 16);
}

TEST_CASE("cos-2s spreading integrates to one with mean cosine s over s plus one") {
  for (double s : {1.0, 4.0, 10.0, 75.0}) {
    const CosineSpreading d(s);
    // (independent midpoint quadrature of D and of cos(b) D) => 1 and s/(s+1)
    const int n = 200000;
    double total = 0, first = 0;
    for (int i = 0; i < n; ++i) {
      const double b = -M_PI + 2 * M_PI * (i + 0.5) / n;
      total += d.density(b) * 2 * M_PI / n;
      first += std::cos(b) * d.density(b) * 2 * M_PI / n;
    }
    INFO("s = " << s);
    CHECK(total == Approx(1.0).epsilon(1e-9));
    CHECK(first == Approx(s / (s + 1)).epsilon(1e-9));
    CHECK(d.quantile(0.5) == Approx(0.0).margin(1e-9));
    CHECK(d.quantile(1e-12) < d.quantile(0.25));
    CHECK(d.quantile(0.25) == Approx(-d.quantile(0.75)).margin(1e-9));
  }
}

TEST_CASE("bad spectrum parameters are refused with their names") {
  CHECK_THROWS_WITH(WaveSpectrum(SpectrumKind::Jonswap, 0.0, 8.0), Catch::Contains("hs"));
  CHECK_THROWS_WITH(WaveSpectrum(SpectrumKind::Jonswap, 2.0, -1.0), Catch::Contains("tp"));
  CHECK_THROWS_WITH(WaveSpectrum(SpectrumKind::Jonswap, 2.0, 8.0, 0.5), Catch::Contains("gamma"));
  CHECK_THROWS_WITH(CosineSpreading(0.0), Catch::Contains("spreading_s"));
  CHECK_THROWS_WITH(spectrumKind("bretschneider"), Catch::Contains("jonswap"));
  CHECK(spectrumKind("pm") == SpectrumKind::PiersonMoskowitz);
}
