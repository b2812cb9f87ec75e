#include "forces/wind_gusts.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "forces/spectral_sampling.hpp"

namespace yardsim::forces {

namespace {
constexpr int kTable = 8192;  // intervals of the cumulative table in ln f
}

GustSpectrumKind gustSpectrumKind(const std::string& name) {
  if (name == "npd") return GustSpectrumKind::Npd;
  throw std::invalid_argument("unknown gust spectrum '" + name + "'; expected npd");
}

NpdGustSpectrum::NpdGustSpectrum(double u0, double z) {
  if (!(u0 > 0) || !std::isfinite(u0))
    throw std::invalid_argument("speed: the gusts need a 1-hour mean U0 > 0 m/s");
  if (!(z > 0) || !std::isfinite(z))
    throw std::invalid_argument("height: the spectrum's height must be > 0 m");
  scale_ = 320.0 * std::pow(u0 / 10.0, 2) * std::pow(z / 10.0, 0.45);
  fScale_ = 172.0 * std::pow(z / 10.0, 2.0 / 3.0) * std::pow(u0 / 10.0, -0.75);
}

double NpdGustSpectrum::density(double f) const {
  if (!(f > 0)) return f == 0 ? scale_ : 0.0;
  return scale_ / std::pow(1.0 + std::pow(fScale_ * f, kN), 5.0 / (3.0 * kN));
}

WindGusts::WindGusts(const GustProperties& p, double u0) : p_(p) {
  if (p_.components < 1 || p_.components > 100000)
    throw std::invalid_argument("components: the number of gust components must be in [1, 100000]");
  if (!(p_.fMin > 0) || !std::isfinite(p_.fMin))
    throw std::invalid_argument("f_min: must be > 0 Hz");
  if (!(p_.fMax > p_.fMin) || !std::isfinite(p_.fMax))
    throw std::invalid_argument("f_max: must be finite and > f_min");
  if (!(p_.ramp >= 0) || !std::isfinite(p_.ramp))
    throw std::invalid_argument("ramp: must be >= 0 s");
  if (!std::isfinite(p_.start)) throw std::invalid_argument("start: must be finite");
  const NpdGustSpectrum spectrum(u0, p_.height);
  // (S on a grid in x = ln f) => the cumulative by the trapezoid rule on S(f) f dx
  const double x0 = std::log(p_.fMin), h = (std::log(p_.fMax) - x0) / kTable;
  std::vector<double> x(kTable + 1), cum(kTable + 1, 0.0);
  double prev = spectrum.density(p_.fMin) * p_.fMin;
  x[0] = x0;
  for (int k = 1; k <= kTable; ++k) {
    x[k] = x0 + k * h;
    const double f = k == kTable ? p_.fMax : std::exp(x[k]);
    const double g = spectrum.density(f) * f;
    cum[k] = cum[k - 1] + 0.5 * h * (prev + g);
    prev = g;
  }
  variance_ = cum.back();
  // (bin i) => frequency by the inverse of the table (linear in ln f), then the phase
  const std::size_t n = static_cast<std::size_t>(p_.components);
  const double a = std::sqrt(2.0 * variance_ / static_cast<double>(n));
  UniformStream u(p_.seed);
  omega_.reserve(n);
  amplitude_.assign(n, a);
  phase_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double target = equalEnergyFraction(i, n, u.next(), 0.0, 1.0) * variance_;
    const auto it = std::upper_bound(cum.begin(), cum.end(), target);
    const std::size_t k =
        std::clamp<std::size_t>(static_cast<std::size_t>(it - cum.begin()), 1, kTable);
    const double span = cum[k] - cum[k - 1];
    const double w = span > 0 ? (target - cum[k - 1]) / span : 0.0;
    omega_.push_back(2.0 * M_PI * std::exp(x[k - 1] + w * h));
    phase_.push_back(2.0 * M_PI * u.next());
  }
}

double WindGusts::frequency(std::size_t i) const {
  return omega_[i] / (2.0 * M_PI);
}

double WindGusts::ramp(double t) const {
  const double tau = t - p_.start;
  if (tau < 0.0) return 0.0;
  if (p_.ramp <= 0.0 || tau >= p_.ramp) return 1.0;
  return 0.5 * (1.0 - std::cos(M_PI * tau / p_.ramp));
}

double WindGusts::speed(double t) const {
  const double r = ramp(t);
  if (r == 0.0) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < omega_.size(); ++i)
    sum += amplitude_[i] * std::cos(omega_[i] * t + phase_[i]);
  return r * sum;
}

}  // namespace yardsim::forces
