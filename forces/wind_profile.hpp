#pragma once
// The wind: a mean speed at a reference height above the still-water level, blowing towards a
// direction, with a vertical profile: uniform, the power law U(z) = U_ref (z / z_ref)^alpha, or
// the NPD (Froya) profile with its gust factor,
//   U(z, t) = U0 [1 + C ln(z/10)] [1 - 0.41 I_u(z) ln(t / t0)],
//   C = 5.73e-2 sqrt(1 + 0.148 U0),  I_u = 0.06 (1 + 0.043 U0) (z/10)^-0.22,  t0 = 3600 s,
// with U0 the 1-hour mean at 10 m and t <= 3600 s the averaging time (3 s: the gust).
// Optional time-varying gusts (forces/wind_gusts.hpp, NPD profile only, with the 1-hour mean:
// averaging time 3600 s): U(z, t) = U_mean(z) + u'(t), one gust series u' for every height.
// Not a force provider: wind loads read it.
#include <optional>
#include <string>

#include "dynamics/spatial.hpp"
#include "forces/wind_gusts.hpp"

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
  std::optional<GustProperties> gusts;  // none: a steady wind
};

class WindField {
 public:
  // (properties) => the field; throws std::invalid_argument for a negative speed, a
  // non-positive height, density or averaging time, an averaging time above 3600 s, an NPD
  // reference height other than 10 m, gusts on another profile than NPD or with another
  // averaging time than 3600 s, or bad gust properties (forces/wind_gusts.hpp)
  explicit WindField(const WindProperties& p);
  const WindProperties& properties() const { return p_; }
  // (height above the still-water level) => mean speed over the averaging time, m/s
  double speedAt(double height) const;
  // (t s) => the gust u'(t), m/s (0 without gusts)
  double gust(double t) const { return gusts_ ? gusts_->speed(t) : 0.0; }
  // the gusts, or null for a steady wind
  const WindGusts* gusts() const { return gusts_ ? &*gusts_ : nullptr; }
  // (world point, t s) => wind velocity there, mean plus gust, m/s (horizontal); allocates nothing
  dynamics::Vector3 velocity(const dynamics::Vector3& p_W, double t) const;

 private:
  WindProperties p_;
  std::optional<WindGusts> gusts_;
};

// (name) => the profile kind, or throws std::invalid_argument listing uniform, power_law, npd
WindProfileKind windProfileKind(const std::string& name);

}  // namespace yardsim::forces
