// The stepper on its own: targets on the grid or at earlier time events, never a shifted grid,
// and the commit with the system's reactions.
#include "dtss/stepper.hpp"

#include <catch2/catch.hpp>

using namespace yardsim;
using dtss::Time;

namespace {
// x counts time (exact); a time event every 0.35 s; reactions counted in the state
struct Clock {
  double t = 0.0;
  int timeEvents = 0;
};
class Ticker final : public dtss::System<Clock> {
 public:
  void advance(Clock& x, Time, Time dt) const override { x.t += dt; }
  Time nextTimeEvent(const Clock&, Time t) const override {
    return 0.35 * (std::floor(t / 0.35 + 1e-12) + 1.0);
  }
  void onTimeEvent(Clock& x, Time) const override { ++x.timeEvents; }
};
}  // namespace

TEST_CASE("targets are grid points or earlier time events, and the grid never shifts") {
  const Ticker sys;
  const dtss::Stepper<Clock> stepper(dtss::Grid{0.0, 0.1}, 1e-9);
  dtss::State<Clock> s{Clock{}, 0.0, Clock{}, 0.0, {}, 0};
  std::vector<Time> targets;
  stepper.lookAhead(sys, s, 0.0);
  while (s.tNext < 1.0 - 1e-12) {
    targets.push_back(s.tNext);
    stepper.commit(sys, s);
    stepper.lookAhead(sys, s, s.tx);
  }
  // (grid 0.1 and events at 0.35, 0.7) => 0.1 0.2 0.3 0.35 0.4 0.5 0.6 0.7 0.8 0.9
  const std::vector<Time> expected{0.1, 0.2, 0.3, 0.35, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9};
  REQUIRE(targets.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    CHECK(targets[i] == Approx(expected[i]).margin(1e-12));
  CHECK(s.x.timeEvents == 2);
  CHECK(s.steps == 9);  // grid points committed: 0.1 ... 0.9 (0.7 is both)
  CHECK(s.x.t == Approx(0.9).margin(1e-12));
}
