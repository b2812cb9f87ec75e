// Scene type `body_actor`: applies a constant force and moment (world frame, at the body
// origin) to a body of a multibody model for `duration` seconds, then releases it.
#include "models/actors/actor.hpp"

namespace yardsim::models {
namespace {

class BodyActor final : public Actor {
 public:
  BodyActor(std::string name, StartRule rule, std::string body, std::vector<double> f,
            std::vector<double> m, double duration)
      : Actor(std::move(name), std::move(rule)), body_(std::move(body)), f_(std::move(f)),
        m_(std::move(m)), duration_(duration) {}

 protected:
  void onStart(std::vector<SetPoint>& out) const override { out.push_back(load(true)); }
  void onFinish(std::vector<SetPoint>& out) const override { out.push_back(load(false)); }
  devs::Time duration() const override { return duration_; }

 private:
  SetPoint load(bool on) const {
    SetPoint s;
    s.kind = SetPoint::Kind::ActorLoad;
    s.element = body_;
    for (int k = 0; k < 3; ++k) {
      s.force[k] = on ? f_[static_cast<std::size_t>(k)] : 0.0;
      s.moment[k] = on ? m_[static_cast<std::size_t>(k)] : 0.0;
    }
    return s;
  }
  std::string body_;
  std::vector<double> f_, m_;
  double duration_;
};

}  // namespace

YARDSIM_REGISTER_TYPE(bodyActor, TypeInfo{
    .name = "body_actor",
    .summary = "applies a force and moment (world frame, at the body origin) to a body for a duration",
    .params =
        [] {
          auto p = startParams();
          p.push_back({"body", ParamKind::String, true, "", "", "body name in the multibody model"});
          p.push_back({"force", ParamKind::NumberList, false, "[0, 0, 0]", "N", "force, world frame"});
          p.push_back({"moment", ParamKind::NumberList, false, "[0, 0, 0]", "N m", "moment, world frame"});
          p.push_back({"duration", ParamKind::Number, true, "", "s", "how long the load acts"});
          return p;
        }(),
    .ports = [](const Params&) { return actorPorts(); },
    .create = [](const std::string& n, const Params& p) -> std::unique_ptr<devs::AtomicBase> {
      return std::make_unique<BodyActor>(n, startRule(p), p.string("body"), p.numbers("force"),
                                         p.numbers("moment"), p.number("duration"));
    },
    .check =
        [](const Params& p, ParamCheck& c) {
          checkStart(p, c);
          if (p.numbers("force").size() != 3) c.error("force", "expected 3 numbers (N)");
          if (p.numbers("moment").size() != 3) c.error("moment", "expected 3 numbers (N m)");
          if (p.number("duration") < 0) c.error("duration", "must be >= 0 s");
        },
    .feedthrough = [](const Params& p) { return p.number("duration") == 0.0; },
    .references = [](const Params& p) {
      return std::vector<ElementRef>{{"body", p.string("body"), "body"}};
    }});

}  // namespace yardsim::models
