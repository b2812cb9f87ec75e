#include "forces/hydro/radiation_memory.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace yardsim::forces::hydro {

using Matrix6 = ImpulseResponse::Matrix6;

RetardationKernel::RetardationKernel(const ImpulseResponse& ir)
    : dt(ir.dt), length(static_cast<Eigen::Index>(ir.radiation.size())) {
  if (!(dt > 0) || !std::isfinite(dt))
    throw std::invalid_argument("impulse response: dt must be > 0 s");
  if (length == 0)
    throw std::invalid_argument("impulse response: no radiation samples (the memory is empty)");
  K.setZero(6, 6 * (length + 1));
  for (Eigen::Index l = 0; l < length; ++l) {
    const Matrix6& k = ir.radiation[static_cast<std::size_t>(l)];
    if (!k.allFinite())
      throw std::invalid_argument("impulse response: radiation sample " + std::to_string(l) +
                                  " is not finite");
    K.middleCols<6>(6 * l) = dt * k;
  }
}

Matrix6 RetardationKernel::at(double s) const {
  const double x = std::max(s, 0.0) / dt;
  const auto j = static_cast<Eigen::Index>(x);
  if (j >= length) return Matrix6::Zero();
  const double f = x - static_cast<double>(j);
  return ((1.0 - f) * K.middleCols<6>(6 * j) + f * K.middleCols<6>(6 * (j + 1))) / dt;
}

RadiationMemory::RadiationMemory(const RetardationKernel& kernel)
    : kernel_(&kernel), n_(kernel.length), ring_(Eigen::VectorXd::Zero(12 * kernel.length)) {}

void RadiationMemory::push(const Vector6& xi) {
  // (C_k of the history before) => C_k after the push without a sum over the memory:
  // C_k(m + 1) = C_k+1(m) + dt/2 (K_k+1 xi_m + K_k xi_m+1)
  const Vector6 previous = newest();
  const auto& K = kernel_->K;
  for (int k = 0; k + 1 < kCached; ++k) {
    have_[k] = have_[k + 1] && k + 1 <= kernel_->length;
    if (have_[k])
      c_[k] =
          c_[k + 1] + 0.5 * (K.middleCols<6>(6 * (k + 1)) * previous + K.middleCols<6>(6 * k) * xi);
  }
  have_[kCached - 1] = false;
  p_ = p_ == 0 ? n_ - 1 : p_ - 1;
  ring_.segment<6>(6 * p_) = xi;
  ring_.segment<6>(6 * (p_ + n_)) = xi;
  ++m_;
  count_ = std::min(count_ + 1, n_);
}

void RadiationMemory::commit(double t, const Vector6& v) {
  if (!started_) {
    // (first commit) => rest before t; the sample at or before t is v when t is on the grid
    started_ = true;
    ring_.setZero();
    p_ = 0;
    count_ = 1;
    m_ = static_cast<std::int64_t>(std::floor(t / kernel_->dt));
    if (sampleTime() == t) {
      ring_.segment<6>(0) = v;
      ring_.segment<6>(6 * n_) = v;
    }
    tc_ = t;
    vc_ = v;
    have_.fill(false);
    return;
  }
  if (t == tc_ && v == vc_) return;
  if (t <= tc_) {
    // (a step taken again from t) => the samples from t on dropped, their slots zeroed
    while (count_ > 0 && sampleTime() >= t) {
      ring_.segment<6>(6 * p_).setZero();
      ring_.segment<6>(6 * (p_ + n_)).setZero();
      p_ = p_ + 1 == n_ ? 0 : p_ + 1;
      --m_;
      --count_;
    }
    have_.fill(false);
    if (count_ == 0) {
      started_ = false;
      commit(t, v);
      return;
    }
    tc_ = sampleTime();
    vc_ = newest();
  }
  // (grid times in (tc, t]) => the velocity linear between the two commits
  const double dt = kernel_->dt;
  for (std::int64_t j = m_ + 1; static_cast<double>(j) * dt <= t; ++j) {
    const double f = (static_cast<double>(j) * dt - tc_) / (t - tc_);
    push(vc_ + f * (v - vc_));
  }
  tc_ = t;
  vc_ = v;
}

