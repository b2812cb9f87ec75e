// Built against the installed yardsim: a DTSS clock feeding a DEVS counter, traced to stdout.
#include <cstdio>
#include <iostream>

#include "devs/coupled.hpp"
#include "devs/jsonl_trace_sink.hpp"
#include "devs/simulator.hpp"
#include "dtss/atomic.hpp"

using namespace yardsim;

struct Clock final : dtss::Atomic<double> {
  Clock() : dtss::Atomic<double>("clock", 0.0, 0.5) {}
  devs::OutPort<double>& tick = addOutPort<double>("tick");
  void advance(double& x, devs::Time, devs::Time dt) const override { x += dt; }
  void outputAt(const double& x, devs::Time, const dtss::Reached& r) const override {
    if (r.grid) tick.add(x);
  }
};

struct Counter final : devs::Atomic<int> {
  Counter() : devs::Atomic<int>("counter", 0) {}
  devs::InPort<double>& in = addInPort<double>("in");
  devs::Time timeAdvance(const int&) const override { return devs::kInfinity; }
  void output(const int&) const override {}
  void internalTransition(int&) const override {}
  void externalTransition(int& n, devs::Time) const override { n += int(in.values().size()); }
};

int main() {
  devs::Coupled root("consumer");
  auto& clock = root.add<Clock>();
  auto& counter = root.add<Counter>();
  root.couple(clock.tick, counter.in);
  devs::Simulator sim(root);
  devs::JsonlTraceSink trace{devs::TraceStream(std::cout), false};
  sim.addListener(trace);
  sim.runUntil(2.0);
  std::printf("consumer: %d ticks by t = %g s\n", counter.state(), sim.time());
  return counter.state() == 4 ? 0 : 1;
}
