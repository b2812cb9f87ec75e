#include "dtss/grid.hpp"

#include <catch2/catch.hpp>
#include <random>

using yardsim::dtss::Grid;

TEST_CASE("the first grid point after t is found exactly, rounding included") {
  std::mt19937 rng(7);
  for (const Grid g : {Grid{0.0, 0.1}, Grid{0.3, 0.01}, Grid{-1.0, 0.0125}, Grid{100.0, 1e-3}}) {
    std::uniform_real_distribution<double> u(g.t0, g.t0 + 1000 * g.h);
    for (int i = 0; i < 2000; ++i) {
      const double t = (i % 2) ? u(rng) : g.at(static_cast<std::int64_t>(i / 2));  // on-grid too
      const auto k = g.indexAfter(t);
      REQUIRE(g.at(k) > t);
      if (k > 0) REQUIRE(g.at(k - 1) <= t);
    }
  }
  CHECK(Grid{0.0, 0.3}.at(7) == 7 * 0.3);  // from k, not by accumulating h
  // steps whose inverse is an integer land on the nearest double of the decimal time
  CHECK(Grid{0.0, 0.05}.at(599) == 29.95);
  CHECK(Grid{0.0, 0.002}.at(14975) == 29.95);
  CHECK(Grid{0.0, 0.1}.at(3) == 0.3);
}
