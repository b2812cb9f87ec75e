#pragma once
// Rotations: exponential and logarithm of SO(3), the inverse right Jacobian, quaternions stored
// scalar first (w, x, y, z), and Euler angles for output.

#include <cmath>

#include "dynamics/spatial.hpp"

namespace yardsim::dynamics {

namespace detail {
// (r, its tail rt: |r + rt| <= pi/4 + 1e-9) => sin(r + rt): fdlibm's __kernel_sin (musl __sin, iy = 1),
// a degree-13 odd minimax polynomial, error < 1 ulp
inline double sinKernel(double r, double rt) {
  constexpr double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
                   S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
                   S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
  const double z = r * r, w = z * z;
  const double p = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
  const double v = z * r;
  return r - ((z * (0.5 * rt - v * p) - rt) - v * S1);
}
// (r, its tail rt: |r + rt| <= pi/4 + 1e-9) => cos(r + rt): fdlibm's __kernel_cos (musl __cos),
// a degree-14 even minimax polynomial with 1 - z/2 summed in two parts, error < 1 ulp
inline double cosKernel(double r, double rt) {
  constexpr double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
                   C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
                   C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
  const double z = r * r, w = z * z;
  const double p = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
  const double hz = 0.5 * z, one = 1.0 - hz;
  return one + (((1.0 - one) - hz) + (z * p - r * rt));
}
}  // namespace detail

/// (angle, rad) => (sin angle, cos angle) in one call, within 1 ulp of std::sin and std::cos
/// (tests/dynamics/rotation_test.cpp). For 2^-26 <= |angle| < 1e5 rad: Cody-Waite reduction by
/// pi/2 with a three-part constant (fdlibm's __rem_pio2 medium case, all three rounds) to
/// r + rt in [-pi/4, pi/4] and quadrant n, fdlibm's minimax kernels, selection by n without
/// branches; elsewhere (0, tiny, subnormal, large, inf, NaN) glibc's sincos, unchanged.
inline void sinCos(double angle, double& s, double& c) {
  const double a = std::fabs(angle);
  if (!(a >= 0x1p-26 && a < 1e5)) [[unlikely]] {
#if defined(__GLIBC__)
    ::sincos(angle, &s, &c);
#else
    s = std::sin(angle);
    c = std::cos(angle);
#endif
    return;
  }
  // (angle) => n = nearest integer of angle * 2/pi (|n| < 2^16), r + rt = angle - n pi/2
  constexpr double invPio2 = 6.36619772367581382433e-01, toInt = 0x1.8p52;
  // pi/2 = pio2_1 + pio2_2 + pio2_3 + pio2_3t, the first two of 33 bits (fdlibm's constants)
  constexpr double pio2_1 = 1.57079632673412561417e+00, pio2_2 = 6.07710050630396597660e-11;
  constexpr double pio2_3 = 2.02226624871116645580e-21, pio2_3t = 8.47842766036889956997e-32;
  const double fn = (angle * invPio2 + toInt) - toInt;
  const int n = static_cast<int>(fn);
  // three rounds each subtraction's
  // rounding error e2, e3 carried in the tail w: good to 151 bits
  double r = angle - fn * pio2_1;  // exact: fn * pio2_1 has at most 49 bits
  double t = r;
  double w = fn * pio2_2;  // exact
  r = t - w;
  const double e2 = (t - r) - w;
  t = r;
  w = fn * pio2_3;
  r = t - w;
  w = fn * pio2_3t - ((t - r) - w) - e2;
  const double y0 = r - w;
  const double y1 = (r - y0) - w;
  // (r + rt, n) => sin, cos of the angle: swap on odd n, sign of sin from bit 1 of n, of cos
  // from bit 1 of n + 1
  const double sk = detail::sinKernel(y0, y1), ck = detail::cosKernel(y0, y1);
  const bool odd = (n & 1) != 0;
  const double s0 = odd ? ck : sk, c0 = odd ? sk : ck;
  s = (n & 2) ? -s0 : s0;
  c = ((n + 1) & 2) ? -c0 : c0;
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