Vector6 RadiationMemory::sum(Eigen::Index k) const {
  const Eigen::Index count = std::min(n_, kernel_->length + 1 - k);
  if (count <= 0) return Vector6::Zero();
  const auto K = kernel_->K.middleCols(6 * k, 6 * count);
  return K * ring_.segment(6 * p_, 6 * count) - 0.5 * kernel_->K.middleCols<6>(6 * k) * newest();
}

Vector6 RadiationMemory::cached(Eigen::Index k) const {
  if (k >= kCached) return sum(k);
  const auto i = static_cast<std::size_t>(k);
  if (!have_[i]) {
    c_[i] = sum(k);
    have_[i] = true;
  }
  return c_[i];
}

Vector6 RadiationMemory::convolution(double t, const Vector6& v) const {
  if (!started_) return Vector6::Zero();
  const double dt = kernel_->dt, tm = sampleTime();
  const double phi = std::max(0.0, (t - tm) / dt);
  const auto k = static_cast<Eigen::Index>(phi);
  const double f = phi - static_cast<double>(k);
  Vector6 mu = f == 0.0 ? cached(k) : Vector6((1.0 - f) * cached(k) + f * cached(k + 1));
  // (pieces of the velocity after the newest sample) => trapezoid in sub-intervals <= dt
  auto piece = [&](double a, const Vector6& va, double b, const Vector6& vb) {
    if (!(b > a)) return;
    const int n = std::max(1, static_cast<int>(std::ceil((b - a) / dt - 1e-9)));
    const double h = (b - a) / n;
    for (int i = 0; i < n; ++i) {
      const double s0 = a + i * h, s1 = s0 + h;
      const Vector6 x0 = va + (s0 - a) / (b - a) * (vb - va),
                    x1 = va + (s1 - a) / (b - a) * (vb - va);
      mu += 0.5 * h * (kernel_->at(t - s0) * x0 + kernel_->at(t - s1) * x1);
    }
  };
  const Vector6 xm = newest();
  if (tc_ > tm && tc_ < t) {
    piece(tm, xm, tc_, vc_);
    piece(tc_, vc_, t, v);
  } else {
    piece(tm, xm, t, v);
  }
  return mu;
}

void RadiationMemory::carried(std::vector<double>& out) const {
  out.push_back(started_ ? 1.0 : 0.0);
  out.push_back(static_cast<double>(p_));
  out.push_back(static_cast<double>(m_));
  out.push_back(static_cast<double>(count_));
  out.push_back(tc_);
  for (int i = 0; i < 6; ++i) out.push_back(vc_[i]);
  for (Eigen::Index i = 0; i < 6 * n_; ++i) out.push_back(ring_[6 * p_ + i]);
  for (int k = 0; k < kCached; ++k) {  // (the sums kept, as the next pushes shift them)
    out.push_back(have_[k] ? 1.0 : 0.0);
    for (int i = 0; i < 6; ++i) out.push_back(have_[k] ? c_[k][i] : 0.0);
  }
}

void RadiationMemory::restore(std::span<const double> x) {
  if (x.size() != carriedSize())
    throw std::invalid_argument("radiation memory: " + std::to_string(x.size()) +
                                " carried values, expected " + std::to_string(carriedSize()) +
                                " (another impulse response?)");
  started_ = x[0] != 0.0;
  p_ = static_cast<Eigen::Index>(x[1]);
  m_ = static_cast<std::int64_t>(x[2]);
  count_ = static_cast<Eigen::Index>(x[3]);
  tc_ = x[4];
  for (int i = 0; i < 6; ++i) vc_[i] = x[5 + static_cast<std::size_t>(i)];
  for (Eigen::Index i = 0; i < 6 * n_; ++i) {
    const Eigen::Index slot = (p_ + i / 6) % n_;
    const double value = x[11 + static_cast<std::size_t>(i)];
    ring_[6 * slot + i % 6] = value;
    ring_[6 * (slot + n_) + i % 6] = value;
  }
  std::size_t at = 11 + 6 * static_cast<std::size_t>(n_);
  for (int k = 0; k < kCached; ++k, at += 7) {
    have_[k] = x[at] != 0.0;
    for (int i = 0; i < 6; ++i) c_[k][i] = x[at + 1 + static_cast<std::size_t>(i)];
  }
}

}  // namespace yardsim::forces::hydro
