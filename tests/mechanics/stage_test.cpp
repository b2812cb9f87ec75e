// The stage function: every provider of the one list, each with its own scratch, then ABA — the
// same accelerations as the providers evaluated one by one and ABA by hand.
#include "mechanics/stage.hpp"

#include <catch2/catch.hpp>
#include <limits>
#include <memory>
#include <random>

#include "dynamics/aba.hpp"
#include "dynamics/kinematics.hpp"
#include "mechanics/data.hpp"
#include "mechanics/system.hpp"
#include "tests/mechanics/mechanics_fixture.hpp"

using namespace yardsim;

using testing::noSetPoints;

TEST_CASE("the stage adds every provider once, each with its scratch, then ABA") {
  const mechanics::System sys(testing::buildFromYaml(testing::kHoistAndEqualizer), {}, "test");
  REQUIRE(sys.ropes().size() == 3);  // two wire ropes, then the equalizer
  CHECK(sys.ropes()[2]->branchCount() == 2);
  mechanics::Data d(sys);
  REQUIRE(d.providerScratch.size() == sys.providers().size());
  for (std::size_t i = 0; i < sys.providers().size(); ++i)
    CHECK(d.scratchOf(sys, *sys.providers()[i]) == d.providerScratch[i].get());
  mechanics::connectStage(sys, d);
  const mechanics::SetPoints sp = noSetPoints(sys);
  d.setPoints = &sp;
  const auto& m = sys.model();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  Eigen::VectorXd v(m.nv);
  for (int i = 0; i < m.nv; ++i) v[i] = u(rng);
  const Eigen::VectorXd q = sys.description().q0;
  Eigen::VectorXd a(m.nv);
  d.kernel.acceleration(0.5, q, v, a);
  // (by hand) => each provider evaluated alone, without a scratch, summed, then ABA
  dynamics::Data kin(m);
  dynamics::forwardKinematics(m, kin, q, v);
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  for (const forces::ForceProvider* p : sys.providers())
    p->evaluate(forces::Stage{0.5, m, kin, q, v}, f, tau);
  REQUIRE(f.worldFrame(1).norm() > 1e3);  // the ropes are taut: real forces
  const Eigen::VectorXd expected = dynamics::aba(m, kin, q, v, tau, &f);
  CHECK((a - expected).norm() <= 1e-12 * expected.norm());
}

namespace {
// A provider that adds NaN to one body's world-frame force, or nothing
class NotFinite final : public forces::ForceProvider {
 public:
  NotFinite(std::string name, int body) : ForceProvider(std::move(name)), body_(body) {}

 protected:
  void doEvaluate(const forces::Stage& /*s*/, dynamics::ExternalForces& f,
                  Eigen::VectorXd& /*tau*/) const override {
    if (body_ < 0) return;
    dynamics::Force F = dynamics::Force::Zero();
    F[4] = std::numeric_limits<double>::quiet_NaN();
    f.addWorldFrame(body_, F);
  }

 private:
  int body_;
};

// (the hoist scene's spec, providers (name, body: -1 adds nothing) after its ropes) => the system
std::unique_ptr<mechanics::System> withProviders(
    const std::vector<std::pair<std::string, int>>& extra) {
  models::Params p;
  const YAML::Node n = YAML::Load(testing::kHoistAndEqualizer);
  for (const char* key : {"bodies", "loops", "ropes", "equalizers"})
    p.set(key, n[key] ? n[key] : YAML::Load("{}"), {});
  p.set("gravity", YAML::Load("[0, 0, -9.81]"), {});
  auto spec = scene::parseMechanics(
      p, [](const std::string& param, const YAML::Node&, const std::string& key,
            const std::string& msg) { FAIL(param + "." + key + ": " + msg); });
  for (const auto& [name, body] : extra) {
    mechanics::MechanicsSpec::ProviderSpec ps;
    ps.kind = "test";
    ps.name = name;
    ps.build = [body = body](const std::string& full, const dynamics::Model&,
                             const std::vector<forces::Attachment>&) {
      return std::make_unique<NotFinite>(full, body);
    };
    spec.providers.push_back(std::move(ps));
  }
  return std::make_unique<mechanics::System>(mechanics::buildMechanics(spec),
                                             mechanics::ServoSettings{}, "test");
}
}  // namespace

TEST_CASE("the stage checks the providers' sum once and names the provider that is not finite") {
  // (a finite provider, then one that adds NaN to the hook, then another finite one) => the
  // error names the second and the hook, as a check after every provider would
  const auto sys = withProviders({{"quiet", -1}, {"broken", 2}, {"after", -1}});
  mechanics::Data d(*sys);
  mechanics::connectStage(*sys, d);
  const mechanics::SetPoints sp = noSetPoints(*sys);
  d.setPoints = &sp;
  const auto& m = sys->model();
  REQUIRE(m.names[2] == "hook");
  Eigen::VectorXd a(m.nv);
  const Eigen::VectorXd q = sys->description().q0, v = Eigen::VectorXd::Zero(m.nv);
  try {
    d.kernel.acceleration(0.5, q, v, a);
    FAIL("no error");
  } catch (const forces::ForceError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("'broken'") != std::string::npos);
    CHECK(what.find("body 'hook'") != std::string::npos);
    CHECK(what.find("t = 0.5") != std::string::npos);
  }
  // (the same providers, all finite) => no error: the check passes finite sums
  const auto fine = withProviders({{"quiet", -1}, {"after", -1}});
  mechanics::Data d2(*fine);
  mechanics::connectStage(*fine, d2);
  d2.setPoints = &sp;
  CHECK_NOTHROW(d2.kernel.acceleration(0.5, q, v, a));
  CHECK(a.allFinite());
}
