// The event locator on its own: a system falling at a known rate, event functions with known
// zeros, checked against the closed form.
#include "dtss/event_locator.hpp"

#include <catch2/catch.hpp>
#include <vector>

using namespace yardsim;
using dtss::Crossing;
using dtss::Time;

namespace {
// x(t) = x0 - t (exact); g_j = x - level_j, crossing Falling
class Descent final : public dtss::System<double> {
 public:
  explicit Descent(std::vector<double> levels)
      : levels_(std::move(levels)), dirs_(levels_.size(), Crossing::Falling) {}
  void advance(double& x, Time, Time dt) const override { x -= dt; }
  std::span<const Crossing> eventDirections() const override { return dirs_; }
  void eventFunctions(const double& x, Time, std::span<double> g) const override {
    for (std::size_t j = 0; j < levels_.size(); ++j) g[j] = x - levels_[j];
  }

 private:
  std::vector<double> levels_;
  std::vector<Crossing> dirs_;
};

// (system, x at t = 0, target) => the state the stepper would hand to the locator
dtss::State<double> stepTo(const dtss::System<double>& sys, double x0, Time target) {
  dtss::State<double> s{x0, 0.0, x0, target, dtss::Reached{true, false, -1}, 0};
  sys.advance(s.xNext, 0.0, target);
  return s;
}
}  // namespace

TEST_CASE("the locator moves the look-ahead to the earliest crossing, within its tolerance") {
  const Descent sys({0.3, 0.7});  // x = 1 - t reaches 0.7 at t = 0.3 first, 0.3 at t = 0.7
  const dtss::EventLocator<double> locator(1e-12);
  auto s = stepTo(sys, 1.0, 1.0);
  locator.locate(sys, s, 0.0);
  CHECK(s.reached.stateEvent == 1);
  CHECK_FALSE(s.reached.grid);  // the grid point is no longer the target
  CHECK(s.tNext >= 0.3);
  CHECK(s.tNext - 0.3 < 1e-12);
  CHECK(s.xNext == Approx(0.7).margin(1e-12));
  CHECK(s.reached.coincident.empty());  // 0.3 is crossed only later
}

TEST_CASE("functions that cross by the located time are reached with it") {
  const Descent sys({0.5, 0.5, 0.2});  // two functions with one zero; a third crossed later
  const dtss::EventLocator<double> locator(1e-9);
  auto s = stepTo(sys, 1.0, 1.0);
  locator.locate(sys, s, 0.0);
  CHECK(s.reached.stateEvent == 0);
  CHECK(s.tNext == Approx(0.5).margin(1e-9));
  CHECK(s.reached.coincident == std::vector<int>{1});
}

TEST_CASE("no crossing in the step leaves the look-ahead as it was") {
  const Descent sys({-1.0});
  const dtss::EventLocator<double> locator(1e-9);
  auto s = stepTo(sys, 1.0, 0.5);
  const auto before = s;
  locator.locate(sys, s, 0.0);
  CHECK(s.xNext == before.xNext);
  CHECK(s.tNext == before.tNext);
  CHECK(s.reached == before.reached);
}
