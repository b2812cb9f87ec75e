#pragma once
// The sea: still-water level, density, depth and regular Airy (linear) wave components,
// superposed. Elevation, particle velocity and acceleration, and dynamic pressure of the
// incident waves; below the instantaneous surface the kinematics use Wheeler stretching (the
// point's height is mapped so that the surface sits at z = level), so the total pressure
// rho g (level - z) + p_dyn is zero exactly on the surface. Calm water: no components.
// Not a force provider: hydrostatics (and later hydrodynamics) read it. Limits: docs/hydrostatics.md.
#include <limits>
#include <vector>

#include "dynamics/spatial.hpp"

namespace yardsim::forces {

// One regular wave: crest-to-trough height H (m), period T (s), the direction it travels
// towards (rad, from +x towards +y) and a phase (rad): eta = H/2 cos(k (x cos b + y sin b) - w t + phase).
struct WaveComponent {
  double height = 0.0;
  double period = 0.0;
  double direction = 0.0;
  double phase = 0.0;
};

struct WaterProperties {
  double density = 1025.0;  // kg/m^3
  double gravity = 9.81;    // m/s^2
  double level = 0.0;       // m, z of the still-water level
  double depth = std::numeric_limits<double>::infinity();  // m below the level; inf: deep water
  double ramp = 0.0;        // s: the wave amplitudes grow as (1 - cos(pi tau/ramp))/2, tau = t - start
  double start = 0.0;       // s: calm water before this time, then the ramp
};

class AiryWaves {
 public:
  // (water, components) => the sea; throws std::invalid_argument for a non-positive density,
  // gravity, depth, height or period, or a component that breaks (H/L above 1/7)
  AiryWaves(const WaterProperties& water, std::vector<WaveComponent> components = {});

  const WaterProperties& water() const { return water_; }
  bool calm() const { return waves_.empty(); }
  std::size_t size() const { return waves_.size(); }
  const WaveComponent& component(std::size_t i) const { return waves_[i].c; }
  double wavenumber(std::size_t i) const { return waves_[i].k; }  // rad/m, from the dispersion relation
  double frequency(std::size_t i) const { return waves_[i].omega; }  // rad/s

  // (x, y, t) => z of the free surface, m
  double elevation(double x, double y, double t) const;
  // (p_W, t) => water particle velocity, m/s; zero above the surface
  dynamics::Vector3 velocity(const dynamics::Vector3& p, double t) const;
  // (p_W, t) => water particle acceleration (local, linear), m/s^2; zero above the surface
  dynamics::Vector3 acceleration(const dynamics::Vector3& p, double t) const;
  // (p_W, t) => dynamic pressure of the incident waves, Pa; zero above the surface
  double dynamicPressure(const dynamics::Vector3& p, double t) const;
  // (p_W, t) => total incident pressure rho g (level - z) + p_dyn below the surface, 0 above, Pa
  double pressure(const dynamics::Vector3& p, double t) const;
  // (p_W, t, r = ramp(t), computed once for many points) => pressure(p, t), the same double, Pa
  double pressure(const dynamics::Vector3& p, double t, double r) const;
  // (p_W) => the still water's pressure rho g (level - z) below the level, 0 above, Pa: the
  // same double as pressure(p, t, r) in calm water or with r = 0 (inline: hot in the clipping)
  double hydrostaticPressure(const dynamics::Vector3& p) const {
    return p.z() < water_.level ? water_.density * water_.gravity * (water_.level - p.z()) : 0.0;
  }
  // (t) => the factor in [0, 1] every amplitude is multiplied by at t (water.start, water.ramp)
  double ramp(double t) const;

  // Half phases, for many points of one surface (a hull's corners and its edges' midpoints): the
  // phase of component i at a point is th_i = k_i (x cos b_i + y sin b_i) - w_i t + phase_i, linear
  // in x and y, so at the midpoint of a and b, cos th_i = cos(th_a/2) cos(th_b/2) - sin(th_a/2)
  // sin(th_b/2): one sincos per corner and component instead of one cosine per point.
  // (x, y, t) => h[2 i] = cos(th_i / 2), h[2 i + 1] = sin(th_i / 2), for the size() components
  void halfPhases(double x, double y, double t, double* h) const;
  // (half phases at (x, y), t) => z of the free surface there, m (elevation(x, y, t) to round-off)
  double elevation(const double* h, double t) const;
  // (half phases, r = ramp(t)) => elevation(h, t), the same double, m
  double elevationRamped(const double* h, double r) const;
  // (p_W the midpoint of a and b, their half phases, t) => pressure(p, t) to round-off, Pa
  double pressureBetween(const dynamics::Vector3& p, const double* ha, const double* hb,
                         double t) const;
  // (as pressureBetween, r = ramp(t)) => pressureBetween(p, ha, hb, t), the same double, Pa
  double pressureBetween(const dynamics::Vector3& p, const double* ha, const double* hb, double t,
                         double r) const;

 private:
  struct Wave {
    WaveComponent c;
    double a, k, omega, cosb, sinb;
    double coshScale;  // 1 / (1 + e^{-2kh}): cosh k(z'+h) / cosh kh = e^{kz'} (1 + e^{-2k(z'+h)}) coshScale
    double floorDecay;  // e^{-2kh} (0 in deep water): e^{kz'} (1 + e^{-2k(z'+h)}) = e^{kz'} +
                        // e^{-2kh} / e^{kz'}
  };
  // (p, t, r = ramp(t) > 0, c(i) = a_i cos th_i at p) => pressure(p, t), Pa
  template <class AmplitudeCos>
  double pressureWith(const dynamics::Vector3& p, double r, AmplitudeCos c) const;
  // (p at or below the surface eta, t) => p_dyn, Pa
  double dynamicPressureBelow(const dynamics::Vector3& p, double t, double eta) const;
  // (p, t, eta) => the stretched height below the level, z' <= 0, for depth decay factors
  double stretched(double z, double eta) const;

  WaterProperties water_;
  std::vector<Wave> waves_;
};

// (omega, depth, g) => k solving omega^2 = g k tanh(k depth) (Newton), rad/m
double waveNumber(double omega, double depth, double g);

}  // namespace yardsim::forces
