#include "models/registry.hpp"

#include <catch2/catch.hpp>

#include "devs/simulator.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
// A user type, registered exactly as the built-in ones are.
struct Counter final : devs::Atomic<int> {
  explicit Counter(std::string n) : devs::Atomic<int>(std::move(n), 0) {}
  devs::InPort<int>& in = addInPort<int>("in");
  devs::Time timeAdvance(const int&) const override { return devs::kInfinity; }
  void output(const int&) const override {}
  void internalTransition(int&) const override {}
  void externalTransition(int& s, devs::Time) const override { s += int(in.values().size()); }
};
YARDSIM_REGISTER_TYPE(testCounter, models::TypeInfo{
    .name = "test_counter",
    .summary = "counts messages",
    .params = {},
    .ports = [](const models::Params&) { return std::vector<models::PortSpec>{{"in", "int", true}}; },
    .create = [](const std::string& n, const models::Params&) -> std::unique_ptr<devs::AtomicBase> {
      return std::make_unique<Counter>(n);
    },
    .check = {},
    .feedthrough = {}});
}  // namespace

TEST_CASE("built-in and user types are found by name") {
  auto& reg = models::Registry::instance();
  for (const char* n : {"generator", "processor", "transducer", "delay", "spring_mass", "test_counter"})
    CHECK(reg.find(n) != nullptr);
  CHECK(reg.find("no_such_type") == nullptr);
  const auto names = reg.names();
  CHECK(std::is_sorted(names.begin(), names.end()));
}

TEST_CASE("a type name is registered once") {
  models::TypeInfo again = *models::Registry::instance().find("delay");
  CHECK_THROWS_WITH(models::Registry::instance().add(again), Catch::Contains("registered twice"));
}

TEST_CASE("a user type runs from a scene, and a scene builds only what it names") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", R"(schema_version: 1
components:
  g: {type: generator, params: {period: 1}}
  c: {type: test_counter}
couplings:
  - {from: g.out, to: c.in}
)"));
  const auto before = models::Registry::instance().instantiated();
  auto root = scene::assemble(*scene);
  auto after = models::Registry::instance().instantiated();
  for (auto& [type, n] : after) n -= before.count(type) ? before.at(type) : 0;
  std::erase_if(after, [](const auto& kv) { return kv.second == 0; });
  CHECK(after == std::map<std::string, std::size_t>{{"generator", 1}, {"test_counter", 1}});
  devs::Simulator sim(*root);
  sim.runUntil(4.5);
  const auto& counter = static_cast<const Counter&>(*root->findComponent("c"));
  CHECK(counter.state() == 5);  // jobs at t = 0, 1, 2, 3, 4
}
