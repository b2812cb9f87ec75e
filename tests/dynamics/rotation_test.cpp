// Rotations: exp/log, quaternions, Euler angles with the documented z-y'-x'' convention.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>

#include "dynamics/rotation.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("exp and log of SO(3) are inverse, and exp matches Eigen's angle-axis") {
  std::mt19937 rng(5);
  for (int k = 0; k < 50; ++k) {
    const Vector3 w = randomVector(rng, 3.0);
    if (w.norm() >= M_PI) continue;
    const Matrix3 R = expSO3(w);
    CHECK((R - Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix()).norm() < 1e-13);
    CHECK((logSO3(R) - w).norm() < 1e-11);
  }
  CHECK((expSO3(Vector3(1e-9, 0, 0)) - Matrix3::Identity()).norm() < 1e-8);
}

TEST_CASE("quaternion (w, x, y, z) round trip") {
  std::mt19937 rng(6);
  for (int k = 0; k < 50; ++k) {
    const Matrix3 R = randomRotation(rng);
    double q[4];
    matrixToQuaternion(R, q);
    CHECK(q[0] >= 0.0);
    CHECK((quaternionToMatrix(q) - R).norm() < 1e-13);
  }
  const double qz[4] = {std::cos(0.25), 0.0, 0.0, std::sin(0.25)};  // 0.5 rad about z
  CHECK((quaternionToMatrix(qz) - axisRotation(Vector3::UnitZ(), 0.5)).norm() < 1e-15);
}

TEST_CASE("Euler angles are roll, pitch, yaw with R = Rz(yaw) Ry(pitch) Rx(roll)") {
  const double roll = 0.3, pitch = -0.4, yaw = 2.5;
  const Matrix3 R = axisRotation(Vector3::UnitZ(), yaw) * axisRotation(Vector3::UnitY(), pitch) *
                    axisRotation(Vector3::UnitX(), roll);
  const Vector3 e = eulerAngles(R);
  CHECK(e.x() == Approx(roll));
  CHECK(e.y() == Approx(pitch));
  CHECK(e.z() == Approx(yaw));
  CHECK((eulerToMatrix(e) - R).norm() < 1e-14);
  // a ship pitched bow-down by 0.1 rad about its y axis reports pitch 0.1 only
  const Vector3 p = eulerAngles(axisRotation(Vector3::UnitY(), 0.1));
  CHECK(p.x() == Approx(0.0).margin(1e-15));
  CHECK(p.y() == Approx(0.1));
  CHECK(p.z() == Approx(0.0).margin(1e-15));
  std::mt19937 rng(7);
  for (int k = 0; k < 50; ++k) {
    const Matrix3 Q = randomRotation(rng);
    CHECK((eulerToMatrix(eulerAngles(Q)) - Q).norm() < 1e-12);
  }
  // gimbal lock keeps the rotation
  const Matrix3 G = eulerToMatrix(Vector3(0.7, M_PI / 2, 0.2));
  CHECK((eulerToMatrix(eulerAngles(G)) - G).norm() < 1e-7);
}

TEST_CASE("right Jacobian inverse maps body angular velocity to the rate of the rotation vector") {
  std::mt19937 rng(8);
  for (int k = 0; k < 20; ++k) {
    const Vector3 w = randomVector(rng, 1.5), omega = randomVector(rng);
    const double h = 1e-6;
    // exp(w + h Jr^-1 omega) ~ exp(w) exp(h omega)
    const Matrix3 lhs = expSO3(w + h * (rightJacobianInverse(w) * omega));
    const Matrix3 rhs = expSO3(w) * expSO3(h * omega);
    CHECK((lhs - rhs).norm() < 1e-10);
  }
}

