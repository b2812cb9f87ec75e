#include "models/multibody/multibody_model.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/crba.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/rnea.hpp"
#include "models/multibody/providers.hpp"
#include "models/numerical_error.hpp"

namespace yardsim::models {

std::ostream& operator<<(std::ostream& os, const MultibodyState& s) {
  os << "q=[";
  for (Eigen::Index i = 0; i < s.q.size(); ++i) os << (i ? "," : "") << s.q[i];
  return os << "]";
}

namespace {
MultibodyState initialState(const BuiltMechanics& m) {
  const auto n = static_cast<std::size_t>(m.model.nbodies);
  return {m.q0, m.v0, std::vector<JointDrive>(n), std::vector<BodyLoad>(n),
          std::vector<WinchJob>(m.ropes.size()), 0.0};
}
}  // namespace

MultibodyModel::MultibodyModel(std::string name, BuiltMechanics mechanics,
                               const MultibodyOptions& options)
    : dtss::Atomic<MultibodyState>(std::move(name), initialState(mechanics), options.dt),
      mech_(std::move(mechanics)),
      opt_(options),
      directions_(static_cast<std::size_t>(mech_.model.nbodies) + 2 * mech_.ropes.size(),
                  dtss::Crossing::Rising),
      system_(mech_.model),
      view_(mech_.model),
      feedforward_(mech_.model),
      scratch_(mech_.model),
      spForces_(mech_.model),
      spTau_(Eigen::VectorXd::Zero(mech_.model.nv)) {
  // (rope and equalizer specs) => providers, evaluated at every stage
  Providers providers = makeProviders(mech_, mech_.model);
  ropes_ = std::move(providers.ropes);
  equalizers_ = std::move(providers.equalizers);
  // (ropes) => their slack/taut functions cross either way
  std::fill(directions_.end() - static_cast<std::ptrdiff_t>(mech_.ropes.size()), directions_.end(),
            dtss::Crossing::Both);
  // (options) => the integrator at step dt; loops kept closed as its spec says
  opt_.integrator.dt = opt_.dt;
  if (!opt_.projectLoops && opt_.integrator.loops == dynamics::LoopStabilization::Projection)
    opt_.integrator.loops = dynamics::LoopStabilization::None;
  integrator_ = dynamics::makeIntegrator(opt_.integrator, mech_.model);
  if (mech_.model.nc > 0) dynamics::configureLoopStabilization(opt_.integrator, system_);
  if (opt_.driveBandwidth <= 0.0) opt_.driveBandwidth = std::min(10.0, 0.1 / opt_.dt);
  // (initial configuration) => joint-space inertia of each 1-dof joint, for servo gains
  dynamics::Data data(mech_.model);
  const Eigen::MatrixXd& M = dynamics::crba(mech_.model, data, mech_.q0);
  servoInertia_.assign(static_cast<std::size_t>(mech_.model.nbodies), 0.0);
  for (int i = 1; i < mech_.model.nbodies; ++i)
    if (mech_.model.jointNv[i] == 1) servoInertia_[i] = M(mech_.model.idxV[i], mech_.model.idxV[i]);
  // (initial state) => the energy balance and the bound on its rise (multibody_blowup.cpp)
  balance0_ = energyOf(state().x, 0.0, scratch_);
  energyBound_ = opt_.energyGrowthLimit * energyScale();
  system_.setForces([this](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                           const dynamics::Data& d, dynamics::ExternalForces& f,
                           Eigen::VectorXd& tau) {
    const forces::Stage stage{t, mech_.model, d, q, v};
    for (auto& r : ropes_) r->evaluate(stage, f, tau);
    for (auto& e : equalizers_) e->evaluate(stage, f, tau);
    setPointForces(t, q, v, d, f, tau);
  });
}

int MultibodyModel::jointBody(const std::string& joint) const {
  for (std::size_t i = 1; i < mech_.jointNames.size(); ++i)
    if (mech_.jointNames[i] == joint) return static_cast<int>(i);
  return -1;
}

void MultibodyModel::setPointForces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                    const dynamics::Data&, dynamics::ExternalForces& f,
                                    Eigen::VectorXd& tau) const {
  const MultibodyState& x = *current_;
  const auto& m = mech_.model;
  const double wc = opt_.driveBandwidth;
  // (q, v) => bias forces h(q, v), the drives' feedforward (gravity and velocity terms)
  const bool driving = std::any_of(x.drives.begin(), x.drives.end(), [](auto& d) { return d.active; });
  if (driving) dynamics::biasForces(m, feedforward_, q, v);
  for (int i = 1; i < m.nbodies; ++i) {
    // (ramp reference, servo, feedforward) => bounded joint force of a driven 1-dof joint
    const JointDrive& d = x.drives[i];
    if (d.active) {
      const int iq = m.idxQ[i], iv = m.idxV[i];
      const double dir = d.target >= d.start ? 1.0 : -1.0;
      const double travel = std::abs(d.target - d.start);
      const double moved = std::min(travel, d.speed * std::max(0.0, t - d.t0));
      const double qRef = d.start + dir * moved;
      const double vRef = moved < travel ? dir * d.speed : 0.0;
      const double I = servoInertia_[i];
      double u = I * (wc * wc * (qRef - q[iq]) + 2.0 * wc * (vRef - v[iv])) + feedforward_.nle[iv];
      if (opt_.driveMaxEffort > 0) u = std::clamp(u, -opt_.driveMaxEffort, opt_.driveMaxEffort);
      tau[iv] += u;
    }
    const BodyLoad& l = x.loads[i];
    if (!l.force.isZero() || !l.moment.isZero()) {
      dynamics::Force F_W;
      F_W << l.moment, l.force;
      f.addWorldFrame(i, F_W);
    }
  }
}

