#include "forces/airy_waves.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace yardsim::forces {

using dynamics::Vector3;

namespace {
// (k, z' <= 0, depth) => cosh(k(z'+h))/cosh(kh), sinh(k(z'+h))/sinh(kh), cosh(k(z'+h))/sinh(kh),
// in forms that neither overflow for large kh nor lose the deep-water limit e^{kz'}
struct Decay {
  double cc, ss, cs;
};
Decay decay(double k, double z, double h) {
  const double e = std::exp(k * z);
  if (!std::isfinite(h)) return {e, e, e};
  const double a = std::exp(-2.0 * k * (z + h)), b = std::exp(-2.0 * k * h);
  return {e * (1.0 + a) / (1.0 + b), e * (1.0 - a) / (1.0 - b), e * (1.0 + a) / (1.0 - b)};
}
}  // namespace

double waveNumber(double omega, double depth, double g) {
  const double deep = omega * omega / g;
  if (!std::isfinite(depth)) return deep;
  // (Newton on f(k) = g k tanh(kh) - w^2 from the larger of the deep and shallow guesses) => k
  double k = std::max(deep, omega / std::sqrt(g * depth));
  for (int i = 0; i < 50; ++i) {
    const double t = std::tanh(k * depth);
    const double f = g * k * t - omega * omega;
    const double df = g * t + g * k * depth * (1.0 - t * t);
    const double step = f / df;
    k -= step;
    if (std::abs(step) < 1e-15 * k) break;
  }
  return k;
}

AiryWaves::AiryWaves(const WaterProperties& water, std::vector<WaveComponent> components) : water_(water) {
  if (!(water_.density > 0) || !(water_.gravity > 0) || !(water_.depth > 0) || !std::isfinite(water_.level) ||
      !(water_.ramp >= 0) || !std::isfinite(water_.ramp) || !std::isfinite(water_.start))
    throw std::invalid_argument("water: density, gravity and depth must be > 0, level and start finite, ramp >= 0");
  for (std::size_t i = 0; i < components.size(); ++i) {
    const WaveComponent& c = components[i];
    const std::string which = "wave " + std::to_string(i) + ": ";
    if (!(c.height > 0) || !(c.period > 0) || !std::isfinite(c.height) || !std::isfinite(c.period) ||
        !std::isfinite(c.direction) || !std::isfinite(c.phase))
      throw std::invalid_argument(which + "height and period must be finite and > 0");
    const double omega = 2.0 * M_PI / c.period;
    const double k = waveNumber(omega, water_.depth, water_.gravity);
    const double steepness = c.height * k / (2.0 * M_PI);
    if (steepness > 1.0 / 7.0)
      throw std::invalid_argument(which + "H/L = " + std::to_string(steepness) +
                                  " is above the breaking limit 1/7; lower the height or lengthen the period");
    const double floorDecay = std::isfinite(water_.depth) ? std::exp(-2.0 * k * water_.depth) : 0.0;
    waves_.push_back({c, 0.5 * c.height, k, omega, std::cos(c.direction), std::sin(c.direction),
                      1.0 / (1.0 + floorDecay), floorDecay});
  }
}

namespace {
// The ramp and the stretching as functions local to this file, so that the hot paths below
// inline them (an exported member of a shared library is called through its PLT entry)
// (water, t) => the factor in [0, 1] of every amplitude
double rampOf(const WaterProperties& w, double t) {
  const double tau = t - w.start;
  if (tau < 0.0) return 0.0;
  if (w.ramp <= 0.0 || tau >= w.ramp) return 1.0;
  return 0.5 * (1.0 - std::cos(M_PI * tau / w.ramp));
}
// (water, z, surface eta) => Wheeler: z' = h (z - eta) / (h + eta) below the level (deep: z - eta)
double stretchedOf(const WaterProperties& w, double z, double eta) {
  const double zr = z - w.level, er = eta - w.level, h = w.depth;
  if (!std::isfinite(h)) return zr - er;
  return h * (zr - er) / (h + er);
}
}  // namespace

double AiryWaves::ramp(double t) const {
  return rampOf(water_, t);
}

double AiryWaves::stretched(double z, double eta) const {
  return stretchedOf(water_, z, eta);
}

double AiryWaves::elevation(double x, double y, double t) const {
  // (before the waves start) => the level, as level + 0 * eta gives, without the cosines
  const double r = rampOf(water_, t);
  if (r == 0.0) return water_.level;
  double eta = 0.0;
  for (const Wave& w : waves_) eta += w.a * std::cos(w.k * (x * w.cosb + y * w.sinb) - w.omega * t + w.c.phase);
  return water_.level + r * eta;
}

Vector3 AiryWaves::velocity(const Vector3& p, double t) const {
  const double eta = elevation(p.x(), p.y(), t);
  if (waves_.empty() || p.z() > eta) return Vector3::Zero();
  const double zs = stretched(p.z(), eta), r = ramp(t);
  Vector3 u = Vector3::Zero();
  for (const Wave& w : waves_) {
    // (a w cosh/sinh cos th along the direction, a w sinh/sinh sin th up)
    const double th = w.k * (p.x() * w.cosb + p.y() * w.sinb) - w.omega * t + w.c.phase;
    const Decay d = decay(w.k, zs, water_.depth);
    const double uh = w.a * w.omega * d.cs * std::cos(th);
    u += Vector3(uh * w.cosb, uh * w.sinb, w.a * w.omega * d.ss * std::sin(th));
  }
  return r * u;
}

