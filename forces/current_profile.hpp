#pragma once
// The current: a horizontal flow of a given surface speed towards a direction, uniform or
// varying with depth by a table of (z, factor) pairs (z relative to the still-water level,
// linear in between, held beyond the ends). Not a force provider: current loads read it.
#include <utility>
#include <vector>

#include "dynamics/spatial.hpp"

namespace yardsim::forces {

struct CurrentProperties {
  double speed = 0.0;      // m/s (times the profile factor)
  double direction = 0.0;  // rad: the direction it flows towards, from +x towards +y
  double level = 0.0;      // m: z of the still-water level
  std::vector<std::pair<double, double>> profile;  // (z - level, factor); empty: uniform
};

class CurrentField {
 public:
  // (properties) => the field; throws std::invalid_argument for a negative or non-finite speed,
  // profile heights not strictly increasing, or a non-finite factor
  explicit CurrentField(CurrentProperties p);
  const CurrentProperties& properties() const { return p_; }
  // (z of a point) => speed there, m/s
  double speedAt(double z) const;
  // (world point) => current velocity there, m/s
  dynamics::Vector3 velocity(const dynamics::Vector3& p_W) const;

 private:
  CurrentProperties p_;
};

}  // namespace yardsim::forces
