#pragma once
// The wind: a mean speed at a reference height above the still-water level, blowing towards a
// direction, with a vertical profile: uniform, the power law U(z) = U_ref (z / z_ref)^alpha, or
// the NPD (Froya) profile with its gust factor,
//   U(z, t) = U0 [1 + C ln(z/10)] [1 - 0.41 I_u(z) ln(t / t0)],
//   C = 5.73e-2 sqrt(1 + 0.148 U0),  I_u = 0.06 (1 + 0.043 U0) (z/10)^-0.22,  t0 = 3600 s,
// with U0 the 1-hour mean at 10 m and t <= 3600 s the averaging time (3 s: the gust).
// Not a force provider: wind loads read it.
#include <string>

#include "dynamics/spatial.hpp"

namespace yardsim::forces {

enum class WindProfileKind { Uniform, PowerLaw, Npd };

struct WindProperties {
  double speed = 0.0;             // m/s at the reference height (NPD: the 1-hour mean at 10 m)
  double direction = 0.0;         // rad: the direction it blows towards, from +x towards +y
  double referenceHeight = 10.0;  // m above the still-water level (NPD: 10)
  WindProfileKind profile = WindProfileKind::PowerLaw;
  double exponent = 0.11;         // power law alpha (0.11 at sea, 0.14 over land ...)
  double averagingTime = 3600.0;  // s, NPD only: 3600 the hourly mean, 60 a 1-minute mean, 3 the gust
  double density = 1.226;         // kg/m^3, air
  double level = 0.0;             // m: z of the still-water level (heights are measured from it)
  double minHeight = 1.0;         // m: heights below this use the speed at this height
};

class WindField {
 public:
  // (properties) => the field; throws std::invalid_argument for a negative speed, a
  // non-positive height, density or averaging time, an averaging time above 3600 s, or an NPD
  // reference height other than 10 m
  explicit WindField(const WindProperties& p);
  const WindProperties& properties() const { return p_; }
  // (height above the still-water level) => mean speed over the averaging time, m/s
  double speedAt(double height) const;
  // (world point) => wind velocity there, m/s (horizontal)
  dynamics::Vector3 velocity(const dynamics::Vector3& p_W) const;

 private:
  WindProperties p_;
};

// (name) => the profile kind, or throws std::invalid_argument listing uniform, power_law, npd
WindProfileKind windProfileKind(const std::string& name);

}  // namespace yardsim::forces
