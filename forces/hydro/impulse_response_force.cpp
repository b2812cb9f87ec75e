#include "forces/hydro/impulse_response_force.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace yardsim::forces::hydro {

struct ImpulseResponseForce::Scratch final : ProviderScratch {
  explicit Scratch(const RetardationKernel& k) : memory(k) {}
  RadiationMemory memory;
  bool haveLast = false;  // the latest stage inside a step, for integrators that never
  double lastT = 0.0;     // evaluate at the step's start
  Vector6 lastV = Vector6::Zero();

  void carried(std::vector<double>& out) const override {
    memory.carried(out);
    out.push_back(haveLast ? 1.0 : 0.0);
    out.push_back(lastT);
    for (int i = 0; i < 6; ++i) out.push_back(lastV[i]);
  }
  void restoreCarried(std::span<const double> x) override {
    const std::size_t n = memory.carriedSize();
    if (x.size() != n + 8)
      throw std::invalid_argument("impulse-response force: wrong number of carried values");
    memory.restore(x.first(n));
    haveLast = x[n] != 0.0;
    lastT = x[n + 1];
    for (std::size_t i = 0; i < 6; ++i) lastV[static_cast<Eigen::Index>(i)] = x[n + 2 + i];
  }
};

namespace {
constexpr double kTwoPi = 2.0 * M_PI;

// (number) => "%.3g" text for messages
std::string shortNumber(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}
double wrapped(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0.0 ? a + kTwoPi : a;
}
}  // namespace

std::vector<std::string> checkResolvedSea(const ImpulseResponse& ir, const AiryWaves& sea) {
  const double wc = ir.excitationWindow;
  if (!(wc > 0.0)) return {};
  // (sea) => how many components lie above w_c, and the highest
  std::size_t above = 0, highest = 0;
  for (std::size_t i = 0; i < sea.size(); ++i) {
    if (sea.frequency(i) > wc) ++above;
    if (sea.frequency(i) > sea.frequency(highest)) highest = i;
  }
  if (above == 0) return {};
  const WaveComponent& c = sea.component(highest);
  return {std::to_string(above) + " of the sea's " + std::to_string(sea.size()) +
          " wave components lie above the impulse response's resolved frequency " +
          shortNumber(wc) + " rad/s (its excitation window's cutoff), the highest component " +
          std::to_string(highest + 1) + " at " + shortNumber(sea.frequency(highest)) +
          " rad/s (period " + shortNumber(c.period) + " s, height " + shortNumber(c.height) +
          " m): leave the shorter waves out of the sea (a longer tp), or compute the response on "
          "a finer free-surface mesh with a cutoff of at least " +
          shortNumber(sea.frequency(highest)) + " rad/s"};
}

ImpulseResponseForce::ImpulseResponseForce(std::string name, const dynamics::Model& model, int body,
                                           std::shared_ptr<const ImpulseResponse> response,
                                           std::shared_ptr<const AiryWaves> sea)
    : ForceProvider(std::move(name)),
      body_(body),
      response_(std::move(response)),
      sea_(std::move(sea)),
      kernel_(*response_) {
  const std::string me = "impulse-response force '" + this->name() + "': ";
  if (body_ < 1 || body_ >= model.nbodies)
    throw std::invalid_argument(me + "the body is the world or outside the model");
  const ImpulseResponse& ir = *response_;
  if (ir.excitation.size() != ir.headings.size())
    throw std::invalid_argument(me + std::to_string(ir.headings.size()) + " headings but " +
                                std::to_string(ir.excitation.size()) + " excitation responses");
  if (!(std::isfinite(ir.excitationWindow) && ir.excitationWindow >= 0.0))
    throw std::invalid_argument(me + "the excitation window's cutoff must be finite and >= 0 (0: none)");
  if (!(ir.excitationStart <= 0.0))
    throw std::invalid_argument(me + "the excitation must start at t0 <= 0");
  if (!sea_ || sea_->calm()) return;
  if (ir.headings.empty())
    throw std::invalid_argument(
        me + "the sea has waves but the impulse response has no excitation (no headings)");
  // (headings sorted in [0, 2 pi)) => H(w_i, b) per sea component by the trapezoid rule
  order_.resize(ir.headings.size());
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
    return wrapped(ir.headings[a]) < wrapped(ir.headings[b]);
  });
  transfer_.assign(sea_->size() * order_.size() * 6, {0.0, 0.0});
  for (std::size_t i = 0; i < sea_->size(); ++i) {
    const double w = sea_->frequency(i);
    // (the response's window W(w) = exp(-(w/w_c)^2)) => divided out, where it leaves X(w)
    // recoverable (w <= 2 w_c: W >= e^-4); above, the response does not carry the wave
    double window = 1.0;
    if (const double wc = ir.excitationWindow; wc > 0.0) {
      if (w > 2.0 * wc)
        throw std::invalid_argument(
            me + "a wave component of " + std::to_string(w) +
            " rad/s lies above twice the excitation window's cutoff (" + std::to_string(wc) +
            " rad/s); compute the response with a cutoff of at least " + std::to_string(0.5 * w) +
            " rad/s (hydrodynamics.cutoff) on a free-surface mesh that resolves that wave");
      window = std::exp(-(w / wc) * (w / wc));
    }
    for (std::size_t b = 0; b < order_.size(); ++b) {
      const auto& h = ir.excitation[order_[b]];
      std::complex<double>* H = &transfer_[(i * order_.size() + b) * 6];
      for (std::size_t k = 0; k < h.size(); ++k) {
        if (!h[k].allFinite())
          throw std::invalid_argument(me + "an excitation sample is not finite");
        const double tau = ir.excitationStart + static_cast<double>(k) * ir.dt;
        const std::complex<double> e = std::polar(ir.dt, w * tau);
        for (int r = 0; r < 6; ++r) H[r] += h[k][r] * e / window;
      }
    }
  }
}