double MultibodyModel::nonConservativePower(const MultibodyState& x, double t) const {
  const auto& m = mech_.model;
  dynamics::forwardKinematics(m, scratch_, x.q, x.v);
  const forces::Stage stage{t, m, scratch_, x.q, x.v};
  double p = 0.0;
  for (const auto& r : ropes_) p += r->power(stage);
  for (const auto& e : equalizers_) p += e->power(stage);
  // (drives, loads) => their forces at this state, and the power they deliver
  const MultibodyState* saved = current_;
  current_ = &x;
  spForces_.clear();
  spTau_.setZero();
  setPointForces(t, x.q, x.v, scratch_, spForces_, spTau_);
  current_ = saved;
  p += spTau_.dot(x.v);
  for (int b = 1; b < m.nbodies; ++b) p += spForces_.inBodyFrame(scratch_, b).dot(scratch_.V[b]);
  return p;
}

void MultibodyModel::advance(MultibodyState& x, devs::Time t, devs::Time dt) const {
  // (power at both ends of the step) => the work of non-conservative forces, trapezoidal
  const double p0 = nonConservativePower(x, t);
  current_ = &x;
  double time = t;
  try {
    integrator_->step(system_, time, x.q, x.v, dt);
  } catch (const devs::SimulationError&) {
    throw;
  } catch (const std::runtime_error& e) {  // the kernel or a force provider gave up: its diagnosis
    throw NumericalError("multibody '" + path() + "'", t, e.what(),
                         "a smaller dt, softer drives (bandwidth), or an implicit integrator");
  }
  if (x.q.allFinite() && x.v.allFinite())
    x.work += 0.5 * dt * (p0 + nonConservativePower(x, t + dt));
  checkBlowUp(x, t + dt);
}

void MultibodyModel::applyInput(MultibodyState& x, devs::Time t) const {
  integrator_->reset();  // the forces change here: no history across it
  for (const SetPoint& s : setpoint.values()) {
    switch (s.kind) {
      case SetPoint::Kind::JointTarget: {
        const int i = jointBody(s.element);
        if (i < 0 || mech_.model.jointNv[i] != 1)
          throw devs::SimulationError("multibody '" + path() + "': set-point from '" + s.actor +
                                      "' names '" + s.element + "', which is not a 1-dof joint here");
        const double q = x.q[mech_.model.idxQ[i]];
        x.drives[i] = JointDrive{true, false, q, s.target, std::abs(s.speed), t, s.actor};
        break;
      }
      case SetPoint::Kind::BodyLoad: {
        const int i = mech_.model.bodyIndex(s.element);
        if (i <= 0)
          throw devs::SimulationError("multibody '" + path() + "': load from '" + s.actor +
                                      "' names unknown body '" + s.element + "'");
        x.loads[i].force = Eigen::Vector3d(s.force[0], s.force[1], s.force[2]);
        x.loads[i].moment = Eigen::Vector3d(s.moment[0], s.moment[1], s.moment[2]);
        break;
      }
      case SetPoint::Kind::WinchPayout: {
        const int r = ropeIndex(s.element);
        if (r < 0 || !(s.speed > 0))
          throw devs::SimulationError("multibody '" + path() + "': winch set-point from '" +
                                      s.actor + "' names '" + s.element +
                                      "', which is not a rope here, or has no positive speed");
        const auto ri = static_cast<std::size_t>(r);
        ropes_[ri]->setPayoutRate(t, s.amount >= 0 ? s.speed : -s.speed);
        x.winches[ri] = WinchJob{true, t + std::abs(s.amount) / s.speed, s.actor};
        break;
      }
    }
  }
}

int MultibodyModel::ropeIndex(const std::string& name) const {
  for (std::size_t i = 0; i < ropes_.size(); ++i)
    if (ropes_[i]->name() == name) return static_cast<int>(i);
  return -1;
}