TEST_CASE("a rotation about a coordinate axis equals the axis-angle formula bit for bit") {
  // the kernels' special case must give the same doubles (signed zeros included), or every
  // scene's results would change
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  std::vector<double> angles{0.0,         -0.0,   M_PI,   -M_PI, 0.5 * M_PI,
                             -0.5 * M_PI, 1e-300, -1e-17, 1e6,   2.0 * M_PI};
  for (int k = 0; k < 200; ++k) angles.push_back(u(rng));
  for (int axis = 0; axis < 3; ++axis) {
    for (const double angle : angles) {
      INFO("axis " << axis << ", angle " << angle);
      Matrix3 R;
      R.setConstant(42.0);
      double s = 0.0, c = 0.0;
      sinCos(angle, s, c);  // axisRotation's sine and cosine
      coordinateAxisRotation(axis, s, c, R);
      const Matrix3 ref = axisRotation(Vector3::Unit(axis), angle);
      CHECK(std::memcmp(R.data(), ref.data(), sizeof(double) * 9) == 0);
    }
  }
}

TEST_CASE("libmSinCos returns the doubles of std::sin and std::cos") {
  // sinCos hands it the large angles, infinities and NaN; special values, every binade of the
  // double range and random angles
  std::mt19937 rng(22);
  std::uniform_real_distribution<double> small(-10.0, 10.0), large(-1e7, 1e7);
  std::vector<double> angles{0.0, -0.0, M_PI, -M_PI, 0.5 * M_PI, 1e-300, -1e-17, 1e22, 2.0 * M_PI};
  for (int e = -1074; e < 1024; e += 3) angles.push_back(std::ldexp(1.3, e));
  for (int k = 0; k < 20000; ++k) angles.push_back(small(rng));
  for (int k = 0; k < 2000; ++k) angles.push_back(large(rng));
  int differ = 0;
  for (const double angle : angles) {
    double s = 42.0, c = 42.0;
    libmSinCos(angle, s, c);
    const double s0 = std::sin(angle), c0 = std::cos(angle);
    if (std::memcmp(&s, &s0, sizeof s) != 0 || std::memcmp(&c, &c0, sizeof c) != 0) ++differ;
  }
  CHECK(differ == 0);
}

TEST_CASE("sinCos is within two units in the last place of std::sin and std::cos") {
  // every revolute placement uses it; the angles of the test above, and angles near multiples of
  // pi/2 (where the reduction cancels); |angle| >= 1e5 goes to libm (exactly)
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> small(-10.0, 10.0), medium(-1e5, 1e5), large(-1e7, 1e7);
  std::vector<double> angles{0.0,    -0.0,   M_PI, -M_PI,      0.5 * M_PI, 0.25 * M_PI,
                             1e-300, -1e-17, 1e22, 2.0 * M_PI, 1e5,        -1e5};
  for (int e = -1074; e < 1024; e += 3) angles.push_back(std::ldexp(1.3, e));
  for (int k = 0; k < 20000; ++k) angles.push_back(small(rng));
  for (int k = 0; k < 20000; ++k) angles.push_back(medium(rng));
  for (int k = 0; k < 2000; ++k) angles.push_back(large(rng));
  for (int n = -40; n <= 40; ++n) {
    double a = n * 0.5 * M_PI;
    for (int k = 0; k < 4; ++k) {
      angles.push_back(a);
      a = std::nextafter(a, 1e300);
    }
  }
  // (x, x0) => |x - x0| in units of x0's last place
  const auto ulps = [](double x, double x0) {
    if (x == x0) return 0.0;
    const double ax = std::abs(x0);
    return std::abs(x - x0) / (std::nextafter(ax, 1e300) - ax);
  };
  double worst = 0.0;
  for (const double angle : angles) {
    double s = 42.0, c = 42.0;
    sinCos(angle, s, c);
    worst = std::max({worst, ulps(s, std::sin(angle)), ulps(c, std::cos(angle))});
    if (std::abs(angle) >= 1e5) {
      double s0 = 0.0, c0 = 0.0;
      libmSinCos(angle, s0, c0);
      CHECK(s == s0);
      CHECK(c == c0);
    }
  }
  CHECK(worst <= 2.0);
  double s = 0.0, c = 0.0;
  sinCos(std::nan(""), s, c);
  CHECK((std::isnan(s) && std::isnan(c)));
  sinCos(INFINITY, s, c);
  CHECK((std::isnan(s) && std::isnan(c)));
}
