// The radiation memory against independent closed forms. The retardation function comes from an
// analytical damping, K(t) = 2/pi int B(w) cos(w t) dw by quadrature in the test (B the Lorentzian
// pair of K = kappa e^(-alpha t) cos(beta t)); a forced oscillation then gives back B(w) and
// A(w) - A_inf by Fourier analysis of the steady memory force, against their closed forms. The
// radiation force only dissipates (the work over a motion from rest to rest is negative, and a
// kernel of the wrong sign is caught); a step taken again gives the same history; the carried
// values restore the memory bit for bit.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <vector>

#include "forces/hydro/radiation_memory.hpp"

using namespace yardsim::forces::hydro;
using Matrix6 = ImpulseResponse::Matrix6;

namespace {
constexpr double kKappa = 2e5, kAlpha = 0.3, kBeta = 0.8;

// (w) => B(w) = int_0^inf K cos(w t) dt and A(w) - A_inf = -1/w int_0^inf K sin(w t) dt, closed
// forms
double damping(double w) {
  return 0.5 * kKappa *
         (kAlpha / (kAlpha * kAlpha + (w - kBeta) * (w - kBeta)) +
          kAlpha / (kAlpha * kAlpha + (w + kBeta) * (w + kBeta)));
}
double addedMass(double w) {
  return -0.5 * kKappa / w *
         ((w - kBeta) / (kAlpha * kAlpha + (w - kBeta) * (w - kBeta)) +
          (w + kBeta) / (kAlpha * kAlpha + (w + kBeta) * (w + kBeta)));
}

// (dt, memory s) => heave-heave K(t_k) = 2/pi int_0^W B(w) cos(w t) dw, midpoint rule, plus the
// closed-form tail of the Lorentzians above W (kappa alpha / w^2 cos(w t): its t = 0 value only)
std::shared_ptr<ImpulseResponse> heaveResponse(double dt, double memory) {
  auto ir = std::make_shared<ImpulseResponse>();
  ir->dt = dt;
  const auto n = static_cast<std::size_t>(memory / dt);
  const double W = 80.0, dw = 2e-3;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * dt;
    double K = 0;
    for (double w = 0.5 * dw; w < W; w += dw) K += damping(w) * std::cos(w * t) * dw;
    K *= 2 / M_PI;
    if (k == 0) K += 2 / M_PI * kKappa * kAlpha / W;
    Matrix6 m = Matrix6::Zero();
    m(2, 2) = K;
    ir->radiation.push_back(m);
  }
  return ir;
}

Vector6 heave(double v) {
  Vector6 x = Vector6::Zero();
  x[2] = v;
  return x;
}
}  // namespace

TEST_CASE("the retardation function from an analytical damping by the cosine transform") {
  const auto ir = heaveResponse(0.05, 5.0);
  for (std::size_t k : {0u, 7u, 30u, 99u}) {
    const double t = 0.05 * static_cast<double>(k);
    CHECK(ir->radiation[k](2, 2) ==
          Approx(kKappa * std::exp(-kAlpha * t) * std::cos(kBeta * t)).margin(2e-3 * kKappa));
  }
}

TEST_CASE("a forced oscillation gives back the damping and added mass by Fourier analysis") {
  const auto ir = heaveResponse(0.05, 60.0);  // e^(-alpha 60) = 1.5e-8: the memory is complete
  const RetardationKernel kernel(*ir);
  for (double w : {0.3, 0.8, 1.5, 3.0}) {
    RadiationMemory memory(kernel);
    const double V = 0.7, period = 2 * M_PI / w;
    const double h = period / 400;  // steps of T/400, not a divisor of the response's dt
    // (xi_dot = V cos(w t), committed every step; stages half a step later read) => mu(t)
    const int settle = static_cast<int>(std::ceil(50.0 / h)), n = 4 * 400;
    double mc = 0, ms = 0;
    for (int i = 0; i < settle + n; ++i) {
      const double t = i * h;
      memory.commit(t, heave(V * std::cos(w * t)));
      const double ts = t + 0.5 * h;
      const double mu = memory.convolution(ts, heave(V * std::cos(w * ts)))[2];
      if (i >= settle) {
        mc += 2.0 / n * mu * std::cos(w * ts);
        ms += 2.0 / n * mu * std::sin(w * ts);
      }
    }
    // (mu = V (B cos + w (A_inf - A) sin)) => B and A - A_inf
    INFO("w = " << w);
    CHECK(mc / V == Approx(damping(w)).epsilon(0.003));
    CHECK(-ms / V / w ==
          Approx(addedMass(w)).margin(0.003 * std::abs(addedMass(w)) + 1e-4 * kKappa));
  }
}