devs::Time MultibodyModel::nextTimeEvent(const MultibodyState& x, devs::Time t) const {
  devs::Time next = devs::kInfinity;
  for (const auto& w : x.winches)
    if (w.active && w.tEnd > t) next = std::min(next, w.tEnd);
  return next;
}

void MultibodyModel::onTimeEvent(MultibodyState& x, devs::Time t) const {
  integrator_->reset();
  // (winch jobs ending now) => winches stopped
  for (std::size_t r = 0; r < x.winches.size(); ++r)
    if (x.winches[r].active && x.winches[r].tEnd <= t) {
      ropes_[r]->setPayoutRate(t, 0.0);
      x.winches[r].active = false;
    }
}

void MultibodyModel::eventFunctions(const MultibodyState& x, devs::Time t, std::span<double> g) const {
  // (drive) => > 0 once the joint is within tolerance of its target, on the side it comes from
  g[0] = -1.0;
  for (int i = 1; i < mech_.model.nbodies; ++i) {
    const JointDrive& d = x.drives[i];
    if (!d.active || d.reported) {
      g[i] = -1.0;
      continue;
    }
    const double dir = d.target >= d.start ? 1.0 : -1.0;
    g[i] = dir * (x.q[mech_.model.idxQ[i]] - d.target) + opt_.driveTolerance;
  }
  // (ropes with a minimum breaking load) => > 0 once the tension exceeds it
  if (ropes_.empty()) return;
  dynamics::forwardKinematics(mech_.model, scratch_, x.q, x.v);
  const forces::Stage stage{t, mech_.model, scratch_, x.q, x.v};
  const std::size_t nb = static_cast<std::size_t>(mech_.model.nbodies), nr = ropes_.size();
  for (std::size_t r = 0; r < nr; ++r) {
    const auto& mbl = ropes_[r]->properties().breakingLoad;
    g[nb + r] = mbl ? ropes_[r]->tension(stage) - *mbl : -1.0;
    // (rope) => its stretch: > 0 taut, < 0 slack
    g[nb + nr + r] = ropes_[r]->length(stage) - ropes_[r]->unstretchedLength(t);
  }
}

void MultibodyModel::outputAt(const MultibodyState& x, devs::Time t, const dtss::Reached& r) const {
  const int nb = mech_.model.nbodies;
  if (r.timeEvent)
    for (std::size_t k = 0; k < x.winches.size(); ++k)
      if (x.winches[k].active && x.winches[k].tEnd <= t)
        event.add({ropes_[k]->name(), x.winches[k].actor, "done", ropes_[k]->unstretchedLength(t)});
  if (r.stateEvent <= 0) return;
  const int nr = static_cast<int>(ropes_.size());
  if (r.stateEvent >= nb + nr) {  // a rope went taut or slack: its length at that time
    const auto k = static_cast<std::size_t>(r.stateEvent - nb - nr);
    dynamics::forwardKinematics(mech_.model, scratch_, x.q, x.v);
    const forces::Stage stage{t, mech_.model, scratch_, x.q, x.v};
    // (direction of the crossing) => lengthening through L0: taut; shortening: slack
    const bool taut = ropes_[k]->lengthRate(stage) >= ropes_[k]->payoutRate(t);
    event.add({ropes_[k]->name(), "", taut ? "taut" : "slack", ropes_[k]->length(stage)});
    return;
  }
  if (r.stateEvent >= nb) {  // a rope passed its minimum breaking load: a warning event
    const auto k = static_cast<std::size_t>(r.stateEvent - nb);
    dynamics::forwardKinematics(mech_.model, scratch_, x.q, x.v);
    event.add({ropes_[k]->name(), "", "over_mbl",
               ropes_[k]->tension({t, mech_.model, scratch_, x.q, x.v})});
    return;
  }
  const auto i = static_cast<std::size_t>(r.stateEvent);
  event.add({mech_.jointNames[i], x.drives[i].actor, "reached", x.q[mech_.model.idxQ[r.stateEvent]]});
}

void MultibodyModel::onStateEvent(MultibodyState& x, devs::Time, int e) const {
  integrator_->reset();
  if (e > 0 && e < mech_.model.nbodies)
    x.drives[static_cast<std::size_t>(e)].reported = true;  // keeps holding the target
}

const dynamics::Data& MultibodyModel::kinematicsOf(const MultibodyState& x) const {
  if (viewState_ != &x || viewTime_ != state().tx) {
    dynamics::forwardKinematics(mech_.model, view_, x.q, x.v);
    viewState_ = &x;
    viewTime_ = state().tx;
  }
  return view_;
}

