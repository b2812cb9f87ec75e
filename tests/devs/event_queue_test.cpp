#include "devs/event_queue.hpp"

#include <catch2/catch.hpp>
#include <random>

using yardsim::devs::EventQueue;
using yardsim::devs::kInfinity;

TEST_CASE("the event queue agrees with a brute-force minimum under random rescheduling") {
  constexpr std::uint32_t n = 300;
  EventQueue q(n);
  std::vector<double> tn(n, kInfinity);
  std::mt19937 rng(42);
  std::uniform_int_distribution<std::uint32_t> pick(0, n - 1);
  std::uniform_real_distribution<double> time(0.0, 100.0);
  for (int it = 0; it < 20000; ++it) {
    const std::uint32_t m = pick(rng);
    const double t = (rng() % 5 == 0) ? kInfinity : std::floor(time(rng));  // ties and removals
    q.schedule(m, t);
    tn[m] = t;
    const double brute = *std::min_element(tn.begin(), tn.end());
    REQUIRE(q.topTime() == brute);
    if (it % 7 == 0 && !q.empty()) {
      const std::uint32_t top = q.pop();
      REQUIRE(tn[top] == brute);
      tn[top] = kInfinity;
    }
  }
}
