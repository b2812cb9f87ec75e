#include "devs/coupled.hpp"
#include "devs/simulator.hpp"

#include <array>
#include <catch2/catch.hpp>
#include <string>

#include "support/test_models.hpp"

using namespace yardsim;
using namespace yardsim::testing;
using devs::Coupled;
using devs::ModelError;

namespace {
struct DoubleSink final : devs::Atomic<int> {
  DoubleSink() : devs::Atomic<int>("dsink", 0) {}
  devs::InPort<double>& in = addInPort<double>("level");
  devs::Time timeAdvance(const int&) const override { return devs::kInfinity; }
  void output(const int&) const override {}
  void internalTransition(int&) const override {}
  void externalTransition(int&, devs::Time) const override {}
};
}  // namespace

TEST_CASE("a coupling between different value types names both ports, types and paths") {
  Coupled root("yard");
  auto& crane = root.add<Coupled>("crane");
  auto& gen = crane.add<Emitter>("gen", std::vector<devs::Time>{});
  auto& out = crane.addOutPort<int>("out");
  crane.couple(gen.out, out);
  auto& sink = root.add<DoubleSink>();
  try {
    root.couple(out, sink.in);
    FAIL("expected a ModelError");
  } catch (const ModelError& e) {
    const std::string msg = e.what();
    CHECK_THAT(msg, Catch::Contains("'out'") && Catch::Contains("'yard.crane'"));
    CHECK_THAT(msg, Catch::Contains("'level'") && Catch::Contains("'yard.dsink'"));
    CHECK_THAT(msg, Catch::Contains("value type int") && Catch::Contains("value type double"));
  }
}

TEST_CASE("couplings must be EIC, IC or EOC of the model that declares them") {
  Coupled root("root");
  auto& a = root.add<Emitter>("a", std::vector<devs::Time>{});
  auto& b = root.add<Collector>("b");
  auto& inner = root.add<Coupled>("inner");
  auto& c = inner.add<Collector>("c");
  // input to output of the same child, output to output of a sibling, reaching two levels down
  CHECK_THROWS_AS(root.couple(b.in, b.tick), ModelError);
  CHECK_THROWS_AS(root.couple(a.out, b.tick), ModelError);
  CHECK_THROWS_WITH(root.couple(a.out, c.in),
                    Catch::Contains("root.inner.c") && Catch::Contains("a coupling goes from"));
  CHECK_NOTHROW(root.couple(a.out, b.in));
  CHECK(root.couplingCount() == 1);
}

TEST_CASE("names are checked: duplicates, dots, re-parenting") {
  Coupled root("root");
  root.add<Collector>("x");
  CHECK_THROWS_WITH(root.add<Collector>("x"), Catch::Contains("already has a component named 'x'"));
  CHECK_THROWS_WITH(Coupled("a.b"), Catch::Contains("dots"));
  CHECK_THROWS_WITH(Coupled(""), Catch::Contains("empty"));
  Coupled other("other");
  auto loose = std::make_unique<Collector>("y");
  CHECK_THROWS_WITH(loose->addInPort<int>("in"), Catch::Contains("already has a port named 'in'"));
  other.addComponent(std::move(loose));
  CHECK(other.findComponent("y")->path() == "other.y");
}

TEST_CASE("paths follow the hierarchy once placed") {
  auto inner = std::make_unique<Coupled>("inner");
  auto& leaf = inner->add<Collector>("leaf");
  CHECK(leaf.path() == "inner.leaf");  // cached before placement...
  Coupled root("root");
  root.addComponent(std::move(inner));
  CHECK(leaf.path() == "root.inner.leaf");  // ...and recomputed after
  CHECK(leaf.in.path() == "root.inner.leaf.in");
}

TEST_CASE("a root with a hidden name leaves it out of the paths below it") {
  Coupled scene("scene");
  scene.hideNameInPaths();
  auto& crane = scene.add<Coupled>("crane1");
  auto& hoist = crane.add<Collector>("hoist");
  CHECK(hoist.path() == "crane1.hoist");
  CHECK(scene.path() == "scene");
}

TEST_CASE("a direct coupling crosses the hierarchy between atomics below the model") {
  Coupled root("root");
  auto& a = root.add<Coupled>("a");
  auto& gen = a.add<Emitter>("gen", std::vector<devs::Time>{1.0});
  auto& b = root.add<Coupled>("b");
  auto& col = b.add<Collector>("col");
  CHECK_THROWS_WITH(a.coupleDirect(gen.out, col.in), Catch::Contains("both below this model"));
  root.coupleDirect(gen.out, col.in);
  devs::Simulator sim(root);
  sim.run();
  REQUIRE(col.state().bags.size() == 1);
  CHECK(col.state().bags[0].first == 1.0);
}

TEST_CASE("a model with many components finds each by name and refuses a duplicate") {
  // past the linear scan the name index is a hash table: every name found, none invented
  Coupled root("root");
  std::vector<Collector*> added;
  for (int i = 0; i < 1000; ++i) added.push_back(&root.add<Collector>("c" + std::to_string(i)));
  for (int i = 0; i < 1000; ++i) CHECK(root.findComponent("c" + std::to_string(i)) == added[i]);
  CHECK(root.findComponent("c1000") == nullptr);
  CHECK(root.findComponent("c") == nullptr);
  CHECK_THROWS_WITH(root.add<Collector>("c517"), Catch::Contains("already has a component named"));
  CHECK(root.components().size() == 1000);
}

namespace {
// A model with more ports, and larger ones, than fit inside it.
struct Wide final : devs::Atomic<int> {
  explicit Wide(std::string name) : devs::Atomic<int>(std::move(name), 0) {}
  std::array<devs::InPort<std::array<double, 16>>*, 3> big{
      &addInPort<std::array<double, 16>>("b0"), &addInPort<std::array<double, 16>>("b1"),
      &addInPort<std::array<double, 16>>("b2")};
  std::array<devs::OutPort<int>*, 4> outs{&addOutPort<int>("o0"), &addOutPort<int>("o1"),
                                          &addOutPort<int>("o2"), &addOutPort<int>("o3")};
  devs::Time timeAdvance(const int&) const override { return devs::kInfinity; }
  void output(const int&) const override {}
  void internalTransition(int&) const override {}
  void externalTransition(int&, devs::Time) const override {}
};
}  // namespace

TEST_CASE("ports beyond what fits inside a model keep their order names and owner") {
  Wide w("w");
  REQUIRE(w.inPorts().size() == 3);
  REQUIRE(w.outPorts().size() == 4);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(w.inPorts()[i] == w.big[i]);
    CHECK(w.inPorts()[i]->name() == "b" + std::to_string(i));
    CHECK(w.findPort("b" + std::to_string(i)) == w.big[i]);
  }
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(w.outPorts()[i] == w.outs[i]);
    CHECK(&w.outPorts()[i]->owner() == &w);
    CHECK(!w.outPorts()[i]->isInput());
  }
  CHECK_THROWS_WITH(w.addOutPort<int>("b1"), Catch::Contains("already has a port named 'b1'"));
  CHECK_THROWS_WITH(w.addOutPort<int>("x.y"), Catch::Contains("dots"));
  CHECK(w.outPorts().size() == 4);
}