const Eigen::VectorXd& MultibodyModel::acceleration() const {
  // (committed state, set-points in force) => accelerations, cached by time
  const auto& s = state();
  if (accelTime_ != s.tx || accel_.size() != s.x.v.size()) {
    accel_.resize(s.x.v.size());
    current_ = &s.x;
    system_.acceleration(s.tx, s.x.q, s.x.v, accel_);
    accelTime_ = s.tx;
  }
  return accel_;
}

double MultibodyModel::energy() const { return energyOf(state().x, state().tx, view_); }

double MultibodyModel::energyOf(const MultibodyState& x, double t, dynamics::Data& d) const {
  // (one kinematics pass) => kinetic + gravity potential of every body, then stored energy
  const auto& m = mech_.model;
  dynamics::forwardKinematics(m, d, x.q, x.v);
  double e = 0.0;
  for (int i = 1; i < m.nbodies; ++i)
    e += 0.5 * d.V[i].dot(m.inertias[i].apply(d.V[i])) -
         m.inertias[i].mass * m.gravity.dot(d.X_WB[i].actPoint(m.inertias[i].com));
  const forces::Stage stage{t, m, d, x.q, x.v};
  for (const auto& r : ropes_) e += r->potentialEnergy(stage);
  for (const auto& q : equalizers_) e += q->potentialEnergy(stage);
  return e;
}

void MultibodyModel::channels(std::vector<Channel>& out) const {
  const auto& m = mech_.model;
  for (int i = 1; i < m.nbodies; ++i) {
    const std::string& j = mech_.jointNames[static_cast<std::size_t>(i)];
    const bool linear = m.joints[i].type == dynamics::JointType::Prismatic;
    for (int k = 0; k < m.jointNq[i] && m.jointNq[i] == m.jointNv[i]; ++k) {
      const std::string suffix = m.jointNq[i] == 1 ? "" : std::to_string(k);
      const int iq = m.idxQ[i] + k, iv = m.idxV[i] + k;
      out.push_back({j + ".q" + suffix, linear ? "m" : "rad", [this, iq] { return state().x.q[iq]; }});
      out.push_back({j + ".v" + suffix, linear ? "m/s" : "rad/s", [this, iv] { return state().x.v[iv]; }});
      out.push_back({j + ".a" + suffix, linear ? "m/s^2" : "rad/s^2",
                     [this, iv] { return acceleration()[iv]; }});
    }
    const std::string& b = m.names[i];
    const char* axes[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k)
      out.push_back({b + "." + axes[k], "m", [this, i, k] { return kinematicsOf(state().x).X_WB[i].p[k]; }});
    const char* angles[3] = {"roll", "pitch", "yaw"};
    for (int k = 0; k < 3; ++k)
      out.push_back({b + "." + angles[k], "rad", [this, i, k] {
                       return dynamics::bodyEulerAngles(kinematicsOf(state().x), i)[k];
                     }});
  }
  for (std::size_t r = 0; r < ropes_.size(); ++r) {
    const std::string& n = ropes_[r]->name();
    auto stage = [this] {
      const auto& s = state();
      return forces::Stage{s.tx, mech_.model, kinematicsOf(s.x), s.x.q, s.x.v};
    };
    out.push_back({n + ".tension", "N", [this, r, stage] { return ropes_[r]->tension(stage()); }});
    out.push_back({n + ".length", "m", [this, r, stage] { return ropes_[r]->length(stage()); }});
    out.push_back({n + ".unstretched_length", "m",
                   [this, r] { return ropes_[r]->unstretchedLength(state().tx); }});
  }
  for (std::size_t k = 0; k < equalizers_.size(); ++k) {
    const forces::Equalizer& e = *equalizers_[k];
    auto stage = [this] {
      const auto& s = state();
      return forces::Stage{s.tx, mech_.model, kinematicsOf(s.x), s.x.q, s.x.v};
    };
    out.push_back({e.name() + ".tension", "N", [&e, stage] { return e.tension(stage()); }});
    out.push_back({e.name() + ".length", "m", [&e, stage] { return e.length(stage()); }});
    for (int j = 0; j < e.branchCount(); ++j)
      out.push_back({e.name() + ".branch" + std::to_string(j) + ".length", "m",
                     [&e, stage, j] { return e.branchLength(stage(), j); }});
  }
  // (system-wide quantities) => under the model's own name when element names are paths
  const std::string own = opt_.elementPaths ? path() + "." : "";
  out.push_back({own + "energy", "J", [this] { return energy(); }});
  out.push_back({own + "work", "J", [this] { return state().x.work; }});
  out.push_back({own + "energy_balance", "J", [this] { return energy() - state().x.work; }});
  if (m.nc > 0)
    out.push_back({own + "loop_residual", "m", [this] {
                     return dynamics::loopResidualNorm(mech_.model, view_, state().x.q);
                   }});
}

}  // namespace yardsim::models
