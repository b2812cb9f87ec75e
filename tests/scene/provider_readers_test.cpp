// A force provider added the way docs/extending.md shows: a provider class and one reader
// function registered for a `mechanics:` key, here both in this test. The scene reads it like a
// built-in provider: names resolved across included fragments, world points placed, the system
// grouped by what it connects, the provider in the one list (stiffness estimate, energy balance,
// channels), problems reported at their YAML nodes.
#include "scene/provider_readers.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "devs/coupled.hpp"
#include "dynamics/kinematics.hpp"
#include "mechanics/build.hpp"
#include "mechanics/stiffness_estimate.hpp"
#include "models/multibody/multibody_model.hpp"
#include "scene/assembler.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using Catch::Matchers::Contains;

namespace {

// (k N/m, free length L m) between two points: F = k (|d| - L) along d, two-way
class TestSpring final : public forces::ForceProvider {
 public:
  TestSpring(std::string name, forces::Attachment a, forces::Attachment b, double k, double length)
      : forces::ForceProvider(std::move(name)), a_(a), b_(b), k_(k), length_(length) {}

 protected:
  void doEvaluate(const forces::Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd&) const override {
    const dynamics::Vector3 pa = dynamics::pointPosition(s.data, a_.body, a_.p_B);
    const dynamics::Vector3 pb = dynamics::pointPosition(s.data, b_.body, b_.p_B);
    const dynamics::Vector3 d = pb - pa;
    const dynamics::Vector3 F = k_ * (d.norm() - length_) * d.normalized();  // on a, towards b
    if (a_.body > 0) f.addPointForceWorld(a_.body, pa, F);
    if (b_.body > 0) f.addPointForceWorld(b_.body, pb, -F);
  }
  double doPotentialEnergy(const forces::Stage& s) const override {
    const double x = (dynamics::pointPosition(s.data, b_.body, b_.p_B) -
                      dynamics::pointPosition(s.data, a_.body, a_.p_B))
                         .norm() -
                     length_;
    return 0.5 * k_ * x * x;
  }

 private:
  forces::Attachment a_, b_;
  double k_, length_;
};

YARDSIM_REGISTER_PROVIDER(
    testSprings, scene::ProviderReader{
                     .key = "test_springs",
                     .summary = "name: {between: [{body, point}, {body, point}], k, free_length}",
                     .read = [](const std::string&, const YAML::Node& n,
                                const scene::spec::Reader& r, const std::string& key) {
                       mechanics::MechanicsSpec::ProviderSpec out;
                       if (!r.keys(n, {"between", "k", "free_length"}, key)) return out;
                       const YAML::Node ends = n["between"];
                       if (!ends.IsSequence() || ends.size() != 2) {
                         r.fail(ends, key + ".between", "expected two points {body, point}");
                         return out;
                       }
                       for (std::size_t i = 0; i < 2; ++i)
                         out.attachments.push_back(scene::readPoint(
                             r, ends[i], key + ".between[" + std::to_string(i) + "]"));
                       const double k = r.number(n["k"], key + ".k", 0.0, true);
                       const double length =
                           r.number(n["free_length"], key + ".free_length", 0.0, true);
                       if (n["k"] && !(k > 0)) r.fail(n["k"], key + ".k", "k must be > 0 N/m");
                       out.build = [k, length](const std::string& name, const dynamics::Model&,
                                               const std::vector<forces::Attachment>& at) {
                         return std::make_unique<TestSpring>(name, at[0], at[1], k, length);
                       };
                       return out;
                     }});

// a 10 kg block on a vertical slider hanging from the world by the spring, 0.3 m below its free
// length: omega = sqrt(k/m)
std::string hanging(const std::string& spring) {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.001}
until: 0.01
mechanics:
  bodies:
    block:
      parent: world
      joint: {type: prismatic, axis: [0, 0, 1], q0: -1.3}
      mass: 10
      inertia: [1, 1, 1]
  test_springs:
)" + spring;
}

const std::string kSpring =
    "    spring: {between: [{point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}], k: 4000, "
    "free_length: 1}\n";

}  // namespace

