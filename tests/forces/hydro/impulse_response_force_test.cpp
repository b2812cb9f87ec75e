// The impulse-response force provider: a free heave decay whose damping ratio and period match
// the roots of the closed-form characteristic equation (M s^2 + c)((s + alpha)^2 + beta^2) +
// kappa s (s + alpha) = 0; the wave excitation equal to the direct convolution of the excitation
// response with the incident elevation at the body, with the heading interpolated and turned with
// the body's yaw; the history committed at the step's start or, for integrators that never stop
// there, the latest stage; the scratch's carried values restore a run bit for bit; bad input
// refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <vector>

#include <Eigen/Eigenvalues>

#include "dynamics/configuration.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/model_builder.hpp"
#include "forces/hydro/impulse_response_force.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::hydro;
using dynamics::Vector3;
using Matrix6 = ImpulseResponse::Matrix6;

namespace {
constexpr double kM = 1e5, kC = 1e6, kKappa = 4e4, kAlpha = 1.0, kBeta = 3.0;

dynamics::Model block(dynamics::Joint joint) {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("hull", "world", joint, dynamics::Transform::identity(),
            dynamics::boxInertia(kM, Vector3(4, 4, 2)));
  return b.build();
}

std::shared_ptr<ImpulseResponse> heaveKernel(double dt, double memory) {
  auto ir = std::make_shared<ImpulseResponse>();
  ir->dt = dt;
  for (int k = 0; k * dt < memory; ++k) {
    Matrix6 K = Matrix6::Zero();
    K(2, 2) = kKappa * std::exp(-kAlpha * k * dt) * std::cos(kBeta * k * dt);
    ir->radiation.push_back(K);
  }
  return ir;
}

// A heaving block on a spring c, its mass M (added mass included), stepped by RK4 with the
// provider evaluated at every stage, the step's start given as Stage::stepStart
struct Heave {
  const dynamics::Model model = block(dynamics::Joint::prismatic(Vector3::UnitZ()));
  dynamics::Data data{model};
  dynamics::ExternalForces f{model};
  Eigen::VectorXd q = Eigen::VectorXd::Zero(1), v = Eigen::VectorXd::Zero(1),
                  tau = Eigen::VectorXd::Zero(1);
  double t = 0;

  // (provider, scratch, stage state) => z''
  double accel(const ImpulseResponseForce& p, ProviderScratch* sc, double ts, double z, double w,
               double start) {
    q[0] = z;
    v[0] = w;
    dynamics::forwardKinematics(model, data, q, v);
    f.clear();
    p.evaluate(Stage{ts, model, data, q, v, sc, start}, f, tau);
    return (-kC * z + f.bodyFrame(1)[5]) / kM;
  }
  void step(const ImpulseResponseForce& p, ProviderScratch* sc, double& z, double& w, double h) {
    const double a1 = accel(p, sc, t, z, w, t);
    const double z2 = z + 0.5 * h * w, w2 = w + 0.5 * h * a1,
                 a2 = accel(p, sc, t + 0.5 * h, z2, w2, t);
    const double z3 = z + 0.5 * h * w2, w3 = w + 0.5 * h * a2,
                 a3 = accel(p, sc, t + 0.5 * h, z3, w3, t);
    const double z4 = z + h * w3, w4 = w + h * a3, a4 = accel(p, sc, t + h, z4, w4, t);
    z += h / 6 * (w + 2 * w2 + 2 * w3 + w4);
    w += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    t += h;
  }
};
}  // namespace

