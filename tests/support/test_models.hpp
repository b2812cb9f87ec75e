#pragma once
// Test support: small DEVS atomics with observable behaviour.
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "devs/atomic.hpp"

namespace yardsim::testing {

using devs::Time;

// Emits `burst` messages (value 100 k + j) at each of the given absolute times.
struct EmitterState {
  std::vector<Time> times;
  std::size_t next = 0;
  Time clock = 0.0;
};
inline std::ostream& operator<<(std::ostream& os, const EmitterState& s) {
  return os << "next=" << s.next;
}

class Emitter final : public devs::Atomic<EmitterState> {
 public:
  Emitter(std::string name, std::vector<Time> times, int burst = 1)
      : devs::Atomic<EmitterState>(std::move(name), EmitterState{std::move(times), 0, 0.0}),
        burst_(burst) {}
  devs::OutPort<int>& out = addOutPort<int>("out");

 protected:
  Time timeAdvance(const EmitterState& s) const override {
    return s.next < s.times.size() ? s.times[s.next] - s.clock : devs::kInfinity;
  }
  void output(const EmitterState& s) const override {
    for (int j = 0; j < burst_; ++j) out.add(100 * static_cast<int>(s.next) + j);
  }
  void internalTransition(EmitterState& s) const override { s.clock = s.times[s.next++]; }
  void externalTransition(EmitterState& s, Time e) const override { s.clock += e; }

 private:
  int burst_;
};

// Records every bag it receives with its time; optionally also fires every `period` s.
struct CollectorState {
  Time clock = 0.0;
  Time sigma = devs::kInfinity;
  std::vector<std::pair<Time, std::vector<int>>> bags;
  int internal = 0, external = 0, confluent = 0;
  Time lastConfluentE = -1.0;
};
inline std::ostream& operator<<(std::ostream& os, const CollectorState& s) {
  return os << "bags=" << s.bags.size();
}

class Collector final : public devs::Atomic<CollectorState> {
 public:
  explicit Collector(std::string name, Time period = devs::kInfinity)
      : devs::Atomic<CollectorState>(std::move(name), CollectorState{0.0, period, {}, 0, 0, 0, -1.0}),
        period_(period) {}
  devs::InPort<int>& in = addInPort<int>("in");
  devs::OutPort<int>& tick = addOutPort<int>("tick");

 protected:
  Time timeAdvance(const CollectorState& s) const override { return s.sigma; }
  void output(const CollectorState& s) const override { tick.add(s.internal + s.confluent); }
  void internalTransition(CollectorState& s) const override {
    s.clock += s.sigma;
    s.sigma = period_;
    ++s.internal;
  }
  void externalTransition(CollectorState& s, Time e) const override {
    s.clock += e;
    s.sigma -= e;
    s.bags.push_back({s.clock, {in.values().begin(), in.values().end()}});
    ++s.external;
  }
  void confluentTransition(CollectorState& s, Time e) const override {
    s.clock += e;
    s.sigma = period_;
    s.bags.push_back({s.clock, {in.values().begin(), in.values().end()}});
    ++s.confluent;
    s.lastConfluentE = e;
  }

 private:
  Time period_;
};

}  // namespace yardsim::testing
