#include "dynamics/integrators/rk4.hpp"

#include "dynamics/configuration.hpp"

#include <utility>

namespace yardsim::dynamics {

namespace {

// (vector x) => x(k), the pair of entries (k, k + 1) or the one entry k (an Eigen map: two-wide
// SSE2 arithmetic on the pairs)
struct Slices {
  double* x;
  explicit Slices(Eigen::VectorXd& v) : x(v.data()) {}
  Eigen::Map<Eigen::Vector2d> operator()(std::pair<int, int> k) const {
    return Eigen::Map<Eigen::Vector2d>(x + k.first);
  }
  double& operator()(int k) const { return x[k]; }
};

// (n, f) => f(pair at k) for k = 0, 2, ... below n - 1, then f(n - 1) if n is odd
template <class F>
inline void forPairs(int n, F&& f) {
  int k = 0;
  for (; k + 1 < n; k += 2) f(std::pair<int, int>(k, k + 1));
  if (k < n) f(k);
}

}  // namespace

Rk4::Rk4(const Model& model)
    : model_(model),
      q0_(model.nq),
      qs_(model.nq),
      v0_(model.nv),
      vs_(model.nv),
      theta_(model.nv),
      sumTheta_(model.nv),
      sumA_(model.nv),
      a_(model.nv),
      kTheta_(model.nv) {}

void Rk4::step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v, double h) {
  if (model_.euclidean) {
    // (q0 (+) theta = q0 + theta, theta rate = v: configuration.cpp's Euclidean case) => the same
    // doubles as the chart form without theta and k_theta (a stage's v is its theta rate); the
    // vector updates between two evaluations in one loop over the coordinates: the previous
    // stage's weighted v and a added to the sums, then the next stage's q and v
    const int n = model_.nv;
    q0_ = q;
    v0_ = v;
    const Slices qs(qs_), vs(vs_), sumTheta(sumTheta_), sumA(sumA_), q0(q0_), v0(v0_), a(a_);
    // stage 1: (t, q0, v0) => a1
    evaluate(system, t, q0_, v0_, a_);
    // (a1) => sums = (v0, a1), stage 2's q = q0 + h/2 v0 and v = v0 + h/2 a1
    const double h2 = 0.5 * h;
    forPairs(n, [&](auto k) {
      sumTheta(k) = v0(k);
      sumA(k) = a(k);
      qs(k) = q0(k) + h2 * v0(k);
      vs(k) = v0(k) + h2 * a(k);
    });
    evaluate(system, t + h2, qs_, vs_, a_);
    // stages 3 and 4: (v, a of the previous stage) => sums += 2 (v, a), q = q0 + c h v and
    // v = v0 + c h a with c = 1/2, 1
    for (const double ch : {h2, h}) {
      forPairs(n, [&](auto k) {
        sumTheta(k) += 2.0 * vs(k);
        sumA(k) += 2.0 * a(k);
        qs(k) = q0(k) + ch * vs(k);
        vs(k) = v0(k) + ch * a(k);
      });
      evaluate(system, t + ch, qs_, vs_, a_);
    }
    // (v4, a4) => q = q0 + h/6 (sum theta rates + v4), v = v0 + h/6 (sum a + a4)
    const double h6 = h / 6.0;
    const Slices qo(q), vo(v);
    forPairs(n, [&](auto k) {
      qo(k) = q0(k) + h6 * (sumTheta(k) + 1.0 * vs(k));
      vo(k) = v0(k) + h6 * (sumA(k) + 1.0 * a(k));
    });
    t += h;
    ++stats_.steps;
    system.afterStep(t, q, v);
    return;
  }
  q0_ = q;
  v0_ = v;
  // stage 1: (t, q0, v0) => a1; theta rate = v0
  evaluate(system, t, q0_, v0_, a_);
  sumTheta_ = v0_;
  sumA_ = a_;
  static constexpr double kC[3] = {0.5, 0.5, 1.0};
  static constexpr double kW[3] = {2.0, 2.0, 1.0};
  for (int s = 0; s < 3; ++s) {
    // stage s+2: (theta = c h k_theta, v = v0 + c h a) => a, k_theta
    const double ch = kC[s] * h;
    theta_ = ch * (s == 0 ? v0_ : kTheta_);
    integrate(model_, q0_, theta_, 1.0, qs_);
    vs_ = v0_ + ch * a_;
    evaluate(system, t + ch, qs_, vs_, a_);
    chartRate(model_, theta_, vs_, kTheta_);
    sumTheta_ += kW[s] * kTheta_;
    sumA_ += kW[s] * a_;
  }
  // (sums) => q = q0 (+) h/6 sum theta rates, v = v0 + h/6 sum a
  theta_ = (h / 6.0) * sumTheta_;
  integrate(model_, q0_, theta_, 1.0, q);
  v = v0_ + (h / 6.0) * sumA_;
  t += h;
  ++stats_.steps;
  system.afterStep(t, q, v);
}

}  // namespace yardsim::dynamics
