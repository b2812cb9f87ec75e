#include "models/multibody/multibody_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "devs/general_text.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/rnea.hpp"
#include "dynamics/static_equilibrium.hpp"
#include "mechanics/energy.hpp"
#include "mechanics/follow_mass.hpp"
#include "mechanics/shared_stage.hpp"
#include "mechanics/stage.hpp"
#include "models/multibody/same_bits.hpp"
#include "models/numerical_error.hpp"

namespace yardsim::models {

namespace {
// (state) => the most chars its text "q=[...]" takes
std::size_t stateTextMost(const MultibodyState& s) {
  return 4 + static_cast<std::size_t>(s.q.size()) * (devs::kGeneral6TextSize + 1);
}

// (state, room for stateTextMost(s) chars at p) => "q=[...]" written at p; the end after it
char* writeStateText(char* p, const MultibodyState& s) {
  std::memcpy(p, "q=[", 3);
  p += 3;
  for (Eigen::Index i = 0; i < s.q.size(); ++i) {
    if (i) *p++ = ',';
    p = devs::writeGeneral6(p, s.q[i]);  // "%g"
  }
  *p++ = ']';
  return p;
}
}  // namespace

void appendStateText(std::string& out, const MultibodyState& s) {
  // (state) => its text written straight into out: room for every coordinate first, then out cut
  // to what was written
  const std::size_t at = out.size();
  out.resize(at + stateTextMost(s));
  char* const end = writeStateText(out.data() + at, s);
  out.resize(static_cast<std::size_t>(end - out.data()));
}

std::ostream& operator<<(std::ostream& os, const MultibodyState& s) {
  std::string text;
  appendStateText(text, s);
  return os << text;
}

namespace {
// (mechanics) => initial state; held joints (brakes) start with a drive holding q0
MultibodyState initialState(const mechanics::BuiltMechanics& m) {
  const auto n = static_cast<std::size_t>(m.model.nbodies);
  const std::size_t ropes = m.ropes.size() + m.equalizers.size();  // (System::ropes())
  MultibodyState x{m.q0,
                   m.v0,
                   {std::vector<mechanics::JointDrive>(n), std::vector<mechanics::ActorLoad>(n),
                    std::vector<mechanics::WinchJob>(ropes)},
                   0.0,
                   std::vector<double>(ropes, 0.0),
                   std::vector<double>(ropes, 0.0)};
  for (std::size_t i = 1; i < n; ++i)
    if (m.hold[i]) {
      const double q = m.q0[m.model.idxQ[i]];
      x.setPoints.drives[i] = mechanics::JointDrive{true, true, q, q, 0.0, 0.0, "", false};
    }
  return x;
}

// (options) => with the servo bandwidth resolved: min(10, 0.1/dt) when not given
MultibodyOptions resolved(MultibodyOptions o) {
  if (o.driveBandwidth <= 0.0) o.driveBandwidth = std::min(10.0, 0.1 / o.dt);
  o.integrator.dt = o.dt;
  if (!o.projectLoops && o.integrator.loops == dynamics::LoopStabilization::Projection)
    o.integrator.loops = dynamics::LoopStabilization::None;
  return o;
}

std::string unbalancedText(const mechanics::System& system, const Eigen::VectorXd& q,
                           const std::vector<dynamics::UnbalancedDirection>& u) {
  // (directions without stiffness, their forces, the initial q where the search found them) =>
  // "hull: sway (y) has no stiffness and a net force of 12.3 kN (along the body's own y axis,
  // world direction [+1, +0, +0] at the initial pose); ..." (body; joint name beside a joint
  // that is not free). A free or spherical joint's directions are its body's own axes (they
  // turn with it); the others' are the joint's axes.
  const auto& m = system.model();
  dynamics::Data kin(m);
  dynamics::forwardKinematics(m, kin, q);
  std::string out;
  for (const auto& d : u) {
    const int body = m.dofBody[static_cast<std::size_t>(d.dof)];
    const auto type = m.joints[static_cast<std::size_t>(body)].type;
    const int k = d.dof - m.idxV[static_cast<std::size_t>(body)];
    const bool rotation = dynamics::jointDirectionIsRotation(type, k);
    const std::string& joint = system.description().jointNames[static_cast<std::size_t>(body)];
    char force[64];
    std::snprintf(force, sizeof force, "%.3g %s", std::abs(d.force) / 1e3, rotation ? "kN m" : "kN");
    std::string frame;
    if (type == dynamics::JointType::Free || type == dynamics::JointType::Spherical) {
      // (the body's axis of that direction, the force's sign) => its world direction now
      const int axis = k % 3;
      const dynamics::Vector3 w =
          (d.force < 0 ? -1.0 : 1.0) * kin.X_WB[static_cast<std::size_t>(body)].R.col(axis);
      auto shown = [](double c) { return std::round(c * 1e3) / 1e3 + 0.0; };  // no -0.000
      char text[160];
      std::snprintf(text, sizeof text,
                    " (%s the body's own %c axis, world direction [%+.3f, %+.3f, %+.3f] at the "
                    "initial pose)",
                    rotation ? "about" : "along", "xyz"[axis], shown(w[0]), shown(w[1]),
                    shown(w[2]));
      frame = text;
    }
    out += (out.empty() ? "" : "; ") + m.names[static_cast<std::size_t>(body)] + ": " +
           std::string(dynamics::jointDirectionName(type, k)) +
           (type == dynamics::JointType::Free || joint.empty() ? "" : " of joint '" + joint + "'") +
           " has no stiffness and a net " + (rotation ? "moment" : "force") + " of " + force +
           frame;
  }
  return out;
}
}  // namespace

MultibodyModel::MultibodyModel(std::string name, mechanics::BuiltMechanics mechanics,
                               const MultibodyOptions& options)
    : dtss::Atomic<MultibodyState>(std::move(name), initialState(mechanics), options.dt),
      opt_(resolved(options)),
      system_(std::move(mechanics), {opt_.driveBandwidth, opt_.driveMaxEffort, opt_.driveTolerance},
              this->name()),
      events_(mechanics::eventTable(system_)),
      ws_(system_) {
  // (event table) => the directions the stepper locates
  for (const auto& e : events_)
    directions_.push_back(e.bothWays ? dtss::Crossing::Both : dtss::Crossing::Rising);
  // (options) => the integrator at step dt; loops kept closed as its spec says
  const auto& model = system_.model();
  ws_.integrator = dynamics::makeIntegrator(opt_.integrator, model);
  if (model.nc > 0) dynamics::configureLoopStabilization(opt_.integrator, ws_.data.kernel);
  mechanics::connectStage(system_, ws_.data);
  ws_.shareStage = mechanics::stageShareable(system_, ws_.data);
  // (initial state) => a force provider that gives up on it (a catenary line whose solve does
  // not converge at t = 0) is a numerical failure of the run (exit 2), not an internal error
  try {
    if (opt_.equilibrium) settle();
    // (initial state) => each winch as it starts (the ropes', then those of ropes with mass); the
    // rope tensions are the first peaks
    MultibodyState& x0 = mutableState().x;
    x0.setPoints.winches.resize(system_.winches().size());
    for (std::size_t r = 0; r < system_.winches().size(); ++r)
      x0.setPoints.winches[r].pieces = system_.winches()[r].winch->history();
    const dynamics::Data& kin0 = ws_.data.scratchKinematics(system_, x0.q, x0.v);
    const forces::Stage stage{0.0, model, kin0, x0.q, x0.v};
    for (std::size_t r = 0; r < system_.ropes().size(); ++r)
      x0.peakTension[r] = system_.ropes()[r]->tension(stage);
    initialTension_ = x0.peakTension;
    // (initial state) => the energy balance and the bound on its rise (mechanics/blowup.hpp)
    limits_.balance0 = mechanics::energyAfterKinematics(
        system_, ws_.data, ws_.data.scratchKinematics(system_, x0.q, x0.v), x0.q, x0.v, 0.0);
    limits_.energyBound =
        opt_.energyGrowthLimit * mechanics::energyScale(system_, ws_.data, x0.q, x0.v);
    limits_.loopResidualLimit = opt_.loopResidualLimit;
    limits_.projectLoops = opt_.projectLoops;
    limits_.method = opt_.integrator.method;
    limits_.dt = opt_.dt;
  } catch (const devs::SimulationError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw NumericalError("multibody '" + path() + "'", 0.0, e.what(),
                         "check the initial positions of the bodies and of what holds them");
  }
}

void MultibodyModel::settle() {
  // (q0, forces at rest) => q0 moved to static equilibrium; holds follow their joints
  MultibodyState& x = mutableState().x;
  ws_.data.setPoints = &x.setPoints;
  const Eigen::VectorXd q0 = x.q;  // where the search starts and names what it cannot balance
  const auto r = dynamics::solveStaticEquilibrium(system_.model(), ws_.data.kernel, 0.0, x.q);
  ws_.data.setPoints = nullptr;
  if (!r.converged) {
    const std::string search = "max |a| = " + std::to_string(r.residual) + " after " +
                               std::to_string(r.iterations) + " Newton iterations";
    if (r.unbalanced.empty())
      throw NumericalError("multibody '" + path() + "'", 0.0,
                           "no static equilibrium found from the given initial state (" + search + ")",
                           "start closer to equilibrium, hold the joints that have no stiffness, or "
                           "set equilibrium: false");
    throw NumericalError(
        "multibody '" + path() + "'", 0.0,
        "no static equilibrium: " + unbalancedText(system_, q0, r.unbalanced) + " (" + search + ")",
        "add a mooring, a rope or a held joint there, or set equilibrium: false");
  }
  x.v.setZero();
}

void MultibodyModel::prescribedVelocityStep(MultibodyState& x, const Eigen::VectorXd& dv,
                                            double t) const {
  // (dv on the prescribed dofs) => every dof's velocity after the impulse; its work = the change
  // of kinetic energy
  const auto& m = system_.model();
  auto& d = ws_.data;
  d.scratchWritten();  // (the impulse writes scratch)
  // (q, t) => the added mass at this pose and time where it follows the draft or a winch (the
  // impulse's mass matrix and both kinetic energies read it), not whatever the scratch held last
  if (mechanics::followsMass(system_)) {
    dynamics::forwardKinematics(m, d.scratch, x.q);
    mechanics::followMass(system_, t, d.scratch, d.scratch);
  }
  const double before = dynamics::kineticEnergy(m, d.scratch, x.q, x.v);
  mechanics::prescribedDofs(system_, d, x.setPoints);
  d.kernel.hybrid().setPrescribed(d.prescribedMask);
  d.kernel.hybrid().velocityStep(d.scratch, x.q, x.v, dv);
  x.work += dynamics::kineticEnergy(m, d.scratch, x.q, x.v) - before;
  dropStepCaches();
}

void MultibodyModel::advance(MultibodyState& x, devs::Time t, devs::Time dt) const {
  // (power at both ends of the step) => the work of non-conservative forces, trapezoidal; the
  // power at the start is the one computed at the end of the previous step when nothing changed
  auto& d = ws_.data;
  d.stepStart = t;  // (body loads) => a stage at the step's end sees the value before a jump
  const double p0 = ws_.powerState == &x && ws_.powerTime == t
                        ? ws_.power
                        : mechanics::nonConservativePower(system_, d, x.setPoints, x.q, x.v, t);
  ws_.powerState = nullptr;
  d.setPoints = &x.setPoints;
  double time = t;
  // (a stage that may be shared) => the kernel keeps the step's first stage: at (t, x.q, x.v)
  // with these set-points, it is the committed state's stage when x is committed at t
  if (ws_.shareStage && ws_.stageRead) {
    d.kernel.keepNextStage();
    ws_.keptStepStart = t;
  }
  try {
    ws_.integrator->step(d.kernel, time, x.q, x.v, dt);
  } catch (const devs::SimulationError&) {
    d.kernel.stopKeeping();
    throw;
  } catch (const std::runtime_error& e) {  // the kernel or a force provider gave up: its diagnosis
    d.kernel.stopKeeping();
    throw NumericalError("multibody '" + path() + "'", t, e.what(),
                         "a smaller dt, softer drives (bandwidth), or an implicit integrator");
  }
  d.kernel.stopKeeping();
  if (x.q.allFinite() && x.v.allFinite()) {
    const double p1 = mechanics::nonConservativePower(system_, d, x.setPoints, x.q, x.v, t + dt);
    x.work += 0.5 * dt * (p0 + p1);
    // (end-of-step kinematics, computed for the power) => running peak of every rope's tension
    const forces::Stage stage{t + dt, system_.model(), d.scratchKinematics(system_, x.q, x.v), x.q,
                              x.v};
    for (std::size_t r = 0; r < system_.ropes().size(); ++r)
      if (const double tension = system_.ropes()[r]->tension(stage); tension > x.peakTension[r]) {
        x.peakTension[r] = tension;
        x.peakTime[r] = t + dt;
      }
    ws_.powerState = &x;
    ws_.powerTime = t + dt;
    ws_.power = p1;
  }
  checkBlowUp(x, t + dt);
}

void MultibodyModel::checkBlowUp(const MultibodyState& x, double t) const {
  try {
    const double energy = mechanics::checkBlowUp(system_, ws_.data, x.q, x.v, x.work, t, limits_);
    if (!ws_.shareStage || !ws_.energyRead) return;
    // (energy at (t, q, v)) => kept in the slot used less recently
    ws_.lastStepEnd = 1 - ws_.lastStepEnd;
    auto& end = ws_.stepEnds[ws_.lastStepEnd];
    end.valid = true;
    end.t = t;
    end.energy = energy;
    end.q = x.q;
    end.v = x.v;
  } catch (const mechanics::BlowUp& b) {
    throw NumericalError("multibody '" + path() + "'" + b.element, t, b.what(), b.suggestion);
  }
}

void MultibodyModel::applyInput(MultibodyState& x, devs::Time t) const {
  dropStepCaches();          // set-points change the forces
  ws_.integrator->reset();   // the forces change here: no history across it
  const auto& model = system_.model();
  auto& sp = x.setPoints;
  for (const SetPoint& s : setpoint.values()) {
    switch (s.kind) {
      case SetPoint::Kind::JointTarget: {
        const int i = system_.jointBody(s.element);
        if (i < 0 || model.jointNv[i] != 1)
          throw devs::SimulationError("multibody '" + path() + "': set-point from '" + s.actor +
                                      "' names '" + s.element +
                                      "', which is not a 1-dof joint here");
        const bool wasPrescribed = sp.drives[i].active && sp.drives[i].prescribed;
        const int iv = model.idxV[i];
        const double step = mechanics::startDrive(sp, i, x.q[model.idxQ[i]], x.v[iv], s.target,
                                                  s.speed, t, s.actor, s.prescribed);
        if (s.prescribed && model.nc > 0)
          throw devs::SimulationError("multibody '" + path() + "': prescribed motion from '" +
                                      s.actor + "' on '" + s.element +
                                      "' needs a system without loop closures; "
                                      "use mode: servo");
        if (s.prescribed || wasPrescribed) {  // (velocity step of the joint) => an impulse
          Eigen::VectorXd& dv = ws_.data.accelScratch;
          dv.setZero();
          dv[iv] = step;
          prescribedVelocityStep(x, dv, t);
        }
        break;
      }
      case SetPoint::Kind::ActorLoad: {
        const int i = model.bodyIndex(s.element);
        if (i <= 0)
          throw devs::SimulationError("multibody '" + path() + "': load from '" + s.actor +
                                      "' names unknown body '" + s.element + "'");
        sp.loads[i].force = Eigen::Vector3d(s.force[0], s.force[1], s.force[2]);
        sp.loads[i].moment = Eigen::Vector3d(s.moment[0], s.moment[1], s.moment[2]);
        break;
      }
      case SetPoint::Kind::WinchPayout: {
        const int r = system_.winchIndex(s.element);
        if (r < 0 || !(s.speed > 0))
          throw devs::SimulationError("multibody '" + path() + "': winch set-point from '" +
                                      s.actor + "' names '" + s.element +
                                      "', which is not a rope here, or has no positive speed");
        forces::Winch& winch = *system_.winches()[static_cast<std::size_t>(r)].winch;
        mechanics::startWinch(sp, r, winch, t, s.amount, {s.speed, s.accel, s.jerk}, s.actor);
        break;
      }
      case SetPoint::Kind::WinchStop: {  // (an actor stopped) => the winch at rest from t on
        const int r = system_.winchIndex(s.element);
        if (r < 0)
          throw devs::SimulationError("multibody '" + path() + "': winch stop from '" + s.actor +
                                      "' names '" + s.element + "', which is not a rope here");
        forces::Winch& winch = *system_.winches()[static_cast<std::size_t>(r)].winch;
        winch.dropPlannedAfter(t);
        winch.setPayoutRate(t, 0.0);
        auto& job = sp.winches[static_cast<std::size_t>(r)];
        job.active = false;
        job.pieces = winch.history();
        break;
      }
    }
  }
}

devs::Time MultibodyModel::nextTimeEvent(const MultibodyState& x, devs::Time t) const {
  return mechanics::nextTimeEvent(system_, x.setPoints, t);
}

void MultibodyModel::onTimeEvent(MultibodyState& x, devs::Time t) const {
  dropStepCaches();
  const auto& model = system_.model();
  // (prescribed ramps ending now) => locked exactly at their targets
  for (int i = 1; i < model.nbodies; ++i) {
    mechanics::JointDrive& d = x.setPoints.drives[i];
    if (!d.active || !d.prescribed || d.reported || d.tEnd() > t) continue;
    const int iq = model.idxQ[i], iv = model.idxV[i];
    x.q[iq] = d.target;
    Eigen::VectorXd& dv = ws_.data.accelScratch;
    dv.setZero();
    dv[iv] = -x.v[iv];
    prescribedVelocityStep(x, dv, t);
    d.reported = true;
  }
  ws_.integrator->reset();
  // (winch jobs ending now) => winches stopped
  auto& winches = x.setPoints.winches;
  for (std::size_t r = 0; r < winches.size(); ++r)
    if (winches[r].active && winches[r].tEnd <= t) {
      forces::Winch& winch = *system_.winches()[r].winch;
      winch.setPayoutRate(t, 0.0);
      winches[r].active = false;
      winches[r].pieces = winch.history();
    }
}

void MultibodyModel::eventFunctions(const MultibodyState& x, devs::Time t,
                                    std::span<double> g) const {
  // (x, t) => g, from the last evaluation when (t, q, v) are the same bit for bit and the
  // set-points have not changed since (dropStepCaches), else computed and kept
  auto& memo = ws_.events;
  if (memo.valid && t == memo.t && memo.g.size() == g.size() && sameBits(x.q, memo.q) &&
      sameBits(x.v, memo.v)) {
    std::copy(memo.g.begin(), memo.g.end(), g.begin());
    return;
  }
  memo.valid = false;
  mechanics::eventFunctions(system_, ws_.data, x.setPoints, x.q, x.v, t, g);
  memo.t = t;
  memo.q = x.q;
  memo.v = x.v;
  memo.g.assign(g.begin(), g.end());
  memo.valid = true;
}

void MultibodyModel::outputAt(const MultibodyState& x, devs::Time t, const dtss::Reached& r) const {
  // (time events due, the state event that fired) => their reports on the event port
  std::vector<mechanics::EventReport> reports;
  if (r.timeEvent) mechanics::reportTimeEvents(system_, x.setPoints, x.q, t, reports);
  if (r.stateEvent > 0)
    reports.push_back(mechanics::reportStateEvent(system_, ws_.data, x.setPoints, x.q, x.v, t,
                                                  events_[static_cast<std::size_t>(r.stateEvent)]));
  for (const int j : r.coincident)
    if (j > 0)
      reports.push_back(mechanics::reportStateEvent(system_, ws_.data, x.setPoints, x.q, x.v, t,
                                                    events_[static_cast<std::size_t>(j)]));
  for (const auto& e : reports) event.add({e.element, e.actor, e.kind, e.value, e.detail});
}

void MultibodyModel::onStateEvent(MultibodyState& x, devs::Time, int e) const {
  dropStepCaches();
  ws_.integrator->reset();
  const mechanics::EventSlot& slot = events_[static_cast<std::size_t>(e)];
  if (slot.kind == mechanics::EventSlot::Kind::DriveReached)
    x.setPoints.drives[static_cast<std::size_t>(slot.index)].reported =
        true;  // keeps holding the target
}

void MultibodyModel::saveWorkspace(devs::CheckpointWriter& w) const {
  // (caches) => the power the next step starts from (the winches are in the state), and what
  // each provider's scratch carries to the next stage (a warm start)
  w.section("multibody");
  w.boolean(ws_.powerState == &state().xNext);
  w.f64(ws_.powerTime);
  w.f64(ws_.power);
  w.list(ws_.data.providerScratch.size());
  std::vector<double> carried;
  for (const auto& scratch : ws_.data.providerScratch) {
    carried.clear();
    if (scratch) scratch->carried(carried);
    devs::save(w, carried);
  }
}

void MultibodyModel::loadWorkspace(devs::CheckpointReader& r) {
  r.section("multibody");
  // (restored state) => every winch as the state has it
  const MultibodyState& x = state().x;
  if (x.setPoints.winches.size() != system_.winches().size())
    throw devs::CheckpointError("multibody '" + path() +
                                "': the checkpoint has another number of winches");
  for (std::size_t k = 0; k < system_.winches().size(); ++k)
    system_.winches()[k].winch->restoreHistory(x.setPoints.winches[k].pieces);
  // (caches of the run that wrote it) => the same reuse of the power at the next step
  ws_.events.valid = false;
  ws_.powerState = r.boolean() ? &state().xNext : nullptr;
  ws_.powerTime = r.f64();
  ws_.power = r.f64();
  if (r.list() != ws_.data.providerScratch.size())
    throw devs::CheckpointError("multibody '" + path() +
                                "': the checkpoint has another number of force providers");
  std::vector<double> carried;
  for (const auto& scratch : ws_.data.providerScratch) {
    devs::load(r, carried);
    if (scratch) scratch->restoreCarried(carried);
  }
  ws_.accelTime = ws_.viewTime = ws_.reactionTime = ws_.energyTime = -1.0;
  ws_.viewState = nullptr;
  ws_.data.kernel.dropKeptStage();
  ws_.stepEnds[0].valid = ws_.stepEnds[1].valid = false;
  ws_.integrator->reset();
}

void MultibodyModel::afterCheckpoint() {
  if (ws_.integrator->carriesHistory()) ws_.integrator->reset();
}

}  // namespace yardsim::models

namespace yardsim::devs {

void TraceFormat<models::MultibodyState>::write(std::string& out, const models::MultibodyState& s) {
  // (state) => its text as a JSON string: digits, signs, 'e', "q=[", ',' and ']' need no escapes
  // (one resize for the quotes and the text, one cut)
  const std::size_t at = out.size();
  out.resize(at + 2 + models::stateTextMost(s));
  char* p = out.data() + at;
  *p++ = '"';
  p = models::writeStateText(p, s);
  *p++ = '"';
  out.resize(static_cast<std::size_t>(p - out.data()));
}

}  // namespace yardsim::devs
