#include "run/profile.hpp"

#include <catch2/catch.hpp>
#include <thread>

using namespace yardsim;

namespace {
// Counts the hooks it receives and spends 1 ms in each.
struct SlowCounter : devs::Listener {
  int calls = 0;
  void hook() {
    ++calls;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  void onStart(devs::Time, std::span<devs::AtomicBase* const>) override { hook(); }
  void onEnd(devs::Time) override { hook(); }
};
}  // namespace

TEST_CASE("a timed listener forwards each hook and books the time spent in it") {
  SlowCounter inner;
  double seconds = 0.0;
  run::TimedListener timed(inner, seconds);
  devs::Listener& l = timed;
  l.onStart(0.0, {});
  l.onEnd(1.0);
  l.onEnd(2.0);
  CHECK(inner.calls == 3);
  CHECK(seconds >= 0.003);
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
