// Once set up, a stage of a system with ropes and an equalizer allocates nothing: the providers'
// scratch is made once in mechanics::Data and handed over at every stage; nor does a stage that
// writes the added mass following a hull's draft.
#include <catch2/catch.hpp>

#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "mechanics/data.hpp"
#include "mechanics/energy.hpp"
#include "mechanics/stage.hpp"
#include "mechanics/system.hpp"
#include "support/allocation_counter.hpp"
#include "support/scene_files.hpp"
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

TEST_CASE("a stage writing the added mass that follows a hull's draft allocates nothing") {
  // (a 20 x 8 x 4 m box whose added mass follows its draft, half in the water, heaving) => each
  // stage interpolates its A-infinity into the kernel's, the servos' and the reactions' workspaces
  // (mechanics/follow_draft.hpp), and the energy into its own, without allocating
  testing::SceneDir dir;
  forces::writeObj(forces::boxMesh(dynamics::Vector3(20, 8, 4), 10, 4, 4), dir.file("box.obj"));
  const mechanics::System sys(testing::buildFromYaml(R"(bodies:
  box:
    parent: world
    joint: {type: free, q0: {xyz: [0, 0, 0.3]}}
    mass: 4.0e5
    inertia: [2.7e6, 1.4e7, 1.5e7]
    added_mass: {hull: )" + dir.file("box.obj") + R"(, follow_draft: [1.0, 2.0, 3.0]}
)"),
                              {}, "test");
  REQUIRE(sys.draftAddedMass().size() == 1);
  mechanics::Data d(sys);
  mechanics::connectStage(sys, d);
  const auto n = static_cast<std::size_t>(sys.model().nbodies);
  const mechanics::SetPoints sp{std::vector<mechanics::JointDrive>(n),
                                std::vector<mechanics::ActorLoad>(n),
                                std::vector<mechanics::WinchJob>(sys.ropes().size())};
  d.setPoints = &sp;
  Eigen::VectorXd q = sys.description().q0;
  const Eigen::VectorXd v = Eigen::VectorXd::Constant(sys.model().nv, -0.1);  // sinking
  Eigen::VectorXd a(sys.model().nv);
  d.kernel.acceleration(0.0, q, v, a);  // set-up
  double sink = 0.0;
  const std::size_t before = testing::allocationCount();
  for (int k = 1; k <= 10; ++k) {
    q[2] = 0.3 - 0.1 * k;  // through the table's drafts: 1.7 .. 2.7 m
    d.kernel.acceleration(0.01 * k, q, v, a);
    sink += a.sum() + mechanics::energy(sys, d, d.view, q, v, 0.01 * k) +
            mechanics::nonConservativePower(sys, d, sp, q, v, 0.01 * k);
  }
  CHECK(testing::allocationCount() == before);
  CHECK(std::isfinite(sink));
  CHECK(d.kernel.data().hasAddedMass[1]);  // (wet: the written added mass is on)
}
