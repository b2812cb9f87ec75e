#include "run/profile.hpp"

#include <catch2/catch.hpp>
#include <cstdint>
#include <vector>

#include "support/test_models.hpp"

using namespace yardsim;

namespace {
// A clock of the test's own: nanoseconds that only the test moves, and how often it was read.
std::int64_t gNow = 0;
int gReads = 0;
std::int64_t fakeClock() {
  ++gReads;
  return gNow;
}
// Counts the hooks it receives and spends 1 ms of the fake clock in each.
struct SlowCounter : devs::Listener {
  SlowCounter(int n, std::vector<int>& calls_log) : id(n), log(calls_log) {}
  int id;
  std::vector<int>& log;  // the ids of the listeners called, in order
  int calls = 0;
  void hook() {
    ++calls;
    log.push_back(id);
    gNow += 1'000'000;
  }
  void onStart(devs::Time, std::span<devs::AtomicBase* const>) override { hook(); }
  void onEnd(devs::Time) override { hook(); }
};
}  // namespace

TEST_CASE(
    "a timed listener forwards each hook to every sink in order and books the time spent in them") {
  std::vector<int> log;
  SlowCounter first(1, log), second(2, log);
  gNow = 0;
  double seconds = 0.0;
  run::TimedListener timed({&first, &second}, seconds, fakeClock);
  devs::Listener& l = timed;
  l.onStart(0.0, {});
  l.onEnd(1.0);
  l.onEnd(2.0);
  CHECK(first.calls == 3);
  CHECK(second.calls == 3);
  CHECK(log == std::vector<int>{1, 2, 1, 2, 1, 2});
  CHECK(seconds == Approx(0.006).epsilon(1e-12));
}

namespace {
// A sink that takes `cost` nanoseconds of the fake clock in every hook it receives.
struct CostlySink : devs::Listener {
  explicit CostlySink(std::int64_t c) : cost(c) {}
  std::int64_t cost;
  int calls = 0;
  void hook() {
    ++calls;
    gNow += cost;
  }
  void onStart(devs::Time, std::span<devs::AtomicBase* const>) override { hook(); }
  void onOutput(devs::Time, const devs::AtomicBase&, const devs::PortBase&) override { hook(); }
  void onInput(devs::Time, const devs::AtomicBase&, const devs::PortBase&) override { hook(); }
  void onTransition(devs::Time, const devs::AtomicBase&, devs::Transition, devs::Time) override {
    hook();
  }
  void onState(devs::Time, const devs::AtomicBase&) override { hook(); }
  void onEnd(devs::Time) override { hook(); }
};
}  // namespace

TEST_CASE(
    "a timed listener books the time inside its sinks' hooks, none of the time between them, and "
    "reads the clock twice for a transition's two hooks") {
  gNow = 0;
  gReads = 0;
  CostlySink a(1'000), b(10);
  double seconds = 0.0;
  run::TimedListener timed({&a, &b}, seconds, fakeClock);
  devs::Listener& l = timed;
  testing::Emitter m("m", {});
  const devs::PortBase& port = m.out;
  // (the Simulator's order: start, the states at start, then per event time outputs, inputs and
  // each model's transition and state) => 1 ms of "simulation" between any two hooks
  const auto simulate = [] { gNow += 1'000'000; };
  l.onStart(0.0, {});
  simulate();
  l.onState(0.0, m);
  for (int k = 1; k <= 100; ++k) {
    simulate();
    l.onOutput(k, m, port);
    simulate();
    l.onInput(k, m, port);
    simulate();
    l.onTransition(k, m, devs::Transition::Internal, 1.0);
    l.onState(k, m);
    simulate();
  }
  l.onEnd(100.0);
  const int hooks = 2 + 4 * 100 + 1;
  CHECK(a.calls == hooks);
  CHECK(b.calls == hooks);
  // exactly the sinks' own time: 1,010 ns a hook
  CHECK(seconds == Approx(hooks * 1'010e-9).epsilon(1e-12));
  // two reads a hook, but two for a transition and its state
  CHECK(gReads == 2 * hooks - 2 * 100);
}

TEST_CASE("a transition hook that no state hook follows is counted up to the next hook") {
  gNow = 0;
  gReads = 0;
  CostlySink a(1'000);
  double seconds = 0.0;
  run::TimedListener timed({&a}, seconds, fakeClock);
  devs::Listener& l = timed;
  testing::Emitter m("m", {});
  l.onTransition(1.0, m, devs::Transition::Internal, 1.0);
  gNow += 500;  // between the two hooks: counted (more output, never less)
  l.onEnd(1.0);
  CHECK(seconds == Approx(2'500e-9).epsilon(1e-12));
  // the next state hook alone is timed by itself, not from the closed transition's start
  gNow += 1'000'000;
  l.onState(2.0, m);
  CHECK(seconds == Approx(3'500e-9).epsilon(1e-12));
}

namespace {
// A tick counter of the test's own: three ticks a nanosecond of the fake clock, from an offset
std::int64_t fakeTicks() {
  return 3 * gNow + 12'345;
}
}  // namespace

TEST_CASE(
    "a timed listener on a tick counter books its sinks' ticks in seconds at every run call's end "
    "and when it goes, at the rate the two clocks show") {
  gNow = 5'000;
  CostlySink a(1'000), b(10);
  double seconds = 0.0;
  testing::Emitter m("m", {});
  {
    run::TimedListener timed({&a, &b}, seconds, fakeTicks, fakeClock);
    devs::Listener& l = timed;
    for (int k = 1; k <= 50; ++k) {
      gNow += 1'000'000;  // simulation between the hooks
      l.onTransition(k, m, devs::Transition::Internal, 1.0);
      l.onState(k, m);
    }
    CHECK(seconds == 0.0);  // the ticks kept until the run call's end
    l.onEnd(50.0);
    // exactly the sinks' own time, 1,010 ns a hook, whatever the ticks' rate
    CHECK(seconds == Approx(101 * 1'010e-9).epsilon(1e-12));
    gNow += 7'000'000;
    l.onTransition(51.0, m, devs::Transition::Internal, 1.0);
    l.onState(51.0, m);
  }
  // (the listener gone) => the last hooks booked too
  CHECK(seconds == Approx(103 * 1'010e-9).epsilon(1e-12));
}

TEST_CASE("the profile line gives every phase and output's share of the total") {
  run::PhaseTimes p;
  p.read = 1.0;
  p.validation = 0.5;
  p.stiffness = 0.5;
  p.build = 1.0;
  p.simulate = 5.0;
  p.output = 2.0;
  const std::string s = run::formatProfile(p);
  CHECK(s ==
        "profile: read 1 s, validation 0.5 s, stiffness guard 0.5 s, build 1 s, simulate 5 s, "
        "output 2 s "
        "(20.0 % of the run), total 10 s");
  CHECK(run::formatProfile({}).find("(0.0 % of the run), total 0 s") != std::string::npos);
}
