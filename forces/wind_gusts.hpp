#pragma once
// Time-varying gusts of the wind (docs/hydrostatics.md, "Gusts"): the longitudinal gust u'(t)
// about the 1-hour mean, one time series per scene, added to the mean speed of the profile at
// every height along the wind's direction (forces/wind_profile.hpp).
//
// Spectrum: NPD (Froya; DNV-RP-C205 §2.3.4, ISO 19901-1), one-sided, f in Hz,
//   S(f) = 320 (U0/10)^2 (z/10)^0.45 / (1 + f~^n)^(5/(3n))   [m^2/s^2 per Hz],
//   f~ = 172 f (z/10)^(2/3) (U0/10)^-0.75,  n = 0.468,
// U0 the 1-hour mean at 10 m (m/s), z the height the spectrum is taken at (`height`, m above the
// still-water level; by default the NPD reference height, 10 m). One height for the whole scene:
// the gust is fully coherent over every body (no coherence function), which overstates the
// gust's load on a large body at the higher frequencies.
//
// Realisation (forces/spectral_sampling.hpp, the irregular sea's discretisation): the band
// [f_min, f_max] (no tail left out) is cut into N bins of equal energy on a table of the
// cumulative (trapezoid in ln f, 8192 intervals); component i takes the frequency at the energy
// fraction (i + u_i)/N, the amplitude a = sqrt(2 sigma^2 / N) with sigma^2 the integral of S over
// the band (so the variance sum a^2/2 is sigma^2 exactly), and a uniform random phase; draws from
// mt19937_64(seed) in the order frequency, phase per component. Random frequencies: the gust does
// not repeat within a run. f_min = 1/3600 Hz (the default) keeps the fluctuations within the hour
// the mean is taken over. Ramp-in: u' is multiplied by 0 before `start` and by
// (1 - cos(pi (t - start)/ramp))/2 over the ramp (as the waves' wave_start, wave_ramp).
#include <cstdint>
#include <string>
#include <vector>

namespace yardsim::forces {

enum class GustSpectrumKind { Npd };

// (name: "npd") => the kind; throws std::invalid_argument listing the known spectra
GustSpectrumKind gustSpectrumKind(const std::string& name);

// The NPD (Froya) gust spectrum at one height
class NpdGustSpectrum {
 public:
  static constexpr double kN = 0.468;
  // (U0 > 0 m/s, the 1-hour mean at 10 m; z > 0 m) => the spectrum; throws std::invalid_argument
  NpdGustSpectrum(double u0, double z);
  // (f Hz) => S(f), m^2/s^2 per Hz; 0 for f < 0
  double density(double f) const;

 private:
  double scale_;   // 320 (U0/10)^2 (z/10)^0.45, m^2/s^2 per Hz
  double fScale_;  // 172 (z/10)^(2/3) (U0/10)^-0.75, s
};

struct GustProperties {
  GustSpectrumKind spectrum = GustSpectrumKind::Npd;
  std::uint64_t seed = 1;
  int components = 200;
  double fMin = 1.0 / 3600.0;  // Hz, the lowest frequency of the band
  double fMax = 1.0;           // Hz, the highest
  double height = 10.0;        // m above the still-water level: where the spectrum is taken
  double start = 0.0;          // s: no gust before this time
  double ramp = 0.0;           // s: the gust grows as (1 - cos(pi tau/ramp))/2, tau = t - start
};

class WindGusts {
 public:
  // (properties, U0 > 0 m/s the 1-hour mean at 10 m) => the components; throws
  // std::invalid_argument (the first word names the property) for components outside
  // [1, 100000], f_min not > 0, f_max not > f_min, a height not > 0, a ramp < 0, anything not
  // finite
  WindGusts(const GustProperties& p, double u0);

  const GustProperties& properties() const { return p_; }
  // (t s) => the gust u'(t) about the 1-hour mean, m/s; allocates nothing
  double speed(double t) const;
  // (t) => the ramp factor in [0, 1]
  double ramp(double t) const;
  // the integral of S over [f_min, f_max] (the table's), m^2/s^2: the variance sum a^2/2
  double variance() const { return variance_; }
  std::size_t size() const { return omega_.size(); }
  double frequency(std::size_t i) const;                           // Hz
  double amplitude(std::size_t i) const { return amplitude_[i]; }  // m/s
  double phase(std::size_t i) const { return phase_[i]; }          // rad

 private:
  GustProperties p_;
  double variance_ = 0.0;
  std::vector<double> omega_, amplitude_, phase_;  // rad/s, m/s, rad
};

}  // namespace yardsim::forces
