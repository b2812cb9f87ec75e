#pragma once
// An irregular sea as regular Airy components (forces::WaveComponent) of the one sea
// (forces::AiryWaves), so that the incident pressure, the hydrostatics clipping surface, the
// excitation and the wave elevation channels all see the same sea (docs/hydrodynamics.md,
// "Irregular seas"). Units: m, s, rad; directions from +x towards +y, the way the waves travel.
//
// Discretisation (equal energy, random frequencies, forces/spectral_sampling.hpp, shared with the
// wind's gusts): the spectrum between its 0.1 % and 99.9 % energy quantiles is cut into N bins of
// equal energy; component i takes the frequency at the energy fraction 0.001 + 0.998 (i + u_i)/N
// (u_i uniform in [0, 1): a random frequency within its bin), the amplitude a = sqrt(2 m0 / N)
// (the variance sum a^2/2 is Hs^2/16 exactly) and a uniform random phase. With a cutoff w_c below
// the upper quantile the bins span the energy from the 0.1 % quantile to F(w_c) instead, each
// component keeping the spectrum's density (a^2/2 = m0 (F(w_c) - 0.001) / (0.998 N)): the variance
// is Hs^2/16 times the kept fraction. Random frequencies have no common period: the sea does not
// repeat within
// any run (equally spaced frequencies d omega would repeat after 2 pi / d omega).
// Spreading (cos-2s, optional): each component one direction, b0 plus the cos-2s quantile of a
// stratified fraction (p_i + v_i)/N, p a random permutation, so that directions and frequencies
// are independent. The random numbers come from std::mt19937_64 (fully specified by the C++
// standard) seeded with `seed`: the same seed gives the same sea on every platform.
#include <cstdint>
#include <vector>

#include "forces/airy_waves.hpp"
#include "forces/hydro/wave_spectrum.hpp"
#include "forces/spectral_sampling.hpp"

namespace yardsim::forces::hydro {

struct IrregularSea {
  SpectrumKind spectrum = SpectrumKind::Jonswap;
  double hs = 0.0;          // m, significant wave height (4 sqrt(m0))
  double tp = 0.0;          // s, peak period
  double gamma = 3.3;       // JONSWAP peak enhancement (ignored for Pierson-Moskowitz)
  double direction = 0.0;   // rad, the mean direction the waves travel towards
  double spreadingS = 0.0;  // cos-2s exponent; 0: long-crested (every component along direction)
  std::uint64_t seed = 1;
  int components = 200;
  // rad/s: the spectrum cut above this frequency (its energy there left out: the sea's variance is
  // m0 times the kept fraction), e.g. at an impulse response's resolved frequency; 0: no cut
  double cutoff = 0.0;
};

// (sea) => its components; throws std::invalid_argument for a bad spectrum or spreading,
// components outside [1, 100000], or a cutoff not above the spectrum's 0.1 % quantile
// (sea) => the fraction of m0 its components carry: 1, or (F(w_c) - 0.001) / 0.998 with a cutoff
double keptEnergy(const IrregularSea& sea);
std::vector<WaveComponent> irregularWaves(const IrregularSea& sea);

// (seed) => uniform numbers in [0, 1) (forces/spectral_sampling.hpp, shared with the gusts)
using forces::UniformStream;

}  // namespace yardsim::forces::hydro
