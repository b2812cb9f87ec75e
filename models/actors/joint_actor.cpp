// Scene type `joint_actor`: drives one joint of a multibody model to a target position at a
// speed, by a bounded servo following a ramp (`mode: servo`, finishing when the model reports
// the target reached within its tolerance, a located state event) or by prescribing the ramp
// exactly (`mode: prescribed`, finishing when the ramp ends, a time event); see
// multibody_model.hpp.
#include <cmath>

#include "models/actors/actor.hpp"

namespace yardsim::models {
namespace {

class JointActor final : public Actor {
 public:
  JointActor(std::string name, StartRule rule, std::string joint, double target, double speed, bool prescribed)
      : Actor(std::move(name), std::move(rule)),
        joint_(std::move(joint)),
        target_(target),
        speed_(speed),
        prescribed_(prescribed) {}

 protected:
  void onStart(std::vector<SetPoint>& out) const override {
    SetPoint s;
    s.kind = SetPoint::Kind::JointTarget;
    s.element = joint_;
    s.target = target_;
    s.speed = speed_;
    s.prescribed = prescribed_;
    out.push_back(s);
  }
  bool finishesOn(const MechanicsEvent& e) const override {
    return e.element == joint_ && e.what == "reached";
  }

 private:
  std::string joint_;
  double target_, speed_;
  bool prescribed_;
};

constexpr double kDeg = M_PI / 180.0;

// (target or target_deg, speed or speed_deg) => radians / metres
double angleOrLength(const Params& p, const char* plain, const char* deg) {
  return !p.node(deg).IsNull() ? p.number(deg) * kDeg : p.number(plain);
}

}  // namespace

YARDSIM_REGISTER_TYPE(jointActor, TypeInfo{
    .name = "joint_actor",
    .summary = "drives a joint of a multibody model to a target at a speed; finishes when reached",
    .params =
        [] {
          auto p = startParams();
          p.push_back({"joint", ParamKind::String, true, "", "", "joint name in the multibody model"});
          p.push_back({"target", ParamKind::Number, false, "~", "rad or m", "target position"});
          p.push_back({"target_deg", ParamKind::Number, false, "~", "deg", "target angle"});
          p.push_back({"speed", ParamKind::Number, false, "~", "rad/s or m/s", "ramp speed"});
          p.push_back({"speed_deg", ParamKind::Number, false, "~", "deg/s", "ramp speed"});
          p.push_back({"mode", ParamKind::String, false, "servo", "",
                       "servo (a bounded controller follows the ramp) or prescribed (the ramp exactly)"});
          return p;
        }(),
    .ports = [](const Params&) { return actorPorts(); },
    .create = [](const std::string& n, const Params& p) -> std::unique_ptr<devs::AtomicBase> {
      return std::make_unique<JointActor>(n, startRule(p), p.string("joint"),
                                          angleOrLength(p, "target", "target_deg"),
                                          angleOrLength(p, "speed", "speed_deg"),
                                          p.string("mode") == "prescribed");
    },
    .check =
        [](const Params& p, ParamCheck& c) {
          checkStart(p, c);
          if (p.string("mode") != "servo" && p.string("mode") != "prescribed")
            c.error("mode", "expected servo or prescribed, got '" + p.string("mode") + "'");
          if (p.node("target").IsNull() == p.node("target_deg").IsNull())
            c.error("target", "give exactly one of target (rad or m) and target_deg");
          if (p.node("speed").IsNull() == p.node("speed_deg").IsNull())
            c.error("speed", "give exactly one of speed (rad/s or m/s) and speed_deg");
          else if (!(angleOrLength(p, "speed", "speed_deg") > 0))
            c.error(p.node("speed").IsNull() ? "speed_deg" : "speed", "must be > 0");
        },
    .feedthrough = {},
    .references = [](const Params& p) {
      return std::vector<ElementRef>{{"joint", p.string("joint"), "joint"}};
    }});

}  // namespace yardsim::models
