#pragma once
// Sampling a one-sided spectrum as a sum of harmonics: equal energy, random frequencies (the
// discretisation of the irregular sea, forces/hydro/irregular_sea.hpp, and of the wind's gusts,
// forces/wind_gusts.hpp; docs/hydrodynamics.md, "Irregular seas"). The band the spectrum is
// sampled over is cut into N bins of equal energy; component i takes the frequency at the energy
// fraction low + span (i + u_i)/N (u_i uniform in [0, 1): a random frequency within its
// bin) and carries 1/N of the band's energy. Random frequencies have no common period: the sum
// does not repeat within any run. The random numbers come from std::mt19937_64 (fully specified
// by the C++ standard): the same seed gives the same numbers on every platform. Dimensionless.
#include <cstddef>
#include <cstdint>
#include <random>

namespace yardsim::forces {

// (seed) => a uniform number in [0, 1) from the top 53 bits of each mt19937_64 draw
class UniformStream {
 public:
  explicit UniformStream(std::uint64_t seed) : engine_(seed) {}
  double next() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

 private:
  std::mt19937_64 engine_;
};

// (bin i of n, u in [0, 1), the band's lower energy fraction and its width) => the energy
// fraction low + span (i + u)/n of component i, in [low, low + span) (the whole band between
// tails t at each end: low = t, span = 1 - 2 t)
double equalEnergyFraction(std::size_t i, std::size_t n, double u, double low, double span);

}  // namespace yardsim::forces
