#pragma once
// A user-defined atomic model: watches a stream of values (a rope tension, a speed), keeps the
// largest magnitude seen, and raises `alarm` the first time it exceeds `limit`.
#include <ostream>

#include "devs/atomic.hpp"
#include "models/channels.hpp"

struct PeakState {
  double peak = 0.0;
  bool alarmed = false;
  bool alarmDue = false;  // send `alarm` now
};
std::ostream& operator<<(std::ostream& os, const PeakState& s);

class PeakMonitor final : public yardsim::devs::Atomic<PeakState>,
                          public yardsim::models::Observable {
 public:
  PeakMonitor(std::string name, double limit);
  yardsim::devs::InPort<double>& in = addInPort<double>("in");
  yardsim::devs::OutPort<bool>& alarm = addOutPort<bool>("alarm");
  void channels(std::vector<yardsim::models::Channel>& out) const override;

 protected:
  yardsim::devs::Time timeAdvance(const PeakState& s) const override;
  void output(const PeakState& s) const override;
  void internalTransition(PeakState& s) const override;
  void externalTransition(PeakState& s, yardsim::devs::Time e) const override;

 private:
  double limit_;
};
