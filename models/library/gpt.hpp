#pragma once
// The classic generator-processor-transducer (GPT) DEVS model (Zeigler), as a hierarchical
// coupled model: gpt = { ef = { genr, transd }, proc }.
//  - genr emits job ids every `period` seconds until it receives `stop`;
//  - proc serves one job at a time for `processing` seconds, ignoring jobs while busy;
//  - transd counts arrived and solved jobs over `observe` seconds, then sends `stop`.
#include <memory>
#include <ostream>

#include "devs/atomic.hpp"
#include "models/channels.hpp"

// Scene types: generator (period), processor (processing_time), transducer (observe).
namespace yardsim::models::library {

using devs::Time;

struct GeneratorState {
  Time sigma = 0.0;
  int next = 1;  // id of the next job
  bool active = true;
};
std::ostream& operator<<(std::ostream& os, const GeneratorState& s);

}  // namespace yardsim::models::library

namespace yardsim::devs {
template <>
struct StateCodec<models::library::GeneratorState> : FieldCodec<models::library::GeneratorState> {
  static auto fields(auto& s) { return std::tie(s.sigma, s.next, s.active); }
};
}  // namespace yardsim::devs

namespace yardsim::models::library {

class Generator final : public devs::Atomic<GeneratorState>, public Observable {
 public:
  Generator(std::string name, Time period);
  devs::InPort<bool>& stop = addInPort<bool>("stop");
  devs::OutPort<int>& out = addOutPort<int>("out");
  void channels(std::vector<Channel>& out) const override;

 protected:
  Time timeAdvance(const GeneratorState& s) const override;
  void output(const GeneratorState& s) const override;
  void internalTransition(GeneratorState& s) const override;
  void externalTransition(GeneratorState& s, Time e) const override;

 private:
  Time period_;
};

struct ProcessorState {
  Time sigma = devs::kInfinity;
  int job = 0;  // job in service, 0 when idle
};
std::ostream& operator<<(std::ostream& os, const ProcessorState& s);

}  // namespace yardsim::models::library

namespace yardsim::devs {
template <>
struct StateCodec<models::library::ProcessorState> : FieldCodec<models::library::ProcessorState> {
  static auto fields(auto& s) { return std::tie(s.sigma, s.job); }
};
}  // namespace yardsim::devs

namespace yardsim::models::library {

class Processor final : public devs::Atomic<ProcessorState>, public Observable {
 public:
  Processor(std::string name, Time processing);
  devs::InPort<int>& in = addInPort<int>("in");
  devs::OutPort<int>& out = addOutPort<int>("out");
  void channels(std::vector<Channel>& out) const override;

 protected:
  Time timeAdvance(const ProcessorState& s) const override { return s.sigma; }
  void output(const ProcessorState& s) const override;
  void internalTransition(ProcessorState& s) const override;
  void externalTransition(ProcessorState& s, Time e) const override;

 private:
  Time processing_;
};

struct TransducerState {
  Time clock = 0.0;
  Time sigma = 0.0;
  int arrived = 0;
  int solved = 0;
  Time turnaroundSum = 0.0;  // sum over solved jobs of (solved time - arrival time)
  std::vector<Time> arrivals;  // arrival time by job id - 1
};
std::ostream& operator<<(std::ostream& os, const TransducerState& s);

}  // namespace yardsim::models::library

namespace yardsim::devs {
template <>
struct StateCodec<models::library::TransducerState> : FieldCodec<models::library::TransducerState> {
  static auto fields(auto& s) {
    return std::tie(s.clock, s.sigma, s.arrived, s.solved, s.turnaroundSum, s.arrivals);
  }
};
}  // namespace yardsim::devs

namespace yardsim::models::library {

class Transducer final : public devs::Atomic<TransducerState>, public Observable {
 public:
  Transducer(std::string name, Time observe);
  devs::InPort<int>& arrived = addInPort<int>("arrived");
  devs::InPort<int>& solved = addInPort<int>("solved");
  devs::OutPort<bool>& stop = addOutPort<bool>("stop");

  double throughput() const;          // solved jobs per second of observation
  double meanTurnaround() const;      // mean time from arrival to solution
  void channels(std::vector<Channel>& out) const override;

 protected:
  Time timeAdvance(const TransducerState& s) const override { return s.sigma; }
  void output(const TransducerState& s) const override;
  void internalTransition(TransducerState& s) const override;
  void externalTransition(TransducerState& s, Time e) const override;
};

}  // namespace yardsim::models::library
