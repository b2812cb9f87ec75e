#include "devs/port.hpp"

#include <catch2/catch.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "devs/atomic.hpp"
#include "support/allocation_counter.hpp"

using namespace yardsim;
using yardsim::testing::allocationCount;

namespace {
struct Pair {
  int a;
  int b;
};
struct Ports final : devs::Atomic<int> {
  Ports() : devs::Atomic<int>("ports", 0) {}
  devs::OutPort<int>& ints = addOutPort<int>("ints");
  devs::InPort<int>& intsIn = addInPort<int>("ints_in");
  devs::OutPort<std::string>& names = addOutPort<std::string>("names");
  devs::InPort<std::string>& namesIn = addInPort<std::string>("names_in");
  devs::Time timeAdvance(const int&) const override { return devs::kInfinity; }
  void output(const int&) const override {}
  void internalTransition(int&) const override {}
  void externalTransition(int&, devs::Time) const override {}
};
}  // namespace

TEST_CASE("a bag of small values keeps its first messages inside the port") {
  STATIC_REQUIRE(devs::kInlineBag<int>);
  STATIC_REQUIRE(devs::kInlineBag<double>);
  STATIC_REQUIRE(devs::kInlineBag<Pair>);
  STATIC_REQUIRE(!devs::kInlineBag<std::string>);
  Ports m;
  const std::size_t before = allocationCount();
  m.ints.add(7);
  m.ints.add(8);  // two ints fit in the pointer's bytes
  CHECK(allocationCount() == before);
  m.ints.appendTo(m.intsIn);
  CHECK(allocationCount() == before);
  CHECK(m.intsIn.values().size() == 2);
  CHECK(m.intsIn.values()[0] == 7);
  CHECK(m.intsIn.values()[1] == 8);
}

TEST_CASE("a bag keeps its messages in order across its move to the heap, and its capacity") {
  Ports m;
  for (int i = 0; i < 1000; ++i) m.ints.add(i * 3);
  REQUIRE(m.ints.size() == 1000);
  std::int64_t sum = 0;
  for (int v : m.ints.values()) sum += v;
  CHECK(sum == 3 * 999 * 1000 / 2);
  CHECK(m.ints.values()[999] == 2997);
  m.ints.appendTo(m.intsIn);
  m.ints.appendTo(m.intsIn);  // appended behind the first copy
  REQUIRE(m.intsIn.size() == 2000);
  CHECK(m.intsIn.values()[1000] == 0);
  CHECK(m.intsIn.values()[1999] == 2997);
  // (cleared bags) => empty, refilled without a heap block
  m.ints.clear();
  m.intsIn.clear();
  CHECK(m.ints.empty());
  CHECK(m.intsIn.values().empty());
  const std::size_t before = allocationCount();
  for (int i = 0; i < 1000; ++i) m.ints.add(i);
  m.ints.appendTo(m.intsIn);
  CHECK(allocationCount() == before);
  CHECK(m.intsIn.values()[500] == 500);
}

TEST_CASE("a bag of other values is a vector with the port's count") {
  Ports m;
  m.names.add(std::string(40, 'x'));
  m.names.add("y");
  m.names.appendTo(m.namesIn);
  REQUIRE(m.namesIn.size() == 2);
  CHECK(m.namesIn.values()[0] == std::string(40, 'x'));
  CHECK(m.namesIn.values()[1] == "y");
  m.namesIn.clear();
  CHECK(m.namesIn.size() == 0);
  CHECK(m.namesIn.values().empty());
}

TEST_CASE("a bag is appended to each of several destinations, in order, the same one twice") {
  Ports a, b;
  // (bags of one and of three messages, inline and on the heap) => every destination gets them all
  for (const int n : {1, 3}) {
    b.ints.add(-1);  // a destination with a message of its own keeps it first
    b.ints.appendTo(b.intsIn);
    b.ints.clear();
    for (int i = 0; i < n; ++i) a.ints.add(10 + i);
    devs::PortBase* const dsts[] = {&a.intsIn, &b.intsIn, &a.intsIn};
    a.ints.appendToEach(dsts);
    REQUIRE(a.intsIn.size() == static_cast<std::size_t>(2 * n));
    REQUIRE(b.intsIn.size() == static_cast<std::size_t>(1 + n));
    CHECK(b.intsIn.values()[0] == -1);
    for (int i = 0; i < n; ++i) {
      CHECK(a.intsIn.values()[static_cast<std::size_t>(i)] == 10 + i);
      CHECK(a.intsIn.values()[static_cast<std::size_t>(n + i)] == 10 + i);
      CHECK(b.intsIn.values()[static_cast<std::size_t>(1 + i)] == 10 + i);
    }
    for (devs::PortBase* p : {static_cast<devs::PortBase*>(&a.ints), dsts[0], dsts[1]}) p->clear();
  }
  // (a bag of strings, two messages) => both destinations get both, in order
  a.names.add("x");
  a.names.add("y");
  devs::PortBase* const named[] = {&b.namesIn, &a.namesIn};
  a.names.appendToEach(named);
  CHECK(std::vector<std::string>(b.namesIn.values().begin(), b.namesIn.values().end()) ==
        std::vector<std::string>{"x", "y"});
  CHECK(std::vector<std::string>(a.namesIn.values().begin(), a.namesIn.values().end()) ==
        std::vector<std::string>{"x", "y"});
}
