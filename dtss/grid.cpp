#include "dtss/grid.hpp"

#include <cmath>

namespace yardsim::dtss {

Time gridOffset(Time h, std::int64_t k) {
  const double inv = 1.0 / h;
  const double n = std::round(inv);
  if (n >= 1.0 && std::abs(inv - n) <= 1e-9 * n) return static_cast<double>(k) / n;
  return static_cast<double>(k) * h;
}

std::int64_t Grid::indexAfter(Time t) const {
  auto k = static_cast<std::int64_t>(std::floor((t - t0) / h));
  while (at(k) <= t) ++k;         // the division may round down one index short
  while (k > 0 && at(k - 1) > t) --k;  // or one too far
  return k;
}

}  // namespace yardsim::dtss
