#include "mechanics/build.hpp"
#include "models/multibody/multibody_model.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/crba.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/rnea.hpp"
#include "dynamics/rotation.hpp"
#include "dynamics/static_equilibrium.hpp"
#include "mechanics/providers.hpp"
#include "forces/current_load.hpp"
#include "forces/wind_load.hpp"
#include "models/numerical_error.hpp"

namespace yardsim::models {

using mechanics::BuiltMechanics;
using mechanics::MechanicsSpec;
using mechanics::Providers;
using mechanics::makeProviders;
using mechanics::missingEnvironment;

std::ostream& operator<<(std::ostream& os, const MultibodyState& s) {
  os << "q=[";
  for (Eigen::Index i = 0; i < s.q.size(); ++i) os << (i ? "," : "") << s.q[i];
  return os << "]";
}

namespace {
// (mechanics) => initial state; held joints (brakes) start with a drive holding q0
MultibodyState initialState(const BuiltMechanics& m) {
  const auto n = static_cast<std::size_t>(m.model.nbodies);
  MultibodyState x{m.q0, m.v0, std::vector<JointDrive>(n), std::vector<BodyLoad>(n),
                   std::vector<WinchJob>(m.ropes.size()), 0.0, std::vector<double>(m.ropes.size(), 0.0)};
  for (std::size_t i = 1; i < n; ++i)
    if (m.hold[i]) {
      const double q = m.q0[m.model.idxQ[i]];
      x.drives[i] = JointDrive{true, true, q, q, 0.0, 0.0, "", false};
    }
  return x;
}
}  // namespace

MultibodyModel::MultibodyModel(std::string name, BuiltMechanics mechanics,
                               const MultibodyOptions& options)
    : dtss::Atomic<MultibodyState>(std::move(name), initialState(mechanics), options.dt),
      mech_(std::move(mechanics)),
      opt_(options),
      directions_(static_cast<std::size_t>(mech_.model.nbodies) + 2 * mech_.ropes.size() + mech_.watches.size(),
                  dtss::Crossing::Rising),
      system_(mech_.model),
      view_(mech_.model),
      feedforward_(mech_.model),
      reaction_(mech_.model),
      scratch_(mech_.model),
      spForces_(mech_.model),
      spTau_(Eigen::VectorXd::Zero(mech_.model.nv)),
      prescribedMask_(static_cast<std::size_t>(mech_.model.nv), 0),
      prescribedAcc_(Eigen::VectorXd::Zero(mech_.model.nv)),
      accelScratch_(Eigen::VectorXd::Zero(mech_.model.nv)) {
  // (ropes) => their slack/taut transitions are events both ways (after the MBL watches)
  const auto slack = directions_.begin() + mech_.model.nbodies + static_cast<std::ptrdiff_t>(mech_.ropes.size());
  std::fill(slack, slack + static_cast<std::ptrdiff_t>(mech_.ropes.size()), dtss::Crossing::Both);
  // (rope and equalizer specs) => providers, evaluated at every stage
  Providers providers = makeProviders(mech_, mech_.model);
  ropes_ = std::move(providers.ropes);
  equalizers_ = std::move(providers.equalizers);
  for (const auto& l : mech_.loads) {
    bodyLoads_.push_back(std::make_unique<forces::BodyLoad>(l.name, mech_.model, mech_.model.bodyIndex(l.body), l.point,
                                                        l.bodyFrame ? forces::LoadFrame::Body : forces::LoadFrame::World));
    bodyLoads_.back()->setTable(l.series);
  }
  // (watches) => what each reads
  for (const auto& w : mech_.watches) {
    using K = WatchRef::Kind;
    WatchRef ref{K::Q, -1, 0};
    const int joint = jointBody(w.element), body = mech_.model.bodyIndex(w.element), rope = ropeIndex(w.element);
    const std::string& q = w.quantity;
    if (joint > 0 && (q == "q" || q == "v"))
      ref = {q == "q" ? K::Q : K::V, q == "q" ? mech_.model.idxQ[joint] : mech_.model.idxV[joint], 0};
    else if (body > 0 && (q == "x" || q == "y" || q == "z"))
      ref = {K::Position, body, q == "x" ? 0 : q == "y" ? 1 : 2};
    else if (body > 0 && (q == "roll" || q == "pitch" || q == "yaw"))
      ref = {K::Angle, body, q == "roll" ? 0 : q == "pitch" ? 1 : 2};
    else if (rope >= 0 && (q == "tension" || q == "length"))
      ref = {q == "tension" ? K::Tension : K::Length, rope, 0};
    else
      throw std::invalid_argument("watch '" + w.name + "': '" + w.element + "' has no quantity '" + q + "'");
    watchRefs_.push_back(ref);
  }
  // (floating-body specs) => hydrostatics on one sea, wind and current loads, damping
  const MechanicsSpec& env = mech_.environment;
  if (const std::string missing = missingEnvironment(env); !missing.empty())
    throw std::invalid_argument("multibody '" + this->name() + "': " + missing);
  forces::WaterProperties water = env.water;
  if (-mech_.model.gravity.z() > 0 && !env.hasWater) water.gravity = -mech_.model.gravity.z();
  const auto sea = std::make_shared<const forces::AiryWaves>(water, env.waves);
  auto bodyOf = [&](const std::string& n) { return mech_.model.bodyIndex(n); };
  for (const auto& h : env.hulls)
    hydros_.push_back(std::make_unique<forces::Hydrostatics>(h.name, mech_.model, bodyOf(h.body), *h.mesh, sea));
  if (env.wind) {
    const auto wind = std::make_shared<const forces::WindField>(*env.wind);
    for (const auto& w : env.windLoads)
      flows_.push_back(std::make_unique<forces::WindLoad>(w.name, mech_.model, bodyOf(w.body), w.point, w.areas,
                                                          w.coefficients, wind));
  }
  if (env.current) {
    const auto current = std::make_shared<const forces::CurrentField>(*env.current);
    for (const auto& c : env.currentLoads)
      flows_.push_back(std::make_unique<forces::CurrentLoad>(c.name, mech_.model, bodyOf(c.body), c.point, c.areas,
                                                             c.coefficients, current, water.density));
  }
  for (const auto& d : env.dampers)
    dampers_.push_back(std::make_unique<forces::LinearQuadraticDamping>(d.name, mech_.model, bodyOf(d.body),
                                                                        d.point, d.coefficients));
  for (auto& h : hydros_) loads_.push_back(h.get());
  for (auto& f : flows_) loads_.push_back(f.get());
  for (auto& d : dampers_) loads_.push_back(d.get());
  for (auto& b : bodyLoads_) loads_.push_back(b.get());
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
  forces_ = [this](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                   const dynamics::Data& d, dynamics::ExternalForces& f, Eigen::VectorXd& tau) {
    const forces::Stage stage{t, mech_.model, d, q, v};
    if (prescribedDofs(*current_) || system_.hybrid().any()) system_.prescribe(prescribedMask_, prescribedAcc_);
    for (auto& r : ropes_) r->evaluate(stage, f, tau);
    for (auto& e : equalizers_) e->evaluate(stage, f, tau);
    for (forces::ForceProvider* l : loads_) l->evaluate(stage, f, tau);
    setPointForces(t, q, v, d, f, tau);
  };
  system_.setForces(forces_);
  if (opt_.equilibrium) settle();
  // (initial state) => the rope tensions it starts with are the first peaks
  MultibodyState& x0 = mutableState().x;
  dynamics::forwardKinematics(mech_.model, scratch_, x0.q, x0.v);
  const forces::Stage stage{0.0, mech_.model, scratch_, x0.q, x0.v};
  for (std::size_t r = 0; r < ropes_.size(); ++r) x0.peakTension[r] = ropes_[r]->tension(stage);
  // (initial state) => the energy balance and the bound on its rise (multibody_blowup.cpp)
  balance0_ = energyOf(state().x, 0.0, scratch_);
  energyBound_ = opt_.energyGrowthLimit * energyScale();
}

void MultibodyModel::settle() {
  // (q0, forces at rest) => q0 moved to static equilibrium; holds follow their joints
  MultibodyState& x = mutableState().x;
  current_ = &x;
  const auto r = dynamics::solveStaticEquilibrium(mech_.model, system_, 0.0, x.q);
  current_ = nullptr;
  if (!r.converged)
    throw NumericalError("multibody '" + path() + "'", 0.0,
                         "no static equilibrium found from the given initial state (max |a| = " +
                             std::to_string(r.residual) + " after " + std::to_string(r.iterations) +
                             " Newton iterations)",
                         "start closer to equilibrium, hold the joints that have no stiffness, or "
                         "set equilibrium: false");
  x.v.setZero();
}

bool MultibodyModel::prescribedDofs(const MultibodyState& x) const {
  bool any = false;
  for (int i = 1; i < mech_.model.nbodies; ++i) {
    const bool on = x.drives[i].active && x.drives[i].prescribed;
    if (mech_.model.jointNv[i] == 1) prescribedMask_[static_cast<std::size_t>(mech_.model.idxV[i])] = on ? 1 : 0;
    any = any || on;
  }
  return any;
}

void MultibodyModel::prescribedVelocityStep(MultibodyState& x, const Eigen::VectorXd& dv) const {
  // (dv on the prescribed dofs) => every dof's velocity after the impulse; its work = the change
  // of kinetic energy
  const auto& m = mech_.model;
  const double before = dynamics::kineticEnergy(m, scratch_, x.q, x.v);
  prescribedDofs(x);
  system_.hybrid().setPrescribed(prescribedMask_);
  system_.hybrid().velocityStep(scratch_, x.q, x.v, dv);
  x.work += dynamics::kineticEnergy(m, scratch_, x.q, x.v) - before;
  powerState_ = nullptr;
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
    if (d.active && !d.prescribed) {
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
  for (const forces::ForceProvider* l : loads_) p += l->power(stage);
  // (drives, loads) => their forces at this state, and the power they deliver
  const MultibodyState* saved = current_;
  current_ = &x;
  spForces_.clear();
  spTau_.setZero();
  setPointForces(t, x.q, x.v, scratch_, spForces_, spTau_);
  p += spTau_.dot(x.v);
  if (prescribedDofs(x)) {  // (prescribed dofs) => the power of the effort that enforces them
    system_.acceleration(t, x.q, x.v, accelScratch_);
    p += system_.prescribedEffort().dot(x.v);
  }
  current_ = saved;
  for (int b = 1; b < m.nbodies; ++b) p += spForces_.inBodyFrame(scratch_, b).dot(scratch_.V[b]);
  return p;
}

void MultibodyModel::advance(MultibodyState& x, devs::Time t, devs::Time dt) const {
  // (power at both ends of the step) => the work of non-conservative forces, trapezoidal; the
  // power at the start is the one computed at the end of the previous step when nothing changed
  for (auto& l : bodyLoads_) l->setStepStart(t);
  const double p0 = powerState_ == &x && powerTime_ == t ? power_ : nonConservativePower(x, t);
  powerState_ = nullptr;
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
  if (x.q.allFinite() && x.v.allFinite()) {
    const double p1 = nonConservativePower(x, t + dt);
    x.work += 0.5 * dt * (p0 + p1);
    // (end-of-step kinematics in scratch_) => running peak of every rope's tension
    const forces::Stage stage{t + dt, mech_.model, scratch_, x.q, x.v};
    for (std::size_t r = 0; r < ropes_.size(); ++r)
      x.peakTension[r] = std::max(x.peakTension[r], ropes_[r]->tension(stage));
    powerState_ = &x;
    powerTime_ = t + dt;
    power_ = p1;
  }
  checkBlowUp(x, t + dt);
}

void MultibodyModel::applyInput(MultibodyState& x, devs::Time t) const {
  powerState_ = nullptr;  // set-points change the forces
  integrator_->reset();  // the forces change here: no history across it
  for (const SetPoint& s : setpoint.values()) {
    switch (s.kind) {
      case SetPoint::Kind::JointTarget: {
        const int i = jointBody(s.element);
        if (i < 0 || mech_.model.jointNv[i] != 1)
          throw devs::SimulationError("multibody '" + path() + "': set-point from '" + s.actor +
                                      "' names '" + s.element + "', which is not a 1-dof joint here");
        const double q = x.q[mech_.model.idxQ[i]];
        const bool wasPrescribed = x.drives[i].active && x.drives[i].prescribed;
        x.drives[i] = JointDrive{true, false, q, s.target, std::abs(s.speed), t, s.actor, s.prescribed};
        if (s.prescribed && mech_.model.nc > 0)
          throw devs::SimulationError("multibody '" + path() + "': prescribed motion from '" + s.actor +
                                      "' on '" + s.element + "' needs a system without loop closures; "
                                      "use mode: servo");
        if (s.prescribed || wasPrescribed) {
          // (ramp start) => the joint takes the ramp's speed at once (servo: keeps its own)
          const int iv = mech_.model.idxV[i];
          accelScratch_.setZero();
          if (s.prescribed) accelScratch_[iv] = (s.target >= q ? 1.0 : -1.0) * std::abs(s.speed) - x.v[iv];
          if (s.prescribed && s.target == q) accelScratch_[iv] = -x.v[iv];
          prescribedVelocityStep(x, accelScratch_);
        }
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
  for (const auto& d : x.drives)
    if (d.active && d.prescribed && !d.reported && d.tEnd() > t) next = std::min(next, d.tEnd());
  for (const auto& l : bodyLoads_) next = std::min(next, l->nextBreak(t));  // kinks and jumps
  return next;
}

void MultibodyModel::onTimeEvent(MultibodyState& x, devs::Time t) const {
  powerState_ = nullptr;
  // (prescribed ramps ending now) => locked exactly at their targets
  for (int i = 1; i < mech_.model.nbodies; ++i) {
    JointDrive& d = x.drives[i];
    if (!d.active || !d.prescribed || d.reported || d.tEnd() > t) continue;
    const int iq = mech_.model.idxQ[i], iv = mech_.model.idxV[i];
    x.q[iq] = d.target;
    accelScratch_.setZero();
    accelScratch_[iv] = -x.v[iv];
    prescribedVelocityStep(x, accelScratch_);
    d.reported = true;
  }
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
    if (!d.active || d.reported || d.prescribed) {
      g[i] = -1.0;
      continue;
    }
    const double dir = d.target >= d.start ? 1.0 : -1.0;
    g[i] = dir * (x.q[mech_.model.idxQ[i]] - d.target) + opt_.driveTolerance;
  }
  // (ropes with a minimum breaking load) => > 0 once the tension exceeds it
  if (ropes_.empty() && watchRefs_.empty()) return;
  dynamics::forwardKinematics(mech_.model, scratch_, x.q, x.v);
  const forces::Stage stage{t, mech_.model, scratch_, x.q, x.v};
  const std::size_t nb = static_cast<std::size_t>(mech_.model.nbodies), nr = ropes_.size();
  for (std::size_t r = 0; r < nr; ++r) {
    const auto& mbl = ropes_[r]->properties().breakingLoad;
    g[nb + r] = mbl ? ropes_[r]->tension(stage) - *mbl : -1.0;
    // (rope) => its stretch: > 0 taut, < 0 slack
    g[nb + nr + r] = ropes_[r]->length(stage) - ropes_[r]->unstretchedLength(t);
  }
  // (watches) => > 0 once the quantity is past its threshold in the watched direction
  for (std::size_t w = 0; w < watchRefs_.size(); ++w) {
    const auto& spec = mech_.watches[w];
    const double value = watched(w, x, t);
    g[nb + 2 * ropes_.size() + w] = spec.above ? value - spec.threshold : spec.threshold - value;
  }
}

double MultibodyModel::watched(std::size_t w, const MultibodyState& x, double t) const {
  const WatchRef& r = watchRefs_[w];
  using K = WatchRef::Kind;
  switch (r.kind) {
    case K::Q: return x.q[r.index];
    case K::V: return x.v[r.index];
    case K::Position: return scratch_.X_WB[static_cast<std::size_t>(r.index)].p[r.axis];
    case K::Angle: return dynamics::bodyEulerAngles(scratch_, r.index)[r.axis];
    case K::Tension:
      return ropes_[static_cast<std::size_t>(r.index)]->tension({t, mech_.model, scratch_, x.q, x.v});
    case K::Length:
      return ropes_[static_cast<std::size_t>(r.index)]->length({t, mech_.model, scratch_, x.q, x.v});
  }
  return 0.0;
}

void MultibodyModel::outputAt(const MultibodyState& x, devs::Time t, const dtss::Reached& r) const {
  const int nb = mech_.model.nbodies;
  if (r.timeEvent) {
    for (std::size_t k = 0; k < x.winches.size(); ++k)
      if (x.winches[k].active && x.winches[k].tEnd <= t)
        event.add({ropes_[k]->name(), x.winches[k].actor, "done", ropes_[k]->unstretchedLength(t)});
    for (int i = 1; i < nb; ++i) {
      const JointDrive& d = x.drives[i];
      if (d.active && d.prescribed && !d.reported && d.tEnd() <= t)
        event.add({mech_.jointNames[i], d.actor, "reached", d.target});
    }
  }
  if (r.stateEvent <= 0) return;
  const int nr = static_cast<int>(ropes_.size());
  if (r.stateEvent >= nb + 2 * nr) {  // a watched quantity crossed
    const auto w = static_cast<std::size_t>(r.stateEvent - nb - 2 * nr);
    dynamics::forwardKinematics(mech_.model, scratch_, x.q, x.v);
    event.add({mech_.watches[w].name, "", "crossed", watched(w, x, t)});
    return;
  }
  if (r.stateEvent >= nb + nr) {  // a rope went slack or snapped taut: its length then
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
  powerState_ = nullptr;
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

const std::vector<dynamics::Force>& MultibodyModel::jointForces() const {
  // (committed state, its accelerations, every force) => RNEA's joint forces, cached by time
  const auto& s = state();
  if (reactionTime_ != s.tx) {
    const Eigen::VectorXd& a = acceleration();
    current_ = &s.x;
    spForces_.clear();
    spTau_.setZero();
    dynamics::forwardKinematics(mech_.model, scratch_, s.x.q, s.x.v);
    forces_(s.tx, s.x.q, s.x.v, scratch_, spForces_, spTau_);
    dynamics::rnea(mech_.model, reaction_, s.x.q, s.x.v, a, &spForces_);
    reactionTime_ = s.tx;
  }
  return reaction_.F_W;
}

double MultibodyModel::energy() const { return energyOf(state().x, state().tx, view_); }

double MultibodyModel::energyOf(const MultibodyState& x, double t, dynamics::Data& d) const {
  // (one kinematics pass) => kinetic + gravity potential of every body, then stored energy
  const auto& m = mech_.model;
  dynamics::forwardKinematics(m, d, x.q, x.v);
  double e = 0.0;
  for (int i = 1; i < m.nbodies; ++i) {
    e += dynamics::bodyKineticEnergy(m, i, d.V[i]) -  // with the fluid's share (added mass)
         m.inertias[i].mass * m.gravity.dot(d.X_WB[i].actPoint(m.inertias[i].com));
  }
  const forces::Stage stage{t, m, d, x.q, x.v};
  for (const auto& r : ropes_) e += r->potentialEnergy(stage);
  for (const auto& q : equalizers_) e += q->potentialEnergy(stage);
  for (const forces::ForceProvider* l : loads_) e += l->potentialEnergy(stage);
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
    if (m.nc == 0 && m.jointNv[i] < 6)  // (joint) => magnitude of the force it transmits
      out.push_back({j + ".reaction", "N", [this, i] { return jointForces()[i].tail<3>().norm(); }});
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
    out.push_back({n + ".peak_tension", "N", [this, r] { return state().x.peakTension[r]; }});
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
  for (std::size_t k = 0; k < bodyLoads_.size(); ++k) {
    const forces::BodyLoad& l = *bodyLoads_[k];
    const char* comps[6] = {"fx", "fy", "fz", "mx", "my", "mz"};
    for (int c = 0; c < 6; ++c)
      out.push_back({l.name() + "." + comps[c], c < 3 ? "N" : "N m", [this, &l, c] {
                       const auto s = l.at(state().tx);
                       return c < 3 ? s.force[c] : s.moment[c - 3];
                     }});
  }
  floatingChannels(out);
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

void MultibodyModel::replayBodies(Replay& out) const {
  // (bodies, ropes and equalizer branches) => replay bodies named by path, ropes as polylines
  const auto& m = mech_.model;
  const std::string prefix = opt_.elementPaths ? "" : path() + ".";
  const auto first = static_cast<int>(out.bodies.size());
  for (int i = 1; i < m.nbodies; ++i) {
    const auto& in = m.inertias[static_cast<std::size_t>(i)];
    out.bodies.push_back(replayShape(mech_.visuals[static_cast<std::size_t>(i)], in.mass, in.com,
                                     in.inertiaCom));
    out.bodies.back().name = prefix + m.names[static_cast<std::size_t>(i)];
  }
  auto point = [&](const MechanicsSpec::Point& p) {
    const int b = m.bodyIndex(p.first);
    return std::pair{b > 0 ? first + b - 1 : -1, p.second};
  };
  for (const auto& r : mech_.ropes) {
    out.ropes.push_back({prefix + r.name, {}});
    for (const auto& p : r.path) out.ropes.back().points.push_back(point(p));
  }
  for (const auto& e : mech_.equalizers)
    for (std::size_t j = 0; j < e.branches.size(); ++j) {
      out.ropes.push_back({prefix + e.name + ".branch" + std::to_string(j), {point(e.sheave)}});
      for (const auto& p : e.branches[j]) out.ropes.back().points.push_back(point(p));
    }
}

void MultibodyModel::replayFrame(Replay& out, std::size_t firstBody) const {
  // (committed state) => each body's world pose, quaternions kept on one hemisphere frame to frame
  const dynamics::Data& d = kinematicsOf(state().x);
  for (int i = 1; i < mech_.model.nbodies; ++i) {
    ReplayBody& b = out.bodies[firstBody + static_cast<std::size_t>(i - 1)];
    const dynamics::Transform& X = d.X_WB[static_cast<std::size_t>(i)];
    double q[4];  // w, x, y, z
    dynamics::matrixToQuaternion(X.R, q);
    std::array<float, 4> r{static_cast<float>(q[1]), static_cast<float>(q[2]),
                           static_cast<float>(q[3]), static_cast<float>(q[0])};
    if (!b.rotation.empty()) {
      const auto& prev = b.rotation.back();
      if (prev[0] * r[0] + prev[1] * r[1] + prev[2] * r[2] + prev[3] * r[3] < 0)
        for (float& c : r) c = -c;
    }
    b.translation.push_back({static_cast<float>(X.p[0]), static_cast<float>(X.p[1]),
                             static_cast<float>(X.p[2])});
    b.rotation.push_back(r);
  }
}

forces::Stage MultibodyModel::committedStage() const {
  const auto& s = state();
  return forces::Stage{s.tx, mech_.model, kinematicsOf(s.x), s.x.q, s.x.v};
}

void MultibodyModel::floatingChannels(std::vector<Channel>& out) const {
  const char* xyz[3] = {"x", "y", "z"};
  for (const auto& hp : hydros_) {
    const forces::Hydrostatics* h = hp.get();
    const std::string& n = h->name();
    auto rep = [this, h]() -> const forces::HydrostaticReport& { return h->report(committedStage()); };
    out.push_back({n + ".draft", "m", [rep] { return rep().draft; }});
    out.push_back({n + ".heel", "rad", [rep] { return rep().heel; }});
    out.push_back({n + ".trim", "rad", [rep] { return rep().trim; }});
    out.push_back({n + ".displacement", "kg", [rep] { return rep().displacement; }});
    out.push_back({n + ".volume", "m^3", [rep] { return rep().submerged.volume; }});
    out.push_back({n + ".waterplane_area", "m^2", [rep] { return rep().submerged.waterplaneArea; }});
    out.push_back({n + ".gm_t", "m", [rep] { return rep().gmTransverse; }});
    out.push_back({n + ".gm_l", "m", [rep] { return rep().gmLongitudinal; }});
    // (force, moment about the world origin) => world axes, moment about the body's centre of mass
    const int b = h->body();
    for (int k = 0; k < 3; ++k)
      out.push_back({n + ".f" + xyz[k], "N", [rep, k] { return rep().submerged.force[k]; }});
    for (int k = 0; k < 3; ++k)
      out.push_back({n + ".m" + xyz[k], "N m", [this, rep, b, k] {
                       const auto& r = rep().submerged;
                       const auto& I = mech_.model.inertias[b];
                       const dynamics::Vector3 G = kinematicsOf(state().x).X_WB[b].actPoint(I.com);
                       return (r.moment - G.cross(r.force))[k];
                     }});
    out.push_back({n + ".wave_elevation", "m", [this, h, b] {
                     const dynamics::Vector3 p = kinematicsOf(state().x).X_WB[b].p;
                     return h->sea().elevation(p.x(), p.y(), state().tx);
                   }});
  }
  for (const auto& fp : flows_) {
    const forces::FlowLoad* f = fp.get();
    auto load = [this, f] { return f->load(committedStage()); };
    out.push_back({f->name() + ".fx", "N", [load] { return load().force.x(); }});
    out.push_back({f->name() + ".fy", "N", [load] { return load().force.y(); }});
    out.push_back({f->name() + ".mz", "N m", [load] { return load().yawMoment; }});
    out.push_back({f->name() + ".speed", "m/s", [load] { return load().speed; }});
    out.push_back({f->name() + ".angle", "rad", [load] { return load().angle; }});
  }
  const char* dof[6] = {"fx", "fy", "fz", "mx", "my", "mz"};
  for (const auto& dp : dampers_) {
    const forces::LinearQuadraticDamping* d = dp.get();
    for (std::size_t k = 0; k < 6; ++k)
      out.push_back({d->name() + "." + dof[k], k < 3 ? "N" : "N m",
                     [this, d, k] { return d->load(committedStage())[k]; }});
  }
}

}  // namespace yardsim::models
