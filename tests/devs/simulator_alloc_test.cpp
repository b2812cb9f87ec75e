// The steady state of a run allocates nothing: bags keep their capacity, the event queue and
// the scratch lists are sized once. Every heap allocation is counted here.
#include <catch2/catch.hpp>

#include "support/allocation_counter.hpp"

#include "devs/coupled.hpp"
#include "devs/simulator.hpp"
#include "models/library/delay.hpp"
#include "support/test_models.hpp"

using yardsim::testing::allocationCount;

using namespace yardsim;

namespace {
struct Ping final : devs::Atomic<int> {
  Ping() : devs::Atomic<int>("ping", 0) {}
  devs::OutPort<int>& out = addOutPort<int>("out");
  devs::Time timeAdvance(const int&) const override { return 1.0; }
  void output(const int& s) const override {
    for (int j = 0; j < 3; ++j) out.add(s + j);
  }
  void internalTransition(int& s) const override { ++s; }
  void externalTransition(int&, devs::Time) const override {}
};
struct Count final : devs::Atomic<long> {
  Count() : devs::Atomic<long>("count", 0) {}
  devs::InPort<int>& in = addInPort<int>("in");
  devs::Time timeAdvance(const long&) const override { return devs::kInfinity; }
  void output(const long&) const override {}
  void internalTransition(long&) const override {}
  void externalTransition(long& s, devs::Time) const override {
    s += static_cast<long>(in.values().size());
  }
};
}  // namespace

TEST_CASE("no heap allocation per message in the steady state") {
  devs::Coupled root("root");
  auto& ping = root.add<Ping>();
  auto& r1 = root.add<models::library::Delay>("r1", 0.25);
  auto& r2 = root.add<models::library::Delay>("r2", 0.0);
  auto& count = root.add<Count>();
  root.couple(ping.out, r1.in);
  root.couple(r1.out, r2.in);
  root.couple(r2.out, count.in);
  root.couple(ping.out, count.in);
  devs::Simulator sim(root);
  sim.runUntil(10.0);  // warm-up: bags reach their capacity
  const std::size_t before = allocationCount();
  const long countBefore = count.state();
  sim.runUntil(10000.0);
  CHECK(count.state() - countBefore > 50000);  // messages did flow
  CHECK(allocationCount() == before);
}
