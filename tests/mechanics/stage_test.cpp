// The stage function: every provider of the one list, each with its own scratch, then ABA — the
// same accelerations as the providers evaluated one by one and ABA by hand.
#include "mechanics/stage.hpp"

#include <catch2/catch.hpp>
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