TEST_CASE("a free heave decay matches the roots of the characteristic equation") {
  // (quartic M s^4 + 2 M alpha s^3 + (M (alpha^2 + beta^2) + c + kappa) s^2 + alpha (2 c + kappa) s
  // + c (alpha^2 + beta^2)) => the root nearest the undamped sqrt(c/M)
  Eigen::Matrix4d companion = Eigen::Matrix4d::Zero();
  const double a2b2 = kAlpha * kAlpha + kBeta * kBeta;
  const double coef[4] = {2 * kM * kAlpha, kM * a2b2 + kC + kKappa, kAlpha * (2 * kC + kKappa),
                          kC * a2b2};
  for (int i = 0; i < 4; ++i) companion(0, i) = -coef[i] / kM;
  for (int i = 1; i < 4; ++i) companion(i, i - 1) = 1.0;
  const Eigen::Vector4cd roots = Eigen::EigenSolver<Eigen::Matrix4d>(companion).eigenvalues();
  std::complex<double> s = roots[0];
  for (int i = 1; i < 4; ++i)
    if (std::abs(std::abs(roots[i].imag()) - std::sqrt(kC / kM)) <
        std::abs(std::abs(s.imag()) - std::sqrt(kC / kM)))
      s = roots[i];
  const double sigma = s.real(), wd = std::abs(s.imag());
  // (released from 0.5 m) => peaks after the kernel's own mode has died out (e^-alpha t)
  const dynamics::Model model = block(dynamics::Joint::prismatic(Vector3::UnitZ()));
  const ImpulseResponseForce p("radiation", model, 1, heaveKernel(0.02, 20.0), nullptr);
  Heave rig;
  auto scratch = p.makeScratch();
  double z = 0.5, w = 0, prev2 = 0, prev1 = 0;
  std::vector<double> peakT, peakZ;
  const double h = 0.005;
  for (int i = 0; i < 8000; ++i) {
    rig.step(p, scratch.get(), z, w, h);
    if (i >= 2 && prev1 > prev2 && prev1 > z && rig.t > 12) {
      // (parabola through three samples) => the peak's time and height
      const double d = 0.5 * (prev2 - z) / (prev2 - 2 * prev1 + z);
      peakT.push_back(rig.t - h * (1 - d));
      peakZ.push_back(prev1 - 0.25 * (prev2 - z) * d);
    }
    prev2 = prev1;
    prev1 = z;
  }
  REQUIRE(peakT.size() >= 5);
  const std::size_t n = peakT.size() - 1;
  const double period = (peakT[n] - peakT[0]) / static_cast<double>(n);
  const double decay = std::log(peakZ[n] / peakZ[0]) / (peakT[n] - peakT[0]);
  CHECK(period == Approx(2 * M_PI / wd).epsilon(1e-3));
  CHECK(decay == Approx(sigma).epsilon(0.01));
  // (the damping ratio) => about B(wn) / (2 M wn) of the Lorentzian pair, not zero
  const double wn = std::sqrt(kC / kM);
  const double B = 0.5 * kKappa *
                   (kAlpha / (kAlpha * kAlpha + std::pow(wn - kBeta, 2)) +
                    kAlpha / (kAlpha * kAlpha + std::pow(wn + kBeta, 2)));
  CHECK(-sigma / std::abs(s) == Approx(B / (2 * kM * wn)).epsilon(0.15));
}

TEST_CASE("the excitation is the convolution of its response with the incident elevation") {
  const dynamics::Model model = block(dynamics::Joint::free());
  // (two headings, 0 and 90 deg; a Gaussian pulse per row, non-causal from t0 = -4 s)
  auto ir = std::make_shared<ImpulseResponse>(*heaveKernel(0.02, 1.0));
  ir->headings = {M_PI / 2, 0.0};
  ir->excitationStart = -4.0;
  ir->excitation.resize(2);
  auto pulse = [](double tau, int row, int heading) {
    return (1e5 + 2e4 * row) * (1 + heading) * std::exp(-std::pow((tau - 0.2 * row) / 0.6, 2));
  };
  for (int k = 0; k < 400; ++k)
    for (int b = 0; b < 2; ++b) {
      Vector6 h;
      for (int r = 0; r < 6; ++r)
        h[r] = pulse(-4.0 + 0.02 * k, r, 1 - b);  // headings[0] = 90 deg: heading index 1
      ir->excitation[static_cast<std::size_t>(b)].push_back(h);
    }
  WaterProperties water;
  water.start = -1e3;  // (waves long before the window of the convolution) => no ramp inside it
  const double dir = M_PI / 6;
  const auto sea = std::make_shared<const AiryWaves>(
      water, std::vector<WaveComponent>{{1.2, 7.0, dir, 0.4}, {0.5, 4.0, dir, 1.0}});
  const ImpulseResponseForce p("waves", model, 1, ir, sea);
  dynamics::Data data(model);
  Eigen::VectorXd q = dynamics::neutralConfiguration(model), v = Eigen::VectorXd::Zero(model.nv);
  q[0] = 5.0, q[1] = -3.0;
  // (body yaw 0: relative heading 30 deg, a third of the way from 0 to 90) => the blend of the two
  // responses convolved with the elevation at the body origin, summed directly here
  auto direct = [&](double t, double weight90) {
    Vector6 F = Vector6::Zero();
    for (int k = 0; k < 400; ++k) {
      const double tau = -4.0 + 0.02 * k, eta = sea->elevation(5.0, -3.0, t - tau);
      for (int r = 0; r < 6; ++r)
        F[r] += 0.02 * ((1 - weight90) * pulse(tau, r, 0) + weight90 * pulse(tau, r, 1)) * eta;
    }
    return F;
  };
  dynamics::forwardKinematics(model, data, q, v);
  for (double t : {0.0, 3.3, 10.7}) {
    const Vector6 F = p.excitation(Stage{t, model, data, q, v});
    const Vector6 G = direct(t, 1.0 / 3.0);
    for (int r = 0; r < 6; ++r) CHECK(F[r] == Approx(G[r]).margin(1e-10 * G.cwiseAbs().maxCoeff()));
  }
  // (body yawed by 30 deg: the waves come along its x axis) => heading 0 alone
  const Eigen::Quaterniond yawed(Eigen::AngleAxisd(dir, Eigen::Vector3d::UnitZ()));
  q[3] = yawed.w(), q[4] = yawed.x(), q[5] = yawed.y(), q[6] = yawed.z();
  dynamics::forwardKinematics(model, data, q, v);
  INFO("q = " << q.transpose());
  const Vector6 F = p.excitation(Stage{2.0, model, data, q, v});
  const Vector6 G = direct(2.0, 0.0);
  for (int r = 0; r < 6; ++r) CHECK(F[r] == Approx(G[r]).margin(1e-10 * G.cwiseAbs().maxCoeff()));
}

