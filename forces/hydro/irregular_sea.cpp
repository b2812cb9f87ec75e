#include "forces/hydro/irregular_sea.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace yardsim::forces::hydro {

namespace {
constexpr double kTail = 0.001;  // energy fraction left out at each end of the spectrum

// (sea, its spectrum) => the fraction of m0 up to which the bins reach: 1 - kTail, or F(w_c)
double upperFraction(const IrregularSea& sea, const WaveSpectrum& spectrum) {
  if (sea.cutoff < 0.0 || std::isnan(sea.cutoff))
    throw std::invalid_argument("cutoff: must be >= 0 rad/s (0: no cut)");
  if (!(sea.cutoff > 0.0)) return 1.0 - kTail;
  const double upper = spectrum.cumulative(sea.cutoff) / (sea.hs * sea.hs / 16.0);
  if (!(upper > kTail))
    throw std::invalid_argument("cutoff: " + std::to_string(sea.cutoff) +
                                " rad/s is below the spectrum's 0.1 % energy quantile " +
                                std::to_string(spectrum.quantile(kTail)) + " rad/s: no wave is left");
  return std::min(upper, 1.0 - kTail);
}
}  // namespace

double keptEnergy(const IrregularSea& sea) {
  const WaveSpectrum spectrum(sea.spectrum, sea.hs, sea.tp, sea.gamma);
  const double upper = upperFraction(sea, spectrum);
  return upper == 1.0 - kTail ? 1.0 : (upper - kTail) / (1.0 - 2.0 * kTail);
}

std::vector<WaveComponent> irregularWaves(const IrregularSea& sea) {
  if (sea.components < 1 || sea.components > 100000)
    throw std::invalid_argument("components: the number of wave components must be in [1, 100000]");
  if (!std::isfinite(sea.direction)) throw std::invalid_argument("direction: must be finite");
  const WaveSpectrum spectrum(sea.spectrum, sea.hs, sea.tp, sea.gamma);
  std::optional<CosineSpreading> spreading;
  if (sea.spreadingS != 0.0) spreading.emplace(sea.spreadingS);
  const std::size_t n = static_cast<std::size_t>(sea.components);
  UniformStream u(sea.seed);
  // (seed) => a random permutation of the direction strata (Fisher-Yates), drawn first
  std::vector<std::size_t> strata(n);
  std::iota(strata.begin(), strata.end(), std::size_t{0});
  for (std::size_t i = n; i > 1; --i) {
    const auto j = static_cast<std::size_t>(u.next() * static_cast<double>(i));
    std::swap(strata[i - 1], strata[std::min(j, i - 1)]);
  }
  // (bin i) => frequency, direction and phase, three draws per component in that order
  // (cutoff) => the energy span of the bins and its share of m0 (without one: exactly 1)
  const double upper = upperFraction(sea, spectrum);
  const bool cut = upper != 1.0 - kTail;
  const double span = cut ? upper - kTail : 1.0 - 2.0 * kTail, kept = cut ? span / (1.0 - 2.0 * kTail) : 1.0;
  const double m0 = sea.hs * sea.hs / 16.0, a = std::sqrt(2.0 * m0 * kept / static_cast<double>(n));
  std::vector<WaveComponent> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double fraction = equalEnergyFraction(i, n, u.next(), kTail, span);
    const double omega = spectrum.quantile(fraction);
    const double v = u.next();
    double direction = sea.direction;
    if (spreading)
      direction +=
          spreading->quantile((static_cast<double>(strata[i]) + v) / static_cast<double>(n));
    const double phase = 2.0 * M_PI * u.next();
    out.push_back({2.0 * a, 2.0 * M_PI / omega, direction, phase});
  }
  return out;
}

}  // namespace yardsim::forces::hydro
