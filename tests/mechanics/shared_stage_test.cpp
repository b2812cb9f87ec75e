// Which systems may share a stage between a step's start and the committed state's reactions
// (mechanics/shared_stage.cpp).
#include "mechanics/shared_stage.hpp"

#include "mechanics_fixture.hpp"

using namespace yardsim;
using testing::StagedSystem;

TEST_CASE("ropes and equalizers may share their stage: every evaluation writes their paths first") {
  StagedSystem s(testing::buildFromYaml(testing::kHoistAndEqualizer));
  REQUIRE(s.system.ropes().size() == 3);
  CHECK(mechanics::stageShareable(s.system, s.data));
}

TEST_CASE("lumped mooring lines keep a scratch between stages: their stage is not shared") {
  StagedSystem s(testing::buildFromScene(testing::mooredBuoyScene()));
  REQUIRE(s.system.ropes().empty());
  CHECK_FALSE(mechanics::stageShareable(s.system, s.data));
}

TEST_CASE("a rope with mass under a winch (a scratch, masses that follow it) is not shared") {
  StagedSystem s(testing::buildFromScene(testing::hangingRopeScene(19.0)));
  REQUIRE_FALSE(s.system.winchedLines().empty());
  CHECK_FALSE(mechanics::stageShareable(s.system, s.data));
}
