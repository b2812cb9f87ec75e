#pragma once
// Actors (Ha et al. 2015, §3.2.5) act on a multibody model through set-points and pass
// triggers to each other. Every actor starts on a trigger — at a time, when all of a set of
// actors have finished, or when any of them has — and emits `started` and `finished` (its own
// path) that other actors listen to on `trigger`; priorities between actors are these couplings.
// This base holds the trigger logic; a kind of actor says what it sends when it starts and
// finishes, and what finishes it.
#include <ostream>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "devs/atomic.hpp"
#include "models/multibody/messages.hpp"
#include "models/params.hpp"
#include "models/registry.hpp"

namespace yardsim::models {

struct StartRule {
  enum class Kind { At, AfterAll, AfterAny };
  Kind kind = Kind::At;
  double at = 0.0;
  std::vector<std::string> names;  // actors (path or last path component)
  // `stop_on`: events `<element>.<kind>` (or a trailing part of it: `rope_block.touched`) that
  // stop the actor while it runs, as its own finish would but at once (a wire actor stops its
  // winch): the event's located time is the stop's
  std::vector<std::string> stopOn;
};

struct ActorState {
  enum class Phase { Waiting, Starting, Running, Finishing, Done, Stopping };
  Phase phase = Phase::Waiting;
  devs::Time sigma = devs::kInfinity;
  devs::Time clock = 0.0;
  std::set<std::string> finished;  // actors seen finishing (paths)
};
std::ostream& operator<<(std::ostream& os, const ActorState& s);

}  // namespace yardsim::models

namespace yardsim::devs {
template <>
struct StateCodec<models::ActorState> : FieldCodec<models::ActorState> {
  static auto fields(auto& s) { return std::tie(s.phase, s.sigma, s.clock, s.finished); }
};
}  // namespace yardsim::devs

namespace yardsim::models {

class Actor : public devs::Atomic<ActorState> {
 public:
  Actor(std::string name, StartRule rule);
  devs::InPort<std::string>& trigger = addInPort<std::string>("trigger");
  devs::InPort<MechanicsEvent>& event = addInPort<MechanicsEvent>("event");
  devs::OutPort<std::string>& started = addOutPort<std::string>("started");
  devs::OutPort<std::string>& finished = addOutPort<std::string>("finished");
  devs::OutPort<SetPoint>& setpoint = addOutPort<SetPoint>("setpoint");

 protected:
  // What a kind of actor does: set-points when it starts and when it finishes, how long it
  // runs (infinity: until finishesOn says so), and which mechanics events finish it.
  virtual void onStart(std::vector<SetPoint>& out) const = 0;
  virtual void onFinish(std::vector<SetPoint>& /*out*/) const {}
  // (stopped by a `stop_on` event while running) => its set-points; by default its finish's
  virtual void onStop(std::vector<SetPoint>& out) const { onFinish(out); }
  virtual devs::Time duration() const { return devs::kInfinity; }
  virtual bool finishesOn(const MechanicsEvent& /*e*/) const { return false; }

 private:
  devs::Time timeAdvance(const ActorState& s) const override { return s.sigma; }
  void output(const ActorState& s) const override;
  void internalTransition(ActorState& s) const override;
  void externalTransition(ActorState& s, devs::Time e) const override;
  bool ready(const ActorState& s) const;
  bool stopsOn(const MechanicsEvent& e) const;

  StartRule rule_;
  mutable std::vector<SetPoint> scratch_;
};

// The parameters every actor type takes: start_at, after_all, after_any (one of them), stop_on.
std::vector<ParamSpec> startParams();
StartRule startRule(const Params& p);
void checkStart(const Params& p, ParamCheck& c);
// Ports of every actor.
std::vector<PortSpec> actorPorts();

}  // namespace yardsim::models
