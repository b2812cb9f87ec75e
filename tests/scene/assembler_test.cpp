#include "scene/assembler.hpp"

#include <catch2/catch.hpp>

#include "devs/simulator.hpp"
#include "models/library/gpt.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

TEST_CASE("the GPT scene assembles into the hierarchy it describes and runs") {
  auto scene = scene::loadSceneOrThrow(std::string(YARDSIM_SOURCE_DIR) + "/examples/gpt/scene.yaml");
  auto root = scene::assemble(*scene);
  auto& ef = dynamic_cast<devs::Coupled&>(*root->findComponent("ef"));
  CHECK(ef.findPort("in") != nullptr);
  CHECK(ef.findPort("out") != nullptr);
  auto& transd = dynamic_cast<models::library::Transducer&>(*ef.findComponent("transd"));
  CHECK(transd.path() == "ef.transd");  // the scene root's name is not part of paths
  devs::Simulator sim(*root);
  sim.run();
  // period 1 s, processing 1.5 s: every other job is lost; 20 s observed
  CHECK(transd.state().arrived == 20);
  CHECK(transd.state().solved == 10);
  CHECK(transd.throughput() == Approx(0.5));
  CHECK(transd.meanTurnaround() == Approx(1.5));
}
