// An irregular sea as Airy components: the components' variance is Hs^2/16, the elevation
// sampled in time has that variance and, by its periodogram (FFT), the target spectrum's energy
// in each of six equal-energy bands; the same seed gives the same sea bit for bit and another
// seed another sea; the sea does not repeat within a three-hour run (its autocorrelation stays
// low, where equally spaced frequencies come back to one); the spread directions follow cos-2s; a
// cutoff keeps the spectrum's energy below it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include <unsupported/Eigen/FFT>

#include "forces/hydro/irregular_sea.hpp"
#include "forces/hydro/wave_spectrum.hpp"

using namespace yardsim::forces;
using namespace yardsim::forces::hydro;

namespace {
IrregularSea jonswap(int n = 200, std::uint64_t seed = 7) {
  IrregularSea s;
  s.spectrum = SpectrumKind::Jonswap;
  s.hs = 2.5;
  s.tp = 8.0;
  s.gamma = 3.3;
  s.seed = seed;
  s.components = n;
  return s;
}

// (components, lag) => the normalised autocorrelation sum a^2 cos(w lag) / sum a^2
double autocorrelation(const AiryWaves& sea, double lag) {
  double num = 0, den = 0;
  for (std::size_t i = 0; i < sea.size(); ++i) {
    const double a2 = std::pow(sea.component(i).height / 2, 2);
    num += a2 * std::cos(sea.frequency(i) * lag);
    den += a2;
  }
  return num / den;
}
}  // namespace

TEST_CASE("the components carry the variance Hs squared over 16") {
  for (int n : {1, 50, 200, 1000}) {
    const auto waves = irregularWaves(jonswap(n));
    REQUIRE(waves.size() == static_cast<std::size_t>(n));
    double variance = 0;
    for (const auto& w : waves) variance += w.height * w.height / 8;
    CHECK(variance == Approx(2.5 * 2.5 / 16).epsilon(1e-12));
  }
}

TEST_CASE("the sampled elevation has the target variance and spectrum by its periodogram") {
  const IrregularSea spec = jonswap(400);
  const AiryWaves sea(WaterProperties{}, irregularWaves(spec));
  // (a record long against 2 pi over the spacing of neighbouring frequencies) => the beats of
  // close components average out; Nyquist 2 pi rad/s, above the sea's 99.9 % quantile
  const double dt = 0.5;
  const int n = 1 << 17;  // 18 h
  std::vector<double> eta(n);
  double variance = 0;
  for (int i = 0; i < n; ++i) {
    eta[i] = sea.elevation(3.0, -2.0, i * dt);
    variance += eta[i] * eta[i] / n;
  }
  const double m0 = spec.hs * spec.hs / 16;
  CHECK(variance == Approx(m0).epsilon(0.03));
  // (periodogram) => one-sided energy per FFT bin, |X_k|^2 2/n^2, summed over equal-energy bands
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> X;
  fft.fwd(X, eta);
  const double dw = 2 * M_PI / (n * dt);
  const WaveSpectrum target(spec.spectrum, spec.hs, spec.tp, spec.gamma);
  for (int b = 0; b < 6; ++b) {
    const double lo = target.quantile(0.05 + 0.15 * b), hi = target.quantile(0.05 + 0.15 * (b + 1));
    double energy = 0;
    for (int k = 1; k < n / 2; ++k)
      if (k * dw >= lo && k * dw < hi)
        energy += 2 * std::norm(X[static_cast<std::size_t>(k)]) / (double(n) * n);
    INFO("band " << b << ": " << lo << " to " << hi << " rad/s");
    CHECK(energy == Approx(0.15 * m0).epsilon(0.03));
  }
}

TEST_CASE("same seed same sea and another seed another sea") {
  const auto a = irregularWaves(jonswap(200, 7)), b = irregularWaves(jonswap(200, 7)),
             c = irregularWaves(jonswap(200, 8));
  bool same = true, differ = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    same = same && a[i].period == b[i].period && a[i].phase == b[i].phase &&
           a[i].height == b[i].height && a[i].direction == b[i].direction;
    differ = differ || a[i].phase != c[i].phase;
  }
  CHECK(same);
  CHECK(differ);
  // (the first numbers of the standard's mt19937_64 with its default seed) => the stream is the
  // standard one
  UniformStream u(5489u);
  CHECK(u.next() == static_cast<double>(14514284786278117030ull >> 11) * 0x1.0p-53);
}

