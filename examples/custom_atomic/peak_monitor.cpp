#include "peak_monitor.hpp"

#include <cmath>

#include "models/registry.hpp"

using namespace yardsim;

std::ostream& operator<<(std::ostream& os, const PeakState& s) {
  return os << "peak=" << s.peak << (s.alarmed ? " alarmed" : "");
}

PeakMonitor::PeakMonitor(std::string name, double limit)
    : devs::Atomic<PeakState>(std::move(name), PeakState{}), limit_(limit) {}

void PeakMonitor::channels(std::vector<models::Channel>& out) const {
  out.push_back({"peak", "-", [this] { return state().peak; }});
}

devs::Time PeakMonitor::timeAdvance(const PeakState& s) const {
  return s.alarmDue ? 0.0 : devs::kInfinity;
}
void PeakMonitor::output(const PeakState&) const { alarm.add(true); }
void PeakMonitor::internalTransition(PeakState& s) const { s.alarmDue = false; }
void PeakMonitor::externalTransition(PeakState& s, devs::Time) const {
  for (double v : in.values()) s.peak = std::max(s.peak, std::abs(v));
  if (!s.alarmed && s.peak > limit_) s.alarmed = s.alarmDue = true;
}

// Registered exactly as yardsim's own types are: the scene names it `peak_monitor`.
YARDSIM_REGISTER_TYPE(peakMonitor, models::TypeInfo{
    .name = "peak_monitor",
    .summary = "keeps the largest |value| received; sends `alarm` once it exceeds `limit`",
    .params = {{"limit", models::ParamKind::Number, true, "", "", "alarm threshold"}},
    .ports =
        [](const models::Params&) {
          return std::vector<models::PortSpec>{{"in", "double", true}, {"alarm", "bool", false}};
        },
    .create = [](const std::string& n, const models::Params& p)
        -> std::unique_ptr<devs::AtomicBase> { return std::make_unique<PeakMonitor>(n, p.number("limit")); },
    .check =
        [](const models::Params& p, models::ParamCheck& c) {
          if (!(p.number("limit") > 0)) c.error("limit", "must be > 0");
        },
    .feedthrough = [](const models::Params&) { return true; }});
