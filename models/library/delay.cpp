#include "models/library/delay.hpp"

#include "models/registry.hpp"

namespace yardsim::models::library {

std::ostream& operator<<(std::ostream& os, const DelayState& s) {
  return os << "held=" << s.held.size();
}

Delay::Delay(std::string name, devs::Time delay)
    : devs::Atomic<DelayState>(std::move(name), DelayState{}), delay_(delay) {}

void Delay::output(const DelayState& s) const {
  for (int v : s.held) out.add(v);
}
void Delay::internalTransition(DelayState& s) const {
  s.held.clear();
  s.sigma = devs::kInfinity;
}
void Delay::externalTransition(DelayState& s, devs::Time e) const {
  // messages already held keep their due time; new ones wait `delay` from now
  s.sigma = s.held.empty() ? delay_ : s.sigma - e;
  s.held.insert(s.held.end(), in.values().begin(), in.values().end());
}

YARDSIM_REGISTER_TYPE(delay, TypeInfo{
    .name = "delay",
    .summary = "forwards every int it receives after `delay` seconds (0: at once)",
    .params = {{"delay", ParamKind::Number, false, "0", "s", "time each message is held"}},
    .ports = [](const Params&) {
      return std::vector<PortSpec>{{"in", "int", true}, {"out", "int", false}};
    },
    .create = [](const std::string& n, const Params& p) -> std::unique_ptr<devs::AtomicBase> {
      return std::make_unique<Delay>(n, p.number("delay"));
    },
    .check =
        [](const Params& p, ParamCheck& c) {
          if (p.number("delay") < 0) c.error("delay", "must be >= 0 s");
        },
    .feedthrough = [](const Params& p) { return p.number("delay") == 0.0; }});

}  // namespace yardsim::models::library
