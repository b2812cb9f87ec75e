#include "forces/rope_law.hpp"

#include <cmath>
#include <stdexcept>

namespace yardsim::forces {

namespace {
void require(bool ok, const std::string& owner, const char* what, double value) {
  if (!ok)
    throw std::invalid_argument("rope '" + owner + "': " + what + " (got " + std::to_string(value) +
                                ")");
}
}  // namespace

void checkRopeProperties(const RopeProperties& p, const std::string& owner) {
  // (properties) => each finite and in range; NaN fails every comparison, so it is refused too
  require(p.ea > 0.0 && std::isfinite(p.ea), owner, "EA must be finite and > 0 N", p.ea);
  require(p.minLength > 0.0 && std::isfinite(p.minLength), owner,
          "the minimum length must be finite and > 0 m", p.minLength);
  require(p.l0 >= p.minLength && std::isfinite(p.l0), owner,
          "the unstretched length must be finite and >= the minimum length", p.l0);
  require(p.damping >= 0.0 && std::isfinite(p.damping), owner,
          "damping must be finite and >= 0 N s/m", p.damping);
  if (p.breakingLoad)
    require(*p.breakingLoad > 0.0 && std::isfinite(*p.breakingLoad), owner,
            "the minimum breaking load must be finite and > 0 N", *p.breakingLoad);
}

double elasticTension(double ea, const RopeStrain& s) {
  // a NaN length or L0 gives NaN (the comparison is false), so evaluate() can refuse it
  return s.length <= s.l0 ? 0.0 : ea / s.l0 * (s.length - s.l0);
}

double ropeTension(double ea, double c, const RopeStrain& s) {
  // (L, L0, rates) => spring + dashpot on the elongation L - L0, only while taut, never negative
  if (s.length <= s.l0) return 0.0;
  const double t = elasticTension(ea, s) + c * (s.lengthRate - s.l0Rate);
  return t < 0.0 ? 0.0 : t;  // NaN passes through
}

double strainEnergy(double ea, double length, double l0) {
  const double e = length - l0;
  return e <= 0.0 ? 0.0 : 0.5 * ea / l0 * e * e;
}

double strainEnergyDl0(double ea, double length, double l0) {
  // d/dL0 [EA e^2 / (2 L0)] with e = L - L0: -EA e / L0 - EA e^2 / (2 L0^2)
  const double e = length - l0;
  return e <= 0.0 ? 0.0 : -ea * e / l0 - 0.5 * ea * e * e / (l0 * l0);
}

double ropePower(double ea, double tension, int parts, const RopeStrain& s) {
  // (T applied, T elastic) => the part of T that is not -dV/dL does work -n (T - Te) L';
  // the winch changes the stored energy by n dV/dL0 L0'
  const double n = static_cast<double>(parts);
  return -n * (tension - elasticTension(ea, s)) * s.lengthRate +
         n * strainEnergyDl0(ea, s.length, s.l0) * s.l0Rate;
}

}  // namespace yardsim::forces
