#include "mechanics/system.hpp"

#include <stdexcept>

#include "dynamics/crba.hpp"
#include "forces/current_load.hpp"
#include "forces/wind_load.hpp"
#include "mechanics/build.hpp"
#include "mechanics/jacobian_pattern.hpp"
#include "mechanics/providers.hpp"

namespace yardsim::mechanics {

System::System(BuiltMechanics mechanics, const ServoSettings& servo, const std::string& name)
    : mech_(std::move(mechanics)), servo_(servo) {
  const auto& model = mech_.model;
  // (rope and equalizer specs) => ropes, evaluated at every stage
  ropes_ = std::move(makeProviders(mech_, model).ropes);
  for (const auto& l : mech_.loads) {
    bodyLoads_.push_back(std::make_unique<forces::BodyLoad>(
        l.name, model, model.bodyIndex(l.body), l.point,
        l.bodyFrame ? forces::LoadFrame::Body : forces::LoadFrame::World));
    bodyLoads_.back()->setTable(l.series);
  }
  // (watches) => what each reads
  for (const auto& w : mech_.watches) {
    using K = WatchRef::Kind;
    WatchRef ref{K::Q, -1, 0};
    const int joint = jointBody(w.element), body = model.bodyIndex(w.element),
              rope = ropeIndex(w.element);
    const std::string& q = w.quantity;
    if (joint > 0 && (q == "q" || q == "v"))
      ref = {q == "q" ? K::Q : K::V, q == "q" ? model.idxQ[joint] : model.idxV[joint], 0};
    else if (body > 0 && (q == "x" || q == "y" || q == "z"))
      ref = {K::Position, body, q == "x" ? 0 : q == "y" ? 1 : 2};
    else if (body > 0 && (q == "roll" || q == "pitch" || q == "yaw"))
      ref = {K::Angle, body, q == "roll" ? 0 : q == "pitch" ? 1 : 2};
    else if (rope >= 0 && (q == "tension" || q == "length"))
      ref = {q == "tension" ? K::Tension : K::Length, rope, 0};
    else
      throw std::invalid_argument("watch '" + w.name + "': '" + w.element + "' has no quantity '" +
                                  q + "'");
    watchRefs_.push_back(ref);
  }
  // (floating-body specs) => hydrostatics on one sea, wind and current loads, damping
  const MechanicsSpec& env = mech_.environment;
  if (const std::string missing = missingEnvironment(env); !missing.empty())
    throw std::invalid_argument("multibody '" + name + "': " + missing);
  forces::WaterProperties water = env.water;
  if (-model.gravity.z() > 0 && !env.hasWater) water.gravity = -model.gravity.z();
  const auto sea = std::make_shared<const forces::AiryWaves>(water, env.waves);
  auto bodyOf = [&](const std::string& n) { return model.bodyIndex(n); };
  for (const auto& h : env.hulls)
    hydros_.push_back(std::make_unique<forces::Hydrostatics>(h.name, model, bodyOf(h.body), *h.mesh,
                                                             sea, h.incidentPressure));
  if (env.wind) {
    const auto wind = std::make_shared<const forces::WindField>(*env.wind);
    for (const auto& w : env.windLoads)
      flows_.push_back(std::make_unique<forces::WindLoad>(w.name, model, bodyOf(w.body), w.point,
                                                          w.areas, w.coefficients, wind));
  }
  if (env.current) {
    const auto current = std::make_shared<const forces::CurrentField>(*env.current);
    for (const auto& c : env.currentLoads)
      flows_.push_back(std::make_unique<forces::CurrentLoad>(
          c.name, model, bodyOf(c.body), c.point, c.areas, c.coefficients, current, water.density));
  }
  for (const auto& d : env.dampers)
    dampers_.push_back(std::make_unique<forces::LinearQuadraticDamping>(
        d.name, model, bodyOf(d.body), d.point, d.coefficients));
  for (const auto& t : mech_.draftAddedMass)
    draftAddedMass_.push_back(std::make_unique<forces::hydro::DraftAddedMass>(
        "added_mass:" + t.body, model, bodyOf(t.body), t.table));
  for (const auto& h : env.hydrodynamics) contributed_.push_back(h.build(h.name, model, bodyOf(h.body), sea));
  // (providers of registered readers) => built at their attachments
  for (const auto& p : mech_.providers) {
    std::vector<forces::Attachment> at;
    for (const auto& [body, p_B] : p.attachments) {
      const int b = body == "world" ? 0 : model.bodyIndex(body);
      if (b < 0)
        throw std::invalid_argument(p.kind + " '" + p.name + "': unknown body '" + body + "'");
      at.push_back({b, p_B});
    }
    contributed_.push_back(p.buildFromSystem ? p.buildFromSystem(p.name, mech_, at)
                                             : p.build(p.name, model, at));
  }
  // (typed providers) => the one list, in the order every stage evaluates them
  for (auto& r : ropes_) providers_.push_back(r.get());
  for (auto& h : hydros_) providers_.push_back(h.get());
  for (auto& f : flows_) providers_.push_back(f.get());
  for (auto& d : dampers_) providers_.push_back(d.get());
  for (auto& b : bodyLoads_) providers_.push_back(b.get());
  for (auto& a : draftAddedMass_) providers_.push_back(a.get());
  for (auto& c : contributed_) providers_.push_back(c.get());
  // (ropes, then contributed providers with a winch) => the winches actors drive, by name
  for (auto& r : ropes_) winches_.push_back({r->name(), &r->winch()});
  for (auto& c : contributed_)
    if (forces::Winch* w = c->payoutWinch()) winches_.push_back({c->name(), w});
  // (contributed lumped lines with a winch) => the lines whose node masses follow it
  for (auto& c : contributed_)
    if (const forces::LumpedLineProvider* l = lumpedLine(*c); l && l->line().winch())
      winchedLines_.push_back(l);
  // (contributed providers with events) => their event functions, in order
  for (auto& c : contributed_)
    if (const auto* e = dynamic_cast<const forces::ProviderEvents*>(c.get()))
      for (const auto& ev : e->events()) providerEvents_.push_back(&ev);
  // (initial configuration) => joint-space inertia of each 1-dof joint, for servo gains
  dynamics::Data data(model);
  const Eigen::MatrixXd& M = dynamics::crba(model, data, mech_.q0);
  servoInertia_.assign(static_cast<std::size_t>(model.nbodies), 0.0);
  for (int i = 1; i < model.nbodies; ++i)
    if (model.jointNv[i] == 1) servoInertia_[i] = M(model.idxV[i], model.idxV[i]);
}

int System::jointBody(const std::string& joint) const {
  for (std::size_t i = 1; i < mech_.jointNames.size(); ++i)
    if (mech_.jointNames[i] == joint) return static_cast<int>(i);
  return -1;
}

int System::winchIndex(const std::string& name) const {
  for (std::size_t i = 0; i < winches_.size(); ++i)
    if (winches_[i].name == name) return static_cast<int>(i);
  return -1;
}

int System::ropeIndex(const std::string& name) const {
  for (std::size_t i = 0; i < ropes_.size(); ++i)
    if (ropes_[i]->name() == name) return static_cast<int>(i);
  return -1;
}

}  // namespace yardsim::mechanics