TEST_CASE("the radiation force only dissipates over a motion from rest to rest") {
  // (K = C e^(-alpha t) cos(beta t), C = L L^T positive semi-definite) => B(w) >= 0 in every mode
  Matrix6 L;
  L << 3, 0, 0, 0, 0, 0, 1, 2, 0, 0, 0, 0, -1, 0.5, 4, 0, 0, 0, 0.2, 0.3, -0.7, 2, 0, 0, 0.1, -0.4,
      0.2, 0.3, 1, 0, 0.5, 0.1, 0.1, -0.2, 0.3, 1.5;
  auto work = [&](double sign) {
    ImpulseResponse ir;
    ir.dt = 0.05;
    for (int k = 0; k < 1200; ++k) {
      const double t = 0.05 * k;
      ir.radiation.push_back(sign * 1e4 * (L * L.transpose()) * std::exp(-kAlpha * t) *
                             std::cos(kBeta * t));
    }
    const RetardationKernel kernel(ir);
    RadiationMemory memory(kernel);
    // (a windowed multi-sine in every mode, at rest before 0 and after 20 s) => int F . xi_dot dt
    auto xi = [](double t) {
      Vector6 x = Vector6::Zero();
      if (t <= 0 || t >= 20) return x;
      const double win = std::pow(std::sin(M_PI * t / 20), 2);
      for (int i = 0; i < 6; ++i)
        x[i] = win * (std::sin((0.4 + 0.3 * i) * t + i) + 0.5 * std::cos((1.7 - 0.2 * i) * t));
      return x;
    };
    double W = 0;
    const double h = 0.01;
    for (int i = 0; i < 8000; ++i) {
      const double t = i * h;
      memory.commit(t, xi(t));
      W += h * (-memory.convolution(t, xi(t))).dot(xi(t));
    }
    return W;
  };
  CHECK(work(1.0) < 0.0);
  CHECK(work(-1.0) > 0.0);  // (the check can fail) => a kernel of the wrong sign gives energy
}

TEST_CASE("a step taken again gives the same history and carried values restore it bit for bit") {
  const auto ir = heaveResponse(0.02, 10.0);
  const RetardationKernel kernel(*ir);
  auto v = [](double t) { return heave(std::sin(1.3 * t) + 0.2 * t); };
  RadiationMemory a(kernel), b(kernel);
  for (int i = 0; i <= 300; ++i) a.commit(i * 0.01, v(i * 0.01));
  for (int i = 0; i <= 350; ++i) b.commit(i * 0.01, v(i * 0.01));
  b.commit(3.0, v(3.0));  // (back to 3 s) => the samples after it dropped
  CHECK(b.committedTime() == 3.0);
  for (double t : {3.0, 3.004, 3.013, 3.05})
    CHECK(b.convolution(t, v(t))[2] == Approx(a.convolution(t, v(t))[2]).epsilon(1e-13));
  // (carried values into a fresh memory) => the same forces from then on, bit for bit
  std::vector<double> saved;
  a.carried(saved);
  CHECK(saved.size() == a.carriedSize());
  RadiationMemory c(kernel);
  c.restore(saved);
  for (int i = 301; i < 2000; ++i) {
    const double t = i * 0.01;
    a.commit(t, v(t));
    c.commit(t, v(t));
    REQUIRE(a.convolution(t + 0.004, v(t)) == c.convolution(t + 0.004, v(t)));
  }
  saved.pop_back();
  CHECK_THROWS_WITH(c.restore(saved), Catch::Contains("carried values"));
}

TEST_CASE("a bad retardation function is refused") {
  ImpulseResponse ir;
  CHECK_THROWS_WITH(RetardationKernel(ir), Catch::Contains("dt"));
  ir.dt = 0.1;
  CHECK_THROWS_WITH(RetardationKernel(ir), Catch::Contains("no radiation samples"));
  ir.radiation.push_back(Matrix6::Constant(NAN));
  CHECK_THROWS_WITH(RetardationKernel(ir), Catch::Contains("not finite"));
}
