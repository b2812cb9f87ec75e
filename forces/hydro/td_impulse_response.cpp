#include "forces/hydro/td_impulse_response.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <string>

#include "forces/airy_waves.hpp"
#include "forces/hydro/emp_scheme.hpp"
#include "forces/hydro/incident_kinematics.hpp"

namespace yardsim::forces::hydro {

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// (6-vector in W, R_WB) => in B
Vector6d toBody(const Vector6d& f_W, const Eigen::Matrix3d& R_WB) {
  Vector6d f_B;
  f_B.head<3>() = R_WB.transpose() * f_W.head<3>();
  f_B.tail<3>() = R_WB.transpose() * f_W.tail<3>();
  return f_B;
}

// (model, dt, steps) => K(t_k) in W, k = 0 .. steps - 1, one impulsive velocity per mode
std::vector<Eigen::Matrix<double, 6, 6>> radiation(const RankineTdModel& model, double dt,
                                                   int steps) {
  std::vector<Eigen::Matrix<double, 6, 6>> K(static_cast<std::size_t>(steps),
                                             Eigen::Matrix<double, 6, 6>::Zero());
  EmpScratch scratch = makeEmpScratch(model);
  const Eigen::VectorXd still = Eigen::VectorXd::Zero(model.problem().bodyCount()), none;
  for (int j = 0; j < 6; ++j) {
    FreeSurfaceState state = quietSurface(model);
    const Eigen::VectorXd kick = model.modes().col(j) / dt;
    for (int n = 0; n < steps; ++n) {
      const Vector6d f = empStep(model, dt, n == 0 ? kick : still, none, state, scratch);
      // (zeta(-dt/2) = 0, zeta(dt/2) = zeta(0+)) => K(0+) is twice the step-0 average
      K[static_cast<std::size_t>(n)].col(j) = (n == 0 ? -2.0 : -1.0) * f;
    }
  }
  return K;
}

// (K, dt, w) => -(1/w) int_0^T K sin(w t) dt = A(w) - A_inf (Ogilvie), trapezoidal rule
Eigen::Matrix<double, 6, 6> addedMassShift(const std::vector<Eigen::Matrix<double, 6, 6>>& K,
                                           double dt, double w) {
  Eigen::Matrix<double, 6, 6> s = Eigen::Matrix<double, 6, 6>::Zero();
  for (std::size_t k = 1; k < K.size(); ++k)
    s += (k + 1 == K.size() ? 0.5 : 1.0) * dt * std::sin(w * static_cast<double>(k) * dt) * K[k];
  return -s / w;
}

// (raw K, dt, w1, w2) => K band-limited through its cosine transform (trapezoidal rule in t and
// w); returns the added mass the cut part contributed below w1: the mean over w in [w1/3, w1] of
// (A_raw(w) - A_band(w)) from the two sine transforms
Eigen::Matrix<double, 6, 6> bandLimit(std::vector<Eigen::Matrix<double, 6, 6>>& K, double dt,
                                      double w1, double w2) {
  const std::vector<Eigen::Matrix<double, 6, 6>> raw = K;
  const auto nt = static_cast<int>(K.size());
  const int nw = std::max(64, static_cast<int>(std::ceil(w2 * dt * nt / std::numbers::pi * 4.0)));
  const double dw = w2 / nw;
  std::vector<Eigen::Matrix<double, 6, 6>> B(static_cast<std::size_t>(nw + 1),
                                             Eigen::Matrix<double, 6, 6>::Zero());
  for (int i = 0; i <= nw; ++i) {
    // (K) => B(w_i) times the taper
    const double w = i * dw;
    const double taper =
        w <= w1 ? 1.0 : 0.5 * (1.0 + std::cos(std::numbers::pi * (w - w1) / (w2 - w1)));
    for (int k = 0; k < nt; ++k) {
      const double weight = (k == 0 || k == nt - 1 ? 0.5 : 1.0) * dt;
      B[static_cast<std::size_t>(i)] +=
          weight * std::cos(w * k * dt) * K[static_cast<std::size_t>(k)];
    }
    B[static_cast<std::size_t>(i)] *= taper;
  }
  for (int k = 0; k < nt; ++k) {
    // (tapered B) => K_band(t_k)
    Eigen::Matrix<double, 6, 6> sum = Eigen::Matrix<double, 6, 6>::Zero();
    for (int i = 0; i <= nw; ++i)
      sum += (i == 0 || i == nw ? 0.5 : 1.0) * dw * std::cos(i * dw * k * dt) *
             B[static_cast<std::size_t>(i)];
    K[static_cast<std::size_t>(k)] = 2.0 / std::numbers::pi * sum;
  }
  Eigen::Matrix<double, 6, 6> shift = Eigen::Matrix<double, 6, 6>::Zero();
  constexpr int kSamples = 8;
  for (int m = 0; m < kSamples; ++m) {
    const double w = w1 / 3.0 + (w1 - w1 / 3.0) * m / (kSamples - 1);
    shift += (addedMassShift(raw, dt, w) - addedMassShift(K, dt, w)) / kSamples;
  }
  return shift;
}

// The incident impulse wave on the hull panels as sums over the quadrature frequencies: for each
// quantity q (dphi_I/dn, d2phi_I/dndt, dphi_I/dt) q(x_k, t) = C_q.row(k) cos(w t) + S_q.row(k)
// sin(w t).
struct IncidentWave {
  Eigen::VectorXd omega;
  Eigen::MatrixXd cN, sN, cNt, sNt, cPt, sPt;  // Nb x nw
};

IncidentWave incidentWave(const RankineTdModel& model, const Vector3& e_beta,
                          const ImpulseResponseSettings& s) {
  const int nb = model.problem().bodyCount(), nw = s.frequencies;
  const double g = model.settings().g, h = model.settings().depth, top = 3.0 * s.cutoff,
               dw = top / (nw - 1);
  IncidentWave w;
  w.omega.resize(nw);
  for (Eigen::MatrixXd* m : {&w.cN, &w.sN, &w.cNt, &w.sNt, &w.cPt, &w.sPt}) m->setZero(nb, nw);
  for (int i = 0; i < nw; ++i) {
    // (w_i) => trapezoid weight times W(w_i) / pi; k on the solver's depth (w^2 = g k tanh kh)
    const double om = i * dw, k = om > 0.0 ? waveNumber(om, h, g) : 0.0,
                 v = velocityPerElevation(om, k, h, g);
    const double weight = (i == 0 || i == nw - 1 ? 0.5 : 1.0) * dw *
                          std::exp(-(om / s.cutoff) * (om / s.cutoff)) / std::numbers::pi;
    w.omega[i] = om;
    for (int p = 0; p < nb; ++p) {
      const Panel& q = model.problem().body()[static_cast<std::size_t>(p)];
      const double xi = (q.centroid - model.origin()).dot(e_beta);
      const auto [cc, sc] = depthFactors(k, q.centroid.z(), h);
      const double ck = std::cos(k * xi), sk = std::sin(k * xi), nh = q.normal.dot(e_beta),
                   nz = q.normal.z();
      // cos(k xi - w t) = ck cos(w t) + sk sin(w t);  sin(k xi - w t) = sk cos(w t) - ck sin(w t)
      // (incident_kinematics.hpp, v = g k / w) dphi/dn = W v (C nh cos + S nz sin);
      // d2phi/dndt = W v w (C nh sin - S nz cos); dphi/dt = -g W C cos
      const double a = weight * v, b = weight * v * om, c = -g * weight;
      w.cN(p, i) = a * (cc * nh * ck + sc * nz * sk);
      w.sN(p, i) = a * (cc * nh * sk - sc * nz * ck);
      w.cNt(p, i) = b * (cc * nh * sk - sc * nz * ck);
      w.sNt(p, i) = b * (-cc * nh * ck - sc * nz * sk);
      w.cPt(p, i) = c * cc * ck;
      w.sPt(p, i) = c * cc * sk;
    }
  }
  return w;
}

// (model, heading in W, settings, start, steps) => h(t0 + k dt) in W
std::vector<Vector6d> excitation(const RankineTdModel& model, const Vector3& e_beta,
                                 const ImpulseResponseSettings& s, double t0, int steps) {
  const IncidentWave w = incidentWave(model, e_beta, s);
  const int nb = model.problem().bodyCount(), nw = s.frequencies;
  FreeSurfaceState state = quietSurface(model);
  EmpScratch scratch = makeEmpScratch(model);
  Eigen::VectorXd cw(nw), sw(nw), a(nb), at(nb), pt(nb);
  // (hull pressure functional) => Froude-Krylov force rho sum A_k phi_t N_k
  Eigen::MatrixXd fk(6, nb);
  for (int p = 0; p < nb; ++p)
    fk.col(p) = model.settings().rho * model.problem().body()[static_cast<std::size_t>(p)].area *
                model.modes().row(p).transpose();
  std::vector<Vector6d> h(static_cast<std::size_t>(steps));
  for (int n = 0; n < steps; ++n) {
    const double t = t0 + n * s.dt;
    cw = (w.omega * t).array().cos();
    sw = (w.omega * t).array().sin();
    a.noalias() = -(w.cN * cw + w.sN * sw);
    at.noalias() = -(w.cNt * cw + w.sNt * sw);
    pt.noalias() = w.cPt * cw + w.sPt * sw;
    h[static_cast<std::size_t>(n)] = empStep(model, s.dt, a, at, state, scratch);
    if (s.froudeKrylov) h[static_cast<std::size_t>(n)] += fk * pt;
  }
  return h;
}

// FNV-1a, 64 bit, over raw bytes
struct Fnv {
  std::uint64_t h = 14695981039346656037ull;
  void bytes(const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
  }
  void number(double x) { bytes(&x, sizeof x); }
  void integer(std::int64_t x) { bytes(&x, sizeof x); }
};

}  // namespace

