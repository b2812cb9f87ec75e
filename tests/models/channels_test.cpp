#include "models/channels.hpp"

#include <catch2/catch.hpp>

#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

TEST_CASE("channels are collected with full names and selected by globs") {
  auto scene = scene::loadSceneOrThrow(std::string(YARDSIM_SOURCE_DIR) + "/examples/gpt/scene.yaml");
  auto root = scene::assemble(*scene);
  const auto all = models::collectChannels(*root);
  std::vector<std::string> names;
  for (const auto& c : all) names.push_back(c.column());
  CHECK(names == std::vector<std::string>{"ef.genr.emitted[-]", "ef.transd.arrived[-]",
                                          "ef.transd.solved[-]", "ef.transd.throughput[1/s]",
                                          "proc.busy[-]"});
  CHECK(models::selectChannels(all, {"ef.transd.*"}).size() == 3);
  CHECK(models::selectChannels(all, {"*.busy", "ef.genr.emitted"}).size() == 2);
  CHECK(models::selectChannels(all, {"nothing*"}).empty());
  CHECK(models::globMatch("crane?.hoist*", "crane1.hoist12.tension"));
  CHECK_FALSE(models::globMatch("crane?.hoist", "crane1.hoist12"));
}