TEST_CASE("the sea does not repeat within a three-hour run") {
  const AiryWaves sea(WaterProperties{}, irregularWaves(jonswap(200)));
  // (lags from 10 Tp to 3 h) => the elevation never correlates with itself again
  double worst = 0;
  for (double lag = 80.0; lag <= 3 * 3600.0; lag += 0.25)
    worst = std::max(worst, std::abs(autocorrelation(sea, lag)));
  CHECK(worst < 0.35);
  // (the check can fail) => 200 equally spaced frequencies dw repeat after 2 pi/dw
  std::vector<WaveComponent> grid;
  const double dw = 0.01;
  for (int i = 1; i <= 200; ++i) grid.push_back({0.1, 2 * M_PI / (0.3 + i * dw), 0.0, 0.1 * i});
  const AiryWaves periodic(WaterProperties{}, grid);
  CHECK(autocorrelation(periodic, 2 * M_PI / dw) == Approx(1.0).epsilon(1e-9));
}

TEST_CASE("spread directions follow cos-2s about the mean direction") {
  IrregularSea spec = jonswap(2000);
  spec.direction = 0.7;
  spec.spreadingS = 10.0;
  const auto waves = irregularWaves(spec);
  double meanCos = 0, meanSin = 0;
  for (const auto& w : waves) {
    meanCos += std::cos(w.direction - 0.7) / static_cast<double>(waves.size());
    meanSin += std::sin(w.direction - 0.7) / static_cast<double>(waves.size());
  }
  CHECK(meanCos == Approx(10.0 / 11.0).epsilon(2e-3));
  CHECK(meanSin == Approx(0.0).margin(5e-3));
  // (no spreading) => every component along the mean direction
  spec.spreadingS = 0.0;
  for (const auto& w : irregularWaves(spec)) CHECK(w.direction == 0.7);
}

TEST_CASE("bad irregular seas are refused") {
  IrregularSea s = jonswap(0);
  CHECK_THROWS_WITH(irregularWaves(s), Catch::Contains("components"));
  s = jonswap();
  s.hs = -1;
  CHECK_THROWS_WITH(irregularWaves(s), Catch::Contains("hs"));
}

TEST_CASE("a cutoff keeps the components below it with the spectrum's energy there") {
  // (JONSWAP Hs 2.5 m, Tp 8 s cut at 1.5 rad/s) => every component at or below 1.5 rad/s, their
  // variance the spectrum's energy from the 0.1 % quantile to 1.5 rad/s (trapezoid of S, 1e-5 rad/s
  // steps) over 0.998; a cut above the 99.9 % quantile is no cut, bit for bit
  IrregularSea s = jonswap();
  s.cutoff = 1.5;
  const auto waves = irregularWaves(s);
  const WaveSpectrum spectrum(s.spectrum, s.hs, s.tp, s.gamma);
  double variance = 0, highest = 0;
  for (const auto& w : waves) {
    variance += w.height * w.height / 8;
    highest = std::max(highest, 2 * M_PI / w.period);
  }
  const double low = spectrum.quantile(0.001), m0 = s.hs * s.hs / 16;
  double below = 0;
  for (double w = low; w < s.cutoff; w += 1e-5)
    below += 0.5 * (spectrum.density(w) + spectrum.density(std::min(w + 1e-5, s.cutoff))) *
             (std::min(w + 1e-5, s.cutoff) - w);
  INFO("variance " << variance << " m^2 of m0 " << m0 << " m^2; highest " << highest << " rad/s");
  CHECK(highest <= 1.5);
  CHECK(highest > 1.4);
  CHECK(variance == Approx(below / 0.998).epsilon(1e-4));
  CHECK(variance == Approx(keptEnergy(s) * m0).epsilon(1e-12));
  CHECK(keptEnergy(s) < 0.97);  // (the cut leaves out a few per cent of a Tp = 8 s sea)
  IrregularSea high = jonswap();
  high.cutoff = 50.0;
  const auto same = irregularWaves(high), none = irregularWaves(jonswap());
  REQUIRE(same.size() == none.size());
  for (std::size_t i = 0; i < same.size(); ++i) {
    CHECK(same[i].height == none[i].height);
    CHECK(same[i].period == none[i].period);
    CHECK(same[i].phase == none[i].phase);
  }
  CHECK(keptEnergy(high) == 1.0);
  s.cutoff = 0.3;  // (below the 0.1 % quantile)
  CHECK_THROWS_WITH(irregularWaves(s), Catch::Contains("cutoff") && Catch::Contains("no wave is left"));
  s.cutoff = -1;
  CHECK_THROWS_WITH(irregularWaves(s), Catch::Contains("cutoff"));
}