ImpulseResponse computeImpulseResponse(const RankineTdModel& model,
                                       const ImpulseResponseSettings& s) {
  if (!(s.dt > 0.0) || !(s.memory > s.dt))
    throw std::invalid_argument("impulse response: need dt > 0 and memory > dt");
  if (!s.headings.empty() && !(s.cutoff > 0.0))
    throw std::invalid_argument("impulse response: excitation needs cutoff > 0 (rad/s)");
  if (s.bandStart > 0.0 && !(s.bandEnd > s.bandStart))
    throw std::invalid_argument("impulse response: need bandEnd > bandStart");
  if (!s.headings.empty() && s.frequencies < 8)
    throw std::invalid_argument("impulse response: need at least 8 frequencies");
  const EmpLimit limit = empLimit(model, 100);
  if (s.dt > limit.dtMax) {
    throw std::invalid_argument("impulse response: dt " + std::to_string(s.dt) +
                                " s is above the emp limit " + std::to_string(limit.dtMax) +
                                " s of the free-surface mesh (lambda_max " +
                                std::to_string(limit.lambdaMax) + " 1/m)");
  }
  ImpulseResponse out;
  out.dt = s.dt;
  out.aInf = toBodyAxes(model.aInf(), model.rotation());
  const int steps = static_cast<int>(std::lround(s.memory / s.dt)) + 1;
  std::vector<Eigen::Matrix<double, 6, 6>> K = radiation(model, s.dt, steps);
  if (s.bandStart > 0.0)
    out.aInf =
        toBodyAxes(model.aInf() + bandLimit(K, s.dt, s.bandStart, s.bandEnd), model.rotation());
  for (const auto& K_W : K) out.radiation.push_back(toBodyAxes(K_W, model.rotation()));
  const double lead = s.lead > 0.0 ? s.lead : (s.headings.empty() ? 0.0 : 12.0 / s.cutoff);
  const int leadSteps = static_cast<int>(std::ceil(lead / s.dt));
  out.excitationStart = -leadSteps * s.dt;
  out.headings = s.headings;
  out.excitationWindow = s.headings.empty() ? 0.0 : s.cutoff;
  out.froudeKrylov = s.froudeKrylov;
  for (const double beta : s.headings) {
    // (beta in B) => e_beta in W, horizontal
    Vector3 e = model.rotation() * Vector3(std::cos(beta), std::sin(beta), 0.0);
    e.z() = 0.0;
    e.normalize();
    std::vector<Vector6d> h = excitation(model, e, s, out.excitationStart, leadSteps + steps);
    for (Vector6d& v : h) v = toBody(v, model.rotation());
    out.excitation.push_back(std::move(h));
  }
  return out;
}

