#pragma once
// Wave spectra of an irregular sea and its directional spreading (docs/hydrodynamics.md,
// "Irregular seas"). Frequencies omega in rad/s, spectral densities S(omega) in m^2 s/rad
// (one-sided, integral of S over omega >= 0 = m0 = Hs^2/16), directions in rad (from +x towards +y,
// the way the waves travel, as forces::WaveComponent).
//   Pierson-Moskowitz (Hs, Tp): S_PM = 5/16 Hs^2 wp^4 w^-5 exp(-5/4 (wp/w)^4), wp = 2 pi/Tp.
//   JONSWAP (Hs, Tp, gamma): A_gamma S_PM gamma^exp(-(w - wp)^2 / (2 sigma^2 wp^2)),
//     sigma = 0.07 (w <= wp) or 0.09, A_gamma such that m0 = Hs^2/16 exactly (computed, not the
//     approximation 1 - 0.287 ln gamma). gamma = 1 is Pierson-Moskowitz.
//   cos-2s spreading about the mean direction b0: D(b) = G(s) cos^2s((b - b0)/2), b - b0 in
//     [-pi, pi], integral 1; E[cos(b - b0)] = s/(s+1).
#include <string>
#include <vector>

namespace yardsim::forces::hydro {

enum class SpectrumKind { PiersonMoskowitz, Jonswap };

// (name: "jonswap", "pierson_moskowitz" or "pm") => the kind; throws std::invalid_argument
SpectrumKind spectrumKind(const std::string& name);

class WaveSpectrum {
 public:
  // (kind, Hs m, Tp s, gamma >= 1) => the spectrum, normalised; throws std::invalid_argument for
  // Hs or Tp not > 0, or gamma outside [1, 20]
  WaveSpectrum(SpectrumKind kind, double hs, double tp, double gamma = 3.3);

  SpectrumKind kind() const { return kind_; }
  double hs() const { return hs_; }
  double tp() const { return tp_; }
  double gamma() const { return gamma_; }
  double peakFrequency() const { return wp_; }      // rad/s
  double normalisation() const { return aGamma_; }  // A_gamma (1 for Pierson-Moskowitz)

  // (omega rad/s) => S(omega), m^2 s/rad; 0 for omega <= 0
  double density(double omega) const;
  // (omega) => integral of S from 0 to omega, m^2 (m0 at infinity)
  double cumulative(double omega) const;
  // (fraction in [0, 1)) => omega with cumulative(omega) = fraction m0 (rad/s)
  double quantile(double fraction) const;
  // (n) => spectral moment m_n = integral omega^n S d omega (n = 0 .. 4; m4 of the truncated tail
  // grows as ln of the cut-off, integrated to 12 wp), m^2 (rad/s)^n
  double moment(int n) const;

 private:
  // (x = omega/wp) => S / (Hs^2/wp) without A_gamma: the Pierson-Moskowitz shape times the peak
  // enhancement
  double shape(double x) const;

  SpectrumKind kind_;
  double hs_, tp_, gamma_, wp_, aGamma_ = 1.0;
  std::vector<double> x_, cum_;  // the cumulative table over x in [kLow, kHigh], fractions of m0
};

// (s > 0) => cos-2s spreading: its density and quantiles (relative to the mean direction)
class CosineSpreading {
 public:
  // throws std::invalid_argument for s not > 0 or above 1000
  explicit CosineSpreading(double s);
  double s() const { return s_; }
  // (b - b0 in [-pi, pi]) => D, 1/rad
  double density(double relative) const;
  // (fraction in [0, 1]) => the relative direction with that much of D to its left, rad
  double quantile(double fraction) const;

 private:
  double s_, scale_;
  std::vector<double> b_, cum_;
};

}  // namespace yardsim::forces::hydro
