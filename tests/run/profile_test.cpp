#include "run/profile.hpp"

#include <catch2/catch.hpp>
#include <thread>
#include <vector>

using namespace yardsim;

namespace {
// Counts the hooks it receives and spends 1 ms in each.
struct SlowCounter : devs::Listener {
  SlowCounter(int n, std::vector<int>& calls_log) : id(n), log(calls_log) {}
  int id;
  std::vector<int>& log;  // the ids of the listeners called, in order
  int calls = 0;
  void hook() {
    ++calls;
    log.push_back(id);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  void onStart(devs::Time, std::span<devs::AtomicBase* const>) override { hook(); }
  void onEnd(devs::Time) override { hook(); }
};
}  // namespace

TEST_CASE(
    "a timed listener forwards each hook to every sink in order and books the time spent in them") {
  std::vector<int> log;
  SlowCounter first(1, log), second(2, log);
  double seconds = 0.0;
  run::TimedListener timed({&first, &second}, seconds);
  devs::Listener& l = timed;
  l.onStart(0.0, {});
  l.onEnd(1.0);
  l.onEnd(2.0);
  CHECK(first.calls == 3);
  CHECK(second.calls == 3);
  CHECK(log == std::vector<int>{1, 2, 1, 2, 1, 2});
  CHECK(seconds >= 0.006);
  CHECK(seconds < 1.0);
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
