#include "dtss/grid.hpp"

#include <cmath>

namespace yardsim::dtss {

std::int64_t Grid::indexAfter(Time t) const {
  auto k = static_cast<std::int64_t>(std::floor((t - t0) / h));
  while (at(k) <= t) ++k;         // the division may round down one index short
  while (k > 0 && at(k - 1) > t) --k;  // or one too far
  return k;
}

}  // namespace yardsim::dtss
