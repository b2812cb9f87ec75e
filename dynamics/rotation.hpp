#pragma once
// Rotations: exponential and logarithm of SO(3), the inverse right Jacobian, quaternions stored
// scalar first (w, x, y, z), and Euler angles for output.

#include <bit>
#include <cmath>
#include <cstdint>

#include "dynamics/spatial.hpp"

namespace yardsim::dynamics {

/// (angle, rad) => (sin angle, cos angle) in one call: glibc's sincos, whose results are the same
/// doubles as std::sin and std::cos (the same code; tests/dynamics/rotation_test.cpp checks it)
/// in about 60 % of their instructions (GCC does not merge the two calls itself: errno).
inline void libmSinCos(double angle, double& s, double& c) {
#if defined(__GLIBC__)
  ::sincos(angle, &s, &c);
#else
  s = std::sin(angle);
  c = std::cos(angle);
#endif
}

/// (angle, rad) => (sin angle, cos angle) without a call, within two units in the last place of
/// std::sin and std::cos (not always the same doubles; rotation_test checks it): every placement
/// of a revolute joint (forward kinematics, ABA, CRBA, RNEA) and axisRotation use it. The angle
/// less n pi/2 (n the nearest integer; pi/2 in three parts, fdlibm's, so that n times the first
/// two is exact), fdlibm's minimax polynomials on [-pi/4, pi/4] side by side in one SSE2 pair,
/// and the quadrant n mod 4 by a swap and two sign flips; |angle| >= 1e5, infinities and NaN by
/// libmSinCos (the same doubles as libm there).
inline void sinCos(double angle, double& s, double& c) {
  constexpr double kPio4 = 0.785398163397448279;  // pi/4 rounded down
  double r = angle;
  std::uint64_t n = 0;
  if (!(std::abs(angle) <= kPio4)) {
    if (!(std::abs(angle) < 1e5)) {
      libmSinCos(angle, s, c);
      return;
    }
    constexpr double kInvPio2 = 6.36619772367581382433e-01;
    constexpr double kPio2a = 1.57079632673412561417e+00;
    constexpr double kPio2b = 6.07710050630396597660e-11;
    constexpr double kPio2c = 2.02226624879595063154e-21;
    constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer
    // (angle) => n, r = angle - n pi/2 with |r| <= pi/4 (plus round-off)
    const double t = angle * kInvPio2 + kRound;
    n = std::bit_cast<std::uint64_t>(t);
    const double fn = t - kRound;
    r = ((angle - fn * kPio2a) - fn * kPio2b) - fn * kPio2c;
  }
  // (r) => sin r, cos r: fdlibm's __kernel_sin and __kernel_cos without the tail of r, their two
  // polynomials in z = r^2 evaluated side by side in one pair (SSE2's width)
  using Pair = Eigen::Vector2d;
  const double z = r * r;
  const Pair zz(z, z);
  Pair p(1.58969099521155010221e-10, -1.13596475577881948265e-11);
  p = Pair(-2.50507602534068634195e-08, 2.08757232129817482790e-09) + zz.cwiseProduct(p);
  p = Pair(2.75573137070700676789e-06, -2.75573143513906633035e-07) + zz.cwiseProduct(p);
  p = Pair(-1.98412698298579493134e-04, 2.48015872894767294178e-05) + zz.cwiseProduct(p);
  p = Pair(8.33333333332248946124e-03, -1.38888888888741095749e-03) + zz.cwiseProduct(p);
  p = Pair(-1.66666666666666324348e-01, 4.16666666666666019037e-02) + zz.cwiseProduct(p);
  p = Pair(z * r, z * z).cwiseProduct(p);
  const double sr = r + p[0];
  const double hz = 0.5 * z;
  const double w = 1.0 - hz;
  const double cr = w + (((1.0 - w) - hz) + p[1]);
  if (n == 0) {
    s = sr;
    c = cr;
    return;
  }
  // (n mod 4) => (s, c) = (sr, cr), (cr, -sr), (-sr, -cr), (-cr, sr)
  const bool odd = (n & 1U) != 0;
  const std::uint64_t signS = (n & 2U) << 62;
  const std::uint64_t signC = ((n + 1U) & 2U) << 62;
  s = std::bit_cast<double>(std::bit_cast<std::uint64_t>(odd ? cr : sr) ^ signS);
  c = std::bit_cast<double>(std::bit_cast<std::uint64_t>(odd ? sr : cr) ^ signC);
}

/// exp([w]x): the rotation by |w| about w/|w| (Rodrigues).
Matrix3 expSO3(const Vector3& w);
/// The rotation vector w with expSO3(w) = R, |w| <= pi.
Vector3 logSO3(const Matrix3& R);
/// Jr^{-1}(w): for R(t) = R0 exp([w(t)]x) with body angular velocity omega, dw/dt = Jr^{-1}(w) omega.
Matrix3 rightJacobianInverse(const Vector3& w);
/// The rotation by angle about a unit axis.
Matrix3 axisRotation(const Vector3& axis, double angle);
/// (k = 0, 1, 2; s = sin angle, c = cos angle) => R = axisRotation(unit vector k, angle), entry
/// for entry the same doubles (the general formula's terms in exact zeros and ones left out, its
/// signed zeros and its diagonal c + (1 - c) on the axis kept), without the general formula's
/// products. The axis's components must be exactly +0 and 1 (Model::jointAxis).
inline void coordinateAxisRotation(int k, double s, double c, Matrix3& R) {
  const int a = (k + 1) % 3;
  const int b = (k + 2) % 3;
  R(k, k) = c + (1.0 - c);
  R(a, a) = c;
  R(b, b) = c;
  R(a, b) = 0.0 - s;
  R(b, a) = 0.0 + s;
  R(k, a) = 0.0;
  R(a, k) = 0.0;
  R(k, b) = 0.0;
  R(b, k) = 0.0;
}

/// The rotation matrix of a unit quaternion stored (w, x, y, z) at q[0..3].
Matrix3 quaternionToMatrix(const double* q);
/// A rotation matrix => unit quaternion (w, x, y, z) with w >= 0, written to q[0..3].
void matrixToQuaternion(const Matrix3& R, double* q);

/// Euler angles (roll, pitch, yaw) of R in the z-y'-x'' intrinsic (Tait-Bryan, aerospace/marine)
/// convention: R = Rz(yaw) * Ry(pitch) * Rx(roll), with pitch in [-pi/2, pi/2] and roll, yaw in
/// (-pi, pi]. At pitch = +-pi/2 (gimbal lock) roll is set to 0 and yaw carries the rotation.
Vector3 eulerAngles(const Matrix3& R);
/// The inverse of eulerAngles: Rz(yaw) * Ry(pitch) * Rx(roll).
Matrix3 eulerToMatrix(const Vector3& rollPitchYaw);

}  // namespace yardsim::dynamics
