#include "forces/hydro/rankine_td_provider.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "forces/hydro/td_checks.hpp"

namespace yardsim::forces::hydro {

namespace {

class Scratch final : public ProviderScratch {
 public:
  explicit Scratch(const RankineTdModel& m)
      : state(quietSurface(m)),
        emp(makeEmpScratch(m)),
        a(Eigen::VectorXd::Zero(m.problem().bodyCount())) {}
  FreeSurfaceState state;
  EmpScratch emp;
  Eigen::VectorXd a;
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
                                     std::shared_ptr<const RankineTdModel> panels, double panelStep)
    : ForceProvider(std::move(name)),
      body_(body),
      panels_(std::move(panels)),
      panelStep_(panelStep) {
  const std::string me = "rankine_td '" + this->name() + "': ";
  if (body_ < 1 || body_ >= model.nbodies)
    throw std::invalid_argument(me + "body " + std::to_string(body_) +
                                " is the world or outside the model");
  if (!panels_) throw std::invalid_argument(me + "no panel model");
  if (!(panelStep_ > 0.0)) throw std::invalid_argument(me + "the panel step must be > 0");
  if (const auto m = checkEmpStep(empLimit(*panels_, 100), panelStep_))
    throw std::invalid_argument(me + *m);
}

std::unique_ptr<ProviderScratch> RankineTdProvider::makeScratch() const {
  return std::make_unique<Scratch>(*panels_);
}

Vector6 RankineTdProvider::velocity_W(const Stage& s) const {
  // (V body frame [omega; v_O]) => [v_O; omega] in the mean pose's world axes
  const dynamics::Motion& V = s.data.V_B[static_cast<std::size_t>(body_)];
  Vector6 u;
  u.head<3>() = panels_->rotation() * V.tail<3>();
  u.tail<3>() = panels_->rotation() * V.head<3>();
  return u;
}

const Vector6& RankineTdProvider::memoryForce(const Stage& s, ProviderScratch& scratch) const {
  auto& c = static_cast<Scratch&>(scratch);
  // (a stage at the start of a step, a panel time due) => one emp step from this accepted state
  const bool stepStartStage = s.t == s.stepStart || !std::isfinite(s.stepStart);
  if (stepStartStage && s.t >= c.last + panelStep_ * (1.0 - 1e-9)) {
    c.a.noalias() = panels_->modes() * velocity_W(s);
    const Eigen::VectorXd none;
    c.held = empStep(*panels_, panelStep_, c.a, none, c.state, c.emp);
    c.last = s.t;
  }
  return c.held;
}

void RankineTdProvider::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                                   Eigen::VectorXd& /*tau*/) const {
  std::unique_ptr<ProviderScratch> temporary;
  const Vector6& F_W = memoryForce(s, scratchOf<ProviderScratch>(s, temporary));
  // (F^M in W about the origin, [force; moment]) => body frame [moment; force]
  dynamics::Force F_B;
  F_B << panels_->rotation().transpose() * F_W.tail<3>(),
      panels_->rotation().transpose() * F_W.head<3>();
  f.addBodyFrame(body_, F_B);
}

double RankineTdProvider::doPower(const Stage& s) const {
  // (held force, velocity) => F^M . u (the radiated power is its mean, <= 0)
  if (s.scratch == nullptr) return 0.0;
  return static_cast<const Scratch&>(*s.scratch).held.dot(velocity_W(s));
}

}  // namespace yardsim::forces::hydro