Vector3 AiryWaves::acceleration(const Vector3& p, double t) const {
  const double eta = elevation(p.x(), p.y(), t);
  if (waves_.empty() || p.z() > eta) return Vector3::Zero();
  const double zs = stretched(p.z(), eta), r = ramp(t);
  Vector3 a = Vector3::Zero();
  for (const Wave& w : waves_) {
    // (d/dt of the velocity at a fixed point, linear theory)
    const double th = w.k * (p.x() * w.cosb + p.y() * w.sinb) - w.omega * t + w.c.phase;
    const Decay d = decay(w.k, zs, water_.depth);
    const double ah = w.a * w.omega * w.omega * d.cs * std::sin(th);
    a += Vector3(ah * w.cosb, ah * w.sinb, -w.a * w.omega * w.omega * d.ss * std::cos(th));
  }
  return r * a;
}

double AiryWaves::dynamicPressure(const Vector3& p, double t) const {
  if (waves_.empty()) return 0.0;
  const double eta = elevation(p.x(), p.y(), t);
  return p.z() > eta ? 0.0 : dynamicPressureBelow(p, t, eta);
}

double AiryWaves::dynamicPressureBelow(const Vector3& p, double t, double eta) const {
  const double zs = stretched(p.z(), eta);
  double pd = 0.0;
  for (const Wave& w : waves_) {
    const double th = w.k * (p.x() * w.cosb + p.y() * w.sinb) - w.omega * t + w.c.phase;
    pd += w.a * decay(w.k, zs, water_.depth).cc * std::cos(th);
  }
  return water_.density * water_.gravity * ramp(t) * pd;
}

template <class AmplitudeCos>
double AiryWaves::pressureWith(const Vector3& p, double r, AmplitudeCos c) const {
  // (a_i cos th_i) => the surface above p; p above it: dry
  double sum = 0.0;
  for (std::size_t i = 0; i < waves_.size(); ++i) sum += c(i);
  const double eta = water_.level + r * sum;
  if (p.z() > eta) return 0.0;
  // (stretched height z') => rho g (level - z) + r sum a_i cos th_i cosh k(z'+h) / cosh kh, with
  // e^{kz'} (1 + e^{-2k(z'+h)}) = e^{kz'} + e^{-2kh} / e^{kz'}: one exponential a component
  const double zs = stretchedOf(water_, p.z(), eta);
  double pd = 0.0;
  for (std::size_t i = 0; i < waves_.size(); ++i) {
    const Wave& w = waves_[i];
    const double e = std::exp(w.k * zs);
    pd += c(i) * (w.floorDecay > 0.0 && e > 0.0 ? (e + w.floorDecay / e) * w.coshScale : e);
  }
  return water_.density * water_.gravity * (water_.level - p.z() + r * pd);
}

double AiryWaves::pressure(const Vector3& p, double t) const {
  return pressure(p, t, rampOf(water_, t));
}

double AiryWaves::pressure(const Vector3& p, double t, double r) const {
  // (calm water, or the waves not started: eta = level and r p_dyn = 0 exactly) => hydrostatic
  if (waves_.empty() || r == 0.0) return hydrostaticPressure(p);
  const double rg = water_.density * water_.gravity;
  // (up to kCached components, an irregular sea's usual 200 included) => each cos(theta) once,
  // for the surface and for the pressure, in a buffer on the stack (2 KB)
  constexpr std::size_t kCached = 256;
  if (waves_.size() > kCached) {
    const double eta = elevation(p.x(), p.y(), t);
    return p.z() > eta ? 0.0 : rg * (water_.level - p.z()) + dynamicPressureBelow(p, t, eta);
  }
  double c[kCached];
  for (std::size_t i = 0; i < waves_.size(); ++i) {
    const Wave& w = waves_[i];
    c[i] = w.a * std::cos(w.k * (p.x() * w.cosb + p.y() * w.sinb) - w.omega * t + w.c.phase);
  }
  return pressureWith(p, r, [&c](std::size_t i) { return c[i]; });
}

void AiryWaves::halfPhases(double x, double y, double t, double* h) const {
  // (x, y, t) => sincos of half of each phase
  for (std::size_t i = 0; i < waves_.size(); ++i) {
    const Wave& w = waves_[i];
    const double half = 0.5 * (w.k * (x * w.cosb + y * w.sinb) - w.omega * t + w.c.phase);
    h[2 * i] = std::cos(half);
    h[2 * i + 1] = std::sin(half);
  }
}

double AiryWaves::elevation(const double* h, double t) const {
  return elevationRamped(h, rampOf(water_, t));
}

double AiryWaves::elevationRamped(const double* h, double r) const {
  // (half phases) => level + r sum a_i cos th_i, cos th = cos^2(th/2) - sin^2(th/2)
  if (r == 0.0) return water_.level;
  double eta = 0.0;
  for (std::size_t i = 0; i < waves_.size(); ++i)
    eta += waves_[i].a * (h[2 * i] * h[2 * i] - h[2 * i + 1] * h[2 * i + 1]);
  return water_.level + r * eta;
}

double AiryWaves::pressureBetween(const Vector3& p, const double* ha, const double* hb,
                                  double t) const {
  return pressureBetween(p, ha, hb, t, rampOf(water_, t));
}

double AiryWaves::pressureBetween(const Vector3& p, const double* ha, const double* hb, double t,
                                  double r) const {
  if (waves_.empty() || r == 0.0) return pressure(p, t, r);
  // (half phases at a and b) => a_i cos((th_a + th_b) / 2), the phase at their midpoint p
  return pressureWith(p, r, [this, ha, hb](std::size_t i) {
    return waves_[i].a * (ha[2 * i] * hb[2 * i] - ha[2 * i + 1] * hb[2 * i + 1]);
  });
}

}  // namespace yardsim::forces
