#include "forces/spectral_sampling.hpp"

namespace yardsim::forces {

double equalEnergyFraction(std::size_t i, std::size_t n, double u, double low, double span) {
  return low + span * (static_cast<double>(i) + u) / static_cast<double>(n);
}

}  // namespace yardsim::forces