TEST_CASE("a windowed excitation response gives back its transfer function") {
  // (h(t) = X0 g(t), g the window's unit-area pulse w_c / (2 sqrt(pi)) exp(-(w_c t / 2)^2), whose
  // transform is W(w) = exp(-(w / w_c)^2): the response's transfer function is X0 W(w)) => with
  // excitationWindow = w_c the force is X0 eta(t) at any w <= 2 w_c; without it, X0 W(w) eta(t)
  const dynamics::Model model = block(dynamics::Joint::free());
  const double wc = 2.0, dt = 0.02, t0 = -8.0;  // dt: the kernel's sample spacing
  Vector6 X0;
  X0 << 1e5, -2e5, 3e5, 4e4, -5e4, 6e4;
  auto ir = std::make_shared<ImpulseResponse>(*heaveKernel(dt, 1.0));
  ir->headings = {0.0};
  ir->excitationStart = t0;
  ir->excitation.resize(1);
  for (int k = 0; k <= static_cast<int>(-2.0 * t0 / dt); ++k) {
    const double t = t0 + dt * k;
    ir->excitation[0].push_back(X0 * (wc / (2.0 * std::sqrt(M_PI)) * std::exp(-std::pow(wc * t / 2, 2))));
  }
  WaterProperties water;
  water.start = -1e3;
  const double w = 3.0;  // W(w) = exp(-2.25) = 0.105
  const auto sea = std::make_shared<const AiryWaves>(
      water, std::vector<WaveComponent>{{0.8, 2.0 * M_PI / w, 0.0, 0.3}});
  dynamics::Data data(model);
  const Eigen::VectorXd q = dynamics::neutralConfiguration(model), v = Eigen::VectorXd::Zero(model.nv);
  dynamics::forwardKinematics(model, data, q, v);
  auto largestError = [&](const ImpulseResponseForce& p, double scale) {
    double worst = 0.0;
    for (double t : {0.0, 1.1, 2.35, 7.9})
      worst = std::max(worst, (p.excitation(Stage{t, model, data, q, v}) -
                               scale * X0 * sea->elevation(0.0, 0.0, t)).cwiseAbs().maxCoeff());
    return worst / (X0.cwiseAbs().maxCoeff() * 0.4);
  };
  ir->excitationWindow = wc;
  CHECK(largestError(ImpulseResponseForce("waves", model, 1, ir, sea), 1.0) < 1e-6);
  ir->excitationWindow = 0.0;  // (the window not divided out) => the wave's force cut to W(w)
  CHECK(largestError(ImpulseResponseForce("waves", model, 1, ir, sea), std::exp(-2.25)) < 1e-6);
  // (a wave above 2 w_c) => refused, naming the cutoff it needs
  ir->excitationWindow = wc;
  const auto shortSea = std::make_shared<const AiryWaves>(
      water, std::vector<WaveComponent>{{0.2, 2.0 * M_PI / 4.5, 0.0, 0.3}});
  CHECK_THROWS_WITH(ImpulseResponseForce("waves", model, 1, ir, shortSea),
                    Catch::Contains("cutoff of at least 2.25"));
  ir->excitationWindow = std::numeric_limits<double>::quiet_NaN();  // (a damaged response) => refused
  CHECK_THROWS_WITH(ImpulseResponseForce("waves", model, 1, ir, sea), Catch::Contains("finite"));
}

