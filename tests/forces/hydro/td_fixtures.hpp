#pragma once
// Shared set-ups of the time-domain Rankine tests (and of bench/hydro/barge_rao.cpp): a floating
// hemisphere of radius 1 m (the lower half of a cube sphere, 3 n^2 quads) with a free surface sized
// for a wave number k; a box barge 6 x 4 m at 1 m draft with its mass and restoring matrix.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "forces/geometry/primitive_meshes.hpp"
#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/panel_mesh.hpp"
#include "forces/hydro/rankine_td_model.hpp"
#include "forces/hydro/regular_wave_run.hpp"

namespace yardsim::forces::hydro::test {

inline constexpr double kG = 9.80665;
inline constexpr double kRho = 1025.0;
/// rho (2/3) pi a^3 for a = 1: Hulme's scale of the hemisphere's added mass
inline constexpr double kHemisphereMass = kRho * 2.0 / 3.0 * std::numbers::pi;

/// (ka, truncation radius in wavelengths, panels per wavelength far out) => settings for a = 1:
/// first ring 0.2 m, growth 1.15, a damping zone one wavelength wide (at most R - a - 2 lambda).
inline RankineTdSettings hemisphereSettings(double ka, double wavelengths = 3.0,
                                            double perWavelength = 10.0) {
  const double k = ka, lambda = 2.0 * std::numbers::pi / k,
               period = 2.0 * std::numbers::pi / std::sqrt(kG * k);
  RankineTdSettings s;
  s.rho = kRho;
  s.g = kG;
  s.freeSurface.firstSpacing = 0.2;
  s.freeSurface.maxSpacing = std::min(lambda / perWavelength, 4.0);
  s.freeSurface.growth = 1.15;
  s.freeSurface.truncationRadius = 1.0 + wavelengths * lambda;
  s.freeSurface = defaultBeach(s.freeSurface, period, kG);
  s.freeSurface.dampingWidth =
      std::min(s.freeSurface.dampingWidth, s.freeSurface.truncationRadius - 1.0 - 2.0 * lambda);
  return s;
}

/// The box barge: 6 m long (x), 4 m wide (y), 2 m deep, origin at the waterline amidships, 1 m
/// draft; `division` panels per metre (triangles, two per square).
struct BoxBarge {
  static constexpr double kLength = 6.0, kBeam = 4.0, kDraft = 1.0;
  int division = 1;
  /// the closed hull in the body frame: z from -1 to +1 m
  PanelMesh hull() const {
    return panelMesh(forces::boxMesh(Vector3(kLength, kBeam, 2.0 * kDraft), 6 * division,
                                     4 * division, 2 * division));
  }
  /// floating freely: mass rho V, centre of mass at the waterline (z_G = 0), radii of gyration
  /// 0.35 B (roll), 0.3 L (pitch, yaw)
  static RigidBody body() {
    const double m = kRho * kLength * kBeam * kDraft;
    RigidBody b;
    b.mass = m;
    b.inertiaCom = Vector3(m * std::pow(0.35 * kBeam, 2), m * std::pow(0.3 * kLength, 2),
                           m * std::pow(0.3 * kLength, 2))
                       .asDiagonal();
    return b;
  }
  /// C33 = rho g L B, C44 = rho g (L B^3 / 12 + V z_B), C55 = rho g (B L^3 / 12 + V z_B), z_B =
  /// -T/2, z_G = 0
  static Eigen::Matrix<double, 6, 6> restoring() {
    const double v = kLength * kBeam * kDraft, zb = -0.5 * kDraft, rg = kRho * kG;
    Eigen::Matrix<double, 6, 6> c = Eigen::Matrix<double, 6, 6>::Zero();
    c(2, 2) = rg * kLength * kBeam;
    c(3, 3) = rg * (kLength * std::pow(kBeam, 3) / 12.0 + v * zb);
    c(4, 4) = rg * (kBeam * std::pow(kLength, 3) / 12.0 + v * zb);
    return c;
  }
  /// a viscous roll damping of 5 % of critical on the dry inertia (the roll transient dies in
  /// a few tens of periods), on both sides of a comparison
  static Eigen::Matrix<double, 6, 6> viscousDamping() {
    Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
    d(3, 3) = 2.0 * 0.05 * std::sqrt(restoring()(3, 3) * body().inertiaCom(0, 0));
    return d;
  }
  /// (w) => a free surface out to 2.5 wavelengths past the hull (at least 30 m), panels of a
  /// tenth of a wavelength far out, the first ring 0.5 m, a damping zone one wavelength wide
  static RankineTdSettings settings(double omega) {
    const double lambda = 2.0 * std::numbers::pi * kG / (omega * omega),
                 period = 2.0 * std::numbers::pi / omega;
    RankineTdSettings s;
    s.rho = kRho;
    s.g = kG;
    s.freeSurface.firstSpacing = 0.5;
    s.freeSurface.maxSpacing = lambda / 10.0;
    s.freeSurface.growth = 1.15;
    s.freeSurface.truncationRadius = 4.0 + std::max(2.5 * lambda, 30.0);
    s.freeSurface = defaultBeach(s.freeSurface, period, kG);
    return s;
  }
};

}  // namespace yardsim::forces::hydro::test
