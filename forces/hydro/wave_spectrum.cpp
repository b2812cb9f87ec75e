#include "forces/hydro/wave_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yardsim::forces::hydro {

namespace {
// the spectrum's table over x = omega/wp: below kLow it is below 1e-300 of its peak, above kHigh
// the peak enhancement is exactly 1 and the Pierson-Moskowitz tail is integrated in closed form
constexpr double kLow = 0.2, kHigh = 12.0;
constexpr int kSteps = 47000;   // x step 2.5e-4: trapezoid error far below 1e-8 of m0
constexpr double kBeta = 1.25;  // 5/4 of the Pierson-Moskowitz exponent

// (table x, table F, value) => the x where F reaches value, linear between table points
double invert(const std::vector<double>& x, const std::vector<double>& F, double value) {
  const auto it = std::upper_bound(F.begin(), F.end(), value);
  if (it == F.begin()) return x.front();
  if (it == F.end()) return x.back();
  const std::size_t i = static_cast<std::size_t>(it - F.begin());
  const double f = (value - F[i - 1]) / (F[i] - F[i - 1]);
  return x[i - 1] + f * (x[i] - x[i - 1]);
}
}  // namespace

SpectrumKind spectrumKind(const std::string& name) {
  if (name == "jonswap") return SpectrumKind::Jonswap;
  if (name == "pierson_moskowitz" || name == "pm") return SpectrumKind::PiersonMoskowitz;
  throw std::invalid_argument("unknown spectrum '" + name +
                              "' (expected jonswap or pierson_moskowitz)");
}

WaveSpectrum::WaveSpectrum(SpectrumKind kind, double hs, double tp, double gamma)
    : kind_(kind), hs_(hs), tp_(tp), gamma_(kind == SpectrumKind::Jonswap ? gamma : 1.0) {
  if (!(hs > 0) || !std::isfinite(hs))
    throw std::invalid_argument("hs: the significant wave height must be > 0 m");
  if (!(tp > 0) || !std::isfinite(tp))
    throw std::invalid_argument("tp: the peak period must be > 0 s");
  if (!(gamma_ >= 1.0 && gamma_ <= 20.0))
    throw std::invalid_argument(
        "gamma: the peak enhancement must be in [1, 20] (3.3: the mean JONSWAP sea)");
  wp_ = 2.0 * M_PI / tp;
  // (shape on the grid) => cumulative by the trapezoid rule, then the closed-form tail above kHigh
  x_.resize(kSteps + 1);
  cum_.resize(kSteps + 1);
  const double h = (kHigh - kLow) / kSteps;
  double sum = 0.0, prev = shape(kLow);
  x_[0] = kLow;
  cum_[0] = 0.0;
  for (int i = 1; i <= kSteps; ++i) {
    x_[i] = kLow + i * h;
    const double s = shape(x_[i]);
    sum += 0.5 * h * (prev + s);
    cum_[i] = sum;
    prev = s;
  }
  const double tail = (1.0 - std::exp(-kBeta / std::pow(kHigh, 4))) / 16.0;  // PM above kHigh
  const double total = sum + tail;
  aGamma_ = (1.0 / 16.0) / total;
  for (double& c : cum_) c /= total;  // fractions of m0
}

double WaveSpectrum::shape(double x) const {
  if (x <= 0.0) return 0.0;
  const double x4 = x * x * x * x;
  double s = 5.0 / 16.0 / (x4 * x) * std::exp(-kBeta / x4);
  if (gamma_ != 1.0) {
    const double sigma = x <= 1.0 ? 0.07 : 0.09;
    s *= std::pow(gamma_, std::exp(-(x - 1.0) * (x - 1.0) / (2.0 * sigma * sigma)));
  }
  return s;
}

double WaveSpectrum::density(double omega) const {
  if (!(omega > 0)) return 0.0;
  return aGamma_ * hs_ * hs_ / wp_ * shape(omega / wp_);
}

double WaveSpectrum::cumulative(double omega) const {
  const double m0 = hs_ * hs_ / 16.0, x = omega / wp_;
  if (x <= kLow) return 0.0;
  if (x >= kHigh) return m0 * (1.0 - aGamma_ * (1.0 - std::exp(-kBeta / (x * x * x * x))));
  const double pos = (x - kLow) / (kHigh - kLow) * kSteps;
  const std::size_t i =
      std::min(static_cast<std::size_t>(pos), static_cast<std::size_t>(kSteps - 1));
  const double f = pos - static_cast<double>(i);
  return m0 * (cum_[i] + f * (cum_[i + 1] - cum_[i]));
}

double WaveSpectrum::quantile(double fraction) const {
  if (!(fraction >= 0.0 && fraction < 1.0))
    throw std::invalid_argument("quantile: fraction outside [0, 1)");
  if (fraction <= cum_.back()) return wp_ * invert(x_, cum_, fraction);
  // (the closed-form Pierson-Moskowitz tail) => 1 - fraction = A (1 - exp(-beta/x^4))
  const double rest = (1.0 - fraction) / aGamma_;
  return wp_ * std::pow(kBeta / -std::log1p(-rest), 0.25);
}

double WaveSpectrum::moment(int n) const {
  if (n < 0 || n > 4) throw std::invalid_argument("moment: n must be 0 .. 4");
  // (trapezoid of x^n shape on the table) + (the tail: integral of 5/16 x^(n-5) (1 - beta x^-4))
  const double h = (kHigh - kLow) / kSteps;
  double sum = 0.0;
  for (int i = 0; i <= kSteps; ++i) {
    const double x = x_[static_cast<std::size_t>(i)];
    sum += (i == 0 || i == kSteps ? 0.5 : 1.0) * std::pow(x, n) * shape(x);
  }
  sum *= h;
  if (n < 4)
    sum +=
        5.0 / 16.0 * (std::pow(kHigh, n - 4) / (4 - n) - kBeta * std::pow(kHigh, n - 8) / (8 - n));
  return aGamma_ * hs_ * hs_ * std::pow(wp_, n) * sum;
}

CosineSpreading::CosineSpreading(double s) : s_(s) {
  if (!(s > 0) || !(s <= 1000.0))
    throw std::invalid_argument(
        "spreading_s: the cos-2s exponent must be in (0, 1000] (long-crested: omit it)");
  // G(s) = 2^(2s-1) Gamma(s+1)^2 / (pi Gamma(2s+1)), in logarithms
  scale_ = std::exp((2.0 * s - 1.0) * std::log(2.0) + 2.0 * std::lgamma(s + 1.0) -
                    std::lgamma(2.0 * s + 1.0)) /
           M_PI;
  constexpr int n = 8000;
  b_.resize(n + 1);
  cum_.resize(n + 1);
  double sum = 0.0, prev = 0.0;
  for (int i = 0; i <= n; ++i) {
    b_[i] = -M_PI + 2.0 * M_PI * i / n;
    const double d = density(b_[i]);
    if (i > 0) sum += 0.5 * (2.0 * M_PI / n) * (prev + d);
    cum_[i] = sum;
    prev = d;
  }
  for (double& c : cum_) c /= sum;
}

double CosineSpreading::density(double relative) const {
  if (std::abs(relative) > M_PI) return 0.0;
  return scale_ * std::pow(std::cos(0.5 * relative), 2.0 * s_);
}

double CosineSpreading::quantile(double fraction) const {
  return invert(b_, cum_, std::clamp(fraction, 0.0, 1.0));
}

}  // namespace yardsim::forces::hydro
