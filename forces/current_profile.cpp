#include "forces/current_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yardsim::forces {

CurrentField::CurrentField(CurrentProperties p) : p_(std::move(p)) {
  if (!(p_.speed >= 0) || !std::isfinite(p_.speed) || !std::isfinite(p_.direction))
    throw std::invalid_argument("current: the speed must be finite and >= 0 and the direction finite");
  std::sort(p_.profile.begin(), p_.profile.end());
  for (std::size_t i = 0; i < p_.profile.size(); ++i) {
    if (!std::isfinite(p_.profile[i].first) || !std::isfinite(p_.profile[i].second))
      throw std::invalid_argument("current: profile entry " + std::to_string(i) + " is not finite");
    if (i > 0 && p_.profile[i].first == p_.profile[i - 1].first)
      throw std::invalid_argument("current: two profile entries at the same depth");
  }
}

double CurrentField::speedAt(double z) const {
  const auto& t = p_.profile;
  if (t.empty()) return p_.speed;
  const double d = z - p_.level;
  // (table sorted by z) => linear between the entries around d, held outside
  if (d <= t.front().first) return p_.speed * t.front().second;
  if (d >= t.back().first) return p_.speed * t.back().second;
  const auto hi = std::upper_bound(t.begin(), t.end(), d, [](double x, const auto& e) { return x < e.first; });
  const auto lo = hi - 1;
  const double w = (d - lo->first) / (hi->first - lo->first);
  return p_.speed * ((1.0 - w) * lo->second + w * hi->second);
}

dynamics::Vector3 CurrentField::velocity(const dynamics::Vector3& p_W) const {
  const double u = speedAt(p_W.z());
  return {u * std::cos(p_.direction), u * std::sin(p_.direction), 0.0};
}

}  // namespace yardsim::forces