std::unique_ptr<ProviderScratch> ImpulseResponseForce::makeScratch() const {
  return std::make_unique<Scratch>(kernel_);
}

ImpulseResponseForce::Scratch& ImpulseResponseForce::prepared(
    const Stage& s, std::unique_ptr<ProviderScratch>& temporary, Vector6& xi) const {
  Scratch& sc = scratchOf<Scratch>(s, temporary);
  const dynamics::Motion& V = s.data.V_B[body_];
  xi << V.tail<3>(), V.head<3>();
  if (!std::isfinite(s.stepStart)) return sc;  // (outside a step) => reads, commits nothing
  if (s.t == s.stepStart) {
    sc.memory.commit(s.t, xi);
  } else if (sc.haveLast && sc.lastT <= s.stepStart + 1e-9 * std::max(1.0, std::abs(s.stepStart)) &&
             (!sc.memory.started() || sc.lastT > sc.memory.committedTime())) {
    sc.memory.commit(sc.lastT, sc.lastV);  // (no stage at the step's start) => the latest before it
  }
  sc.haveLast = true;
  sc.lastT = s.t;
  sc.lastV = xi;
  return sc;
}

Vector6 ImpulseResponseForce::radiation(const Stage& s) const {
  std::unique_ptr<ProviderScratch> temporary;
  Vector6 xi;
  const Scratch& sc = prepared(s, temporary, xi);
  return -sc.memory.convolution(s.t, xi);
}

Vector6 ImpulseResponseForce::excitation(const Stage& s) const {
  Vector6 F = Vector6::Zero();
  if (transfer_.empty()) return F;
  const dynamics::Transform& X = s.data.X_WB[body_];
  const double yaw = std::atan2(X.R(1, 0), X.R(0, 0)), x = X.p.x(), y = X.p.y();
  const std::size_t nh = order_.size();
  const auto& headings = response_->headings;
  for (std::size_t i = 0; i < sea_->size(); ++i) {
    const WaveComponent& c = sea_->component(i);
    // (heading relative to the body) => the bracketing responses b0, b1 and the weight of b1
    const double rel = wrapped(c.direction - yaw);
    std::size_t b1 = 0;
    while (b1 < nh && wrapped(headings[order_[b1]]) <= rel) ++b1;
    const std::size_t b0 = (b1 + nh - 1) % nh;
    b1 %= nh;
    double f = 0.0;
    if (nh > 1) {
      const double lo = wrapped(headings[order_[b0]]);
      const double span = wrapped(headings[order_[b1]] - lo);
      f = span > 0.0 ? wrapped(rel - lo) / span : 0.0;
    }
    const double k = sea_->wavenumber(i);
    const double theta = k * (x * std::cos(c.direction) + y * std::sin(c.direction)) -
                         sea_->frequency(i) * s.t + c.phase;
    const double a = 0.5 * c.height, ct = std::cos(theta), st = std::sin(theta);
    const std::complex<double>* H0 = &transfer_[(i * nh + b0) * 6];
    const std::complex<double>* H1 = &transfer_[(i * nh + b1) * 6];
    for (int r = 0; r < 6; ++r) {
      const std::complex<double> H = (1.0 - f) * H0[r] + f * H1[r];
      F[r] += a * (H.real() * ct - H.imag() * st);
    }
  }
  return sea_->ramp(s.t) * F;
}

void ImpulseResponseForce::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                                      Eigen::VectorXd& /*tau*/) const {
  const Vector6 F = radiation(s) + excitation(s);
  dynamics::Force F_B;
  F_B << F.tail<3>(), F.head<3>();
  f.addBodyFrame(body_, F_B);
}

double ImpulseResponseForce::doPower(const Stage& s) const {
  const dynamics::Motion& V = s.data.V_B[body_];
  Vector6 xi;
  xi << V.tail<3>(), V.head<3>();
  return (radiation(s) + excitation(s)).dot(xi);
}

}  // namespace yardsim::forces::hydro