TEST_CASE(
    "a registered provider is read, built into the system's one list, and seen by the stiffness "
    "estimate") {
  testing::SceneDir dir;
  auto r = scene::loadScene(dir.write("s.yaml", hanging(kSpring)));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  REQUIRE(r.scene->systems.size() == 1);
  const auto& spec = r.scene->systems[0]->spec;
  REQUIRE(spec.providers.size() == 1);
  CHECK(spec.providers[0].kind == "test_springs");
  CHECK(spec.providers[0].name == "spring");
  CHECK(spec.providers[0].attachments[0].first == "world");
  CHECK(spec.providers[0].attachments[1].first == "block");
  // (linearised stage function) => the spring's own frequency, attributed to it
  const auto e = mechanics::estimateStiffness(mechanics::buildMechanics(spec));
  CHECK(e.omegaMax == Approx(std::sqrt(4000.0 / 10.0)).epsilon(1e-5));
  CHECK(e.element == "provider 'spring'");
  // (assembled run) => the provider's energy channel at the start: k x^2 / 2 with x = 0.3 m
  auto root = scene::assemble(*r.scene);
  std::vector<models::Channel> channels;
  for (const auto& c : root->components())
    if (auto* mb = dynamic_cast<const models::MultibodyModel*>(c.get())) {
      CHECK(mb->system().contributed().size() == 1);
      mb->channels(channels);
    }
  bool found = false;
  for (const auto& c : channels)
    if (c.name == "spring.energy") {
      found = true;
      CHECK(c.read() == Approx(0.5 * 4000.0 * 0.09).epsilon(1e-12));
    }
  CHECK(found);
}

TEST_CASE(
    "a registered provider in an included, placed fragment: names resolved, world points placed") {
  testing::SceneDir dir;
  dir.write("rig.yaml", R"(schema_version: 1
mechanics:
  bodies:
    block:
      parent: world
      joint: {type: prismatic, axis: [0, 0, 1], q0: -1.3}
      mass: 10
      inertia: [1, 1, 1]
  test_springs:
    spring: {between: [{point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}], k: 4000, free_length: 1}
)");
  auto r = scene::loadScene(dir.write("s.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.001}
components:
  rig: {include: rig.yaml, placement: {xyz: [5, 0, 2]}}
)"));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  const auto& spec = r.scene->systems.at(0)->spec;
  REQUIRE(spec.providers.size() == 1);
  CHECK(spec.providers[0].name == "rig.spring");
  CHECK(spec.providers[0].attachments[1].first == "rig.block");
  CHECK(spec.providers[0].attachments[0].second.isApprox(dynamics::Vector3(5, 0, 2)));
}

TEST_CASE("a registered provider's problems are reported at their nodes") {
  testing::SceneDir dir;
  const auto unknown = scene::loadScene(
      dir.write("a.yaml", hanging("    spring: {between: [{point: [0, 0, 0]}, {body: blok, point: "
                                  "[0, 0, 0]}], k: 4000, free_length: 1}\n")));
  CHECK_FALSE(unknown.scene);
  CHECK_THAT(unknown.diagnostics.report(), Contains("unknown body 'blok'") && Contains("block"));
  const auto key = scene::loadScene(dir.write(
      "b.yaml",
      hanging(
          "    spring: {between: [{point: [0, 0, 0]}, {body: block}], k: -1, free_lenght: 1}\n")));
  CHECK_FALSE(key.scene);
  CHECK_THAT(key.diagnostics.report(),
             Contains("b.yaml:") && Contains("free_lenght") && Contains("free_length"));
  const auto misspelt =
      scene::loadScene(dir.write("c.yaml", hanging(kSpring) + "  test_sprngs: {}\n"));
  CHECK_THAT(misspelt.diagnostics.report(), Contains("test_sprngs") && Contains("test_springs"));
}

TEST_CASE("a mechanics key is registered once") {
  CHECK_THROWS_AS(scene::registerProviderReader({"test_springs", "", {}}), std::invalid_argument);
  CHECK_THROWS_AS(scene::registerProviderReader({"ropes", "", {}}), std::invalid_argument);
  const auto keys = scene::mechanicsKeys();
  CHECK(std::count(keys.begin(), keys.end(), "test_springs") == 1);
}
