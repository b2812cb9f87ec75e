#pragma once
// An irregular sea as regular Airy components (forces::WaveComponent) of the one sea
// (forces::AiryWaves), so that the incident pressure, the hydrostatics clipping surface, the
// excitation and the wave elevation channels all see the same sea (docs/hydrodynamics.md,
// "Irregular seas"). Units: m, s, rad; directions from +x towards +y, the way the waves travel.
//
// Discretisation (equal energy, random frequencies, forces/spectral_sampling.hpp, shared with the
// wind's gusts): the spectrum between its 0.1 % and 99.9 % energy quantiles is cut into N bins of
// equal energy; component i takes the frequency at the energy fraction 0.001 + 0.998 (i + u_i)/N
// (u_i uniform in [0, 1): a random frequency within its bin), the amplitude a = sqrt(2 m0 / N) (the variance sum a^2/2 is Hs^2/16 exactly) and a
// uniform random phase. Random frequencies have no common period: the sea does not repeat within
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
};

// (sea) => its components; throws std::invalid_argument for a bad spectrum or spreading, or
// components outside [1, 100000]
std::vector<WaveComponent> irregularWaves(const IrregularSea& sea);

// (seed) => uniform numbers in [0, 1) (forces/spectral_sampling.hpp, shared with the gusts)
using forces::UniformStream;

}  // namespace yardsim::forces::hydro