double resolvedFrequency(const RankineTdModel& model, double panelsPerWave) {
  // (largest panel diameter h inside the zone's inner edge) => w = sqrt(2 pi g / (panelsPerWave h))
  const FreeSurfaceSettings& fs = model.settings().freeSurface;
  const double inner = fs.truncationRadius - fs.dampingWidth;
  double h = 0.0;
  for (const Panel& p : model.problem().surface()) {
    if ((p.centroid - model.freeSurface().centre).head<2>().norm() < inner)
      h = std::max(h, p.diameter);
  }
  return std::sqrt(2.0 * std::numbers::pi * model.settings().g / (panelsPerWave * h));
}

ImpulseResponse computeImpulseResponse(const PanelMesh& hull_B, const dynamics::Transform& X_WB,
                                       const ImpulseResponseSettings& s) {
  const RankineTdModel model(hull_B, X_WB, s.solver);
  ImpulseResponse out = computeImpulseResponse(model, s);
  out.key = impulseResponseKey(hull_B, X_WB, s);
  return out;
}

std::string impulseResponseKey(const PanelMesh& hull_B, const dynamics::Transform& X_WB,
                               const ImpulseResponseSettings& s) {
  Fnv f;
  f.integer(static_cast<std::int64_t>(hull_B.vertices.size()));
  for (const Vector3& v : hull_B.vertices) f.bytes(v.data(), 3 * sizeof(double));
  f.integer(static_cast<std::int64_t>(hull_B.panels.size()));
  for (const auto& p : hull_B.panels) f.bytes(p.data(), sizeof p);
  f.bytes(X_WB.R.data(), 9 * sizeof(double));
  f.bytes(X_WB.p.data(), 3 * sizeof(double));
  const FreeSurfaceSettings& fs = s.solver.freeSurface;
  for (const double x :
       {fs.truncationRadius, fs.firstSpacing, fs.maxSpacing, fs.growth, fs.dampingWidth,
        fs.dampingStrength, s.solver.rho, s.solver.g, s.solver.depth, s.solver.waterLevel, s.dt,
        s.memory, s.cutoff, s.lead, s.bandStart, s.bandEnd})
    f.number(x);
  f.integer(s.frequencies);
  if (!s.froudeKrylov) f.integer(-1);  // (diffraction only) => another key; the default's unchanged
  // (a finite depth) => another key than before the impulsive wave followed the depth (2026-11-25):
  // a cached response of the old deep-water wave on a finite depth is not found any more
  if (std::isfinite(s.solver.depth)) f.integer(-2);
  // (a uniform surface damping) => another key; without one the key is unchanged
  if (fs.surfaceDamping != 0.0) {
    f.integer(-3);
    f.number(fs.surfaceDamping);
  }
  // (a free surface refined in azimuth or with its own beach spacing) => another key
  if (fs.azimuthSpacing > 0.0 || fs.beachSpacing > 0.0) {
    f.integer(-4);
    f.number(fs.azimuthSpacing);
    f.number(fs.beachSpacing);
  }
  f.integer(static_cast<std::int64_t>(s.headings.size()));
  for (const double b : s.headings) f.number(b);
  static const char* hex = "0123456789abcdef";
  std::string key = "rankine_td-";
  for (int i = 15; i >= 0; --i) key += hex[(f.h >> (4 * i)) & 0xF];
  return key;
}

}  // namespace yardsim::forces::hydro
