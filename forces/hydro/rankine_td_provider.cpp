#include "forces/hydro/rankine_td_provider.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "forces/hydro/incident_kinematics.hpp"
#include "forces/hydro/td_checks.hpp"

namespace yardsim::forces::hydro {

namespace {

class Scratch final : public ProviderScratch {
 public:
  explicit Scratch(const RankineTdModel& m)
      : state(quietSurface(m)),
        emp(makeEmpScratch(m)),
        a(Eigen::VectorXd::Zero(m.problem().bodyCount())),
        at(Eigen::VectorXd::Zero(m.problem().bodyCount())) {}
  FreeSurfaceState state;
  EmpScratch emp;
  Eigen::VectorXd a, at, cw, sw;
  double last = -std::numeric_limits<double>::infinity();  ///< time of the last panel step, s
  Vector6 held = Vector6::Zero();                          ///< F^M held since then, W axes

  void carried(std::vector<double>& out) const override {
    out.push_back(last);
    out.insert(out.end(), held.data(), held.data() + 6);
    out.insert(out.end(), state.zeta.data(), state.zeta.data() + state.zeta.size());
    out.insert(out.end(), state.phi.data(), state.phi.data() + state.phi.size());
  }
  void restoreCarried(std::span<const double> v) override {
    const auto nf = static_cast<std::size_t>(state.zeta.size());
    if (v.size() != 7 + 2 * nf)
      throw std::invalid_argument("rankine_td: checkpoint holds " + std::to_string(v.size()) +
                                  " values, expected " + std::to_string(7 + 2 * nf));
    last = v[0];
    for (int i = 0; i < 6; ++i) held[i] = v[static_cast<std::size_t>(1 + i)];
    for (std::size_t k = 0; k < nf; ++k) {
      state.zeta[static_cast<Eigen::Index>(k)] = v[7 + k];
      state.phi[static_cast<Eigen::Index>(k)] = v[7 + nf + k];
    }
  }
};

}  // namespace

RankineTdProvider::RankineTdProvider(std::string name, const dynamics::Model& model, int body,
                                     std::shared_ptr<const RankineTdModel> panels, double panelStep,
                                     std::shared_ptr<const AiryWaves> sea, bool froudeKrylov)
    : ForceProvider(std::move(name)),
      body_(body),
      panels_(std::move(panels)),
      panelStep_(panelStep),
      sea_(std::move(sea)) {
  const std::string me = "rankine_td '" + this->name() + "': ";
  if (body_ < 1 || body_ >= model.nbodies)
    throw std::invalid_argument(me + "body " + std::to_string(body_) +
                                " is the world or outside the model");
  if (!panels_) throw std::invalid_argument(me + "no panel model");
  if (!(panelStep_ > 0.0)) throw std::invalid_argument(me + "the panel step must be > 0");
  if (const auto m = checkEmpStep(empLimit(*panels_, 100), panelStep_))
    throw std::invalid_argument(me + *m);
  if (!sea_ || sea_->calm()) return;
  // (sea components, mean hull centroids) => the incident tables: for eta = a cos(theta),
  // theta = k (x cos b + y sin b) - w t + phase, phi_I = g a / w cosh/cosh sin(theta), so
  //   dphi_I/dn     = g a k / w (cc n_h cos theta + sc n_z sin theta)
  //   d2phi_I/dndt  = g a k (cc n_h sin theta - sc n_z cos theta)
  //   dphi_I/dt     = -g a cc cos theta,
  // with cos theta = cp cos(w t) + sp sin(w t), sin theta = sp cos(w t) - cp sin(w t),
  // cp, sp = cos, sin(k (x cos b + y sin b) + phase)
  const int nb = panels_->problem().bodyCount(), nc = static_cast<int>(sea_->size());
  const double g = panels_->settings().g, rho = panels_->settings().rho,
               h = panels_->settings().depth;
  for (Eigen::MatrixXd* m : {&cN_, &sN_, &cNt_, &sNt_}) m->setZero(nb, nc);
  cF_.setZero(6, nc);
  sF_.setZero(6, nc);
  omega_.resize(nc);
  for (int i = 0; i < nc; ++i) {
    const WaveComponent& c = sea_->component(static_cast<std::size_t>(i));
    const double a = 0.5 * c.height, k = sea_->wavenumber(static_cast<std::size_t>(i)),
                 w = sea_->frequency(static_cast<std::size_t>(i));
    const Vector3 e(std::cos(c.direction), std::sin(c.direction), 0.0);
    omega_[i] = w;
    for (int p = 0; p < nb; ++p) {
      const Panel& q = panels_->problem().body()[static_cast<std::size_t>(p)];
      const double th = k * q.centroid.dot(e) + c.phase, cp = std::cos(th), sp = std::sin(th);
      const auto [cc, sc] = depthFactors(k, q.centroid.z(), h);
      const double nh = q.normal.dot(e), nz = q.normal.z(), v = g * a * k / w;
      cN_(p, i) = v * (cc * nh * cp + sc * nz * sp);
      sN_(p, i) = v * (cc * nh * sp - sc * nz * cp);
      cNt_(p, i) = w * v * (cc * nh * sp - sc * nz * cp);
      sNt_(p, i) = w * v * (-cc * nh * cp - sc * nz * sp);
      if (froudeKrylov) {
        // (rho phi_t A N) => the Froude-Krylov force's cosine and sine parts
        const Vector6 n = rho * q.area * panels_->modes().row(p).transpose();
        cF_.col(i) += -g * a * cc * cp * n;
        sF_.col(i) += -g * a * cc * sp * n;
      }
    }
  }
}

std::unique_ptr<ProviderScratch> RankineTdProvider::makeScratch() const {
  auto s = std::make_unique<Scratch>(*panels_);
  s->cw.resize(omega_.size());
  s->sw.resize(omega_.size());
  return s;
}

Vector6 RankineTdProvider::velocity_W(const Stage& s) const {
  // (V body frame [omega; v_O], the body's rotation now R_WB) => [v_O; omega] in world axes, the
  // panels' axes (not the mean rotation times the body-frame velocity: a body that drifts and
  // rolls would see its drift velocity turned into a heave and roll velocity,
  // docs/hydrodynamics.md)
  const dynamics::Motion& V = s.data.V_B[static_cast<std::size_t>(body_)];
  const Eigen::Matrix3d& R_WB = s.data.X_WB[static_cast<std::size_t>(body_)].R;
  Vector6 u;
  u.head<3>() = R_WB * V.tail<3>();
  u.tail<3>() = R_WB * V.head<3>();
  return u;
}

const Vector6& RankineTdProvider::memoryForce(const Stage& s, ProviderScratch& scratch) const {
  auto& c = static_cast<Scratch&>(scratch);
  // (a stage at the start of a step, a panel time due) => one emp step from this accepted state
  const bool stepStartStage = s.t == s.stepStart || !std::isfinite(s.stepStart);
  if (stepStartStage && s.t >= c.last + panelStep_ * (1.0 - 1e-9)) {
    c.a.noalias() = panels_->modes() * velocity_W(s);
    if (omega_.size() == 0) {
      const Eigen::VectorXd none;
      c.held = empStep(*panels_, panelStep_, c.a, none, c.state, c.emp);
    } else {
      // (the incident wave at t) => -dphi_I/dn on the hull, -d2phi_I/dndt for dphi^M/dt, F-K
      const double r = sea_->ramp(s.t);
      c.cw = r * (omega_ * s.t).array().cos();
      c.sw = r * (omega_ * s.t).array().sin();
      c.a.noalias() -= cN_ * c.cw;
      c.a.noalias() -= sN_ * c.sw;
      c.at.setZero();
      c.at.noalias() -= cNt_ * c.cw;
      c.at.noalias() -= sNt_ * c.sw;
      c.held = empStep(*panels_, panelStep_, c.a, c.at, c.state, c.emp);
      c.held.noalias() += cF_ * c.cw;
      c.held.noalias() += sF_ * c.sw;
    }
    c.last = s.t;
  }
  return c.held;
}

void RankineTdProvider::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                                   Eigen::VectorXd& /*tau*/) const {
  std::unique_ptr<ProviderScratch> temporary;
  const Vector6& F_W = memoryForce(s, scratchOf<ProviderScratch>(s, temporary));
  // (F^M in world axes about the body origin, [force; moment], R_WB now) => body frame [moment;
  // force]: the force keeps its world direction while the body rolls (turned with the body, a
  // heave force rolled by the roll angle gave a spurious mean sway force that drifted a free body)
  const Eigen::Matrix3d& R_WB = s.data.X_WB[static_cast<std::size_t>(body_)].R;
  dynamics::Force F_B;
  F_B << R_WB.transpose() * F_W.tail<3>(), R_WB.transpose() * F_W.head<3>();
  f.addBodyFrame(body_, F_B);
}

double RankineTdProvider::doPower(const Stage& s) const {
  // (held force, velocity) => F^M . u (the radiated power is its mean, <= 0)
  if (s.scratch == nullptr) return 0.0;
  return static_cast<const Scratch&>(*s.scratch).held.dot(velocity_W(s));
}

}  // namespace yardsim::forces::hydro
