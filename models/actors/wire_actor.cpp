// Scene type `wire_actor`: hoists or lowers a wire rope of a multibody model — changes the
// unstretched length of each part by `payout` metres (negative: hauls in, the load rises) at
// `speed` m/s (0.083 m/s is a typical goliath-crane hoist), the speed ramping up and down with
// the drive's `accel` (m/s^2) and `jerk` (m/s^3) limits when given (forces/winch_profile.hpp);
// finishes when the winch is done (a time event of the multibody model, exact).
#include <cmath>

#include "models/actors/actor.hpp"

namespace yardsim::models {
namespace {

class WireActor final : public Actor {
 public:
  WireActor(std::string name, StartRule rule, std::string rope, double payout, double speed,
            double accel, double jerk)
      : Actor(std::move(name), std::move(rule)),
        rope_(std::move(rope)),
        payout_(payout),
        speed_(speed),
        accel_(accel),
        jerk_(jerk) {}

 protected:
  void onStart(std::vector<SetPoint>& out) const override {
    SetPoint s;
    s.kind = SetPoint::Kind::WinchPayout;
    s.element = rope_;
    s.amount = payout_;
    s.speed = speed_;
    s.accel = accel_;
    s.jerk = jerk_;
    out.push_back(s);
  }
  // (stopped by a stop_on event) => the winch stops where it is
  void onStop(std::vector<SetPoint>& out) const override {
    SetPoint s;
    s.kind = SetPoint::Kind::WinchStop;
    s.element = rope_;
    out.push_back(s);
  }
  bool finishesOn(const MechanicsEvent& e) const override {
    return e.element == rope_ && e.what == "done";
  }

 private:
  std::string rope_;
  double payout_, speed_, accel_, jerk_;
};

}  // namespace

YARDSIM_REGISTER_TYPE(wireActor, TypeInfo{
    .name = "wire_actor",
    .summary = "pays out (or, negative, hauls in) a rope of a multibody model by a length at a speed",
    .params =
        [] {
          auto p = startParams();
          p.push_back({"rope", ParamKind::String, true, "", "", "rope name in the multibody model"});
          p.push_back({"payout", ParamKind::Number, true, "", "m",
                       "change of unstretched length per part (negative hoists the load)"});
          p.push_back({"speed", ParamKind::Number, true, "", "m/s", "winch speed per part (> 0)"});
          p.push_back({"accel", ParamKind::Number, false, "0", "m/s^2",
                       "drive acceleration limit per part (>= 0; 0: the speed steps at once)"});
          p.push_back({"jerk", ParamKind::Number, false, "0", "m/s^3",
                       "drive jerk limit (>= 0; 0: none, a trapezoid; needs accel)"});
          return p;
        }(),
    .ports = [](const Params&) { return actorPorts(); },
    .create = [](const std::string& n, const Params& p) -> std::unique_ptr<devs::AtomicBase> {
      return std::make_unique<WireActor>(n, startRule(p), p.string("rope"), p.number("payout"),
                                         p.number("speed"), p.number("accel"), p.number("jerk"));
    },
    .check =
        [](const Params& p, ParamCheck& c) {
          checkStart(p, c);
          if (!(p.number("speed") > 0)) c.error("speed", "must be > 0 m/s");
          if (p.number("payout") == 0) c.error("payout", "must not be 0 m");
          if (!(p.number("accel") >= 0)) c.error("accel", "must be >= 0 m/s^2 (0: no limit)");
          if (!(p.number("jerk") >= 0)) c.error("jerk", "must be >= 0 m/s^3 (0: no limit)");
          else if (p.number("jerk") > 0 && !(p.number("accel") > 0))
            c.error("jerk", "a jerk limit needs an acceleration limit: give accel > 0");
        },
    .feedthrough = {},
    .references = [](const Params& p) {
      return std::vector<ElementRef>{{"rope", p.string("rope"), "rope"}};
    }});

}  // namespace yardsim::models
