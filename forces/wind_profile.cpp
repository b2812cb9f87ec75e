#include "forces/wind_profile.hpp"

#include <cmath>
#include <stdexcept>

namespace yardsim::forces {

WindProfileKind windProfileKind(const std::string& name) {
  if (name == "uniform") return WindProfileKind::Uniform;
  if (name == "power_law") return WindProfileKind::PowerLaw;
  if (name == "npd") return WindProfileKind::Npd;
  throw std::invalid_argument("unknown wind profile '" + name + "'; expected uniform, power_law or npd");
}

WindField::WindField(const WindProperties& p) : p_(p) {
  if (!(p_.speed >= 0) || !std::isfinite(p_.speed) || !std::isfinite(p_.direction))
    throw std::invalid_argument("wind: the speed must be finite and >= 0 and the direction finite");
  if (!(p_.referenceHeight > 0) || !(p_.density > 0) || !(p_.minHeight > 0))
    throw std::invalid_argument("wind: the reference height, air density and minimum height must be > 0");
  if (!(p_.exponent >= 0) || !std::isfinite(p_.exponent))
    throw std::invalid_argument("wind: the power-law exponent must be >= 0");
  if (!(p_.averagingTime > 0) || p_.averagingTime > 3600.0)
    throw std::invalid_argument("wind: the averaging time must be in (0, 3600] s");
  if (p_.profile == WindProfileKind::Npd && std::abs(p_.referenceHeight - 10.0) > 1e-12)
    throw std::invalid_argument("wind: the NPD profile takes the 1-hour mean speed at 10 m (reference height 10)");
  if (!p_.gusts) return;
  // (gusts) => on the NPD profile's 1-hour mean only: a shorter averaging time's gust factor
  // already holds the fluctuations the gusts add
  if (p_.profile != WindProfileKind::Npd)
    throw std::invalid_argument("wind: gusts go with profile: npd (the NPD spectrum takes U0, the 1-hour mean at 10 m)");
  if (p_.averagingTime != 3600.0)
    throw std::invalid_argument("wind: with gusts the profile gives the 1-hour mean: averaging_time must be 3600 s "
                                "(a shorter one's gust factor would count the gusts twice)");
  gusts_.emplace(*p_.gusts, p_.speed);
}

double WindField::speedAt(double height) const {
  const double z = std::max(height, p_.minHeight);
  switch (p_.profile) {
    case WindProfileKind::Uniform:
      return p_.speed;
    case WindProfileKind::PowerLaw:
      return p_.speed * std::pow(z / p_.referenceHeight, p_.exponent);
    case WindProfileKind::Npd: {
      const double U0 = p_.speed;
      const double C = 5.73e-2 * std::sqrt(1.0 + 0.148 * U0);
      const double Iu = 0.06 * (1.0 + 0.043 * U0) * std::pow(z / 10.0, -0.22);
      return U0 * (1.0 + C * std::log(z / 10.0)) * (1.0 - 0.41 * Iu * std::log(p_.averagingTime / 3600.0));
    }
  }
  return 0.0;
}

dynamics::Vector3 WindField::velocity(const dynamics::Vector3& p_W, double t) const {
  const double mean = speedAt(p_W.z() - p_.level);
  const double u = gusts_ ? mean + gusts_->speed(t) : mean;
  return {u * std::cos(p_.direction), u * std::sin(p_.direction), 0.0};
}

}  // namespace yardsim::forces