TEST_CASE("integrators that never stop at the step's start still feed the memory") {
  // (forced heave, stages only at the step's end, as an implicit method) => the same memory force
  // as stages at the start, to the step
  const dynamics::Model model = block(dynamics::Joint::prismatic(Vector3::UnitZ()));
  const ImpulseResponseForce p("radiation", model, 1, heaveKernel(0.02, 20.0), nullptr);
  dynamics::Data data(model);
  auto a = p.makeScratch(), b = p.makeScratch();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(1), v(1);
  const double h = 0.01, w = 2.0;
  double worst = 0, scale = 0;
  for (int i = 0; i < 3000; ++i) {
    const double t = i * h;
    auto at = [&](double ts) {
      v[0] = std::cos(w * ts);
      dynamics::forwardKinematics(model, data, q, v);
    };
    at(t);
    p.radiation(Stage{t, model, data, q, v, a.get(), t});  // (explicit: a stage at the start)
    at(t + h);
    const double fa = p.radiation(Stage{t + h, model, data, q, v, a.get(), t})[2];
    const double fb =
        p.radiation(Stage{t + h, model, data, q, v, b.get(), t})[2];  // (implicit: the end only)
    if (t > 20) worst = std::max(worst, std::abs(fa - fb)), scale = std::max(scale, std::abs(fa));
  }
  CHECK(scale > 1e3);
  CHECK(worst < 1e-6 * scale);
}

TEST_CASE("the scratch's carried values restart a decay bit for bit") {
  const dynamics::Model model = block(dynamics::Joint::prismatic(Vector3::UnitZ()));
  const ImpulseResponseForce p("radiation", model, 1, heaveKernel(0.02, 20.0), nullptr);
  Heave one, two;
  auto s1 = p.makeScratch(), s2 = p.makeScratch();
  double z1 = 0.5, w1 = 0;
  for (int i = 0; i < 700; ++i) one.step(p, s1.get(), z1, w1, 0.01);
  std::vector<double> saved;
  s1->carried(saved);
  s2->restoreCarried(saved);
  double z2 = z1, w2 = w1;
  two.t = one.t;
  for (int i = 0; i < 700; ++i) {
    one.step(p, s1.get(), z1, w1, 0.01);
    two.step(p, s2.get(), z2, w2, 0.01);
  }
  CHECK(z1 == z2);
  CHECK(w1 == w2);
  CHECK(std::abs(z1) > 1e-4);  // still moving: the comparison means something
}

TEST_CASE("bad impulse-response input is refused") {
  const dynamics::Model model = block(dynamics::Joint::free());
  auto ir = heaveKernel(0.02, 1.0);
  const auto sea = std::make_shared<const AiryWaves>(
      WaterProperties{}, std::vector<WaveComponent>{{1.0, 8.0, 0.0, 0.0}});
  CHECK_THROWS_WITH(ImpulseResponseForce("x", model, 0, ir, nullptr), Catch::Contains("world"));
  CHECK_THROWS_WITH(ImpulseResponseForce("x", model, 1, ir, sea), Catch::Contains("no excitation"));
  ir->headings = {0.0};
  CHECK_THROWS_WITH(ImpulseResponseForce("x", model, 1, ir, sea),
                    Catch::Contains("1 headings but 0 excitation"));
  ir->excitation.resize(1);
  ir->excitationStart = 1.0;
  CHECK_THROWS_WITH(ImpulseResponseForce("x", model, 1, ir, sea), Catch::Contains("t0 <= 0"));
  // (calm water) => radiation alone, no excitation needed
  CHECK_NOTHROW(ImpulseResponseForce("x", model, 1, heaveKernel(0.02, 1.0),
                                     std::make_shared<const AiryWaves>(WaterProperties{})));
}
