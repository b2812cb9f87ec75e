#include "models/library/spring_mass.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <yaml-cpp/yaml.h>

#include "devs/coupled.hpp"
#include "devs/simulator.hpp"
#include "support/record_collector.hpp"

using namespace yardsim;
using models::library::SpringMass;
using models::library::SpringMassParams;
using models::library::StepMethod;

namespace {
std::vector<double> upcrossings(const SpringMassParams& p, double until) {
  devs::Coupled root("root");
  root.add<SpringMass>("s", p);
  devs::Simulator sim(root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  sim.runUntil(until);
  std::vector<double> t;
  for (const auto& r : rec.ofKind("out")) t.push_back(r.t);
  return t;
}
}  // namespace

TEST_CASE("an undamped spring-mass oscillates at 2 pi sqrt(m/k), located by state events") {
  const SpringMassParams p{4.0, 9.0, 0.0, 0.0, 1.0, 0.01, StepMethod::Rk4, 1e6};
  const double period = 2.0 * M_PI * std::sqrt(4.0 / 9.0);
  const auto t = upcrossings(p, 20.0);
  REQUIRE(t.size() >= 4);
  // x(t) = sin(w t) / w crosses zero upwards at t = k T (k >= 1; t = 0 is the start)
  for (std::size_t k = 0; k < 4; ++k) CHECK(t[k] == Approx(double(k + 1) * period).margin(1e-8));
}

TEST_CASE("RK4 keeps the energy of an undamped spring — damping removes it") {
  auto finalEnergy = [](double damping) {
    devs::Coupled root("root");
    auto& s = root.add<SpringMass>("s", SpringMassParams{1, 1, damping, 1, 0, 0.01, StepMethod::Rk4, 1e6});
    devs::Simulator sim(root);
    sim.runUntil(50.0);
    return s.energy(s.state().x);
  };
  CHECK(finalEnergy(0.0) == Approx(0.5).epsilon(1e-6));
  // light damping: E(t) ~ E0 exp(-c t / m) averaged over a cycle
  CHECK(finalEnergy(0.02) == Approx(0.5 * std::exp(-0.02 * 50.0)).epsilon(0.02));
}

TEST_CASE("explicit Euler converges at first order and RK4 at fourth") {
  auto error = [](StepMethod m, double dt) {
    devs::Coupled root("root");
    auto& s = root.add<SpringMass>("s", SpringMassParams{1, 1, 0, 1, 0, dt, m, 1e6});
    devs::Simulator sim(root);
    sim.runUntil(1.0);
    return std::abs(s.state().x.x - std::cos(1.0));
  };
  const double e1 = error(StepMethod::Euler, 0.01), e2 = error(StepMethod::Euler, 0.005);
  CHECK(std::log2(e1 / e2) == Approx(1.0).margin(0.05));
  const double r1 = error(StepMethod::Rk4, 0.1), r2 = error(StepMethod::Rk4, 0.05);
  CHECK(std::log2(r1 / r2) == Approx(4.0).margin(0.2));
}
