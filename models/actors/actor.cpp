#include "models/actors/actor.hpp"

namespace yardsim::models {

std::ostream& operator<<(std::ostream& os, const ActorState& s) {
  static const char* names[] = {"waiting", "starting", "running", "finishing", "done", "stopping"};
  return os << names[static_cast<int>(s.phase)];
}

Actor::Actor(std::string name, StartRule rule)
    : devs::Atomic<ActorState>(std::move(name),
                               ActorState{ActorState::Phase::Waiting,
                                          rule.kind == StartRule::Kind::At ? rule.at : devs::kInfinity,
                                          0.0, {}}),
      rule_(std::move(rule)) {}

bool Actor::ready(const ActorState& s) const {
  auto seen = [&](const std::string& name) {
    for (const auto& p : s.finished)
      if (p == name || (p.size() > name.size() && p.ends_with("." + name))) return true;
    return false;
  };
  if (rule_.kind == StartRule::Kind::AfterAll)
    return std::all_of(rule_.names.begin(), rule_.names.end(), seen);
  if (rule_.kind == StartRule::Kind::AfterAny)
    return std::any_of(rule_.names.begin(), rule_.names.end(), seen);
  return false;
}

bool Actor::stopsOn(const MechanicsEvent& e) const {
  const std::string full = e.element + "." + e.what;
  for (const auto& name : rule_.stopOn)
    if (full == name || (full.size() > name.size() && full.ends_with("." + name))) return true;
  return false;
}

void Actor::output(const ActorState& s) const {
  scratch_.clear();
  if (s.phase == ActorState::Phase::Stopping) {
    onStop(scratch_);
    finished.add(path());
  } else if (s.phase == ActorState::Phase::Waiting || s.phase == ActorState::Phase::Starting) {
    started.add(path());
    onStart(scratch_);
    if (duration() == 0.0) {
      onFinish(scratch_);
      finished.add(path());
    }
  } else if (s.phase == ActorState::Phase::Running || s.phase == ActorState::Phase::Finishing) {
    onFinish(scratch_);
    finished.add(path());
  }
  for (auto& sp : scratch_) {
    sp.actor = path();
    setpoint.add(sp);
  }
}

void Actor::internalTransition(ActorState& s) const {
  s.clock += s.sigma;
  if (s.phase == ActorState::Phase::Waiting || s.phase == ActorState::Phase::Starting) {
    const devs::Time d = duration();
    s.phase = d == 0.0 ? ActorState::Phase::Done : ActorState::Phase::Running;
    s.sigma = d == 0.0 ? devs::kInfinity : d;
  } else {
    s.phase = ActorState::Phase::Done;
    s.sigma = devs::kInfinity;
  }
}

void Actor::externalTransition(ActorState& s, devs::Time e) const {
  s.clock += e;
  s.sigma -= e;
  for (const auto& name : trigger.values()) s.finished.insert(name);
  if (s.phase == ActorState::Phase::Waiting && rule_.kind != StartRule::Kind::At && ready(s)) {
    s.phase = ActorState::Phase::Starting;
    s.sigma = 0.0;
  }
  if (s.phase == ActorState::Phase::Running)
    for (const auto& ev : event.values()) {
      if (ev.actor == path() && finishesOn(ev)) {
        s.phase = ActorState::Phase::Finishing;
        s.sigma = 0.0;
      } else if (stopsOn(ev)) {  // (a stop_on event) => stopped at once, its time the event's
        s.phase = ActorState::Phase::Stopping;
        s.sigma = 0.0;
        break;
      }
    }
}

std::vector<ParamSpec> startParams() {
  return {{"start_at", ParamKind::Number, false, "~", "s", "start at this time"},
          {"after_all", ParamKind::StringList, false, "~", "",
           "start when all these actors have finished"},
          {"after_any", ParamKind::StringList, false, "~", "",
           "start when any of these actors has finished"},
          {"stop_on", ParamKind::StringList, false, "~", "",
           "stop at once on any of these events <element>.<kind> while running (e.g. "
           "rope_block.touched)"}};
}

StartRule startRule(const Params& p) {
  StartRule r;
  if (!p.node("after_all").IsNull()) {
    r.kind = StartRule::Kind::AfterAll;
    r.names = p.strings("after_all");
  } else if (!p.node("after_any").IsNull()) {
    r.kind = StartRule::Kind::AfterAny;
    r.names = p.strings("after_any");
  } else {
    r.at = p.node("start_at").IsNull() ? 0.0 : p.number("start_at");
  }
  if (!p.node("stop_on").IsNull()) r.stopOn = p.strings("stop_on");
  return r;
}

void checkStart(const Params& p, ParamCheck& c) {
  const int given = int(!p.node("start_at").IsNull()) + int(!p.node("after_all").IsNull()) +
                    int(!p.node("after_any").IsNull());
  if (given > 1) c.error("start_at", "give only one of start_at, after_all and after_any");
  if (!p.node("start_at").IsNull() && p.number("start_at") < 0) c.error("start_at", "must be >= 0 s");
}

std::vector<PortSpec> actorPorts() {
  return {{"trigger", "string", true, true},
          {"event", "mechanics_event", true, true},
          {"started", "string", false},
          {"finished", "string", false},
          {"setpoint", "setpoint", false}};
}

}  // namespace yardsim::models
