// Once set up, a stage of a system with ropes and an equalizer allocates nothing: the providers'
// scratch is made once in mechanics::Data and handed over at every stage.
#include <catch2/catch.hpp>

#include "mechanics/data.hpp"
#include "mechanics/energy.hpp"
#include "mechanics/stage.hpp"
#include "mechanics/system.hpp"
#include "support/allocation_counter.hpp"
#include "tests/mechanics/mechanics_fixture.hpp"

using namespace yardsim;

TEST_CASE("a stage, the energy and the power allocate nothing once the system is set up") {
  const mechanics::System sys(testing::buildFromYaml(testing::kHoistAndEqualizer), {}, "test");
  mechanics::Data d(sys);
  mechanics::connectStage(sys, d);
  const auto n = static_cast<std::size_t>(sys.model().nbodies);
  const mechanics::SetPoints sp{std::vector<mechanics::JointDrive>(n),
                                std::vector<mechanics::ActorLoad>(n),
                                std::vector<mechanics::WinchJob>(sys.ropes().size())};
  d.setPoints = &sp;
  const Eigen::VectorXd q = sys.description().q0;
  const Eigen::VectorXd v = Eigen::VectorXd::Constant(sys.model().nv, 0.1);
  Eigen::VectorXd a(sys.model().nv);
  d.kernel.acceleration(0.0, q, v, a);  // set-up
  double sink = 0.0;
  const std::size_t before = testing::allocationCount();
  for (int k = 1; k <= 10; ++k) {
    d.kernel.acceleration(0.01 * k, q, v, a);
    sink += a.sum() + mechanics::energy(sys, d, d.view, q, v, 0.01 * k) +
            mechanics::nonConservativePower(sys, d, sp, q, v, 0.01 * k);
  }
  CHECK(testing::allocationCount() == before);
  CHECK(std::isfinite(sink));
}
