#include "devs/flatten.hpp"

#include <catch2/catch.hpp>

#include "support/gpt_builders.hpp"

using namespace yardsim;

TEST_CASE("flattening reaches atomic inputs through every level") {
  auto gpt = testing::makeGpt(testing::GptParameters{});
  const auto flat = devs::flatten(*gpt);
  REQUIRE(flat.atomics.size() == 3);
  CHECK(flat.atomics[0]->path() == "gpt.ef.genr");
  CHECK(flat.atomics[1]->path() == "gpt.ef.transd");
  CHECK(flat.atomics[2]->path() == "gpt.proc");
  for (std::uint32_t i = 0; i < 3; ++i) CHECK(flat.atomics[i]->simIndex() == i);
  // genr.out reaches transd.arrived (IC) and proc.in (EOC then IC at the top)
  const std::uint32_t genrOut = flat.outBegin[0];
  std::vector<std::string> reached;
  for (auto k = flat.destBegin[genrOut]; k < flat.destBegin[genrOut + 1]; ++k)
    reached.push_back(flat.dests[k].port->path());
  std::sort(reached.begin(), reached.end());
  CHECK(reached == std::vector<std::string>{"gpt.ef.transd.arrived", "gpt.proc.in"});
  // proc.out reaches transd.solved (IC at the top, then EIC into ef)
  const std::uint32_t procOut = flat.outBegin[2];
  REQUIRE(flat.destBegin[procOut + 1] - flat.destBegin[procOut] == 1);
  CHECK(flat.dests[flat.destBegin[procOut]].port->path() == "gpt.ef.transd.solved");
  CHECK(flat.dests[flat.destBegin[procOut]].atomic == 1);
}
