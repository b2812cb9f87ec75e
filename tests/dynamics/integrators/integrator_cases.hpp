#pragma once
// Shared by the integrator tests: a smooth tree with quaternion joints and its tight reference,
// the observed order when the step halves, and a one-degree-of-freedom oscillator for stability.

#include <cmath>
#include <random>

#include "dynamics/configuration.hpp"
#include "dynamics/integrators/factory.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/model_builder.hpp"
#include "dynamics/multibody_system.hpp"
#include "../test_models.hpp"

namespace yardsim::dynamics::testing {

/// A 5-body tree (free root, then revolute, prismatic, cylindrical, universal joints) released
/// with random q0, v0 and integrated over T = 0.2 s.
struct SmoothTree {
  Model model;
  Eigen::VectorXd q0, v0, qRef, vRef;
  double T = 0.2;
  SmoothTree() {
    std::mt19937 rng(23);
    model = randomTree(rng, 5);
    q0 = randomConfiguration(model, rng);
    v0 = randomVectorX(rng, model.nv);
    // (RK4 at 3200 steps) => reference, error ~1e-15
    run(model, q0, v0, T, 3200, qRef, vRef);
  }
  static void run(const Model& m, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, double T, int steps,
                  Eigen::VectorXd& q, Eigen::VectorXd& v) {
    MultibodySystem sys(m);
    Rk4 rk(m);
    q = q0;
    v = v0;
    double t = 0.0;
    for (int k = 0; k < steps; ++k) rk.step(sys, t, q, v, T / steps);
  }
  /// (method spec, steps) => |q - q_ref| + |v - v_ref| at T (q compared through difference()).
  double error(IntegratorSpec spec, int steps) const {
    spec.dt = T / steps;
    const auto integ = makeIntegrator(spec, model);
    MultibodySystem sys(model);
    Eigen::VectorXd q = q0, v = v0, d(model.nv);
    double t = 0.0;
    for (int k = 0; k < steps; ++k) integ->step(sys, t, q, v, spec.dt);
    difference(model, qRef, q, d);
    return d.norm() + (v - vRef).norm();
  }
  /// log2(e(n) / e(2n))
  double observedOrder(const IntegratorSpec& spec, int n) const { return std::log2(error(spec, n) / error(spec, 2 * n)); }
};

/// A unit mass on a prismatic joint with a linear spring of frequency omega, optional damping and
/// a slowly moving anchor: a = -omega^2 (q - forcing sin t) - 2 zeta omega v. (An AccelerationSource
/// of its own: no forces layer needed.)
struct Oscillator final : AccelerationSource {
  Model model;
  double omega = 1.0, zeta = 0.0, forcing = 0.0;
  explicit Oscillator(double w, double z = 0.0) : omega(w), zeta(z) {
    ModelBuilder b;
    b.addBody("mass", "world", Joint::prismatic(Vector3::UnitX()), {}, boxInertia(1.0, Vector3(1, 1, 1)));
    model = b.build();
  }
  void acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) override {
    a[0] = -omega * omega * (q[0] - forcing * std::sin(t)) - 2.0 * zeta * omega * v[0];
  }
  /// amplitude sqrt(q^2 + (v / omega)^2) after n steps of h from q = 1, v = 0
  double amplitude(IntegratorSpec spec, double h, int n) {
    spec.dt = h;
    const auto integ = makeIntegrator(spec, model);
    Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
    double t = 0.0;
    for (int k = 0; k < n; ++k) integ->step(*this, t, q, v, h);
    return std::hypot(q[0], v[0] / omega);
  }
  /// the forced response A sin t + B cos t that remains once the free motion has decayed
  double steadyState(double t) const {
    const double k = omega * omega - 1.0, c = 2.0 * zeta * omega, det = k * k + c * c;
    const double A = forcing * omega * omega * k / det, B = -forcing * omega * omega * c / det;
    return A * std::sin(t) + B * std::cos(t);
  }
};

inline IntegratorSpec specOf(const std::string& method) {
  IntegratorSpec s;
  s.method = method;
  return s;
}

}  // namespace yardsim::dynamics::testing

namespace yardsim::dynamics::testing {

/// A mass falling from rest along a prismatic joint (q up, a = -g) with one event function
/// g = q + drop, which crosses zero at t = sqrt(2 drop / g).
struct FallingMass final : AccelerationSource {
  Model model;
  double gravity = 9.81, drop = 1.0;
  FallingMass() {
    ModelBuilder b;
    b.addBody("mass", "world", Joint::prismatic(Vector3::UnitZ()), {}, boxInertia(1.0, Vector3(1, 1, 1)));
    model = b.build();
  }
  void acceleration(double, const Eigen::VectorXd&, const Eigen::VectorXd&, Eigen::VectorXd& a) override {
    a[0] = -gravity;
  }
  int eventCount() const override { return 1; }
  void eventFunctions(double, const Eigen::VectorXd& q, const Eigen::VectorXd&, std::span<double> g) override {
    g[0] = q[0] + drop;
  }
};

}  // namespace yardsim::dynamics::testing
