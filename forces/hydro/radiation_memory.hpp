#pragma once
// The memory part of the Cummins radiation force, mu(t) = int_0^t K(t - tau) xi_dot(tau) dtau
// (forces/hydro/impulse_response.hpp; rows N and N m, velocities m/s and rad/s, naval order,
// body frame), evaluated at microseconds per stage (docs/hydrodynamics.md, "The Cummins
// convolution").
//
// The velocity history is kept on the response's grid t_j = j dt (the absolute time grid), in a
// preallocated ring buffer of the memory length L = radiation.size(); samples come from the
// committed states (commit(t, v)) by linear interpolation between them. At a stage at t, with
// t_m the newest sample and phi = (t - t_m)/dt = k + f:
//   mu(t) = (1 - f) C_k + f C_k+1 + tail,
//   C_k = dt (1/2 K_k xi_m + sum_{l >= 1} K_{l+k} xi_{m-l})   (K linear between samples, zero from
//   L on) tail = int_{t_m}^{t} K(t - tau) xi_dot(tau) dtau, trapezoid in sub-intervals <= dt over
//   the
//          velocity linear from (t_m, xi_m) through the last commit to (t, the stage's velocity).
// C_k depends on the committed history only: computed when a stage first needs it and reused by
// every later stage; a new sample shifts them, C_k(m + 1) = C_k+1(m) + dt/2 (K_k+1 xi_m + K_k
// xi_m+1), so that a step of one sample costs one sum over the memory. Nothing allocates after
// construction.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "forces/hydro/impulse_response.hpp"

namespace yardsim::forces::hydro {

using Vector6 = ImpulseResponse::Vector6;

// The response's retardation functions laid out for the sums: immutable, shared by every scratch.
struct RetardationKernel {
  // (response) => the kernel; throws std::invalid_argument for dt not > 0, no radiation samples
  // or a non-finite one
  explicit RetardationKernel(const ImpulseResponse& ir);
  double dt;
  Eigen::Index length;                         // L, samples of memory
  Eigen::Matrix<double, 6, Eigen::Dynamic> K;  // dt [K_0 K_1 ... K_L-1 0], 6 x 6 (L + 1)
  // (lag s >= 0) => K(s), linear between samples, zero from L dt on (without the factor dt)
  ImpulseResponse::Matrix6 at(double s) const;
};

class RadiationMemory {
 public:
  explicit RadiationMemory(const RetardationKernel& kernel);

  // (t, the committed velocity at t) => the samples up to t appended; a t before the last
  // commit first drops the samples from t on (a step taken again)
  void commit(double t, const Vector6& v);
  // (t at or after the newest sample, the stage's velocity at t) => mu(t)
  Vector6 convolution(double t, const Vector6& v) const;

  bool started() const { return started_; }
  double committedTime() const { return tc_; }
  // checkpoints: () => every value the results depend on appended; (those values) => restored
  void carried(std::vector<double>& out) const;
  void restore(std::span<const double> values);
  std::size_t carriedSize() const { return 11 + 6 * static_cast<std::size_t>(n_) + 7 * kCached; }

 private:
  static constexpr int kCached = 8;  // C_k kept for k < kCached
  // (velocity sample at the grid index m + 1) => pushed, the C_k forgotten
  void push(const Vector6& xi);
  // (k) => C_k of the present history
  Vector6 sum(Eigen::Index k) const;
  // (k) => C_k, cached
  Vector6 cached(Eigen::Index k) const;
  double sampleTime() const { return static_cast<double>(m_) * kernel_->dt; }
  Eigen::Map<const Vector6> newest() const {
    return Eigen::Map<const Vector6>(ring_.data() + 6 * p_);
  }

  const RetardationKernel* kernel_;
  Eigen::Index n_;          // ring slots (L)
  Eigen::VectorXd ring_;    // 2 n slots of 6: the window newest first is [p, p + n)
  Eigen::Index p_ = 0;      // slot of the newest sample
  std::int64_t m_ = 0;      // grid index of the newest sample
  Eigen::Index count_ = 0;  // samples held (<= n)
  bool started_ = false;
  double tc_ = 0.0;               // last committed time
  Vector6 vc_ = Vector6::Zero();  // velocity committed at tc_
  mutable std::array<Vector6, kCached> c_;
  mutable std::array<bool, kCached> have_{};
};

}  // namespace yardsim::forces::hydro
